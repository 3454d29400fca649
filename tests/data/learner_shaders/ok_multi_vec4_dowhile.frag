#version 330 core
// model: multiple_lights
// expect: agrees
// style: vec4 colours and directions (w = 0), a do-while over the point lights, one generic light function with a cone flag
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

vec4 gDiffuse;
vec4 gSpecular;

vec4 phong(vec4 L, vec4 N, vec4 V, vec3 a, vec3 d, vec3 s)
{
    vec4 R = reflect(-L, N);
    return vec4(a, 0.0) * gDiffuse
         + vec4(d, 0.0) * gDiffuse * max(dot(N, L), 0.0)
         + vec4(s, 0.0) * gSpecular * pow(max(dot(V, R), 0.0), material.shininess);
}

void main()
{
    gDiffuse = texture(material.diffuse, TexCoords);
    gSpecular = texture(material.specular, TexCoords);
    vec4 P = vec4(FragPos, 1.0);
    vec4 N = vec4(normalize(Normal), 0.0);
    vec4 V = normalize(vec4(viewPos, 1.0) - P);

    vec4 sum = phong(normalize(vec4(-dirLight.direction, 0.0)), N, V,
                     dirLight.ambient, dirLight.diffuse, dirLight.specular);
    int i = 0;
    do {
        vec4 D = vec4(pointLights[i].position, 1.0) - P;
        float r = length(D);
        float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * r
                           + pointLights[i].quadratic * r * r);
        sum += att * phong(D / r, N, V, pointLights[i].ambient, pointLights[i].diffuse, pointLights[i].specular);
        i += 1;
    } while (i < 4);

    vec4 D = vec4(spotLight.position, 1.0) - P;
    float r = length(D);
    vec4 L = D / r;
    float theta = dot(L, normalize(vec4(-spotLight.direction, 0.0)));
    float k = clamp((theta - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    float att = 1.0 / (spotLight.constant + spotLight.linear * r + spotLight.quadratic * r * r);
    sum += (att * k) * phong(L, N, V, spotLight.ambient, spotLight.diffuse, spotLight.specular);

    FragColor = vec4(sum.rgb, 1.0);
}
