// LearnOpenGL, Lighting > Basic lighting, exercise "Gouraud": the same Phong terms computed
// in the vertex shader, so the fragment stage only interpolates the resulting color.
// gouraud_vertex is the vertex-stage body: it moves the vertex to world space with the
// model matrix and the normal with the normal matrix transpose(inverse(mat3(model))),
// then returns the lighting color (without the object color) that the vertex would emit.
// gouraud_fragment is the fragment-stage body: interpolated lighting times object color.
vec3 gouraud_vertex(vec3 aPos, vec3 aNormal, mat4 model, vec3 lightPos, vec3 viewPos,
                    vec3 lightColor, float ambientStrength, float specularStrength,
                    float shininess)
{
    vec3 Position = vec3(model * vec4(aPos, 1.0));
    vec3 Normal = mat3(transpose(inverse(model))) * aNormal;

    vec3 ambient = ambientStrength * lightColor;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - Position);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;

    vec3 viewDir = normalize(viewPos - Position);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    vec3 specular = specularStrength * spec * lightColor;

    return ambient + diffuse + specular;
}

vec3 gouraud_fragment(vec3 LightingColor, vec3 objectColor)
{
    return LightingColor * objectColor;
}
