#version 330 core
// model: multiple_lights
// uniforms: ok_multi_engine_fields.toml
// expect: agrees
// style: engine structs with short field names (pos, dir, kc/kl/kq, amb/dif/spc), helper per light kind, for loop counting down
#define LAMP_COUNT 4
struct DirectionalLight { vec3 dir; vec3 amb; vec3 dif; vec3 spc; };
struct Lamp { vec3 pos; float kc; float kl; float kq; vec3 amb; vec3 dif; vec3 spc; };
struct Cone { vec3 pos; vec3 dir; float inner; float outer; float kc; float kl; float kq; vec3 amb; vec3 dif; vec3 spc; };

in vec3 v_pos;
in vec3 v_nrm;
in vec2 v_uv;
out vec4 f_color;

uniform vec3 u_eye;
uniform sampler2D u_albedoMap;
uniform sampler2D u_specMap;
uniform float u_specPower;
uniform DirectionalLight u_sun;
uniform Lamp u_lamps[LAMP_COUNT];
uniform Cone u_flash;

vec3 g_albedo;
vec3 g_specTint;

vec3 shadeTerms(vec3 amb, vec3 dif, vec3 spc, vec3 N, vec3 L, vec3 V)
{
    float lam = max(dot(N, L), 0.0);
    float hi = pow(max(dot(reflect(-L, N), V), 0.0), u_specPower);
    return amb * g_albedo + dif * lam * g_albedo + spc * hi * g_specTint;
}

float distanceFalloff(float kc, float kl, float kq, float d)
{
    return 1.0 / (kc + d * (kl + kq * d));
}

void main()
{
    g_albedo = texture(u_albedoMap, v_uv).rgb;
    g_specTint = texture(u_specMap, v_uv).rgb;
    vec3 N = normalize(v_nrm);
    vec3 V = normalize(u_eye - v_pos);

    vec3 c = shadeTerms(u_sun.amb, u_sun.dif, u_sun.spc, N, normalize(-u_sun.dir), V);

    for (int i = LAMP_COUNT - 1; i >= 0; --i) {
        vec3 toL = u_lamps[i].pos - v_pos;
        float d = length(toL);
        c += distanceFalloff(u_lamps[i].kc, u_lamps[i].kl, u_lamps[i].kq, d)
           * shadeTerms(u_lamps[i].amb, u_lamps[i].dif, u_lamps[i].spc, N, toL / d, V);
    }

    vec3 toF = u_flash.pos - v_pos;
    float dF = length(toF);
    vec3 LF = toF / dF;
    float cosT = dot(LF, -normalize(u_flash.dir));
    float soft = clamp((cosT - u_flash.outer) / (u_flash.inner - u_flash.outer), 0.0, 1.0);
    c += soft * distanceFalloff(u_flash.kc, u_flash.kl, u_flash.kq, dF)
       * shadeTerms(u_flash.amb, u_flash.dif, u_flash.spc, N, LF, V);

    f_color = vec4(c, 1.0);
}
