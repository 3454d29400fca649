// LearnOpenGL, Advanced Lighting > Blinn-Phong, on the basic-lighting inputs: the specular
// factor uses the halfway vector between the light and view directions instead of the
// reflected light direction. Everything else is Basic lighting's Phong shader (world space,
// ambientStrength, specularStrength, shininess as parameters).
// Out parameters: the diffuse and specular factors, for diagnosis.
vec3 blinn_phong(vec3 FragPos, vec3 Normal, vec3 lightPos, vec3 viewPos,
                 vec3 lightColor, vec3 objectColor, float ambientStrength,
                 float specularStrength, float shininess,
                 out float diff, out float spec)
{
    vec3 ambient = ambientStrength * lightColor;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;

    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 halfwayDir = normalize(lightDir + viewDir);
    spec = pow(max(dot(norm, halfwayDir), 0.0), shininess);
    vec3 specular = specularStrength * spec * lightColor;

    return (ambient + diffuse + specular) * objectColor;
}
