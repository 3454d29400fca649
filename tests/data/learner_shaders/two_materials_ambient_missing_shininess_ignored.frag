#version 330 core
// model: materials
// uniforms: two_materials_ambient_missing_shininess_ignored.toml
// expect: ambient-missing + shininess-ignored
// style: mtl-style names (Kd/Ks), a helper per term; no ambient at all and the exponent typed as 32
in vec3 v_pos;
in vec3 v_nrm;
out vec4 f_col;
uniform vec3 u_eye;
uniform vec3 Ka;
uniform vec3 Kd;
uniform vec3 Ks;
uniform float Ns;
uniform vec3 u_lightPos;
uniform vec3 u_lightAmb;
uniform vec3 u_lightDif;
uniform vec3 u_lightSpec;

vec3 diffuseTerm(vec3 n, vec3 l) { return u_lightDif * Kd * max(dot(n, l), 0.0); }
vec3 specularTerm(vec3 n, vec3 l, vec3 v) { return u_lightSpec * Ks * pow(max(dot(v, reflect(-l, n)), 0.0), 32.0); }

void main()
{
    vec3 n = normalize(v_nrm);
    vec3 l = normalize(u_lightPos - v_pos);
    vec3 v = normalize(u_eye - v_pos);
    f_col = vec4(diffuseTerm(n, l) + specularTerm(n, l, v), 1.0);
}
