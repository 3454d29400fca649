#version 330 core
// model: point
// uniforms: one_point_reflect_sign.toml
// expect: reflect-sign
// style: engine names, reflect() fed the direction towards the light, attenuation applied per term
struct Omni { vec3 position; vec3 ambient; vec3 diffuse; vec3 specular; float constant; float linear; float quadratic; };
in vec3 wsPos;
in vec3 wsNormal;
in vec2 uv0;
out vec4 outColor;
uniform sampler2D diffuseTex;
uniform sampler2D specularTex;
uniform float specPower;
uniform vec3 eyeWs;
uniform Omni omni;

void main()
{
    vec3 N = normalize(wsNormal);
    vec3 L = normalize(omni.position - wsPos);
    vec3 V = normalize(eyeWs - wsPos);
    vec3 R = reflect(L, N);
    float dist = length(omni.position - wsPos);
    float att = 1.0 / (omni.constant + omni.linear * dist + omni.quadratic * (dist * dist));
    vec3 albedo = texture(diffuseTex, uv0).rgb;
    vec3 amb = att * omni.ambient * albedo;
    vec3 dif = att * omni.diffuse * max(dot(N, L), 0.0) * albedo;
    vec3 spe = att * omni.specular * pow(max(dot(V, R), 0.0), specPower) * texture(specularTex, uv0).rgb;
    outColor = vec4(amb + dif + spe, 1.0);
}
