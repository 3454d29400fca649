// Harness for lighting_maps: inputs
//   0 = (FragPos, material.shininess)   1 = (Normal, -)   2 = (viewPos, -)
//   3 = (diffuse map texel rgb, -)      4 = (specular map texel rgb, -)
//   5 = (light.position, -)   6 = (light.ambient, -)   7 = (light.diffuse, -)
//   8 = (light.specular, -)
// outputs 0 = (result, 1), 1 = (diff, spec, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    Light light = Light(v[5].xyz, v[6].rgb, v[7].rgb, v[8].rgb);
    float diff;
    float spec;
    vec3 result = lighting_maps(v[3].rgb, v[4].rgb, v[0].w, light, v[0].xyz, v[1].xyz,
                                v[2].xyz, diff, spec);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, 0.0, 0.0);
}
