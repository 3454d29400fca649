#version 330 core
// model: multiple_lights
// expect: clamp-per-light
// style: every light's contribution saturated before it is added ("colours go from 0 to 1"), array of results summed at the end
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

void main()
{
    vec3 cd = texture(material.diffuse, TexCoords).rgb;
    vec3 cs = texture(material.specular, TexCoords).rgb;
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    vec3 parts[6];

    vec3 L = normalize(-dirLight.direction);
    parts[0] = clamp(dirLight.ambient * cd + dirLight.diffuse * max(dot(N, L), 0.0) * cd
                     + dirLight.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * cs, 0.0, 1.0);
    for (int i = 0; i < 4; i++) {
        vec3 toL = pointLights[i].position - FragPos;
        float r = length(toL);
        L = normalize(toL);
        float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * r + pointLights[i].quadratic * (r * r));
        vec3 c = pointLights[i].ambient * cd + pointLights[i].diffuse * max(dot(N, L), 0.0) * cd
               + pointLights[i].specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * cs;
        parts[i + 1] = clamp(c * att, 0.0, 1.0);
    }
    vec3 toS = spotLight.position - FragPos;
    float rs = length(toS);
    L = normalize(toS);
    float atts = 1.0 / (spotLight.constant + spotLight.linear * rs + spotLight.quadratic * (rs * rs));
    float cone = clamp((dot(L, normalize(-spotLight.direction)) - spotLight.outerCutOff)
                       / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    vec3 cspot = spotLight.ambient * cd + spotLight.diffuse * max(dot(N, L), 0.0) * cd
               + spotLight.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * cs;
    parts[5] = clamp(cspot * (atts * cone), 0.0, 1.0);

    vec3 sum = vec3(0.0);
    for (int i = 0; i < 6; i++) sum += parts[i];
    FragColor = vec4(sum, 1.0);
}
