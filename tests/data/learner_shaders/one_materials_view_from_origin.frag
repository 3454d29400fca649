#version 330 core
// model: materials
// expect: view-from-origin
// style: helper returning the specular factor, eye taken at the origin as in a view-space tutorial, viewPos declared but unused
struct Material { vec3 ambient; vec3 diffuse; vec3 specular; float shininess; };
struct Light { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

float specFactor(vec3 n, vec3 toLight)
{
    vec3 toEye = normalize(-FragPos);
    return pow(max(dot(toEye, reflect(-toLight, n)), 0.0), material.shininess);
}

void main()
{
    vec3 n = normalize(Normal);
    vec3 toLight = normalize(light.position - FragPos);
    vec3 c = light.ambient * material.ambient;
    c += light.diffuse * material.diffuse * max(dot(n, toLight), 0.0);
    c += light.specular * material.specular * specFactor(n, toLight);
    FragColor = vec4(c, 1.0);
}
