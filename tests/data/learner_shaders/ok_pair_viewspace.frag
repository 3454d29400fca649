#version 330 core
// model: basic_lighting
// vertex: ok_pair_viewspace.vert
// expect: agrees
// style: view-space lighting (eye at the origin), plain in/out variables, strengths as uniforms, no viewPos
in vec3 eyePos;
in vec3 eyeNormal;
in vec3 eyeLight;
out vec4 FragColor;

uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

void main()
{
    vec3 N = normalize(eyeNormal);
    vec3 L = normalize(eyeLight - eyePos);
    vec3 V = normalize(-eyePos);
    float diffuse = max(dot(N, L), 0.0);
    float specular = specularStrength * pow(max(dot(V, reflect(-L, N)), 0.0), shininess);
    FragColor = vec4((ambientStrength + diffuse + specular) * lightColor * objectColor, 1.0);
}
