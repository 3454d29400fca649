// Harness for opengl_tutorial8: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = (color, 1), 1 = (cosTheta, cosAlpha, distance, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    float cosTheta;
    float cosAlpha;
    float distance;
    vec3 color = ot8_shade(IN_Position_worldspace, IN_LightPosition_worldspace, IN_Normal_cameraspace, IN_EyeDirection_cameraspace, IN_LightDirection_cameraspace, IN_MaterialDiffuseColor,
                           IN_MaterialSpecularColor, IN_MaterialAmbientFactor, IN_LightColor, IN_LightPower, IN_specularExponent,
                           cosTheta, cosAlpha, distance);
    o[0] = vec4(color, 1.0);
    o[1] = vec4(cosTheta, cosAlpha, distance, 0.0);
}
