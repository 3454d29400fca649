#version 330 core
// Vertex half of pair_phong_for_gouraud.frag: only passes world position and normal on.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 pos;
out vec3 nrm;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    pos = vec3(model * vec4(aPos, 1.0));
    nrm = mat3(transpose(inverse(model))) * aNormal;
    gl_Position = projection * view * vec4(pos, 1.0);
}
