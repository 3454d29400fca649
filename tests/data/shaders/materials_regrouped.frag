#version 330 core
// Correct Materials shader: struct fields read into locals, the specular written with
// a helper function and the sum ordered differently.
struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
};
struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

float phongLobe(vec3 n, vec3 toLight, vec3 toEye, float power)
{
    vec3 r = reflect(-toLight, n);
    return pow(max(dot(toEye, r), 0.0), power);
}

void main()
{
    vec3 n = normalize(Normal);
    vec3 toLight = normalize(light.position - FragPos);
    vec3 toEye = normalize(viewPos - FragPos);
    vec3 color = light.specular * (phongLobe(n, toLight, toEye, material.shininess) * material.specular);
    color += light.diffuse * (max(dot(toLight, n), 0.0) * material.diffuse);
    color += light.ambient * material.ambient;
    FragColor = vec4(color, 1.0);
}
