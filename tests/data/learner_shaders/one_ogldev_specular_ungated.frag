#version 330 core
// model: ogldev19
// expect: specular-ungated
// style: ogldev's names and vec4 colours, but the specular block moved out of the "if (DiffuseFactor > 0)" test
struct DirectionalLight {
    vec3 Color;
    float AmbientIntensity;
    vec3 Direction;
    float DiffuseIntensity;
};
in vec2 TexCoord0;
in vec3 Normal0;
in vec3 WorldPos0;
out vec4 FragColor;
uniform DirectionalLight gDirectionalLight;
uniform sampler2D gSampler;
uniform vec3 gEyeWorldPos;
uniform float gMatSpecularIntensity;
uniform float gSpecularPower;

void main()
{
    vec4 AmbientColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.AmbientIntensity;
    vec3 LightDirection = -gDirectionalLight.Direction;
    vec3 Normal = normalize(Normal0);
    float DiffuseFactor = dot(Normal, LightDirection);
    vec4 DiffuseColor = vec4(0.0);
    if (DiffuseFactor > 0.0) {
        DiffuseColor = vec4(gDirectionalLight.Color, 1.0) * gDirectionalLight.DiffuseIntensity * DiffuseFactor;
    }
    // specular for every face, lit or not
    vec4 SpecularColor = vec4(0.0);
    vec3 VertexToEye = normalize(gEyeWorldPos - WorldPos0);
    vec3 LightReflect = normalize(reflect(gDirectionalLight.Direction, Normal));
    float SpecularFactor = pow(dot(VertexToEye, LightReflect), gSpecularPower);
    if (SpecularFactor > 0.0) {
        SpecularColor = vec4(gDirectionalLight.Color, 1.0) * gMatSpecularIntensity * SpecularFactor;
    }
    FragColor = texture(gSampler, TexCoord0) * (AmbientColor + DiffuseColor + SpecularColor);
}
