#version 330 core
// model: lighting_maps
// expect: normal-not-normalized + ambient-missing
// style: everything on one expression per term, the interpolated normal used directly, no ambient ("the texture is enough")
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
    vec3 L = normalize(light.position - FragPos);
    vec3 V = normalize(viewPos - FragPos);
    vec3 D = light.diffuse * max(dot(Normal, L), 0.0) * texture(material.diffuse, TexCoords).rgb;
    vec3 S = light.specular * pow(max(dot(V, reflect(-L, Normal)), 0.0), material.shininess) * texture(material.specular, TexCoords).rgb;
    FragColor = vec4(D + S, 1.0);
}
