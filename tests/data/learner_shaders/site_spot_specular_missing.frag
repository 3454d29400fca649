#version 330 core
// model: multiple_lights
// expect: specular-missing@spot
// style: everything in main with a for loop; the flashlight written from memory with ambient and diffuse only
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
    vec3 diffuseColor = vec3(texture(material.diffuse, TexCoords));
    vec3 specularColor = vec3(texture(material.specular, TexCoords));
    vec3 norm = normalize(Normal);
    vec3 eye = normalize(viewPos - FragPos);

    vec3 toSun = normalize(-dirLight.direction);
    vec3 result = dirLight.ambient * diffuseColor
                + dirLight.diffuse * max(dot(norm, toSun), 0.0) * diffuseColor
                + dirLight.specular * pow(max(dot(eye, reflect(-toSun, norm)), 0.0), material.shininess) * specularColor;

    for (int i = 0; i < 4; i++) {
        vec3 toLamp = normalize(pointLights[i].position - FragPos);
        float dist = length(pointLights[i].position - FragPos);
        float att = 1.0 / (pointLights[i].constant + pointLights[i].linear * dist + pointLights[i].quadratic * dist * dist);
        result += att * pointLights[i].ambient * diffuseColor;
        result += att * pointLights[i].diffuse * max(dot(norm, toLamp), 0.0) * diffuseColor;
        result += att * pointLights[i].specular * pow(max(dot(eye, reflect(-toLamp, norm)), 0.0), material.shininess) * specularColor;
    }

    vec3 toTorch = normalize(spotLight.position - FragPos);
    float dist = length(spotLight.position - FragPos);
    float att = 1.0 / (spotLight.constant + spotLight.linear * dist + spotLight.quadratic * dist * dist);
    float theta = dot(toTorch, normalize(-spotLight.direction));
    float intensity = clamp((theta - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    result += att * intensity * (spotLight.ambient * diffuseColor
                               + spotLight.diffuse * max(dot(norm, toTorch), 0.0) * diffuseColor);
    FragColor = vec4(result, 1.0);
}
