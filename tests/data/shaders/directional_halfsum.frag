#version 330 core
// Correct directional light; the reflection computed with the formula 2(N·L)N - L written
// out, and the terms collected in a loop-free helper.
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};
struct DirLight {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform DirLight light;

vec3 shade(DirLight l, vec3 n, vec3 v, vec3 kd, vec3 ks, float s)
{
    vec3 toLight = normalize(-l.direction);
    float nl = dot(n, toLight);
    vec3 r = 2.0 * nl * n - toLight;
    return l.ambient * kd + l.diffuse * max(nl, 0.0) * kd + l.specular * pow(max(dot(v, r), 0.0), s) * ks;
}

void main()
{
    FragColor = vec4(shade(light, normalize(Normal), normalize(viewPos - FragPos),
                           texture(material.diffuse, TexCoords).rgb,
                           texture(material.specular, TexCoords).rgb, material.shininess), 1.0);
}
