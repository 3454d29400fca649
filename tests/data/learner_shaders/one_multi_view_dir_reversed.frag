#version 330 core
// model: multiple_lights
// expect: view-dir-reversed
// style: the tutorial's three Calc functions renamed and regrouped, view vector taken from the eye to the fragment
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

struct Texels { vec3 d; vec3 s; };

vec3 shadeDirectional(DirLight lt, vec3 n, vec3 eyeVec, Texels t)
{
    vec3 l = normalize(-lt.direction);
    return lt.ambient * t.d + lt.diffuse * max(dot(n, l), 0.0) * t.d
         + lt.specular * pow(max(dot(eyeVec, reflect(-l, n)), 0.0), material.shininess) * t.s;
}

vec3 shadePoint(PointLight lt, vec3 n, vec3 eyeVec, Texels t)
{
    vec3 l = normalize(lt.position - FragPos);
    float r = length(lt.position - FragPos);
    float a = 1.0 / (lt.constant + lt.linear * r + lt.quadratic * r * r);
    return a * (lt.ambient * t.d + lt.diffuse * max(dot(n, l), 0.0) * t.d
              + lt.specular * pow(max(dot(eyeVec, reflect(-l, n)), 0.0), material.shininess) * t.s);
}

vec3 shadeSpot(SpotLight lt, vec3 n, vec3 eyeVec, Texels t)
{
    vec3 l = normalize(lt.position - FragPos);
    float r = length(lt.position - FragPos);
    float a = 1.0 / (lt.constant + lt.linear * r + lt.quadratic * r * r);
    float i = clamp((dot(l, normalize(-lt.direction)) - lt.outerCutOff) / (lt.cutOff - lt.outerCutOff), 0.0, 1.0);
    return (a * i) * (lt.ambient * t.d + lt.diffuse * max(dot(n, l), 0.0) * t.d
                    + lt.specular * pow(max(dot(eyeVec, reflect(-l, n)), 0.0), material.shininess) * t.s);
}

void main()
{
    Texels t = Texels(texture(material.diffuse, TexCoords).rgb, texture(material.specular, TexCoords).rgb);
    vec3 n = normalize(Normal);
    vec3 eyeVec = normalize(FragPos - viewPos);   // the ray from the camera
    vec3 c = shadeDirectional(dirLight, n, eyeVec, t) + shadeSpot(spotLight, n, eyeVec, t);
    for (int i = 0; i < 4; i++) c += shadePoint(pointLights[i], n, eyeVec, t);
    FragColor = vec4(c, 1.0);
}
