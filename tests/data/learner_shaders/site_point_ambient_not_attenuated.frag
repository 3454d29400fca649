#version 330 core
// model: multiple_lights
// expect: ambient-not-attenuated@point
// style: ambient of all lights collected first in its own sum; the bulbs' ambient added before the falloff, loop counting down
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
    vec3 tex = texture(material.diffuse, TexCoords).rgb;
    vec3 spm = texture(material.specular, TexCoords).rgb;
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);

    vec3 ambientSum = dirLight.ambient * tex;
    vec3 directSum = vec3(0.0);

    vec3 L = normalize(-dirLight.direction);
    directSum += dirLight.diffuse * max(dot(N, L), 0.0) * tex;
    directSum += dirLight.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * spm;

    for (int i = 3; i >= 0; i--) {
        vec3 D = pointLights[i].position - FragPos;
        float r = length(D);
        L = D / r;
        float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * r + pointLights[i].quadratic * (r * r));
        ambientSum += pointLights[i].ambient * tex;   // ambient is everywhere
        directSum += att * (pointLights[i].diffuse * max(dot(N, L), 0.0) * tex
                          + pointLights[i].specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * spm);
    }

    vec3 D = spotLight.position - FragPos;
    float r = length(D);
    L = D / r;
    float att = 1.0 / (spotLight.constant + spotLight.linear * r + spotLight.quadratic * (r * r));
    float k = clamp((dot(L, normalize(-spotLight.direction)) - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    ambientSum += att * k * spotLight.ambient * tex;
    directSum += att * k * (spotLight.diffuse * max(dot(N, L), 0.0) * tex
                          + spotLight.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * spm);

    FragColor = vec4(ambientSum + directSum, 1.0);
}
