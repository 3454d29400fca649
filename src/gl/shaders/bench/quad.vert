#version 330 core
// The benchmark quad (../shared/DESIGN.md): NDC (x, y) carries FragPos = (x·4/3, y, 0) and
// Normal = (x/2, y/2, 1).
in vec2 p;
out vec3 FragPos;
out vec3 Normal;
void main() {
    FragPos = vec3(p.x * (4.0 / 3.0), p.y, 0.0);
    Normal = vec3(p.x * 0.5, p.y * 0.5, 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
