#version 330 core
// model: gouraud
// vertex: pair_phong_for_gouraud.vert
// expect: phong-for-gouraud
// style: the Gouraud exercise answered with the per-fragment shader from the chapter (lighting moved back to the fragment stage)
in vec3 pos;
in vec3 nrm;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;

void main()
{
    vec3 n = normalize(nrm);
    vec3 l = normalize(lightPos - pos);
    vec3 v = normalize(viewPos - pos);
    vec3 light = lightColor * (0.1 + max(dot(n, l), 0.0) + 0.5 * pow(max(dot(v, reflect(-l, n)), 0.0), 32.0));
    FragColor = vec4(light * objectColor, 1.0);
}
