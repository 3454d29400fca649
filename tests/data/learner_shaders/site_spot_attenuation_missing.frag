#version 330 core
// model: multiple_lights
// uniforms: site_spot_attenuation_missing.toml
// expect: attenuation-missing@spot
// style: all inline in main, while loop; the flashlight "is attached to the camera so it needs no falloff"
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 fsPos;
in vec3 fsNormal;
in vec2 fsTex;
out vec4 fsOut;
uniform vec3 eyePos;
uniform Material material;
uniform DirLight sky;
uniform PointLight torches[4];
uniform SpotLight headlamp;

void main()
{
    vec3 Cd = texture(material.diffuse, fsTex).rgb;
    vec3 Cs = texture(material.specular, fsTex).rgb;
    vec3 N = normalize(fsNormal);
    vec3 V = normalize(eyePos - fsPos);
    vec3 L = normalize(-sky.direction);
    vec3 acc = sky.ambient * Cd + sky.diffuse * max(dot(N, L), 0.0) * Cd
             + sky.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * Cs;
    int j = 0;
    while (j < 4) {
        float dj = length(torches[j].position - fsPos);
        L = normalize(torches[j].position - fsPos);
        float fall = 1.0 / (torches[j].constant + torches[j].linear * dj + torches[j].quadratic * dj * dj);
        acc += fall * (torches[j].ambient * Cd + torches[j].diffuse * max(dot(N, L), 0.0) * Cd
                     + torches[j].specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * Cs);
        j = j + 1;
    }
    L = normalize(headlamp.position - fsPos);
    float cosA = dot(L, normalize(-headlamp.direction));
    float beam = clamp((cosA - headlamp.outerCutOff) / (headlamp.cutOff - headlamp.outerCutOff), 0.0, 1.0);
    acc += beam * (headlamp.ambient * Cd + headlamp.diffuse * max(dot(N, L), 0.0) * Cd
                 + headlamp.specular * pow(max(dot(V, reflect(-L, N)), 0.0), material.shininess) * Cs);
    fsOut = vec4(acc, 1.0);
}
