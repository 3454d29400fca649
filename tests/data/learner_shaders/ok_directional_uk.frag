#version 330 core
// model: directional
// uniforms: ok_directional_uk.toml
// expect: agrees
// style: українські коментарі, власні імена (sun, surf), освітлення у допоміжній функції, що повертає vec3
struct Sun {
    vec3 direction;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
};
struct Surface {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};

in vec3 vPos;
in vec3 vNorm;
in vec2 vUv;
out vec4 color;

uniform vec3 eye;
uniform Sun sun;
uniform Surface surf;

// Сонце: напрямок зберігається ВІД джерела, тому для L його треба обернути.
vec3 sunLight(vec3 n, vec3 toEye, vec3 albedo, vec3 shine)
{
    vec3 l = normalize(-sun.direction);
    float lambert = max(dot(n, l), 0.0);
    // дзеркальне відбиття падаючого променя
    vec3 r = reflect(-l, n);
    float blik = pow(max(dot(toEye, r), 0.0), surf.shininess);
    return sun.ambient * albedo + sun.diffuse * lambert * albedo + sun.specular * blik * shine;
}

void main()
{
    vec3 albedo = texture(surf.diffuse, vUv).rgb;
    vec3 shine = texture(surf.specular, vUv).rgb;
    // нормаль після інтерполяції треба знову нормалізувати
    vec3 n = normalize(vNorm);
    color = vec4(sunLight(n, normalize(eye - vPos), albedo, shine), 1.0);
}
