// Harness for opengl_tutorial8 (fragment stage): inputs
//   0 = (Position_worldspace, LightPower)   1 = (Normal_cameraspace, specular exponent)
//   2 = (EyeDirection_cameraspace, -)       3 = (LightDirection_cameraspace, -)
//   4 = (LightPosition_worldspace, -)       5 = (MaterialDiffuseColor, -)
//   6 = (MaterialSpecularColor, -)          7 = (LightColor, -)
//   8 = (ambient factor, -)  (the tutorial uses 0.1, 0.1, 0.1)
// outputs 0 = (color, 1), 1 = (cosTheta, cosAlpha, distance, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    float cosTheta;
    float cosAlpha;
    float distance;
    vec3 color = ot8_shade(v[0].xyz, v[4].xyz, v[1].xyz, v[2].xyz, v[3].xyz, v[5].rgb,
                           v[6].rgb, v[8].rgb, v[7].rgb, v[0].w, v[1].w,
                           cosTheta, cosAlpha, distance);
    o[0] = vec4(color, 1.0);
    o[1] = vec4(cosTheta, cosAlpha, distance, 0.0);
}
