#version 330 core
// model: point
// uniforms: ok_point_engine_att.toml
// expect: agrees
// style: engine names, attenuation coefficients in one helper, inverse square root for normalisation
struct PointLamp {
    vec3 position;
    vec3 ambient;
    vec3 diffuse;
    vec3 specular;
    float constant;
    float linear;
    float quadratic;
};

in vec3 vs_Position;
in vec3 vs_Normal;
in vec2 vs_UV;
out vec4 out_Color;

uniform sampler2D t_Albedo;
uniform sampler2D t_Specular;
uniform float m_Gloss;
uniform vec3 cam_Position;
uniform PointLamp lamp;

float falloff(PointLamp p, float d)
{
    return 1.0 / (p.constant + p.linear * d + p.quadratic * d * d);
}

void main()
{
    vec3 toLamp = lamp.position - vs_Position;
    float dist2 = dot(toLamp, toLamp);
    float dist = sqrt(dist2);
    vec3 L = toLamp * inversesqrt(dist2);
    vec3 N = normalize(vs_Normal);
    vec3 V = normalize(cam_Position - vs_Position);
    vec3 base = texture(t_Albedo, vs_UV).rgb;
    vec3 spot = texture(t_Specular, vs_UV).rgb;
    float NdotL = max(dot(N, L), 0.0);
    float RdotV = max(dot(reflect(-L, N), V), 0.0);
    vec3 lit = lamp.ambient * base + lamp.diffuse * NdotL * base
             + lamp.specular * pow(RdotV, m_Gloss) * spot;
    out_Color = vec4(lit * falloff(lamp, dist), 1.0);
}
