// LearnOpenGL, Lighting > Basic lighting: the Phong model evaluated per fragment.
// Vectors are in world space. lightDir and viewDir point away from the surface;
// reflect() wants the incident vector, so it receives -lightDir.
// The chapter hard-codes ambientStrength 0.1, specularStrength 0.5 and shininess 32;
// here they are parameters so that tests can vary them.
// Out parameters: the diffuse and specular factors, for diagnosis.
vec3 basic_lighting(vec3 FragPos, vec3 Normal, vec3 lightPos, vec3 viewPos,
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
    vec3 reflectDir = reflect(-lightDir, norm);
    spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = specularStrength * spec * lightColor;

    return (ambient + diffuse + specular) * objectColor;
}
