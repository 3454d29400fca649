#version 330 core
// model: multiple_lights
// uniforms: site_directional_specular_no_clamp.toml
// expect: specular-no-clamp@directional
// style: engine names, one generic helper taking the clamp as written by the caller; the sun's R·V goes to pow unclamped
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 vWorldPos;
in vec3 vWorldNormal;
in vec2 vTexcoord;
out vec4 oColor;
uniform vec3 uCameraPos;
uniform Material uMaterial;
uniform DirLight uDirectional;
uniform PointLight uPoints[4];
uniform SpotLight uSpot;

vec3 gAlbedo;
vec3 gSpecMask;

vec3 combine(vec3 a, vec3 d, vec3 s, float lambert, float lobe)
{
    return a * gAlbedo + d * lambert * gAlbedo + s * lobe * gSpecMask;
}

void main()
{
    gAlbedo = texture(uMaterial.diffuse, vTexcoord).rgb;
    gSpecMask = texture(uMaterial.specular, vTexcoord).rgb;
    vec3 N = normalize(vWorldNormal);
    vec3 V = normalize(uCameraPos - vWorldPos);
    float e = uMaterial.shininess;

    vec3 L = normalize(-uDirectional.direction);
    vec3 color = combine(uDirectional.ambient, uDirectional.diffuse, uDirectional.specular,
                         max(dot(N, L), 0.0), pow(dot(V, reflect(-L, N)), e));

    for (int i = 0; i < 4; i++) {
        vec3 toL = uPoints[i].position - vWorldPos;
        float d = length(toL);
        L = toL / d;
        float att = 1.0 / (uPoints[i].constant + uPoints[i].linear * d + uPoints[i].quadratic * d * d);
        color += att * combine(uPoints[i].ambient, uPoints[i].diffuse, uPoints[i].specular,
                               max(dot(N, L), 0.0), pow(max(dot(V, reflect(-L, N)), 0.0), e));
    }

    vec3 toS = uSpot.position - vWorldPos;
    float ds = length(toS);
    L = toS / ds;
    float atts = 1.0 / (uSpot.constant + uSpot.linear * ds + uSpot.quadratic * ds * ds);
    float inten = clamp((dot(L, normalize(-uSpot.direction)) - uSpot.outerCutOff) / (uSpot.cutOff - uSpot.outerCutOff), 0.0, 1.0);
    color += atts * inten * combine(uSpot.ambient, uSpot.diffuse, uSpot.specular,
                                    max(dot(N, L), 0.0), pow(max(dot(V, reflect(-L, N)), 0.0), e));
    oColor = vec4(color, 1.0);
}
