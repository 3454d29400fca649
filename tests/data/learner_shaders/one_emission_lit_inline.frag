#version 330 core
// model: lighting_maps_emission
// expect: emission-lit
// style: everything inlined, the emission tinted by the lamp's diffuse colour "so it matches the scene"
struct Material { sampler2D diffuse; sampler2D specular; sampler2D emission; float shininess; };
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
    vec3 tex = vec3(texture(material.diffuse, TexCoords));
    vec3 nrm = normalize(Normal);
    vec3 L = normalize(light.position - FragPos);
    vec3 V = normalize(viewPos - FragPos);
    vec3 color = light.ambient * tex
               + light.diffuse * max(dot(nrm, L), 0.0) * tex
               + light.specular * pow(max(dot(V, reflect(-L, nrm)), 0.0), material.shininess)
                 * vec3(texture(material.specular, TexCoords));
    vec3 glowing = vec3(texture(material.emission, TexCoords)) * light.diffuse;
    FragColor = vec4(color + glowing, 1.0);
}
