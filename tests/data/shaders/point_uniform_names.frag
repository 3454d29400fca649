#version 330 core
// Correct point light with attenuation; the attenuation applied once to the sum, and the
// light vector's length reused for the distance.
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};
struct PointLight {
    vec3 position;
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
uniform PointLight light;

void main()
{
    vec3 albedo = texture(material.diffuse, TexCoords).rgb;
    vec3 gloss = texture(material.specular, TexCoords).rgb;
    vec3 d = light.position - FragPos;
    float dist = length(d);
    vec3 lightDir = normalize(d);
    vec3 norm = normalize(Normal);
    vec3 viewDir = normalize(viewPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    float spec = pow(max(dot(viewDir, reflect(-lightDir, norm)), 0.0), material.shininess);
    float att = 1.0 / (light.constant + dist * (light.linear + light.quadratic * dist));
    vec3 lit = light.ambient * albedo + light.diffuse * diff * albedo + light.specular * spec * gloss;
    FragColor = vec4(att * lit, 1.0);
}
