#version 330 core
// model: spot
// expect: spot-epsilon-swapped + attenuation-missing
// style: cone written as (θ − outer)/(outer − inner), no distance falloff; vec4 colour accumulation
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light {
    vec3 position; vec3 direction; float cutOff; float outerCutOff;
    vec3 ambient; vec3 diffuse; vec3 specular;
    float constant; float linear; float quadratic;
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
    vec4 kd = texture(material.diffuse, TexCoords);
    vec4 ks = texture(material.specular, TexCoords);
    vec3 L = normalize(light.position - FragPos);
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    float theta = dot(L, normalize(-light.direction));
    float width = light.outerCutOff - light.cutOff;
    float cone = clamp((theta - light.outerCutOff) / width, 0.0, 1.0);
    vec4 c = vec4(light.ambient, 0.0) * kd;
    c += cone * vec4(light.diffuse, 0.0) * kd * max(dot(N, L), 0.0);
    c += cone * vec4(light.specular, 0.0) * ks * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess);
    FragColor = vec4(c.rgb, 1.0);
}
