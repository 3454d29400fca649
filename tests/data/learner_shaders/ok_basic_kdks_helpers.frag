#version 330 core
// model: basic_lighting
// uniforms: ok_basic_kdks_helpers.toml
// expect: agrees
// style: engine names (u_*, v_*), small helper functions, strengths as uniforms ka/ks
in vec3 v_worldPos;
in vec3 v_worldNormal;

layout(location = 0) out vec4 o_color;

uniform vec3 u_lightPos;
uniform vec3 u_cameraPos;
uniform vec3 u_lightRgb;
uniform vec3 u_albedo;
uniform float u_ka;
uniform float u_ks;
uniform float u_gloss;

float lambert(vec3 n, vec3 l)
{
    return max(dot(n, l), 0.0);
}

float phongLobe(vec3 n, vec3 l, vec3 v, float power)
{
    vec3 r = reflect(-l, n);
    return pow(max(dot(r, v), 0.0), power);
}

void main()
{
    vec3 N = normalize(v_worldNormal);
    vec3 L = normalize(u_lightPos - v_worldPos);
    vec3 V = normalize(u_cameraPos - v_worldPos);
    float kd = lambert(N, L);
    float ks = u_ks * phongLobe(N, L, V, u_gloss);
    vec3 radiance = u_lightRgb * (u_ka + kd + ks);
    o_color = vec4(radiance * u_albedo, 1.0);
}
