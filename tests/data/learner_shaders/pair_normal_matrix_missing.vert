#version 330 core
// Vertex half of pair_normal_matrix_missing.frag: engine-style attribute block, normal turned by mat3(model).
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out VertexData {
    vec3 worldPos;
    vec3 worldNormal;
} vout;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    vec4 wp = model * vec4(aPos, 1.0);
    vout.worldPos = wp.xyz;
    vout.worldNormal = mat3(model) * aNormal;    // rotate the normal with the object
    gl_Position = projection * view * wp;
}
