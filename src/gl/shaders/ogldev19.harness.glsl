// Harness for ogldev19: the inputs come through the IN_ macros that lightlab generates
// from the model's layout (src/gl/layout), one per quantity, named after it.
// outputs 0 = FragColor (rgba), 1 = (DiffuseFactor, SpecularFactor after pow, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    DirectionalLight light = DirectionalLight(IN_gDirectionalLight_Color, IN_gDirectionalLight_AmbientIntensity, IN_gDirectionalLight_Direction, IN_gDirectionalLight_DiffuseIntensity);
    float DiffuseFactor;
    float SpecularFactor;
    o[0] = ogldev19_shade(light, IN_WorldPos0, IN_Normal0, IN_gEyeWorldPos, IN_gMatSpecularIntensity, IN_gSpecularPower, IN_gSampler,
                          DiffuseFactor, SpecularFactor);
    o[1] = vec4(DiffuseFactor, SpecularFactor, 0.0, 0.0);
}
