#version 330 core
// LearnOpenGL, Lighting > Multiple lights: one directional light, NR_POINT_LIGHTS point
// lights and a spotlight (the flashlight), each adding its contribution to the result.
// The chapter's functions read `material` (a struct with samplers) globally; here the
// sampled texels and the shininess are passed in, because samplers cannot be arguments.
// Struct layouts and field order follow the chapter; the lights are uniforms, as there.
const int NR_POINT_LIGHTS = 4;

struct DirLight {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

struct PointLight {
    vec3 position;
    float constant;
    float linear;
    float quadratic;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

struct SpotLight {
    vec3 position;
    vec3 direction;
    float cutOff;
    float outerCutOff;
    float constant;
    float linear;
    float quadratic;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

uniform DirLight dirLight;
uniform PointLight pointLights[NR_POINT_LIGHTS];
uniform SpotLight spotLight;

vec3 CalcDirLight(DirLight light, vec3 normal, vec3 viewDir,
                  vec3 diffuseTexel, vec3 specularTexel, float shininess)
{
    vec3 lightDir = normalize(-light.direction);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 ambient = light.ambient * diffuseTexel;
    vec3 diffuse = light.diffuse * diff * diffuseTexel;
    vec3 specular = light.specular * spec * specularTexel;
    return ambient + diffuse + specular;
}

vec3 CalcPointLight(PointLight light, vec3 normal, vec3 fragPos, vec3 viewDir,
                    vec3 diffuseTexel, vec3 specularTexel, float shininess)
{
    vec3 lightDir = normalize(light.position - fragPos);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    float distance = length(light.position - fragPos);
    float attenuation = 1.0 / (light.constant + light.linear * distance +
                               light.quadratic * (distance * distance));
    vec3 ambient = light.ambient * diffuseTexel;
    vec3 diffuse = light.diffuse * diff * diffuseTexel;
    vec3 specular = light.specular * spec * specularTexel;
    return (ambient + diffuse + specular) * attenuation;
}

vec3 CalcSpotLight(SpotLight light, vec3 normal, vec3 fragPos, vec3 viewDir,
                   vec3 diffuseTexel, vec3 specularTexel, float shininess)
{
    vec3 lightDir = normalize(light.position - fragPos);
    float diff = max(dot(normal, lightDir), 0.0);
    vec3 reflectDir = reflect(-lightDir, normal);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    float distance = length(light.position - fragPos);
    float attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance));
    float theta = dot(lightDir, normalize(-light.direction));
    float epsilon = light.cutOff - light.outerCutOff;
    float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);
    vec3 ambient = light.ambient * diffuseTexel;
    vec3 diffuse = light.diffuse * diff * diffuseTexel;
    vec3 specular = light.specular * spec * specularTexel;
    return (ambient + diffuse + specular) * attenuation * intensity;
}

// The chapter's main, split: phases 1 and 2 (directional and point lights) go to
// withoutSpot; phase 3 (the spotlight, commented out in the chapter's listing) is added
// for the returned total.
vec3 multiple_lights(vec3 FragPos, vec3 Normal, vec3 viewPos, vec3 diffuseTexel,
                     vec3 specularTexel, float shininess, out vec3 withoutSpot)
{
    vec3 norm = normalize(Normal);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 result = CalcDirLight(dirLight, norm, viewDir, diffuseTexel, specularTexel, shininess);
    for (int i = 0; i < NR_POINT_LIGHTS; i++)
        result += CalcPointLight(pointLights[i], norm, FragPos, viewDir,
                                 diffuseTexel, specularTexel, shininess);
    withoutSpot = result;
    result += CalcSpotLight(spotLight, norm, FragPos, viewDir,
                            diffuseTexel, specularTexel, shininess);
    return result;
}

struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;

void main()
{
    vec3 diffuseTexel = vec3(texture(material.diffuse, TexCoords));
    vec3 specularTexel = vec3(texture(material.specular, TexCoords));
    vec3 withoutSpot;
    vec3 result = multiple_lights(FragPos, Normal, viewPos, diffuseTexel, specularTexel,
                                  material.shininess, withoutSpot);
    FragColor = vec4(result, 1.0);
}
