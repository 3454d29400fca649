#version 330 core
// Vertex half of ok_pair_gouraud.frag: Phong evaluated per vertex (the Gouraud exercise), split in helpers.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 vertexLight;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

vec3 worldNormal()
{
    return normalize(mat3(transpose(inverse(model))) * aNormal);
}

float highlight(vec3 n, vec3 l, vec3 v)
{
    return pow(max(dot(v, reflect(-l, n)), 0.0), shininess);
}

void main()
{
    vec4 world = model * vec4(aPos, 1.0);
    gl_Position = projection * view * world;
    vec3 n = worldNormal();
    vec3 l = normalize(lightPos - world.xyz);
    vec3 v = normalize(viewPos - world.xyz);
    vertexLight = lightColor * (ambientStrength + max(dot(n, l), 0.0)
                                + specularStrength * highlight(n, l, v));
}
