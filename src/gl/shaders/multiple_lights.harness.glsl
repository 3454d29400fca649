// Harness for multiple_lights: inputs
//   0 = (FragPos, material.shininess)   1 = (Normal, -)   2 = (viewPos, -)
//   3 = (diffuse map texel rgb, -)      4 = (specular map texel rgb, -)
// The lights are uniforms (dirLight, pointLights[4], spotLight), shared by all cases.
// outputs 0 = (all lights, 1), 1 = (without the spotlight, 1).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    vec3 withoutSpot;
    vec3 result = multiple_lights(v[0].xyz, v[1].xyz, v[2].xyz, v[3].rgb, v[4].rgb, v[0].w,
                                  withoutSpot);
    o[0] = vec4(result, 1.0);
    o[1] = vec4(withoutSpot, 1.0);
}
