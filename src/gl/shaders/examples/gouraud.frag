#version 330 core
// The fragment half of the Gouraud exercise: the colour was lit per vertex.
in vec3 LightingColor;
out vec4 FragColor;
uniform vec3 objectColor;

void main()
{
    FragColor = vec4(LightingColor * objectColor, 1.0);
}
