#version 330 core
// model: multiple_lights
// expect: normal-not-normalized
// style: one helper per light kind with the lights read as globals, indices in a for loop, interpolated normal used as it comes
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

vec3 texD;
vec3 texS;

vec3 lit(vec3 a, vec3 d, vec3 s, vec3 N, vec3 L, vec3 V)
{
    return a * texD + d * max(dot(N, L), 0.0) * texD
         + s * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * texS;
}

vec3 sunContribution(vec3 N, vec3 V)
{
    return lit(dirLight.ambient, dirLight.diffuse, dirLight.specular, N, normalize(-dirLight.direction), V);
}

vec3 bulbContribution(int i, vec3 N, vec3 V)
{
    float r = length(pointLights[i].position - FragPos);
    float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * r + pointLights[i].quadratic * r * r);
    vec3 L = normalize(pointLights[i].position - FragPos);
    return att * lit(pointLights[i].ambient, pointLights[i].diffuse, pointLights[i].specular, N, L, V);
}

vec3 torchContribution(vec3 N, vec3 V)
{
    vec3 L = normalize(spotLight.position - FragPos);
    float r = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * r + spotLight.quadratic * r * r);
    float theta = dot(L, normalize(-spotLight.direction));
    float k = clamp((theta - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    return att * k * lit(spotLight.ambient, spotLight.diffuse, spotLight.specular, N, L, V);
}

void main()
{
    texD = texture(material.diffuse, TexCoords).rgb;
    texS = texture(material.specular, TexCoords).rgb;
    vec3 N = Normal;                        // already a normal, isn't it?
    vec3 V = normalize(viewPos - FragPos);
    vec3 c = sunContribution(N, V);
    for (int i = 0; i < 4; ++i)
        c += bulbContribution(i, N, V);
    c += torchContribution(N, V);
    FragColor = vec4(c, 1.0);
}
