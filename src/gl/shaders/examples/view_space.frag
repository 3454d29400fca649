#version 330 core
// The fragment half of view_space.vert: the eye sits at the origin of view space.
in VS_OUT {
    vec3 FragPos;
    vec3 Normal;
    vec3 LightPos;
} fs_in;

out vec4 FragColor;

uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 n = normalize(fs_in.Normal);
    vec3 l = normalize(fs_in.LightPos - fs_in.FragPos);
    vec3 v = normalize(-fs_in.FragPos);
    vec3 r = reflect(-l, n);
    vec3 lit = 0.1 * lightColor + max(dot(n, l), 0.0) * lightColor
             + 0.5 * pow(max(dot(v, r), 0.0), 32.0) * lightColor;
    FragColor = vec4(lit * objectColor, 1.0);
}
