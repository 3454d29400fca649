// Harness for spot: inputs
//   0 = (FragPos, material.shininess)   1 = (Normal, -)   2 = (viewPos, -)
//   3 = (diffuse map texel rgb, -)      4 = (specular map texel rgb, -)
//   5 = (light.position, light.cutOff)  6 = (light.direction, light.outerCutOff)
//   7 = (light.ambient, -)   8 = (light.diffuse, -)   9 = (light.specular, -)
//   10 = (light.constant, light.linear, light.quadratic, -)
// outputs 0 = (soft-edged result, 1), 1 = (hard-cutoff result, theta).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    SpotLight light = SpotLight(v[5].xyz, v[6].xyz, v[5].w, v[6].w, v[7].rgb, v[8].rgb,
                                v[9].rgb, v[10].x, v[10].y, v[10].z);
    float theta;
    float intensity;
    float attenuation;
    vec3 soft = spot_light(light, v[3].rgb, v[4].rgb, v[0].w, v[0].xyz, v[1].xyz, v[2].xyz,
                           theta, intensity, attenuation);
    vec3 hard = spot_light_hard(light, v[3].rgb, v[4].rgb, v[0].w, v[0].xyz, v[1].xyz, v[2].xyz);
    o[0] = vec4(soft, 1.0);
    o[1] = vec4(hard, theta);
}
