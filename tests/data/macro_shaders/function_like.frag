#version 330 core
// a function-like macro declares each uniform, one call over two lines.
in vec3 FragPos;
in vec3 Normal;

out vec4 FragColor;
#define DECL(t, n) uniform t n;
DECL(vec3, lightPos)
DECL(vec3, viewPos)
DECL(vec3,
     lightColor)
DECL( vec3 , objectColor )

void main()
{
    float ambientStrength = 0.1;
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
