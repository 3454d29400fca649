#version 330 core
// BUG (deliberate): the application passes the cut-off angles in degrees (12.5, 17.5) where
// the shader expects cosines. theta is a cosine in [-1, 1], so theta > 12.5 never holds and
// the spotlight contributes only its ambient term: the scene goes dark.
// (The correct uniform values are cos(radians(12.5)) and cos(radians(17.5)).)
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
    vec3 texel = texture(material.diffuse, TexCoords).rgb;
    vec3 ambient = light.ambient * texel;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(light.position - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * diff * texel;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
    vec3 specular = light.specular * spec * texture(material.specular, TexCoords).rgb;
    float theta = dot(lightDir, normalize(-light.direction));
    float epsilon = light.cutOff - light.outerCutOff;
    float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);
    FragColor = vec4(ambient + (diffuse + specular) * intensity, 1.0);
}
