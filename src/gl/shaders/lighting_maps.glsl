// LearnOpenGL, Lighting > Lighting maps: the material's diffuse and specular colors come
// from textures. The chapter samples `material.diffuse` / `material.specular` at TexCoords;
// a sampler cannot be a function argument, so this function takes the sampled texels
// (vec3(texture(material.diffuse, TexCoords)) and vec3(texture(material.specular, TexCoords)))
// and the caller samples. The ambient term reuses the diffuse map, as in the chapter.
struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

vec3 lighting_maps(vec3 diffuseTexel, vec3 specularTexel, float shininess, Light light,
                   vec3 FragPos, vec3 Normal, vec3 viewPos, out float diff, out float spec)
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

    return ambient + diffuse + specular;
}
