#version 330 core
// model: multiple_lights
// expect: reflect-sign@spot
// style: українські коментарі, окрема функція на кожне джерело; у ліхтарику reflect отримує напрямок до світла
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
uniform PointLight pointLights[4];
uniform SpotLight spotLight;

// Сонце: без затухання.
vec3 sonce(vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(-dirLight.direction);
    vec3 r = reflect(-l, n);
    return dirLight.ambient * td + dirLight.diffuse * max(dot(n, l), 0.0) * td
         + dirLight.specular * pow(max(dot(v, r), 0.0), material.shininess) * ts;
}

// Точкова лампа: затухання 1 / (Kc + Kl d + Kq d²) на всі три складові.
vec3 lampa(PointLight p, vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(p.position - FragPos);
    vec3 r = reflect(-l, n);
    float d = length(p.position - FragPos);
    float z = 1.0 / (p.constant + p.linear * d + p.quadratic * d * d);
    return z * (p.ambient * td + p.diffuse * max(dot(n, l), 0.0) * td
              + p.specular * pow(max(dot(v, r), 0.0), material.shininess) * ts);
}

// Ліхтарик: м'який край конуса і затухання.
vec3 likhtaryk(vec3 n, vec3 v, vec3 td, vec3 ts)
{
    vec3 l = normalize(spotLight.position - FragPos);
    vec3 r = reflect(l, n);   // відбитий промінь
    float d = length(spotLight.position - FragPos);
    float z = 1.0 / (spotLight.constant + spotLight.linear * d + spotLight.quadratic * d * d);
    float kut = dot(l, normalize(-spotLight.direction));
    float m = clamp((kut - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    return (z * m) * (spotLight.ambient * td + spotLight.diffuse * max(dot(n, l), 0.0) * td
                    + spotLight.specular * pow(max(dot(v, r), 0.0), material.shininess) * ts);
}

void main()
{
    vec3 td = texture(material.diffuse, TexCoords).rgb;
    vec3 ts = texture(material.specular, TexCoords).rgb;
    vec3 n = normalize(Normal);
    vec3 v = normalize(viewPos - FragPos);
    vec3 suma = sonce(n, v, td, ts);
    for (int i = 0; i < 4; ++i) suma += lampa(pointLights[i], n, v, td, ts);
    suma += likhtaryk(n, v, td, ts);
    FragColor = vec4(suma, 1.0);
}
