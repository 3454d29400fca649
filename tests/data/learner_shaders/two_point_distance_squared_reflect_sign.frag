#version 330 core
// model: point
// uniforms: two_point_distance_squared_reflect_sign.toml
// expect: attenuation-distance-squared-twice + reflect-sign
// style: українські коментарі, рушійні імена; відстань як dot(v, v) і reflect з вектором до світла
struct Lamp { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; float constant; float linear; float quadratic; };
in vec3 vPozytsiia;
in vec3 vNormal;
in vec2 vUv;
out vec4 fKolir;
uniform sampler2D tDyfuz;
uniform sampler2D tDzerkalo;
uniform float blyskuchist;
uniform vec3 kamera;
uniform Lamp lampa;

void main()
{
    vec3 doLampy = lampa.position - vPozytsiia;
    float d = dot(doLampy, doLampy);            // відстань (без кореня, так швидше)
    float z = 1.0 / (lampa.constant + lampa.linear * d + lampa.quadratic * d * d);
    vec3 l = normalize(doLampy);
    vec3 n = normalize(vNormal);
    vec3 v = normalize(kamera - vPozytsiia);
    vec3 r = reflect(l, n);                      // відбиття напрямку на світло
    vec3 td = texture(tDyfuz, vUv).rgb;
    vec3 c = lampa.ambient * td + lampa.diffuse * max(dot(n, l), 0.0) * td
           + lampa.specular * pow(max(dot(v, r), 0.0), blyskuchist) * texture(tDzerkalo, vUv).rgb;
    fKolir = vec4(z * c, 1.0);
}
