#version 330 core
// model: basic_lighting
// vertex: pair_light_in_view.vert
// expect: spaces-light-in-view
// style: half-converted to view space: light position from the vertex stage in eye space, eye and surface still in world space
in vec3 wPos;
in vec3 wNormal;
in vec3 lightEye;
out vec4 FragColor;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

void main()
{
    vec3 N = normalize(wNormal);
    vec3 L = normalize(lightEye - wPos);
    vec3 V = normalize(viewPos - wPos);
    float diff = max(dot(N, L), 0.0);
    float spec = pow(max(dot(V, reflect(-L, N)), 0.0), shininess);
    FragColor = vec4((ambientStrength + diff + specularStrength * spec) * lightColor * objectColor, 1.0);
}
