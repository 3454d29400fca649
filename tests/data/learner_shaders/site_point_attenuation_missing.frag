#version 330 core
// model: multiple_lights
// expect: attenuation-missing@point
// style: tutorial-like function per light kind, renamed (sun/bulb/torch); the bulbs forgot their falloff, the torch kept it
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

vec3 sun(vec3 n, vec3 v, vec3 kd, vec3 ks)
{
    vec3 l = normalize(-dirLight.direction);
    float diff = max(dot(n, l), 0.0);
    float spec = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    return dirLight.ambient * kd + dirLight.diffuse * diff * kd + dirLight.specular * spec * ks;
}

vec3 bulb(PointLight p, vec3 n, vec3 v, vec3 kd, vec3 ks)
{
    vec3 l = normalize(p.position - FragPos);
    float diff = max(dot(n, l), 0.0);
    float spec = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    return p.ambient * kd + p.diffuse * diff * kd + p.specular * spec * ks;
}

vec3 torch(vec3 n, vec3 v, vec3 kd, vec3 ks)
{
    vec3 l = normalize(spotLight.position - FragPos);
    float diff = max(dot(n, l), 0.0);
    float spec = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    float d = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * d * d);
    float theta = dot(l, normalize(-spotLight.direction));
    float eps = spotLight.cutOff - spotLight.outerCutOff;
    float k = clamp((theta - spotLight.outerCutOff) / eps, 0.0, 1.0);
    return (spotLight.ambient * kd + spotLight.diffuse * diff * kd + spotLight.specular * spec * ks) * att * k;
}

void main()
{
    vec3 kd = texture(material.diffuse, TexCoords).rgb;
    vec3 ks = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);
    vec3 c = sun(n, v, kd, ks);
    for (int i = 0; i < 4; i++)
        c += bulb(pointLights[i], n, v, kd, ks);
    c += torch(n, v, kd, ks);
    FragColor = vec4(c, 1.0);
}
