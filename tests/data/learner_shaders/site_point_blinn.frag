#version 330 core
// model: multiple_lights
// expect: blinn-for-phong@point
// style: two lobe helpers (phongLobe, blinnLobe); the point lights were "upgraded" to Blinn, the sun and torch kept Phong
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform DirLight dirLight;
uniform PointLight pointLights[4];
uniform SpotLight spotLight;

float phongLobe(vec3 n, vec3 l, vec3 v) { return pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess); }
float blinnLobe(vec3 n, vec3 l, vec3 v) { return pow(max(dot(n, normalize(l + v)), 0.0), material.shininess); }
float lambert(vec3 n, vec3 l) { return max(dot(n, l), 0.0); }

void main()
{
    vec3 A = texture(material.diffuse, TexCoords).rgb;
    vec3 S = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);

    vec3 l = normalize(-dirLight.direction);
    vec3 outc = dirLight.ambient * A + dirLight.diffuse * lambert(n, l) * A + dirLight.specular * phongLobe(n, l, v) * S;

    for (int i = 0; i < 4; i++) {
        PointLight p = pointLights[i];
        l = normalize(p.position - FragPos);
        float d = length(p.position - FragPos);
        float a = 1.0 / (p.constant + p.linear * d + p.quadratic * (d * d));
        outc += a * (p.ambient * A + p.diffuse * lambert(n, l) * A + p.specular * blinnLobe(n, l, v) * S);
    }

    l = normalize(spotLight.position - FragPos);
    float d = length(spotLight.position - FragPos);
    float a = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * (d * d));
    float t = clamp((dot(l, normalize(-spotLight.direction)) - spotLight.outerCutOff)
                    / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    outc += a * t * (spotLight.ambient * A + spotLight.diffuse * lambert(n, l) * A + spotLight.specular * phongLobe(n, l, v) * S);
    FragColor = vec4(outc, 1.0);
}
