#version 330 core
// model: materials
// uniforms: ok_materials_ubo_vec4.toml
// expect: agrees
// style: engine std140 uniform block, vec4 members carrying vec3 (w unused), a padding member, named block holding a struct
struct SurfaceParams {
    vec4 ka;
    vec4 kd;
    vec4 ks;
    float gloss;
    float _pad0;
    float _pad1;
    float _pad2;
};

in vec3 v_position;
in vec3 v_normal;
out vec4 o_color;

layout(std140) uniform FrameLight {
    vec4 u_lightPosition;
    vec4 u_lightAmbient;
    vec4 u_lightDiffuse;
    vec4 u_lightSpecular;
    vec4 u_eyePosition;
};

layout(std140) uniform Surface {
    SurfaceParams params;
} surface;

void main()
{
    vec3 N = normalize(v_normal);
    vec3 L = normalize(u_lightPosition.xyz - v_position);
    vec3 V = normalize(u_eyePosition.xyz - v_position);
    float NdotL = max(dot(N, L), 0.0);
    float RdotV = max(dot(reflect(-L, N), V), 0.0);
    vec3 c = u_lightAmbient.rgb * surface.params.ka.rgb
           + u_lightDiffuse.rgb * surface.params.kd.rgb * NdotL
           + u_lightSpecular.rgb * surface.params.ks.rgb * pow(RdotV, surface.params.gloss);
    o_color = vec4(c, 1.0);
}
