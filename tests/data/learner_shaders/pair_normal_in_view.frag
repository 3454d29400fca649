#version 330 core
// model: basic_lighting
// vertex: pair_normal_in_view.vert
// expect: spaces-normal-in-view
// style: the chapter's fragment shader unchanged, the mistake is in the vertex shader's normal matrix (view space)
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 ambient = 0.1 * lightColor;
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    vec3 diffuse = max(dot(norm, lightDir), 0.0) * lightColor;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 specular = 0.5 * pow(max(dot(viewDir, reflect(-lightDir, norm)), 0.0), 32.0) * lightColor;
    FragColor = vec4((ambient + diffuse + specular) * objectColor, 1.0);
}
