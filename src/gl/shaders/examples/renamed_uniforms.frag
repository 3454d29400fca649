#version 330 core
// A correct basic-lighting shader whose names differ from the tutorial's, and whose
// shininess is 64 instead of 32: check it with the mapping renamed_uniforms.toml:
//   lightlab check-shader renamed_uniforms.frag --model basic_lighting --uniforms renamed_uniforms.toml
in vec3 vWorldPos;
in vec3 vNormal;

out vec4 outColor;

uniform vec3 uLightPos;
uniform vec3 uEye;
uniform vec3 uLightColor;
uniform vec3 uAlbedo;

void main()
{
    vec3 n = normalize(vNormal);
    vec3 l = normalize(uLightPos - vWorldPos);
    vec3 v = normalize(uEye - vWorldPos);
    float diff = max(dot(n, l), 0.0);
    float spec = pow(max(dot(v, reflect(-l, n)), 0.0), 64.0);
    outColor = vec4((0.1 + diff + 0.5 * spec) * uLightColor * uAlbedo, 1.0);
}
