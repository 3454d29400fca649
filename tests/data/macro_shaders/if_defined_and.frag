#version 330 core
// #if with defined() and arithmetic picks the uniform declaration.
in vec3 FragPos;
in vec3 Normal;

out vec4 FragColor;
#define TWEAKABLE
#if defined(TWEAKABLE) && 1
#define PARAM uniform float
#elif 2 * 3 > 5
#define PARAM float
#else
#define PARAM const float
#endif
PARAM ambientStrength;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 ambient = ambientStrength * lightColor;

    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 diffuse = diff * lightColor;

    float specularStrength = 0.5;
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), 32.0);
    vec3 specular = specularStrength * spec * lightColor;

    FragColor = vec4((ambient + diffuse + specular) * objectColor, 1.0);
}
