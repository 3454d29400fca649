#version 330 core
// ogldev 19 with the specular intensity and power as vertex attributes: the vertex shader
// passes them through, so here they are inputs instead of uniforms.
struct DirectionalLight {
    vec3 Color;
    float AmbientIntensity;
    vec3 Direction;
    float DiffuseIntensity;
};

in vec2 TexCoord0;
in vec3 Normal0;
in vec3 WorldPos0;
in float SpecularIntensity0;
in float SpecularPower0;

out vec4 FragColor;

uniform DirectionalLight gDirectionalLight;
uniform sampler2D gSampler;
uniform vec3 gEyeWorldPos;

void main()
{
    vec4 AmbientColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.AmbientIntensity;
    vec3 LightDirection = -gDirectionalLight.Direction;
    vec3 Normal = normalize(Normal0);

    float DiffuseFactor = dot(Normal, LightDirection);
    vec4 DiffuseColor = vec4(0.0);
    vec4 SpecularColor = vec4(0.0);

    if (DiffuseFactor > 0.0) {
        DiffuseColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.DiffuseIntensity * DiffuseFactor;
        vec3 VertexToEye = normalize(gEyeWorldPos - WorldPos0);
        vec3 LightReflect = normalize(reflect(gDirectionalLight.Direction, Normal));
        float SpecularFactor = dot(VertexToEye, LightReflect);
        SpecularFactor = pow(SpecularFactor, SpecularPower0);
        if (SpecularFactor > 0.0) {
            SpecularColor = vec4(gDirectionalLight.Color, 1.0) * SpecularIntensity0 * SpecularFactor;
        }
    }
    FragColor = texture(gSampler, TexCoord0) * (AmbientColor + DiffuseColor + SpecularColor);
}
