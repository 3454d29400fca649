#version 330 core
// model: lighting_maps_emission
// expect: emission-lit
// style: a helper that "applies the lamp" to any colour, used for the emission too
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    sampler2D emission;
    float shininess;
};
struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform Light light;

vec3 underLamp(vec3 c)
{
    return c * light.diffuse;
}

void main()
{
    vec3 kd = texture(material.diffuse, TexCoords).rgb;
    vec3 ks = texture(material.specular, TexCoords).rgb;
    vec3 ke = texture(material.emission, TexCoords).rgb;
    vec3 N = normalize(Normal);
    vec3 toLight = normalize(light.position - FragPos);
    vec3 toView = normalize(viewPos - FragPos);
    float NdotL = max(dot(N, toLight), 0.0);
    float RdotV = max(dot(reflect(-toLight, N), toView), 0.0);
    vec3 result = light.ambient * kd;
    result += underLamp(kd) * NdotL;
    result += light.specular * pow(RdotV, material.shininess) * ks;
    result += underLamp(ke);
    FragColor = vec4(result, 1.0);
}
