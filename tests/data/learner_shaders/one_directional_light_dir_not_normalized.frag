#version 330 core
// model: directional
// expect: light-dir-not-normalized
// style: українські коментарі, напрямок сонця лише обернено (без normalize), усе в main
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    vec3 kolir = texture(material.diffuse, TexCoords).rgb;
    vec3 maska = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    // напрямок до сонця: протилежний до напрямку променів (вважаємо, що він уже одиничний)
    vec3 l = -light.direction;
    vec3 v = normalize(viewPos - FragPos);
    vec3 r = reflect(-l, n);
    float dyfuz = max(dot(n, l), 0.0);
    float blysk = pow(max(dot(v, r), 0.0), material.shininess);
    FragColor = vec4(light.ambient * kolir + light.diffuse * dyfuz * kolir + light.specular * blysk * maska, 1.0);
}
