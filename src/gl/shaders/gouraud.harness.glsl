// Harness for gouraud: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (FragColor.rgb, 1), 1 = (LightingColor, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    mat4 model = IN_model;
    vec3 LightingColor = gouraud_vertex(IN_aPos, IN_aNormal, model, IN_lightPos, IN_viewPos,
                                        IN_lightColor, IN_ambientStrength, IN_specularStrength, IN_shininess);
    o[0] = vec4(gouraud_fragment(LightingColor, IN_objectColor), 1.0);
    o[1] = vec4(LightingColor, 0.0);
}
