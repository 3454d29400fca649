#version 330 core
// model: spot
// expect: spot-hard-edge
// style: the chapter's first flashlight (inside/outside test on cutOff only) kept after adding attenuation; outerCutOff declared, unused
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
    vec3 tex = texture(material.diffuse, TexCoords).rgb;
    vec3 L = normalize(light.position - FragPos);
    float d = length(light.position - FragPos);
    float att = 1.0 / (light.constant + light.linear * d + light.quadratic * (d * d));
    vec3 color = light.ambient * tex * att;
    float theta = dot(L, normalize(-light.direction));
    if (theta > light.cutOff) {
        vec3 N = normalize(Normal);
        vec3 V = normalize(viewPos - FragPos);
        color += att * light.diffuse * max(dot(N, L), 0.0) * tex;
        color += att * light.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess)
               * texture(material.specular, TexCoords).rgb;
    }
    FragColor = vec4(color, 1.0);
}
