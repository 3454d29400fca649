// Harness for point: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (result, 1), 1 = (diff, spec, attenuation, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    PointLight light = PointLight(IN_light_position, IN_light_ambient, IN_light_diffuse, IN_light_specular, IN_light_constant, IN_light_linear, IN_light_quadratic);
    float diff;
    float spec;
    float attenuation;
    vec3 result = point_light(light, IN_material_diffuse, IN_material_specular, IN_material_shininess, IN_FragPos, IN_Normal, IN_viewPos,
                              diff, spec, attenuation);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, attenuation, 0.0);
}
