#version 330 core
// model: multiple_lights
// expect: light-dir-reversed@directional
// style: commentaires en français, une fonction par type de lumière ; la direction du soleil utilisée sans la changer de signe
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

// Phong pour une direction de lumière donnée (l : du fragment vers la lumière)
vec3 phong(vec3 l, vec3 n, vec3 v, vec3 a, vec3 d, vec3 s, vec3 td, vec3 ts)
{
    float lambert = max(dot(n, l), 0.0);
    float brillant = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    return a * td + d * lambert * td + s * brillant * ts;
}

// le soleil : sa direction « est déjà la direction de la lumière »
vec3 soleil(vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(dirLight.direction);
    return phong(l, n, v, dirLight.ambient, dirLight.diffuse, dirLight.specular, td, ts);
}

vec3 ampoule(int i, vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 versAmpoule = pointLights[i].position - FragPos;
    float d = length(versAmpoule);
    float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * d + pointLights[i].quadratic * d * d);
    return att * phong(normalize(versAmpoule), n, v, pointLights[i].ambient, pointLights[i].diffuse,
                       pointLights[i].specular, td, ts);
}

vec3 lampeTorche(vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 versLampe = spotLight.position - FragPos;
    float d = length(versLampe);
    vec3 l = normalize(versLampe);
    float att = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * d * d);
    float theta = dot(l, normalize(-spotLight.direction));
    float intensite = clamp((theta - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    return att * intensite * phong(l, n, v, spotLight.ambient, spotLight.diffuse, spotLight.specular, td, ts);
}

void main()
{
    vec3 td = texture(material.diffuse, TexCoords).rgb;
    vec3 ts = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);
    vec3 couleur = soleil(n, v, td, ts);
    for (int i = 0; i < 4; i++)
        couleur += ampoule(i, n, v, td, ts);
    couleur += lampeTorche(n, v, td, ts);
    FragColor = vec4(couleur, 1.0);
}
