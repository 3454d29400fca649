#version 330 core
// Vertex half of pair_position_not_transformed.frag: gl_Position is right, but the position
// handed to the fragment stage is the raw attribute (object space).
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 vPos;
out vec3 vNormal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    vPos = aPos;
    vNormal = mat3(transpose(inverse(model))) * aNormal;
    gl_Position = projection * view * model * vec4(aPos, 1.0);
}
