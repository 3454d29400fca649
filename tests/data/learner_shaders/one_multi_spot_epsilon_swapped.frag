#version 330 core
// model: multiple_lights
// expect: spot-epsilon-swapped
// style: commentaires en français, la torche avec ε = extérieur − intérieur ; le reste comme le chapitre mais réécrit en boucle for sur un tableau local
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
    vec3 td = texture(material.diffuse, TexCoords).rgb;
    vec3 ts = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);

    // directions vers chaque source, et leur facteur (atténuation × cône)
    vec3 dirs[6];
    float facteurs[6];
    vec3 amb[6]; vec3 dif[6]; vec3 spe[6];

    dirs[0] = normalize(-dirLight.direction); facteurs[0] = 1.0;
    amb[0] = dirLight.ambient; dif[0] = dirLight.diffuse; spe[0] = dirLight.specular;
    for (int i = 0; i < 4; i++) {
        float d = length(pointLights[i].position - FragPos);
        dirs[i + 1] = normalize(pointLights[i].position - FragPos);
        facteurs[i + 1] = 1.0 / (pointLights[i].constant + pointLights[i].linear * d + pointLights[i].quadratic * d * d);
        amb[i + 1] = pointLights[i].ambient; dif[i + 1] = pointLights[i].diffuse; spe[i + 1] = pointLights[i].specular;
    }
    float d = length(spotLight.position - FragPos);
    dirs[5] = normalize(spotLight.position - FragPos);
    float theta = dot(dirs[5], normalize(-spotLight.direction));
    float epsilon = spotLight.outerCutOff - spotLight.cutOff;   // largeur du bord
    float intensite = clamp((theta - spotLight.outerCutOff) / epsilon, 0.0, 1.0);
    facteurs[5] = intensite / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * d * d);
    amb[5] = spotLight.ambient; dif[5] = spotLight.diffuse; spe[5] = spotLight.specular;

    vec3 c = vec3(0.0);
    for (int i = 0; i < 6; i++) {
        vec3 l = dirs[i];
        c += facteurs[i] * (amb[i] * td + dif[i] * max(dot(n, l), 0.0) * td
                          + spe[i] * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * ts);
    }
    FragColor = vec4(c, 1.0);
}
