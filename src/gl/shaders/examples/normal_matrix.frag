#version 330 core
// A user's fragment shader that receives the OBJECT-space normal (aNormal, passed through
// from the vertex attribute) and the model matrix, and moves the normal to world space
// itself. This one is correct: the normal goes through the normal matrix
// transpose(inverse(mat3(model))), as LearnOpenGL's Basic lighting chapter explains.
// Check it with: lightlab check-shader normal_matrix.frag --model normal_matrix
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
    vec3 Normal = mat3(transpose(inverse(model))) * aNormal;

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
