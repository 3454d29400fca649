#version 330 core
// Vertex half of ok_pair_viewspace.frag: everything moved to eye space, the eye at the origin.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 eyePos;
out vec3 eyeNormal;
out vec3 eyeLight;

uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;
uniform vec3 lightPos;

void main()
{
    vec4 p = view * model * vec4(aPos, 1.0);
    eyePos = p.xyz;
    mat3 nrm = transpose(inverse(mat3(view * model)));
    eyeNormal = nrm * aNormal;
    eyeLight = (view * vec4(lightPos, 1.0)).xyz;
    gl_Position = projection * p;
}
