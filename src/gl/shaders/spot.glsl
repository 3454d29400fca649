// LearnOpenGL, Lighting > Light casters, spotlight.
// cutOff and outerCutOff are COSINES of the inner and outer angles (the application passes
// cos(radians(12.5)) etc.), so "inside the cone" is theta > cutOff.
//   theta     = dot(lightDir, normalize(-light.direction))
//   epsilon   = cutOff - outerCutOff
//   intensity = clamp((theta - outerCutOff) / epsilon, 0, 1)
// spot_light: the chapter's final version (soft edges, with attenuation); intensity scales
// diffuse and specular only, the ambient term stays so the outside is not black.
// spot_light_hard: the chapter's first version: full lighting where theta > cutOff, else the
// ambient term alone (no attenuation in that version).
struct SpotLight {
    vec3 position;
    vec3 direction;
    float cutOff;
    float outerCutOff;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float constant;
    float linear;
    float quadratic;
};

vec3 spot_light(SpotLight light, vec3 diffuseTexel, vec3 specularTexel, float shininess,
                vec3 FragPos, vec3 Normal, vec3 viewPos,
                out float theta, out float intensity, out float attenuation)
{
    vec3 ambient = light.ambient * diffuseTexel;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(light.position - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * diff * diffuseTexel;

    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = light.specular * spec * specularTexel;

    theta = dot(lightDir, normalize(-light.direction));
    float epsilon = light.cutOff - light.outerCutOff;
    intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);
    diffuse *= intensity;
    specular *= intensity;

    float distance = length(light.position - FragPos);
    attenuation = 1.0 / (light.constant + light.linear * distance +
                         light.quadratic * (distance * distance));
    ambient *= attenuation;
    diffuse *= attenuation;
    specular *= attenuation;

    return ambient + diffuse + specular;
}

vec3 spot_light_hard(SpotLight light, vec3 diffuseTexel, vec3 specularTexel, float shininess,
                     vec3 FragPos, vec3 Normal, vec3 viewPos)
{
    vec3 lightDir = normalize(light.position - FragPos);
    float theta = dot(lightDir, normalize(-light.direction));
    vec3 ambient = light.ambient * diffuseTexel;
    if (theta > light.cutOff) {
        vec3 norm = normalize(Normal);
        float diff = max(dot(norm, lightDir), 0.0);
        vec3 diffuse = light.diffuse * diff * diffuseTexel;
        vec3 viewDir = normalize(viewPos - FragPos);
        vec3 reflectDir = reflect(-lightDir, norm);
        float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
        vec3 specular = light.specular * spec * specularTexel;
        return ambient + diffuse + specular;
    }
    return ambient;
}
