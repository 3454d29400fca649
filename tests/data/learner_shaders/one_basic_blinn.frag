#version 330 core
// model: basic_lighting
// uniforms: one_basic_blinn.toml
// expect: blinn-for-phong
// style: renamed uniforms (uLight*, uCam), halfway vector from a later chapter, one float accumulator
in vec3 vFrag;
in vec3 vN;
out vec4 fragOut;
uniform vec3 uLightPos;
uniform vec3 uCam;
uniform vec3 uLightColor;
uniform vec3 uObjColor;
uniform float uShininess;

void main()
{
    vec3 N = normalize(vN);
    vec3 L = normalize(uLightPos - vFrag);
    vec3 V = normalize(uCam - vFrag);
    vec3 H = normalize(L + V);
    float k = 0.1;
    k += max(dot(N, L), 0.0);
    k += 0.5 * pow(max(dot(N, H), 0.0), uShininess);
    fragOut = vec4(k * uLightColor * uObjColor, 1.0);
}
