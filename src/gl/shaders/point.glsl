// LearnOpenGL, Lighting > Light casters, point light with attenuation
//   attenuation = 1 / (constant + linear * d + quadratic * d^2),  d = |position - FragPos|.
// All three terms (ambient included) are attenuated, as the chapter does.
struct PointLight {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float constant;
    float linear;
    float quadratic;
};

vec3 point_light(PointLight light, vec3 diffuseTexel, vec3 specularTexel, float shininess,
                 vec3 FragPos, vec3 Normal, vec3 viewPos,
                 out float diff, out float spec, out float attenuation)
{
    vec3 ambient = light.ambient * diffuseTexel;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(light.position - FragPos);
    diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * diff * diffuseTexel;

    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = light.specular * spec * specularTexel;

    float distance = length(light.position - FragPos);
    attenuation = 1.0 / (light.constant + light.linear * distance +
                         light.quadratic * (distance * distance));
    ambient *= attenuation;
    diffuse *= attenuation;
    specular *= attenuation;

    return ambient + diffuse + specular;
}
