#version 330 core
// model: multiple_lights
// uniforms: two_multi_spot_blinn_point_ambient_kept.toml
// expect: blinn-for-phong@spot + ambient-not-attenuated@point
// style: engine names, everything in main; torch uses the halfway vector, bulbs attenuate only diffuse and specular
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight { vec3 position; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
struct SpotLight { vec3 position; vec3 direction; float cutOff; float outerCutOff; float constant; float linear; float quadratic; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 v_P;
in vec3 v_N;
in vec2 v_T;
out vec4 o_C;
uniform vec3 u_E;
uniform Material u_mat;
uniform DirLight u_dir;
uniform PointLight u_pt[4];
uniform SpotLight u_spot;

void main()
{
    vec3 Td = texture(u_mat.diffuse, v_T).rgb;
    vec3 Ts = texture(u_mat.specular, v_T).rgb;
    vec3 N = normalize(v_N);
    vec3 V = normalize(u_E - v_P);
    float p = u_mat.shininess;

    vec3 L = normalize(-u_dir.direction);
    vec3 C = u_dir.ambient * Td + u_dir.diffuse * max(dot(N, L), 0.0) * Td
           + u_dir.specular * pow(max(dot(V, reflect(-L, N)), 0.0), p) * Ts;

    for (int i = 0; i < 4; ++i) {
        vec3 D = u_pt[i].position - v_P;
        float r = length(D);
        L = D / r;
        float a = 1.0 / (u_pt[i].constant + u_pt[i].linear * r + u_pt[i].quadratic * r * r);
        C += u_pt[i].ambient * Td
           + a * (u_pt[i].diffuse * max(dot(N, L), 0.0) * Td + u_pt[i].specular * pow(max(dot(V, reflect(-L, N)), 0.0), p) * Ts);
    }

    vec3 D = u_spot.position - v_P;
    float r = length(D);
    L = D / r;
    vec3 H = normalize(L + V);
    float a = 1.0 / (u_spot.constant + u_spot.linear * r + u_spot.quadratic * r * r);
    float k = clamp((dot(L, normalize(-u_spot.direction)) - u_spot.outerCutOff) / (u_spot.cutOff - u_spot.outerCutOff), 0.0, 1.0);
    C += a * k * (u_spot.ambient * Td + u_spot.diffuse * max(dot(N, L), 0.0) * Td + u_spot.specular * pow(max(dot(N, H), 0.0), p) * Ts);
    o_C = vec4(C, 1.0);
}
