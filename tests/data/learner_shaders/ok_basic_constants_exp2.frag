#version 330 core
// model: basic_lighting
// expect: agrees
// style: chapter constants hard-coded as consts, the lobe written as exp2(32·log2(x)) with a guard, reflection by hand
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;

uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

const float AMBIENT = 0.1;
const float SPECULAR = 0.5;
const float SHINE = 32.0;

void main()
{
    vec3 n = Normal / length(Normal);
    vec3 l = normalize(lightPos - FragPos);
    vec3 e = normalize(viewPos - FragPos);
    float nl = dot(n, l);
    vec3 mirrorDir = 2.0 * nl * n - l;
    float base = dot(e, mirrorDir);
    float lobe = base > 0.0 ? exp2(SHINE * log2(base)) : 0.0;
    vec3 light = lightColor * (AMBIENT + max(nl, 0.0) + SPECULAR * lobe);
    FragColor = vec4(light * objectColor, 1.0);
}
