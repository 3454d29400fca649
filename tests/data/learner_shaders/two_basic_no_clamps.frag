#version 330 core
// model: basic_lighting
// expect: diffuse-no-clamp + specular-no-clamp
// style: commentaires en français, aucune des deux bornes à zéro (« les produits scalaires sont déjà entre -1 et 1 »), intensités en uniforms
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

void main()
{
    vec3 n = normalize(Normal);
    vec3 versLumiere = normalize(lightPos - FragPos);
    vec3 versOeil = normalize(viewPos - FragPos);
    // cosinus de l'angle d'incidence
    float diffus = dot(n, versLumiere);
    // reflet : le rayon incident est -versLumiere
    float speculaire = specularStrength * pow(dot(versOeil, reflect(-versLumiere, n)), shininess);
    FragColor = vec4((ambientStrength + diffus + speculaire) * lightColor * objectColor, 1.0);
}
