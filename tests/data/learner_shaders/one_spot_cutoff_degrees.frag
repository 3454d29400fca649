#version 330 core
// model: spot
// expect: spot-cutoff-degrees
// style: commentaires en français, les angles de coupure « convertis » comme s'ils étaient en degrés, intensité dans une fonction
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

// intensité du cône : 1 au centre, 0 au-delà du cône extérieur
float intensiteCone(vec3 versLampe)
{
    float interieur = cos(radians(light.cutOff));       // angles donnés en degrés (pensait-on)
    float exterieur = cos(radians(light.outerCutOff));
    float theta = dot(versLampe, normalize(-light.direction));
    return clamp((theta - exterieur) / (interieur - exterieur), 0.0, 1.0);
}

void main()
{
    vec3 albedo = texture(material.diffuse, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 l = normalize(light.position - FragPos);
    vec3 v = normalize(viewPos - FragPos);
    float dist = length(light.position - FragPos);
    float attenuation = 1.0 / (light.constant + light.linear * dist + light.quadratic * dist * dist);
    float k = intensiteCone(l);
    vec3 ambiant = light.ambient * albedo;
    vec3 diffus = light.diffuse * max(dot(n, l), 0.0) * albedo * k;
    vec3 speculaire = light.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess)
                    * texture(material.specular, TexCoords).rgb * k;
    FragColor = vec4((ambiant + diffus + speculaire) * attenuation, 1.0);
}
