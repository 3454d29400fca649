#version 330 core
// BUG (deliberate): the chapter's cut-off angles, 12.5 and 17.5 degrees, are typed into the
// shader as they are, where the cone test needs their cosines. theta is a cosine in
// [-1, 1]; with "cosines" 12.5 and 17.5, epsilon = 12.5 - 17.5 = -5 and
// (theta - 17.5) / -5 is above 3, so the intensity clamps to 1 everywhere: the cone is
// gone and the spotlight lights every fragment like a point light.
// The cut-offs are not uniforms here, so check-shader fixes light.cutOff and
// light.outerCutOff to the chapter's cos(12.5°) and cos(17.5°) and says so.
// (The fix: const float cutOff = cos(radians(12.5)); likewise for 17.5.)
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};

struct Light {
    vec3 position;
    vec3 direction;
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

const float cutOff = 12.5;
const float outerCutOff = 17.5;

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
    float epsilon = cutOff - outerCutOff;
    float intensity = clamp((theta - outerCutOff) / epsilon, 0.0, 1.0);
    float distance = length(light.position - FragPos);
    float attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance));
    FragColor = vec4((ambient + (diffuse + specular) * intensity) * attenuation, 1.0);
}
