// Harness for blinn_phong: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (result, 1), 1 = (diff, spec, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    float diff;
    float spec;
    vec3 result = blinn_phong(IN_FragPos, IN_Normal, IN_lightPos, IN_viewPos, IN_lightColor, IN_objectColor,
                              IN_ambientStrength, IN_specularStrength, IN_shininess, diff, spec);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, 0.0, 0.0);
}
