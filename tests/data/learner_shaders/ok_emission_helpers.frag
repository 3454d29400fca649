#version 330 core
// model: lighting_maps_emission
// expect: agrees
// style: one helper per term and one for the glow, the lamp's vectors passed in, short names
struct Material {
    sampler2D diffuse;
    sampler2D specular;
    sampler2D emission;
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

vec3 ambientPart(vec3 albedo)
{
    return light.ambient * albedo;
}

vec3 diffusePart(vec3 albedo, vec3 n, vec3 toLamp)
{
    float lambert = max(dot(n, toLamp), 0.0);
    return light.diffuse * lambert * albedo;
}

vec3 specularPart(vec3 mask, vec3 n, vec3 toLamp, vec3 toEye)
{
    vec3 mirror = reflect(-toLamp, n);
    return light.specular * pow(max(dot(toEye, mirror), 0.0), material.shininess) * mask;
}

// The glow is the surface's own light: it goes in as it is, after the lamp's terms.
vec3 glow(vec2 uv)
{
    return texture(material.emission, uv).rgb;
}

void main()
{
    vec3 albedo = texture(material.diffuse, TexCoords).rgb;
    vec3 mask = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 toLamp = normalize(light.position - FragPos);
    vec3 toEye = normalize(viewPos - FragPos);
    vec3 lit = ambientPart(albedo) + diffusePart(albedo, n, toLamp) + specularPart(mask, n, toLamp, toEye);
    FragColor = vec4(lit + glow(TexCoords), 1.0);
}
