#version 330 core
// model: spot
// expect: spot-cutoff-as-angle
// style: the angle to the axis recovered with acos and compared with the cut-offs, renamed locals, attenuation first
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
    vec3 ray = light.position - FragPos;
    float dist = length(ray);
    float fade = 1.0 / (light.constant + light.linear * dist + light.quadratic * dist * dist);
    vec3 toLight = ray / dist;
    float angle = acos(dot(toLight, normalize(-light.direction)));   // angle from the axis
    float spot = clamp((angle - light.outerCutOff) / (light.cutOff - light.outerCutOff), 0.0, 1.0);
    vec3 n = normalize(Normal);
    vec3 e = normalize(viewPos - FragPos);
    vec3 tex = texture(material.diffuse, TexCoords).rgb;
    vec3 amb = light.ambient * tex;
    vec3 dif = light.diffuse * max(dot(n, toLight), 0.0) * tex * spot;
    vec3 spe = light.specular * pow(max(dot(e, reflect(-toLight, n)), 0.0), material.shininess)
             * texture(material.specular, TexCoords).rgb * spot;
    FragColor = vec4(fade * (amb + dif + spe), 1.0);
}
