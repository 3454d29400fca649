#version 330 core
// Correct Basic lighting, written differently: a hand-written reflect, other local names,
// the terms regrouped (the object color applied to each term).
in vec3 FragPos;
in vec3 Normal;
out vec4 outColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;

vec3 mirror(vec3 incident, vec3 n)
{
    return incident - 2.0 * dot(n, incident) * n;
}

void main()
{
    vec3 N = normalize(Normal);
    vec3 L = normalize(lightPos - FragPos);
    vec3 V = normalize(viewPos - FragPos);
    vec3 R = mirror(-L, N);
    float kd = max(dot(N, L), 0.0);
    float ks = specularStrength * pow(max(dot(R, V), 0.0), shininess);
    outColor = vec4(objectColor * lightColor * ambientStrength
                    + objectColor * lightColor * kd
                    + objectColor * lightColor * ks, 1.0);
}
