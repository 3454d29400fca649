#version 330 core
// Vertex half of pair_light_in_view.frag: the light moved to view space "like in the exercise",
// but position and normal left in world space.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;
out vec3 wPos;
out vec3 wNormal;
out vec3 lightEye;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;

void main()
{
    vec4 world = model * vec4(aPos, 1.0);
    wPos = world.xyz;
    wNormal = transpose(inverse(mat3(model))) * aNormal;
    lightEye = vec3(view * vec4(lightPos, 1.0));
    gl_Position = projection * view * world;
}
