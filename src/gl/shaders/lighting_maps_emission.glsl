// LearnOpenGL, Lighting > Lighting maps, exercise 4: an emission map. The shader is
// lighting_maps' with a third texel, vec3(texture(material.emission, TexCoords)), added
// to the result as it is: the emission is light the surface gives off itself, so no
// light's colour, no diffuse factor and no attenuation touches it. As in lighting_maps,
// the caller samples the maps and passes the texels.
struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

vec3 lighting_maps_emission(vec3 diffuseTexel, vec3 specularTexel, vec3 emissionTexel, float shininess,
                            Light light, vec3 FragPos, vec3 Normal, vec3 viewPos, out float diff, out float spec)
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

    vec3 emission = emissionTexel;

    return ambient + diffuse + specular + emission;
}
