#version 330 core
// model: multiple_lights
// uniforms: ok_multi_four_uniforms_uk.toml
// expect: agrees
// style: чотири окремі uniform-лампи замість масиву, українські коментарі, функція з inout-накопичувачем
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };

in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform DirLight dirLight;
uniform PointLight lamp0;
uniform PointLight lamp1;
uniform PointLight lamp2;
uniform PointLight lamp3;
uniform SpotLight spotLight;

// Додає внесок однієї точкової лампи до суми (затухання множить усі три складові).
void addLamp(PointLight p, vec3 n, vec3 v, vec3 dif, vec3 spe, inout vec3 sum)
{
    vec3 doLampy = p.position - FragPos;
    float vidstan = length(doLampy);
    vec3 l = normalize(doLampy);
    float zatukhannia = 1.0 / (p.constant + p.linear * vidstan + p.quadratic * vidstan * vidstan);
    float dyf = max(dot(n, l), 0.0);
    float dz = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    sum += zatukhannia * (p.ambient * dif + p.diffuse * dyf * dif + p.specular * dz * spe);
}

void main()
{
    vec3 dif = vec3(texture(material.diffuse, TexCoords));
    vec3 spe = vec3(texture(material.specular, TexCoords));
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);

    // Напрямлене світло: напрямок обертаємо, бо він задано від джерела.
    vec3 l = normalize(-dirLight.direction);
    vec3 sum = dirLight.ambient * dif
             + dirLight.diffuse * max(dot(n, l), 0.0) * dif
             + dirLight.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * spe;

    addLamp(lamp0, n, v, dif, spe, sum);
    addLamp(lamp1, n, v, dif, spe, sum);
    addLamp(lamp2, n, v, dif, spe, sum);
    addLamp(lamp3, n, v, dif, spe, sum);

    // Ліхтарик: м'який край між cutOff і outerCutOff (обидва — косинуси).
    vec3 doLikht = spotLight.position - FragPos;
    float d = length(doLikht);
    l = doLikht / d;
    float kut = dot(l, normalize(-spotLight.direction));
    float m = clamp((kut - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    float z = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * d * d);
    sum += (spotLight.ambient * dif
          + spotLight.diffuse * max(dot(n, l), 0.0) * dif
          + spotLight.specular * pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess) * spe) * (z * m);

    FragColor = vec4(sum, 1.0);
}
