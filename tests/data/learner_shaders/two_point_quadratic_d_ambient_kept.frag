#version 330 core
// model: point
// expect: attenuation-quadratic-uses-d + ambient-not-attenuated
// style: Horner-like falloff written wrong (kc + d·(kl + kq)), the ambient added after the falloff; helper for the direct light
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

vec3 direct(vec3 n, vec3 l, vec3 v, vec3 kd, vec3 ks)
{
    return light.diffuse * max(dot(n, l), 0.0) * kd
         + light.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * ks;
}

void main()
{
    vec3 kd = texture(material.diffuse, TexCoords).rgb;
    vec3 ks = texture(material.specular, TexCoords).rgb;
    float d = length(light.position - FragPos);
    float att = 1.0 / (light.constant + d * (light.linear + light.quadratic));
    vec3 n = normalize(Normal);
    vec3 l = normalize(light.position - FragPos);
    vec3 v = normalize(viewPos - FragPos);
    FragColor = vec4(light.ambient * kd + att * direct(n, l, v, kd, ks), 1.0);
}
