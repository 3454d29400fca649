// Harness for materials: inputs
//   0 = (FragPos, -)   1 = (Normal, -)   2 = (viewPos, -)
//   3 = (material.ambient, material.shininess)   4 = (material.diffuse, -)
//   5 = (material.specular, -)
//   6 = (light.position, -)   7 = (light.ambient, -)   8 = (light.diffuse, -)
//   9 = (light.specular, -)
// outputs 0 = (result, 1), 1 = (diff, spec, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    Material material = Material(v[3].rgb, v[4].rgb, v[5].rgb, v[3].w);
    Light light = Light(v[6].xyz, v[7].rgb, v[8].rgb, v[9].rgb);
    float diff;
    float spec;
    vec3 result = materials_lighting(material, light, v[0].xyz, v[1].xyz, v[2].xyz, diff, spec);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, 0.0, 0.0);
}
