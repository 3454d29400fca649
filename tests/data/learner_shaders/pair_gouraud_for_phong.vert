#version 330 core
// Vertex half of pair_gouraud_for_phong.frag: the whole Phong sum per vertex, strengths as uniforms.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 vColor;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

void main()
{
    vec3 P = vec3(model * vec4(aPos, 1.0));
    vec3 N = normalize(mat3(transpose(inverse(model))) * aNormal);
    vec3 L = normalize(lightPos - P);
    vec3 V = normalize(viewPos - P);
    float k = ambientStrength + max(dot(N, L), 0.0)
            + specularStrength * pow(max(dot(V, reflect(-L, N)), 0.0), shininess);
    vColor = k * lightColor * objectColor;
    gl_Position = projection * view * vec4(P, 1.0);
}
