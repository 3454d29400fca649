#version 330 core
// model: basic_lighting
// expect: light-dir-reversed
// style: short names, the chapter's constants inlined, light vector taken as "from the lamp to the point"
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 n = normalize(Normal);
    vec3 l = normalize(FragPos - lightPos);   // direction of the light ray
    vec3 v = normalize(viewPos - FragPos);
    float d = max(dot(n, l), 0.0);
    float s = pow(max(dot(v, reflect(-l, n)), 0.0), 32.0);
    FragColor = vec4((0.1 + d + 0.5 * s) * lightColor * objectColor, 1.0);
}
