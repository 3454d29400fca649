#version 330 core
// a mistake: the ambient term is left out; the uniforms are declared through macros.
in vec3 FragPos;
in vec3 Normal;

out vec4 FragColor;
#define TWEAKABLE
#ifdef TWEAKABLE
#define PARAM uniform float
#endif
#define UV uniform vec3
PARAM ambientStrength;
UV lightPos;
UV viewPos;
UV lightColor;
UV objectColor;

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

    FragColor = vec4((diffuse + specular) * objectColor, 1.0);
}
