#version 330 core
// model: lighting_maps
// expect: agrees
// style: vec4 arithmetic throughout (w = 0 for directions), colours kept as vec4 until the end
struct Material {
    sampler2D diffuse;
    sampler2D specular;
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
in vec2 TexCoords;
out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    vec4 P = vec4(FragPos, 1.0);
    vec4 N = vec4(normalize(Normal), 0.0);
    vec4 L = normalize(vec4(light.position, 1.0) - P);
    vec4 E = normalize(vec4(viewPos, 1.0) - P);
    vec4 R = reflect(-L, N);
    vec4 albedo = vec4(texture(material.diffuse, TexCoords).rgb, 1.0);
    vec4 gloss = vec4(texture(material.specular, TexCoords).rgb, 1.0);
    vec4 c = vec4(light.ambient, 0.0) * albedo;
    c += vec4(light.diffuse, 0.0) * albedo * max(dot(N, L), 0.0);
    c += vec4(light.specular, 0.0) * gloss * pow(max(dot(R, E), 0.0), material.shininess);
    FragColor = vec4(c.rgb, 1.0);
}
