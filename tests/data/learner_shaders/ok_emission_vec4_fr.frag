#version 330 core
// model: lighting_maps_emission
// expect: agrees
// style: everything inlined in main, vec4 colours, French comments, the emission added to the vec4 at the end
struct Materiau {
    sampler2D diffuse;
    sampler2D specular;
    sampler2D emission;
    float shininess;
};
struct Lumiere {
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
uniform Materiau material;
uniform Lumiere light;

void main()
{
    // couleurs lues dans les textures
    vec4 couleur = texture(material.diffuse, TexCoords);
    vec4 brillance = texture(material.specular, TexCoords);
    // vecteurs unitaires au point de la surface
    vec3 n = normalize(Normal);
    vec3 versLumiere = normalize(light.position - FragPos);
    vec3 versOeil = normalize(viewPos - FragPos);
    float d = max(dot(n, versLumiere), 0.0);
    float s = pow(max(dot(versOeil, reflect(-versLumiere, n)), 0.0), material.shininess);
    vec4 resultat = vec4(light.ambient, 0.0) * couleur
                  + vec4(light.diffuse * d, 0.0) * couleur
                  + vec4(light.specular * s, 0.0) * brillance;
    // l'émission ne dépend d'aucune lumière : on l'ajoute telle quelle
    resultat += vec4(texture(material.emission, TexCoords).rgb, 0.0);
    FragColor = vec4(resultat.rgb, 1.0);
}
