#version 330 core
// model: basic_lighting
// expect: light-color-twice
// style: each term already tinted by the light, then the sum multiplied by the light colour again; strengths as uniforms
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

void main()
{
    vec3 norm = normalize(Normal);
    vec3 toLight = normalize(lightPos - FragPos);
    vec3 toEye = normalize(viewPos - FragPos);
    vec3 ambient = ambientStrength * lightColor;
    vec3 diffuse = max(dot(norm, toLight), 0.0) * lightColor;
    vec3 specular = specularStrength * pow(max(dot(toEye, reflect(-toLight, norm)), 0.0), shininess) * lightColor;
    vec3 result = (ambient + diffuse + specular) * lightColor * objectColor;
    FragColor = vec4(result, 1.0);
}
