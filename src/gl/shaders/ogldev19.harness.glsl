// Harness for ogldev19: inputs
//   0 = (WorldPos0, gSpecularPower)   1 = (Normal0, gMatSpecularIntensity)
//   2 = (gEyeWorldPos, -)
//   3 = (gDirectionalLight.Color, gDirectionalLight.AmbientIntensity)
//   4 = (gDirectionalLight.Direction, gDirectionalLight.DiffuseIntensity)
//   5 = sampled texel rgba (texture2D(gSampler, TexCoord0.xy))
// outputs 0 = FragColor (rgba), 1 = (DiffuseFactor, SpecularFactor after pow, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    DirectionalLight light = DirectionalLight(v[3].rgb, v[3].w, v[4].xyz, v[4].w);
    float DiffuseFactor;
    float SpecularFactor;
    o[0] = ogldev19_shade(light, v[0].xyz, v[1].xyz, v[2].xyz, v[1].w, v[0].w, v[5],
                          DiffuseFactor, SpecularFactor);
    o[1] = vec4(DiffuseFactor, SpecularFactor, 0.0, 0.0);
}
