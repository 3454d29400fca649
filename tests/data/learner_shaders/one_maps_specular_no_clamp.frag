#version 330 core
// model: lighting_maps
// expect: specular-no-clamp
// style: everything in main, R·V raised to the power directly (no max), texel fetched once into vec4
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    vec4 kd = texture(material.diffuse, TexCoords);
    vec4 ks = texture(material.specular, TexCoords);
    vec3 N = normalize(Normal);
    vec3 L = normalize(light.position - FragPos);
    vec3 V = normalize(viewPos - FragPos);
    vec3 R = reflect(-L, N);
    float lambert = max(dot(N, L), 0.0);
    float phong = pow(dot(R, V), material.shininess);
    FragColor = vec4(light.ambient * kd.rgb + light.diffuse * lambert * kd.rgb + light.specular * phong * ks.rgb, 1.0);
}
