#version 330 core
// model: lighting_maps
// expect: shininess-ignored
// style: struct declared as in the chapter but the exponent typed in as 32, named constants for the terms
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

const float HIGHLIGHT_EXP = 32.0;

void main()
{
    vec3 base = vec3(texture(material.diffuse, TexCoords));
    vec3 mask = vec3(texture(material.specular, TexCoords));
    vec3 nrm = normalize(Normal);
    vec3 toLamp = normalize(light.position - FragPos);
    vec3 toCam = normalize(viewPos - FragPos);
    vec3 ambientTerm = light.ambient * base;
    vec3 diffuseTerm = light.diffuse * max(dot(nrm, toLamp), 0.0) * base;
    vec3 specularTerm = light.specular * pow(max(dot(toCam, reflect(-toLamp, nrm)), 0.0), HIGHLIGHT_EXP) * mask;
    FragColor = vec4(ambientTerm + diffuseTerm + specularTerm, 1.0);
}
