#version 330 core
// model: basic_lighting
// uniforms: one_basic_specular_missing.toml
// expect: specular-missing
// style: a "diffuse-only first" learner: specular computed into a variable but never added; renamed inputs
in vec3 worldPos;
in vec3 worldNormal;
out vec4 fragColor;
uniform vec3 light_position;
uniform vec3 camera_position;
uniform vec3 light_color;
uniform vec3 object_color;

void main()
{
    vec3 n = normalize(worldNormal);
    vec3 l = normalize(light_position - worldPos);
    vec3 v = normalize(camera_position - worldPos);
    vec3 ambient = 0.1 * light_color;
    vec3 diffuse = max(dot(n, l), 0.0) * light_color;
    vec3 specular = 0.5 * pow(max(dot(v, reflect(-l, n)), 0.0), 32.0) * light_color;
    fragColor = vec4((ambient + diffuse) * object_color, 1.0);
}
