// Harness for spot: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (soft-edged result, 1), 1 = (hard-cutoff result, theta).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    SpotLight light = SpotLight(IN_light_position, IN_light_direction, IN_light_cutOff, IN_light_outerCutOff, IN_light_ambient, IN_light_diffuse,
                                IN_light_specular, IN_light_constant, IN_light_linear, IN_light_quadratic);
    float theta;
    float intensity;
    float attenuation;
    vec3 soft = spot_light(light, IN_material_diffuse, IN_material_specular, IN_material_shininess, IN_FragPos, IN_Normal, IN_viewPos,
                           theta, intensity, attenuation);
    vec3 hard = spot_light_hard(light, IN_material_diffuse, IN_material_specular, IN_material_shininess, IN_FragPos, IN_Normal, IN_viewPos);
    o[0] = vec4(soft, 1.0);
    o[1] = vec4(hard, theta);
}
