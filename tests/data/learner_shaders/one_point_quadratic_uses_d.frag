#version 330 core
// model: point
// uniforms: one_point_quadratic_uses_d.toml
// expect: attenuation-quadratic-uses-d
// style: attenuation coefficients packed in locals kc/kl/kq, Kq multiplied by d once, engine-style names
struct PointLight { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; float constant; float linear; float quadratic; };
in vec3 a_worldPos;
in vec3 a_worldNormal;
in vec2 a_uv;
out vec4 o_frag;
uniform sampler2D s_diffuse;
uniform sampler2D s_specular;
uniform float m_shininess;
uniform vec3 u_viewPos;
uniform PointLight u_point;

void main()
{
    float kc = u_point.constant;
    float kl = u_point.linear;
    float kq = u_point.quadratic;
    float d = distance(u_point.position, a_worldPos);
    float attenuation = 1.0 / (kc + kl * d + kq * d);
    vec3 N = normalize(a_worldNormal);
    vec3 L = normalize(u_point.position - a_worldPos);
    vec3 V = normalize(u_viewPos - a_worldPos);
    vec3 albedo = texture(s_diffuse, a_uv).rgb;
    vec3 lit = u_point.ambient * albedo;
    lit += u_point.diffuse * max(dot(N, L), 0.0) * albedo;
    lit += u_point.specular * pow(max(dot(V, reflect(-L, N)), 0.0), m_shininess) * texture(s_specular, a_uv).rgb;
    o_frag = vec4(attenuation * lit, 1.0);
}
