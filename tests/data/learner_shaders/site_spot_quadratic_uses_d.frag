#version 330 core
// model: multiple_lights
// uniforms: site_spot_quadratic_uses_d.toml
// expect: attenuation-quadratic-uses-d@spot
// style: four point lights as separate uniforms, a shared shading helper; the torch's falloff typed by hand with Kq·d
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
uniform PointLight light0;
uniform PointLight light1;
uniform PointLight light2;
uniform PointLight light3;
uniform SpotLight spotLight;

vec3 shade(vec3 amb, vec3 dif, vec3 spc, vec3 L, vec3 N, vec3 V, vec3 tD, vec3 tS)
{
    return amb * tD + dif * max(dot(N, L), 0.0) * tD
         + spc * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * tS;
}

vec3 point(PointLight p, vec3 N, vec3 V, vec3 tD, vec3 tS)
{
    float d = length(p.position - FragPos);
    return shade(p.ambient, p.diffuse, p.specular, normalize(p.position - FragPos), N, V, tD, tS)
         / (p.constant + p.linear * d + p.quadratic * d * d);
}

void main()
{
    vec3 tD = texture(material.diffuse, TexCoords).rgb;
    vec3 tS = texture(material.specular, TexCoords).rgb;
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    vec3 c = shade(dirLight.ambient, dirLight.diffuse, dirLight.specular, normalize(-dirLight.direction), N, V, tD, tS);
    c += point(light0, N, V, tD, tS);
    c += point(light1, N, V, tD, tS);
    c += point(light2, N, V, tD, tS);
    c += point(light3, N, V, tD, tS);
    vec3 Ls = normalize(spotLight.position - FragPos);
    float ds = length(spotLight.position - FragPos);
    float falloff = 1.0 / (spotLight.constant + spotLight.linear * ds + spotLight.quadratic * ds);
    float theta = dot(Ls, normalize(-spotLight.direction));
    float soft = clamp((theta - spotLight.outerCutOff) / (spotLight.cutOff - spotLight.outerCutOff), 0.0, 1.0);
    c += falloff * soft * shade(spotLight.ambient, spotLight.diffuse, spotLight.specular, Ls, N, V, tD, tS);
    FragColor = vec4(c, 1.0);
}
