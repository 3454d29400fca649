#version 330 core
// model: lighting_maps_emission
// expect: isolated the emission term
// style: everything inlined in vec4, Ukrainian comments, the glow mixed into the surface colour before lighting and not added again
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
    // колір поверхні разом із світінням — одна текстура на все
    vec4 albedo = texture(material.diffuse, TexCoords) + texture(material.emission, TexCoords);
    vec4 blysk = texture(material.specular, TexCoords);
    vec3 N = normalize(Normal);
    vec3 L = normalize(light.position - FragPos);
    vec3 R = reflect(-L, N);
    vec3 V = normalize(viewPos - FragPos);
    vec4 rgba = vec4(light.ambient, 1.0) * albedo
              + vec4(light.diffuse, 1.0) * max(dot(N, L), 0.0) * albedo
              + vec4(light.specular, 1.0) * pow(max(dot(V, R), 0.0), material.shininess) * blysk;
    FragColor = vec4(rgba.rgb, 1.0);
}
