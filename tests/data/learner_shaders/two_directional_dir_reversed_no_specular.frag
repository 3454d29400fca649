#version 330 core
// model: directional
// uniforms: two_directional_dir_reversed_no_specular.toml
// expect: light-dir-reversed + specular-missing
// style: engine names, the stored direction used as the light vector, a matte "first pass" without specular
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
in vec3 in_pos;
in vec3 in_normal;
in vec2 in_uv;
out vec4 out_color;
uniform sampler2D tex_diffuse;
uniform sampler2D tex_specular;
uniform float shininess;
uniform vec3 eye_position;
uniform DirLight sun;

void main()
{
    vec3 albedo = texture(tex_diffuse, in_uv).rgb;
    vec3 n = normalize(in_normal);
    vec3 l = normalize(sun.direction);
    out_color = vec4(sun.ambient * albedo + sun.diffuse * max(dot(n, l), 0.0) * albedo, 1.0);
}
