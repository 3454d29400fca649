// Harness for normal_matrix: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// output 0 = (result, 1).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    vec3 result = normal_matrix_lighting(IN_FragPos, IN_aNormal, IN_model, IN_lightPos, IN_viewPos, IN_lightColor,
                                         IN_objectColor, IN_ambientStrength, IN_specularStrength, IN_shininess);
    o[0] = vec4(result, 1.0);
}
