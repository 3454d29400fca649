#version 330 core
// model: basic_lighting
// vertex: pair_position_not_transformed.vert
// uniforms: pair_position_not_transformed.toml
// expect: position-not-transformed
// style: engine uniform names mapped for both stages, vec4 arithmetic in the fragment stage, object-space position sent on
in vec3 vPos;
in vec3 vNormal;
out vec4 outColor;
uniform vec3 u_lightPos;
uniform vec3 u_eye;
uniform vec3 u_lightColor;
uniform vec3 u_baseColor;

void main()
{
    vec4 P = vec4(vPos, 1.0);
    vec4 N = vec4(normalize(vNormal), 0.0);
    vec4 L = normalize(vec4(u_lightPos, 1.0) - P);
    vec4 V = normalize(vec4(u_eye, 1.0) - P);
    float k = 0.1 + max(dot(N, L), 0.0) + 0.5 * pow(max(dot(V, reflect(-L, N)), 0.0), 32.0);
    outColor = vec4(k * u_lightColor * u_baseColor, 1.0);
}
