#version 330 core
// model: gouraud
// vertex: ok_pair_gouraud.vert
// expect: agrees
// style: Gouraud exercise done right, strengths as uniforms, vertex lighting in helper functions
in vec3 vertexLight;
out vec4 FragColor;
uniform vec3 objectColor;

void main()
{
    FragColor = vec4(objectColor * vertexLight, 1.0);
}
