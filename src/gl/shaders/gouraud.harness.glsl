// Harness for gouraud: inputs
//   0 = (aPos, ambientStrength)   1 = (aNormal, specularStrength)
//   2 = (lightPos, shininess)     3 = (viewPos, -)
//   4 = (lightColor, -)           5 = (objectColor, -)
//   6..9 = model matrix columns 0..3
// outputs 0 = (FragColor.rgb, 1), 1 = (LightingColor, 0).
void batch_main(in vec4 v[LIGHTLAB_N_INPUTS], out vec4 o[LIGHTLAB_N_OUTPUTS])
{
    mat4 model = mat4(v[6], v[7], v[8], v[9]);
    vec3 LightingColor = gouraud_vertex(v[0].xyz, v[1].xyz, model, v[2].xyz, v[3].xyz,
                                        v[4].rgb, v[0].w, v[1].w, v[2].w);
    o[0] = vec4(gouraud_fragment(LightingColor, v[5].rgb), 1.0);
    o[1] = vec4(LightingColor, 0.0);
}
