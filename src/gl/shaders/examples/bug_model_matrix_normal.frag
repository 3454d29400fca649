#version 330 core
// BUG (deliberate): the object-space normal is moved to world space with the model matrix
// itself, mat3(model) * aNormal, instead of the normal matrix. Under a non-uniform scale the
// result is no longer perpendicular to the surface, and the diffuse and specular terms tilt:
// LearnOpenGL's Basic lighting chapter shows the figure. Rotations and uniform scales hide
// the bug (after normalize they give the same direction).
// Check it with: lightlab check-shader bug_model_matrix_normal.frag --model normal_matrix
in vec3 FragPos;
in vec3 aNormal;

out vec4 FragColor;

uniform mat4 model;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 Normal = mat3(model) * aNormal;

    vec3 ambient = 0.1 * lightColor;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 specular = 0.5 * spec * lightColor;
    FragColor = vec4((ambient + diffuse + specular) * objectColor, 1.0);
}
