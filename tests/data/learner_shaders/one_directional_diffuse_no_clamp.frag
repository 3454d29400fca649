#version 330 core
// model: directional
// expect: diffuse-no-clamp
// style: commentaires en français, produit scalaire gardé tel quel pour le diffus, fonctions d'aide par terme
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct Light { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

// terme diffus : cosinus de l'angle entre la normale et la direction du soleil
vec3 termeDiffus(vec3 n, vec3 l, vec3 couleur)
{
    return light.diffuse * dot(n, l) * couleur;
}

// terme spéculaire de Phong
vec3 termeSpeculaire(vec3 n, vec3 l, vec3 v, vec3 masque)
{
    float r = max(dot(v, reflect(-l, n)), 0.0);
    return light.specular * pow(r, material.shininess) * masque;
}

void main()
{
    vec3 couleur = texture(material.diffuse, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 l = normalize(-light.direction);     // vers le soleil
    vec3 v = normalize(viewPos - FragPos);
    vec3 total = light.ambient * couleur + termeDiffus(n, l, couleur)
               + termeSpeculaire(n, l, v, texture(material.specular, TexCoords).rgb);
    FragColor = vec4(total, 1.0);
}
