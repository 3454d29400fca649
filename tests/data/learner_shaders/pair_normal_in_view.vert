#version 330 core
// Vertex half of pair_normal_in_view.frag: the normal matrix built from view * model (as in a
// view-space tutorial), while the position stays in world space and the fragment shader uses
// the world-space light and eye.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 FragPos;
out vec3 Normal;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    FragPos = vec3(model * vec4(aPos, 1.0));
    Normal = mat3(transpose(inverse(view * model))) * aNormal;
    gl_Position = projection * view * vec4(FragPos, 1.0);
}
