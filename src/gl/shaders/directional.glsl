// LearnOpenGL, Lighting > Light casters, directional light.
// light.direction points FROM the light (as the chapter stores it); the shader negates and
// normalizes it to get lightDir, which points toward the light. No attenuation.
// Texels are the sampled lighting maps, as in lighting_maps.glsl.
struct DirectionalLight {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

vec3 directional_light(DirectionalLight light, vec3 diffuseTexel, vec3 specularTexel,
                       float shininess, vec3 FragPos, vec3 Normal, vec3 viewPos,
                       out float diff, out float spec)
{
    vec3 ambient = light.ambient * diffuseTexel;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(-light.direction);
    diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = light.diffuse * diff * diffuseTexel;

    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = light.specular * spec * specularTexel;

    return ambient + diffuse + specular;
}
