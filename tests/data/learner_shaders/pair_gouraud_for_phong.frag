#version 330 core
// model: basic_lighting
// vertex: pair_gouraud_for_phong.vert
// expect: gouraud-for-phong
// style: "faster" per-vertex lighting with every strength a uniform, the fragment shader only passes the colour on
in vec3 vColor;
out vec4 FragColor;

void main()
{
    FragColor = vec4(vColor, 1.0);
}
