// opengl-tutorial.org, tutorial 8 "Basic shading": fragment stage.
// The light is a point light with inverse-square falloff scaled by LightPower:
//   color = MaterialAmbientColor
//         + MaterialDiffuseColor  * LightColor * LightPower * cosTheta        / distance^2
//         + MaterialSpecularColor * LightColor * LightPower * cosAlpha^power  / distance^2
// with cosTheta = clamp(dot(n, l), 0, 1), cosAlpha = clamp(dot(E, R), 0, 1), R = reflect(-l, n),
// n, l and E normalized camera-space vectors, and distance measured in world space.
// The tutorial's ambient is vec3(0.1) * MaterialDiffuseColor and its exponent is 5; both
// are parameters here. The printed listing ends the diffuse line with ';', which turns the
// specular line into a discarded expression; this function sums all three terms, as the
// surrounding text intends.
vec3 ot8_shade(vec3 Position_worldspace, vec3 LightPosition_worldspace,
               vec3 Normal_cameraspace, vec3 EyeDirection_cameraspace,
               vec3 LightDirection_cameraspace, vec3 MaterialDiffuseColor,
               vec3 MaterialSpecularColor, vec3 ambientFactor, vec3 LightColor,
               float LightPower, float specularExponent,
               out float cosTheta, out float cosAlpha, out float distance)
{
    vec3 MaterialAmbientColor = ambientFactor * MaterialDiffuseColor;
    distance = length(LightPosition_worldspace - Position_worldspace);

    vec3 n = normalize(Normal_cameraspace);
    vec3 l = normalize(LightDirection_cameraspace);
    cosTheta = clamp(dot(n, l), 0.0, 1.0);

    vec3 E = normalize(EyeDirection_cameraspace);
    vec3 R = reflect(-l, n);
    cosAlpha = clamp(dot(E, R), 0.0, 1.0);

    return MaterialAmbientColor
         + MaterialDiffuseColor * LightColor * LightPower * cosTheta / (distance * distance)
         + MaterialSpecularColor * LightColor * LightPower * pow(cosAlpha, specularExponent)
               / (distance * distance);
}

// Vertex stage of the tutorial: the camera-space vectors the fragment stage receives.
// M and V are the model and view matrices; the normal goes through V * M, which the tutorial
// notes is only right without scaling in M.
void ot8_vertex(vec3 vertexPosition_modelspace, vec3 vertexNormal_modelspace, mat4 M, mat4 V,
                vec3 LightPosition_worldspace, out vec3 Position_worldspace,
                out vec3 EyeDirection_cameraspace, out vec3 LightDirection_cameraspace,
                out vec3 Normal_cameraspace)
{
    Position_worldspace = (M * vec4(vertexPosition_modelspace, 1.0)).xyz;
    vec3 vertexPosition_cameraspace = (V * M * vec4(vertexPosition_modelspace, 1.0)).xyz;
    EyeDirection_cameraspace = vec3(0.0) - vertexPosition_cameraspace;
    vec3 LightPosition_cameraspace = (V * vec4(LightPosition_worldspace, 1.0)).xyz;
    LightDirection_cameraspace = LightPosition_cameraspace + EyeDirection_cameraspace;
    Normal_cameraspace = (V * M * vec4(vertexNormal_modelspace, 0.0)).xyz;
}
