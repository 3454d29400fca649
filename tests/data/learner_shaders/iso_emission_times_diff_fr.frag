#version 330 core
// model: lighting_maps_emission
// expect: isolated the emission term
// style: French names and comments, a helper returning the Lambert factor, the glow scaled by it "pour qu'elle suive la lampe"
struct Materiau {
    sampler2D diffuse;
    sampler2D specular;
    sampler2D emission;
    float shininess;
};
struct Lampe {
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
uniform Lampe light;

// facteur de Lambert : cosinus entre la normale et la direction de la lampe
float lambert(vec3 n, vec3 versLampe)
{
    return max(dot(n, versLampe), 0.0);
}

void main()
{
    vec3 couleur = texture(material.diffuse, TexCoords).rgb;
    vec3 masque = texture(material.specular, TexCoords).rgb;
    vec3 lueur = texture(material.emission, TexCoords).rgb;

    vec3 n = normalize(Normal);
    vec3 versLampe = normalize(light.position - FragPos);
    vec3 versOeil = normalize(viewPos - FragPos);
    float kd = lambert(n, versLampe);
    float ks = pow(max(dot(versOeil, reflect(-versLampe, n)), 0.0), material.shininess);

    vec3 eclairage = light.ambient * couleur + light.diffuse * kd * couleur + light.specular * ks * masque;
    // la lueur suit la lampe : plus la face est éclairée, plus elle brille
    FragColor = vec4(eclairage + lueur * kd, 1.0);
}
