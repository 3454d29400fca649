// Harness for lighting_maps_emission: the inputs come through the IN_ macros that lightlab
// generates from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (result, 1), 1 = (diff, spec, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    Light light = Light(IN_light_position, IN_light_ambient, IN_light_diffuse, IN_light_specular);
    float diff;
    float spec;
    vec3 result = lighting_maps_emission(IN_material_diffuse, IN_material_specular, IN_material_emission,
                                         IN_material_shininess, light, IN_FragPos, IN_Normal, IN_viewPos,
                                         diff, spec);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, 0.0, 0.0);
}
