#version 330 core
// model: point
// expect: ambient-not-attenuated
// style: commentaires en français, l'atténuation appliquée au diffus et au spéculaire seulement (« l'ambiant est partout »)
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

void main()
{
    vec3 texel = texture(material.diffuse, TexCoords).rgb;
    // la lumière ambiante ne dépend pas de la distance : pas d'atténuation
    vec3 ambiant = light.ambient * texel;
    vec3 n = normalize(Normal);
    vec3 l = normalize(light.position - FragPos);
    vec3 v = normalize(viewPos - FragPos);
    float d = length(light.position - FragPos);
    float att = 1.0 / (light.constant + light.linear * d + light.quadratic * d * d);
    vec3 diffus = light.diffuse * max(dot(n, l), 0.0) * texel;
    vec3 spec = light.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess)
              * texture(material.specular, TexCoords).rgb;
    FragColor = vec4(ambiant + att * (diffus + spec), 1.0);
}
