#version 330 core
// model: multiple_lights
// expect: specular-missing@directional + attenuation-quadratic-uses-d@point
// style: commentaires en français ; le soleil sans reflet spéculaire, les ampoules avec Kq·d ; boucle while et fonctions par source
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

// soleil : ambiant + diffus (« un soleil ne fait pas de reflet »)
vec3 soleil(vec3 n, vec3 td)
{
    vec3 l = normalize(-dirLight.direction);
    return dirLight.ambient * td + dirLight.diffuse * max(dot(n, l), 0.0) * td;
}

// ampoule : atténuation Kc + Kl d + Kq d
vec3 ampoule(PointLight p, vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(p.position - FragPos);
    float d = length(p.position - FragPos);
    float att = 1.0 / (p.constant + p.linear * d + p.quadratic * d);
    return att * (p.ambient * td + p.diffuse * max(dot(n, l), 0.0) * td
                + p.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * ts);
}

// lampe torche : cône adouci et atténuation complète
vec3 torche(vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(spotLight.position - FragPos);
    float d = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * (d * d));
    float i = clamp((dot(l, normalize(-spotLight.direction)) - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    return att * i * (spotLight.ambient * td + spotLight.diffuse * max(dot(n, l), 0.0) * td
                    + spotLight.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * ts);
}

void main()
{
    vec3 td = texture(material.diffuse, TexCoords).rgb;
    vec3 ts = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);
    vec3 c = soleil(n, td);
    int k = 0;
    while (k < 4) { c += ampoule(pointLights[k], n, v, td, ts); k++; }
    c += torche(n, v, td, ts);
    FragColor = vec4(c, 1.0);
}
