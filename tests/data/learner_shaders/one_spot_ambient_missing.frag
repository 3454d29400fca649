#version 330 core
// model: spot
// expect: ambient-missing
// style: flashlight with only diffuse and specular ("the ambient is for the sun"), the cone factor in a helper
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light {
    vec3 position; vec3 direction; float cutOff; float outerCutOff;
    vec3 ambient; vec3 diffuse; vec3 specular;
    float constant; float linear; float quadratic;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

float cone(vec3 L)
{
    float theta = dot(L, normalize(-light.direction));
    return clamp((theta - light.outerCutOff) / (light.cutOff - light.outerCutOff), 0.0, 1.0);
}

void main()
{
    vec3 N = normalize(Normal);
    vec3 L = normalize(light.position - FragPos);
    vec3 V = normalize(viewPos - FragPos);
    float d = length(light.position - FragPos);
    float att = 1.0 / (light.constant + light.linear * d + light.quadratic * d * d);
    vec3 diffuse = light.diffuse * max(dot(N, L), 0.0) * texture(material.diffuse, TexCoords).rgb;
    vec3 specular = light.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess)
                  * texture(material.specular, TexCoords).rgb;
    FragColor = vec4((diffuse + specular) * cone(L) * att, 1.0);
}
