// ogldev tutorial 19 "Specular lighting": a directional light with ambient, diffuse and
// specular terms computed in world space, all multiplied by the sampled texture color.
// gDirectionalLight.Direction points FROM the light; the diffuse factor uses its negation.
// The specular factor is pow(dot(VertexToEye, LightReflect), gSpecularPower) computed BEFORE
// the "> 0" test, so for a negative dot the tutorial relies on pow(negative, p), which GLSL
// leaves undefined (llvmpipe returns NaN, and NaN > 0 is false, so the term is dropped).
// Colors are vec4 with alpha 1 scaled by the intensities, as in the tutorial, so the
// returned alpha is texel.a * (AmbientIntensity + DiffuseIntensity * DiffuseFactor + ...).
struct DirectionalLight {
    vec3 Color;
    float AmbientIntensity;
    vec3 Direction;
    float DiffuseIntensity;
};

vec4 ogldev19_shade(DirectionalLight gDirectionalLight, vec3 WorldPos0, vec3 Normal0,
                    vec3 gEyeWorldPos, float gMatSpecularIntensity, float gSpecularPower,
                    vec4 texel, out float DiffuseFactor, out float SpecularFactor)
{
    vec4 AmbientColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.AmbientIntensity;
    vec3 LightDirection = -gDirectionalLight.Direction;
    vec3 Normal = normalize(Normal0);

    DiffuseFactor = dot(Normal, LightDirection);
    SpecularFactor = 0.0;
    vec4 DiffuseColor = vec4(0.0);
    vec4 SpecularColor = vec4(0.0);

    if (DiffuseFactor > 0.0) {
        DiffuseColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.DiffuseIntensity
                     * DiffuseFactor;
        vec3 VertexToEye = normalize(gEyeWorldPos - WorldPos0);
        vec3 LightReflect = normalize(reflect(gDirectionalLight.Direction, Normal));
        SpecularFactor = dot(VertexToEye, LightReflect);
        SpecularFactor = pow(SpecularFactor, gSpecularPower);
        if (SpecularFactor > 0.0) {
            SpecularColor = vec4(gDirectionalLight.Color, 1.0) * gMatSpecularIntensity
                          * SpecularFactor;
        }
    }
    return texel * (AmbientColor + DiffuseColor + SpecularColor);
}
