#version 330 core
// model: multiple_lights
// expect: attenuation-missing@point + light-dir-reversed@directional
// style: one generic Phong helper and a struct of texels; the bulbs have no falloff and the sun's direction is not negated
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

struct Tex { vec3 d; vec3 s; };

vec3 phongSum(Tex t, vec3 N, vec3 L, vec3 V, vec3 a, vec3 d, vec3 s)
{
    return a * t.d + d * max(dot(N, L), 0.0) * t.d + s * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * t.s;
}

void main()
{
    Tex t = Tex(texture(material.diffuse, TexCoords).rgb, texture(material.specular, TexCoords).rgb);
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    vec3 c = phongSum(t, N, normalize(dirLight.direction), V, dirLight.ambient, dirLight.diffuse, dirLight.specular);
    for (int i = 0; i < 4; i++)
        c += phongSum(t, N, normalize(pointLights[i].position - FragPos), V,
                      pointLights[i].ambient, pointLights[i].diffuse, pointLights[i].specular);
    vec3 Ls = normalize(spotLight.position - FragPos);
    float r = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * r + spotLight.quadratic * r * r);
    float k = clamp((dot(Ls, normalize(-spotLight.direction)) - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    c += att * k * phongSum(t, N, Ls, V, spotLight.ambient, spotLight.diffuse, spotLight.specular);
    FragColor = vec4(c, 1.0);
}
