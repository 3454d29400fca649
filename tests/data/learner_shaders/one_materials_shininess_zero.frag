#version 330 core
// model: materials
// uniforms: one_materials_shininess_zero.toml
// expect: shininess-zero
// style: material as separate uniforms (Ka/Kd/Ks like an .mtl file), the exponent a local left at 0 "until the material has Ns"
in vec3 P;
in vec3 Nrm;
out vec4 color;
uniform vec3 eye;
uniform vec3 Ka;
uniform vec3 Kd;
uniform vec3 Ks;
uniform vec3 lampPos;
uniform vec3 lampAmbient;
uniform vec3 lampDiffuse;
uniform vec3 lampSpecular;

void main()
{
    float Ns = 0.0;   // TODO: read Ns from the material
    vec3 N = normalize(Nrm);
    vec3 L = normalize(lampPos - P);
    vec3 V = normalize(eye - P);
    vec3 R = reflect(-L, N);
    vec3 c = lampAmbient * Ka
           + lampDiffuse * Kd * max(dot(N, L), 0.0)
           + lampSpecular * Ks * pow(max(dot(R, V), 0.0), Ns);
    color = vec4(c, 1.0);
}
