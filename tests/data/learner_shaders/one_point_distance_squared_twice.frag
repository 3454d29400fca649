#version 330 core
// model: point
// expect: attenuation-distance-squared-twice
// style: distance taken as dot(v, v) "to skip the sqrt", then squared again in the formula; helper for the falloff
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light {
    vec3 position; vec3 ambient; vec3 diffuse; vec3 specular;
    float constant; float linear; float quadratic;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

float falloff(float d)
{
    return 1.0 / (light.constant + light.linear * d + light.quadratic * (d * d));
}

void main()
{
    vec3 toLight = light.position - FragPos;
    float d = dot(toLight, toLight);   // cheaper than length()
    vec3 L = normalize(toLight);
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    vec3 base = texture(material.diffuse, TexCoords).rgb;
    vec3 c = light.ambient * base
           + light.diffuse * max(dot(N, L), 0.0) * base
           + light.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess)
             * texture(material.specular, TexCoords).rgb;
    FragColor = vec4(c * falloff(d), 1.0);
}
