#version 330 core
// model: multiple_lights
// uniforms: one_multi_attenuation_missing.toml
// expect: attenuation-missing
// style: attenuation constants declared but never used (neither for the bulbs nor for the torch), loop with a running index variable
#define NB_LAMPES 4
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 fragPosition;
in vec3 fragNormal;
in vec2 fragUV;
out vec4 finalColor;
uniform vec3 cameraPosition;
uniform Material mat;
uniform DirLight sunLight;
uniform PointLight bulbs[NB_LAMPES];
uniform SpotLight flashLight;

vec3 phongTerms(vec3 amb, vec3 dif, vec3 spe, vec3 n, vec3 l, vec3 v, vec3 cd, vec3 cs)
{
    float lambert = max(dot(n, l), 0.0);
    float shine = pow(max(dot(v, reflect(-l, n)), 0.0), mat.shininess);
    return amb * cd + dif * lambert * cd + spe * shine * cs;
}

void main()
{
    vec3 cd = texture(mat.diffuse, fragUV).rgb;
    vec3 cs = texture(mat.specular, fragUV).rgb;
    vec3 n = normalize(fragNormal);
    vec3 v = normalize(cameraPosition - fragPosition);
    vec3 result = phongTerms(sunLight.ambient, sunLight.diffuse, sunLight.specular, n,
                             normalize(-sunLight.direction), v, cd, cs);
    for (int b = 0; b < NB_LAMPES; b++) {
        vec3 l = normalize(bulbs[b].position - fragPosition);
        result += phongTerms(bulbs[b].ambient, bulbs[b].diffuse, bulbs[b].specular, n, l, v, cd, cs);
    }
    vec3 l = normalize(flashLight.position - fragPosition);
    float theta = dot(l, normalize(-flashLight.direction));
    float soft = clamp((theta - flashLight.outerCutOff) / (flashLight.cutOff - flashLight.outerCutOff), 0.0, 1.0);
    result += soft * phongTerms(flashLight.ambient, flashLight.diffuse, flashLight.specular, n, l, v, cd, cs);
    finalColor = vec4(result, 1.0);
}
