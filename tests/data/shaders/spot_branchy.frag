#version 330 core
// Correct soft-edged spotlight, written with the cone test as explicit branches (inside,
// edge, outside) instead of one clamp.
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};
struct Light {
    vec3 position;
    vec3 direction;
    float cutOff;
    float outerCutOff;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float constant;
    float linear;
    float quadratic;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    vec3 texel = vec3(texture(material.diffuse, TexCoords));
    vec3 L = normalize(light.position - FragPos);
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    float theta = dot(L, normalize(-light.direction));
    float intensity;
    if (theta >= light.cutOff) {
        intensity = 1.0;
    } else if (theta <= light.outerCutOff) {
        intensity = 0.0;
    } else {
        intensity = (theta - light.outerCutOff) / (light.cutOff - light.outerCutOff);
    }
    float d = length(light.position - FragPos);
    float attenuation = 1.0 / (light.constant + light.linear * d + light.quadratic * d * d);
    vec3 ambient = light.ambient * texel;
    vec3 diffuse = light.diffuse * max(dot(N, L), 0.0) * texel;
    vec3 specular = light.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess)
                  * vec3(texture(material.specular, TexCoords));
    FragColor = vec4(attenuation * (ambient + intensity * (diffuse + specular)), 1.0);
}
