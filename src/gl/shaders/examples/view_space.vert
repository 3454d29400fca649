#version 330 core
// LearnOpenGL "Basic lighting", exercise 3: lighting in view space. Position, normal and
// light move by view * model; the eye is then at the origin (view_space.frag). Correct.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out VS_OUT {
    vec3 FragPos;
    vec3 Normal;
    vec3 LightPos;
} vs_out;

uniform vec3 lightPos;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    mat4 modelView = view * model;
    vs_out.FragPos = vec3(modelView * vec4(aPos, 1.0));
    vs_out.Normal = mat3(transpose(inverse(modelView))) * aNormal;
    vs_out.LightPos = vec3(view * vec4(lightPos, 1.0));
    gl_Position = projection * vec4(vs_out.FragPos, 1.0);
}
