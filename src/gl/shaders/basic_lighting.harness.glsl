// Harness for basic_lighting: inputs
//   0 = (FragPos, ambientStrength)   1 = (Normal, specularStrength)
//   2 = (lightPos, shininess)        3 = (viewPos, -)
//   4 = (lightColor, -)              5 = (objectColor, -)
// outputs 0 = (result, 1), 1 = (diff, spec, 0, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    float diff;
    float spec;
    vec3 result = basic_lighting(v[0].xyz, v[1].xyz, v[2].xyz, v[3].xyz, v[4].rgb, v[5].rgb,
                                 v[0].w, v[1].w, v[2].w, diff, spec);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(diff, spec, 0.0, 0.0);
}
