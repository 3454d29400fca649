#version 330 core
// model: multiple_lights
// uniforms: site_directional_shininess_ignored.toml
// expect: shininess-ignored@directional
// style: Ukrainian-named engine uniforms; the sun's highlight copied from the Basic lighting chapter with its 32, the others use the material
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 pozytsiia;
in vec3 normal;
in vec2 uv;
out vec4 kolir;
uniform vec3 kamera;
uniform Material material;
uniform DirLight sonce;
uniform PointLight lampy[4];
uniform SpotLight likhtar;

vec3 td;
vec3 ts;

// сонце (скопійовано з першого уроку)
vec3 vidSoncia(vec3 n, vec3 v)
{
    vec3 l = normalize(-sonce.direction);
    float blysk = pow(max(dot(v, reflect(-l, n)), 0.0), 32.0);
    return sonce.ambient * td + sonce.diffuse * max(dot(n, l), 0.0) * td + sonce.specular * blysk * ts;
}

vec3 vidLampy(PointLight p, vec3 n, vec3 v)
{
    vec3 l = normalize(p.position - pozytsiia);
    float d = length(p.position - pozytsiia);
    float z = 1.0 / (p.constant + p.linear * d + p.quadratic * d * d);
    float blysk = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    return z * (p.ambient * td + p.diffuse * max(dot(n, l), 0.0) * td + p.specular * blysk * ts);
}

vec3 vidLikhtaria(vec3 n, vec3 v)
{
    vec3 l = normalize(likhtar.position - pozytsiia);
    float d = length(likhtar.position - pozytsiia);
    float z = 1.0 / (likhtar.constant + likhtar.linear * d + likhtar.quadratic * d * d);
    float m = clamp((dot(l, normalize(-likhtar.direction)) - likhtar.outerCutOff) / (likhtar.cutOff - likhtar.outerCutOff), 0.0, 1.0);
    float blysk = pow(max(dot(v, reflect(-l, n)), 0.0), material.shininess);
    return z * m * (likhtar.ambient * td + likhtar.diffuse * max(dot(n, l), 0.0) * td + likhtar.specular * blysk * ts);
}

void main()
{
    td = texture(material.diffuse, uv).rgb;
    ts = texture(material.specular, uv).rgb;
    vec3 n = normalize(normal);
    vec3 v = normalize(kamera - pozytsiia);
    vec3 c = vidSoncia(n, v) + vidLikhtaria(n, v);
    for (int i = 0; i < 4; i++) c += vidLampy(lampy[i], n, v);
    kolir = vec4(c, 1.0);
}
