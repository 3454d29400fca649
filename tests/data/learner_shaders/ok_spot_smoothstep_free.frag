#version 330 core
// model: spot
// expect: agrees
// style: cone factor from a helper using min/max instead of clamp, terms accumulated step by step
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

float coneFactor(vec3 toLight)
{
    float cosAngle = dot(toLight, normalize(-light.direction));
    float t = (cosAngle - light.outerCutOff) / (light.cutOff - light.outerCutOff);
    return min(max(t, 0.0), 1.0);
}

void main()
{
    vec3 kd = texture(material.diffuse, TexCoords).rgb;
    vec3 ks = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 toLight = normalize(light.position - FragPos);
    vec3 toEye = normalize(viewPos - FragPos);
    float d = distance(light.position, FragPos);
    float att = 1.0 / (light.constant + light.linear * d + light.quadratic * d * d);
    float cone = coneFactor(toLight);

    vec3 acc = light.ambient * kd * att;
    acc += light.diffuse * kd * max(dot(n, toLight), 0.0) * cone * att;
    acc += light.specular * ks * pow(max(dot(toEye, reflect(-toLight, n)), 0.0), material.shininess) * cone * att;
    FragColor = vec4(acc, 1.0);
}
