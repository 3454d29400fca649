#version 330 core
// model: materials
// expect: agrees
// style: tout dans main, commentaires en français, noms du tutoriel, somme écrite en une fois
struct Material {
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float shininess;
};
struct Light {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};

in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    // la normale interpolée n'est plus unitaire : on la renormalise
    vec3 n = normalize(Normal);
    // vecteur vers la lampe et vecteur vers l'œil, tous deux depuis le fragment
    vec3 versLampe = normalize(light.position - FragPos);
    vec3 versOeil = normalize(viewPos - FragPos);
    // reflet du rayon incident (de la lampe vers la surface)
    vec3 reflet = reflect(-versLampe, n);
    float cosDiffus = max(dot(n, versLampe), 0.0);
    float brillance = pow(max(dot(versOeil, reflet), 0.0), material.shininess);
    FragColor = vec4(light.ambient * material.ambient
                   + light.diffuse * material.diffuse * cosDiffus
                   + light.specular * material.specular * brillance, 1.0);
}
