// lightlab's normal-matrix exercise (LearnOpenGL, Lighting > Basic lighting, "the normal
// matrix"): Basic lighting with the normal given in object space (aNormal) beside the
// model matrix. The shader moves the normal to world space itself, through the normal
// matrix transpose(inverse(mat3(model))), written here as the chapter's vertex shader
// writes it; FragPos is already in world space. Then it lights as Basic lighting does.
vec3 normal_matrix_lighting(vec3 FragPos, vec3 aNormal, mat4 model, vec3 lightPos, vec3 viewPos,
                            vec3 lightColor, vec3 objectColor, float ambientStrength,
                            float specularStrength, float shininess)
{
    vec3 Normal = mat3(transpose(inverse(model))) * aNormal;

    vec3 ambient = ambientStrength * lightColor;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;

    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = specularStrength * spec * lightColor;

    return (ambient + diffuse + specular) * objectColor;
}
