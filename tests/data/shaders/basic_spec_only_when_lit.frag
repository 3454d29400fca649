#version 330 core
// NOT the chapter's model: the specular term is dropped on faces turned away from the
// light (a common "fix"), while the chapter's shader keeps it. No catalogue mistake
// matches; the diagnosis must isolate it to the specular term, only when N·L < 0.
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
    vec3 norm = normalize(Normal);
    vec3 lightDir = normalize(lightPos - FragPos);
    float diff = max(dot(norm, lightDir), 0.0);
    vec3 viewDir = normalize(viewPos - FragPos);
    vec3 reflectDir = reflect(-lightDir, norm);
    float spec = pow(max(dot(viewDir, reflectDir), 0.0), shininess);
    if (dot(norm, lightDir) < 0.0) {
        spec = 0.0;
    }
    vec3 color = ambientStrength * lightColor + diff * lightColor + specularStrength * spec * lightColor;
    FragColor = vec4(color * objectColor, 1.0);
}
