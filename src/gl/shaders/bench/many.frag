#version 330 core
// floor-lights256: LearnOpenGL's point light (ambient 0.05, diffuse 0.8, specular 1 times
// the light's colour) with Ogre's range-7 attenuation (1, 0.7, 1.8), looped over 256
// lights as a plain forward shader does.
out vec4 FragColor;
in vec3 FragPos;
in vec3 Normal;
struct Material { vec3 diffuse; vec3 specular; float shininess; };
#define NR_LIGHTS 256
uniform vec3 viewPos;
uniform Material material;
uniform vec3 lightPositions[NR_LIGHTS];
uniform vec3 lightColors[NR_LIGHTS];
const float Kc = 1.0, Kl = 0.7, Kq = 1.8;
void main() {
    vec3 norm = normalize(Normal);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 result = vec3(0.0);
    for (int i = 0; i < NR_LIGHTS; i++) {
        vec3 lightDir = normalize(lightPositions[i] - FragPos);
        float diff = max(dot(norm, lightDir), 0.0);
        vec3 reflectDir = reflect(-lightDir, norm);
        float spec = pow(max(dot(viewDir, reflectDir), 0.0), material.shininess);
        float distance = length(lightPositions[i] - FragPos);
        float attenuation = 1.0 / (Kc + Kl * distance + Kq * (distance * distance));
        vec3 ambient = 0.05 * lightColors[i] * material.diffuse;
        vec3 diffuse = 0.8 * lightColors[i] * diff * material.diffuse;
        vec3 specular = lightColors[i] * spec * material.specular;
        result += (ambient + diffuse + specular) * attenuation;
    }
    FragColor = vec4(result, 1.0);
}
