#version 330 core
// model: multiple_lights
// expect: clamp-per-light@point
// style: point lights saturated one by one with min(…, 1) "so four bulbs cannot blow out"; sun and torch added raw; helper per kind
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

struct Surf { vec3 n; vec3 v; vec3 cd; vec3 cs; };

vec3 terms(Surf s, vec3 l, vec3 a, vec3 d, vec3 sp)
{
    return a * s.cd + d * max(dot(s.n, l), 0.0) * s.cd
         + sp * pow(max(dot(s.v, reflect(-l, s.n)), 0.0), material.shininess) * s.cs;
}

vec3 bulb(Surf s, PointLight p)
{
    vec3 l = normalize(p.position - FragPos);
    float d = length(p.position - FragPos);
    vec3 c = terms(s, l, p.ambient, p.diffuse, p.specular) / (p.constant + p.linear * d + p.quadratic * (d * d));
    return max(min(c, vec3(1.0)), vec3(0.0));
}

vec3 torch(Surf s)
{
    vec3 l = normalize(spotLight.position - FragPos);
    float d = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * (d * d));
    float k = clamp((dot(l, normalize(-spotLight.direction)) - spotLight.outerCutOff)
                    / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    return terms(s, l, spotLight.ambient, spotLight.diffuse, spotLight.specular) * (att * k);
}

void main()
{
    Surf s = Surf(normalize(Normal), normalize(viewPos - FragPos),
                  texture(material.diffuse, TexCoords).rgb, texture(material.specular, TexCoords).rgb);
    vec3 c = terms(s, normalize(-dirLight.direction), dirLight.ambient, dirLight.diffuse, dirLight.specular);
    for (int i = 0; i < 4; i++) c += bulb(s, pointLights[i]);
    c += torch(s);
    FragColor = vec4(c, 1.0);
}
