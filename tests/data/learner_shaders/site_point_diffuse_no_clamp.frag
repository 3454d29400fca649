#version 330 core
// model: multiple_lights
// expect: diffuse-no-clamp@point
// style: vec4 arithmetic (directions with w = 0), separate loops for diffuse and specular sums; N·L left unclamped for the bulbs only
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
    vec4 Kd = texture(material.diffuse, TexCoords);
    vec4 Ks = texture(material.specular, TexCoords);
    vec4 P = vec4(FragPos, 1.0);
    vec4 N = vec4(normalize(Normal), 0.0);
    vec4 V = normalize(vec4(viewPos, 1.0) - P);

    vec4 Ld = vec4(normalize(-dirLight.direction), 0.0);
    vec4 sum = Kd * vec4(dirLight.ambient + dirLight.diffuse * max(dot(N, Ld), 0.0), 0.0)
             + Ks * vec4(dirLight.specular * pow(max(dot(V, reflect(-Ld, N)), 0.0), material.shininess), 0.0);

    vec4 att;
    for (int i = 0; i < 4; i++) {
        float r = distance(pointLights[i].position, FragPos);
        att[i] = 1.0 / (pointLights[i].constant + pointLights[i].linear * r + pointLights[i].quadratic * r * r);
    }
    for (int i = 0; i < 4; i++) {
        vec4 L = normalize(vec4(pointLights[i].position, 1.0) - P);
        float lambert = dot(N, L);
        sum += att[i] * Kd * vec4(pointLights[i].ambient + pointLights[i].diffuse * lambert, 0.0);
    }
    for (int i = 0; i < 4; i++) {
        vec4 L = normalize(vec4(pointLights[i].position, 1.0) - P);
        sum += att[i] * Ks * vec4(pointLights[i].specular, 0.0)
             * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess);
    }

    vec4 Ls = normalize(vec4(spotLight.position, 1.0) - P);
    float rs = distance(spotLight.position, FragPos);
    float atts = 1.0 / (spotLight.constant + spotLight.linear * rs + spotLight.quadratic * rs * rs);
    float cone = clamp((dot(Ls.xyz, normalize(-spotLight.direction)) - spotLight.outerCutOff)
                       / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    sum += (atts * cone) * (Kd * vec4(spotLight.ambient + spotLight.diffuse * max(dot(N, Ls), 0.0), 0.0)
                          + Ks * vec4(spotLight.specular * pow(max(dot(V, reflect(-Ls, N)), 0.0), material.shininess), 0.0));
    FragColor = vec4(sum.rgb, 1.0);
}
