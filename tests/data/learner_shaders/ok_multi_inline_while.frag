#version 330 core
// model: multiple_lights
// uniforms: ok_multi_inline_while.toml
// expect: agrees
// style: everything inlined in main, a while loop over the lamps, lights renamed sun/lamps/torch
struct Material { sampler2D diffuse; sampler2D specular; float shininess; };
struct DirLight { vec3 direction; vec3 ambient; vec3 diffuse; vec3 specular; };
struct PointLight {
    vec3 position;
    float constant; float linear; float quadratic;
    vec3 ambient; vec3 diffuse; vec3 specular;
};
struct SpotLight {
    vec3 position; vec3 direction;
    float cutOff; float outerCutOff;
    float constant; float linear; float quadratic;
    vec3 ambient; vec3 diffuse; vec3 specular;
};

in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;

uniform vec3 viewPos;
uniform Material material;
uniform DirLight sun;
uniform PointLight lamps[4];
uniform SpotLight torch;

void main()
{
    vec3 A = texture(material.diffuse, TexCoords).rgb;
    vec3 S = texture(material.specular, TexCoords).rgb;
    vec3 N = normalize(Normal);
    vec3 V = normalize(viewPos - FragPos);
    float e = material.shininess;

    vec3 L = normalize(-sun.direction);
    vec3 total = sun.ambient * A
               + sun.diffuse * max(dot(N, L), 0.0) * A
               + sun.specular * pow(max(dot(V, reflect(-L, N)), 0.0), e) * S;

    int k = 0;
    while (k < 4) {
        vec3 d = lamps[k].position - FragPos;
        float r = length(d);
        L = d / r;
        float att = 1.0 / (lamps[k].constant + lamps[k].linear * r + lamps[k].quadratic * r * r);
        total += att * (lamps[k].ambient * A
                      + lamps[k].diffuse * max(dot(N, L), 0.0) * A
                      + lamps[k].specular * pow(max(dot(V, reflect(-L, N)), 0.0), e) * S);
        k++;
    }

    vec3 dt = torch.position - FragPos;
    float rt = length(dt);
    L = normalize(dt);
    float attT = 1.0 / (torch.constant + torch.linear * rt + torch.quadratic * rt * rt);
    float theta = dot(L, normalize(-torch.direction));
    float cone = clamp((theta - torch.outerCutOff) / (torch.cutOff - torch.outerCutOff), 0.0, 1.0);
    total += attT * cone * (torch.ambient * A
                          + torch.diffuse * max(dot(N, L), 0.0) * A
                          + torch.specular * pow(max(dot(V, reflect(-L, N)), 0.0), e) * S);

    FragColor = vec4(total, 1.0);
}
