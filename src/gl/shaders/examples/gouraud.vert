#version 330 core
// LearnOpenGL "Basic lighting", exercise 4: Phong's terms per vertex (Gouraud shading);
// the fragment shader (gouraud.frag) only scales the interpolated colour. Correct.
layout (location = 0) in vec3 aPos;
layout (location = 1) in vec3 aNormal;

out vec3 LightingColor;

uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform mat4 model;
uniform mat4 view;
uniform mat4 projection;

void main()
{
    vec3 position = vec3(model * vec4(aPos, 1.0));
    vec3 n = normalize(mat3(transpose(inverse(model))) * aNormal);
    gl_Position = projection * view * vec4(position, 1.0);

    vec3 toLight = normalize(lightPos - position);
    vec3 toEye = normalize(viewPos - position);
    vec3 ambient = 0.1 * lightColor;
    vec3 diffuse = max(dot(n, toLight), 0.0) * lightColor;
    float spec = pow(max(dot(toEye, reflect(-toLight, n)), 0.0), 32.0);
    vec3 specular = 0.5 * spec * lightColor;
    LightingColor = ambient + diffuse + specular;
}
