// Harness for multiple_lights: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (all lights, 1), 1 = (without the spotlight, 1).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    vec3 withoutSpot;
    vec3 result = multiple_lights(IN_FragPos, IN_Normal, IN_viewPos, IN_material_diffuse, IN_material_specular, IN_material_shininess,
                                  withoutSpot);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(withoutSpot, 1.0);
}
