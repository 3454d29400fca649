#version 330 core
// Correct Basic lighting in one expression, with the chapter's constants hard-coded
// (ambient 0.1, specular strength 0.5, shininess 32) and the light vector kept unnormalized
// until it is needed.
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 toLight = lightPos - FragPos;
    vec3 n = normalize(Normal);
    vec3 l = toLight / length(toLight);
    float spec = pow(max(dot(normalize(viewPos - FragPos), reflect(-l, n)), 0.0), 32.0);
    FragColor = vec4((0.1 + max(dot(n, l), 0.0) + 0.5 * spec) * lightColor * objectColor, 1.0);
}
