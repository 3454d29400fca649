#version 330 core
// opengl-tutorial 8 as its final listing is printed: the diffuse line ends with ';', so the
// specular line that follows is a separate expression statement whose value is discarded.
// It compiles (GLSL allows expression statements) and the highlight silently disappears.
in vec3 Position_worldspace;
in vec3 Normal_cameraspace;
in vec3 EyeDirection_cameraspace;
in vec3 LightDirection_cameraspace;

out vec3 color;

uniform vec3 LightPosition_worldspace;
uniform vec3 MaterialDiffuseColor;

void main()
{
    vec3 LightColor = vec3(1.0, 1.0, 1.0);
    float LightPower = 60.0; // "for example 60 watts" in the tutorial text
    vec3 MaterialAmbientColor = vec3(0.1, 0.1, 0.1) * MaterialDiffuseColor;
    vec3 MaterialSpecularColor = vec3(0.3, 0.3, 0.3);
    float distance = length(LightPosition_worldspace - Position_worldspace);
    vec3 n = normalize(Normal_cameraspace);
    vec3 l = normalize(LightDirection_cameraspace);
    float cosTheta = clamp(dot(n, l), 0.0, 1.0);
    vec3 E = normalize(EyeDirection_cameraspace);
    vec3 R = reflect(-l, n);
    float cosAlpha = clamp(dot(E, R), 0.0, 1.0);
    color =
        MaterialAmbientColor +
        MaterialDiffuseColor * LightColor * LightPower * cosTheta / (distance * distance);
        MaterialSpecularColor * LightColor * LightPower * pow(cosAlpha, 5.0) / (distance * distance);
}
