#version 330 core
// model: basic_lighting
// vertex: pair_normal_matrix_missing.vert
// expect: normal-matrix-missing
// style: interface block between the stages, helper for the Phong factor, the normal moved by mat3(model) in the vertex shader
in VertexData {
    vec3 worldPos;
    vec3 worldNormal;
} vin;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

float phongFactor(vec3 n, vec3 l, vec3 v)
{
    return 0.1 + max(dot(n, l), 0.0) + 0.5 * pow(max(dot(v, reflect(-l, n)), 0.0), 32.0);
}

void main()
{
    vec3 n = normalize(vin.worldNormal);
    vec3 l = normalize(lightPos - vin.worldPos);
    vec3 v = normalize(viewPos - vin.worldPos);
    FragColor = vec4(phongFactor(n, l, v) * lightColor * objectColor, 1.0);
}
