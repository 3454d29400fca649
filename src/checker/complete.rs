//! Complete fragment shaders built from the function files: the declarations a learner's
//! shader has (`in`, `uniform`, `out`, named as in the chapter) and a `main` that calls the
//! model's function.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | function file | `src/gl/shaders/<model>.glsl`, verified by the oracle |
//! | frame | the declarations and `main` around it, one per model, written here |
//! | complete shader | `#version 330 core`, the function file (possibly mutated), the frame |
//!
//! They serve as the exercises' reference solutions and as learner-style shaders carrying
//! one catalogue mistake, so that the checker is tested end to end on the text it will
//! see. The function file comes first because it declares the structs the frame uses.

use super::mistakes::{Mistake, MutateError};
use crate::gl::model_id::ModelId;
use std::borrow::Cow;

/// The Basic lighting uniforms as the chapter names them: the one declaration both this
/// frame and the live figures' programs use (a macro, so that `concat!` can take it).
macro_rules! basic_lighting_uniforms {
    () => {
        "uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
uniform float ambientStrength;
uniform float specularStrength;
uniform float shininess;
"
    };
}
#[cfg(feature = "book")]
pub(crate) use basic_lighting_uniforms;

/// opengl-tutorial 8's fragment inputs and uniforms as its shader names them, around the
/// output line `out` (the tutorial's `out vec3 color;`, the live figure's `out vec4
/// FragColor;`): the one declaration both this frame and the live figure's program use.
macro_rules! opengl_tutorial8_declarations {
    ($out:literal) => {
        concat!(
            "in vec3 Position_worldspace;
in vec3 Normal_cameraspace;
in vec3 EyeDirection_cameraspace;
in vec3 LightDirection_cameraspace;
",
            $out,
            "
uniform vec3 LightPosition_worldspace;
uniform vec3 MaterialDiffuseColor;
uniform vec3 MaterialSpecularColor;
uniform vec3 MaterialAmbientFactor;
uniform vec3 LightColor;
uniform float LightPower;
uniform float specularExponent;
"
        )
    };
}
#[cfg(feature = "book")]
pub(crate) use opengl_tutorial8_declarations;

/// The frame of each model with a function file (see the module docs): written out whole
/// for the models without texture maps, built by [`maps_frame`] for the others; `None`
/// for `gouraud` (per vertex) and `blinn_phong`.
fn frame(model: ModelId) -> Option<Cow<'static, str>> {
    let caster =
        |light: &str, function: &str, outs: &[&str]| Cow::Owned(maps_frame(Some(light), &caster_call(function, outs)));
    Some(match model {
        ModelId::BasicLighting => Cow::Borrowed(BASIC_LIGHTING_FRAME),
        ModelId::Materials => Cow::Borrowed(MATERIALS_FRAME),
        ModelId::OpenGLTutorial8 => Cow::Borrowed(OPENGL_TUTORIAL8_FRAME),
        ModelId::Ogldev19 => Cow::Borrowed(OGLDEV19_FRAME),
        ModelId::LightingMaps => Cow::Owned(maps_frame(
            Some("Light"),
            "    float diff;
    float spec;
    vec3 result = lighting_maps(diffuseTexel, specularTexel, material.shininess, light,
                                FragPos, Normal, viewPos, diff, spec);",
        )),
        ModelId::LightingMapsEmission => Cow::Owned(emission_frame()),
        ModelId::Directional => caster("DirectionalLight", "directional_light", &["diff", "spec"]),
        ModelId::Point => caster("PointLight", "point_light", &["diff", "spec", "attenuation"]),
        ModelId::Spot => caster("SpotLight", "spot_light", &["theta", "intensity", "attenuation"]),
        ModelId::MultipleLights => Cow::Owned(maps_frame(
            None,
            "    vec3 withoutSpot;
    vec3 result = multiple_lights(FragPos, Normal, viewPos, diffuseTexel, specularTexel,
                                  material.shininess, withoutSpot);",
        )),
        ModelId::NormalMatrix => Cow::Borrowed(NORMAL_MATRIX_FRAME),
        ModelId::Gouraud | ModelId::BlinnPhong => return None,
    })
}

/// Basic lighting's frame.
const BASIC_LIGHTING_FRAME: &str = concat!(
    "in vec3 FragPos;\nin vec3 Normal;\nout vec4 FragColor;\n",
    basic_lighting_uniforms!(),
    "
void main()
{
    float diff;
    float spec;
    vec3 result = basic_lighting(FragPos, Normal, lightPos, viewPos, lightColor, objectColor,
                                 ambientStrength, specularStrength, shininess, diff, spec);
    FragColor = vec4(result, 1.0);
}
"
);

/// The normal-matrix exercise's frame: the object-space normal `aNormal` and the `model`
/// matrix beside Basic lighting's inputs.
const NORMAL_MATRIX_FRAME: &str = concat!(
    "in vec3 FragPos;\nin vec3 aNormal;\nout vec4 FragColor;\nuniform mat4 model;\n",
    basic_lighting_uniforms!(),
    "
void main()
{
    vec3 result = normal_matrix_lighting(FragPos, aNormal, model, lightPos, viewPos, lightColor, objectColor,
                                         ambientStrength, specularStrength, shininess);
    FragColor = vec4(result, 1.0);
}
"
);

/// Materials' frame.
const MATERIALS_FRAME: &str = "in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
uniform Light light;

void main()
{
    float diff;
    float spec;
    FragColor = vec4(materials_lighting(material, light, FragPos, Normal, viewPos, diff, spec), 1.0);
}
";

/// opengl-tutorial 8's frame.
const OPENGL_TUTORIAL8_FRAME: &str = concat!(
    opengl_tutorial8_declarations!("out vec3 color;"),
    "
void main()
{
    float cosTheta;
    float cosAlpha;
    float lightDistance;
    color = ot8_shade(Position_worldspace, LightPosition_worldspace, Normal_cameraspace,
                      EyeDirection_cameraspace, LightDirection_cameraspace, MaterialDiffuseColor,
                      MaterialSpecularColor, MaterialAmbientFactor, LightColor, LightPower,
                      specularExponent, cosTheta, cosAlpha, lightDistance);
}
"
);

/// ogldev 19's frame.
const OGLDEV19_FRAME: &str = "in vec2 TexCoord0;
in vec3 Normal0;
in vec3 WorldPos0;
out vec4 FragColor;
uniform DirectionalLight gDirectionalLight;
uniform sampler2D gSampler;
uniform vec3 gEyeWorldPos;
uniform float gMatSpecularIntensity;
uniform float gSpecularPower;

void main()
{
    float DiffuseFactor;
    float SpecularFactor;
    FragColor = ogldev19_shade(gDirectionalLight, WorldPos0, Normal0, gEyeWorldPos,
                               gMatSpecularIntensity, gSpecularPower,
                               texture(gSampler, TexCoord0), DiffuseFactor, SpecularFactor);
}
";

/// The head every texture-mapped frame shares: the `Material` of two maps and a
/// shininess, the vertex outputs, `viewPos` and `material`.
const MAPS_HEAD: &str = "struct Material {
    sampler2D diffuse;
    sampler2D specular;
    float shininess;
};
in vec3 FragPos;
in vec3 Normal;
in vec2 TexCoords;
out vec4 FragColor;
uniform vec3 viewPos;
uniform Material material;
";

/// A texture-mapped frame: [`MAPS_HEAD`], `uniform {light} light;` when the function file
/// takes its light as an argument, then a `main` that reads the two texels and runs `call`,
/// which sets `result`.
fn maps_frame(light: Option<&str>, call: &str) -> String {
    maps_frame_with(MAPS_HEAD, "", light, call)
}

/// [`maps_frame`] with `head` for [`MAPS_HEAD`] and the texel lines `texels` after the two
/// of the diffuse and specular maps.
fn maps_frame_with(head: &str, texels: &str, light: Option<&str>, call: &str) -> String {
    let light = light.map(|s| format!("uniform {s} light;\n")).unwrap_or_default();
    format!(
        "{head}{light}
void main()
{{
    vec3 diffuseTexel = vec3(texture(material.diffuse, TexCoords));
    vec3 specularTexel = vec3(texture(material.specular, TexCoords));
{texels}{call}
    FragColor = vec4(result, 1.0);
}}
"
    )
}

/// Lighting maps' exercise 4: [`MAPS_HEAD`] with a third map, `material.emission`, whose
/// texel the function file adds unlit.
fn emission_frame() -> String {
    let head = MAPS_HEAD.replace("    sampler2D specular;\n", "    sampler2D specular;\n    sampler2D emission;\n");
    maps_frame_with(
        &head,
        "    vec3 emissionTexel = vec3(texture(material.emission, TexCoords));\n",
        Some("Light"),
        "    float diff;
    float spec;
    vec3 result = lighting_maps_emission(diffuseTexel, specularTexel, emissionTexel, material.shininess,
                                         light, FragPos, Normal, viewPos, diff, spec);",
    )
}

/// The call of one caster's function file, `function(light, diffuseTexel, specularTexel,
/// material.shininess, FragPos, Normal, viewPos, outs…)`, after declaring its float
/// outputs `outs`; the second line is aligned under the first argument.
fn caster_call(function: &str, outs: &[&str]) -> String {
    let declared: String = outs.iter().map(|o| format!("    float {o};\n")).collect();
    let head = format!("    vec3 result = {function}(");
    let indent = " ".repeat(head.len());
    format!(
        "{declared}{head}light, diffuseTexel, specularTexel, material.shininess,\n{indent}FragPos, Normal, viewPos, {});",
        outs.join(", ")
    )
}

/// The models that have a complete shader (every model with a function file except the
/// per-vertex `gouraud` and the check-shader-only `blinn_phong`), in [`ModelId::ALL`] order.
pub const MODELS: &[ModelId] = &[
    ModelId::BasicLighting,
    ModelId::Materials,
    ModelId::LightingMaps,
    ModelId::Directional,
    ModelId::Point,
    ModelId::Spot,
    ModelId::MultipleLights,
    ModelId::OpenGLTutorial8,
    ModelId::Ogldev19,
    ModelId::NormalMatrix,
    ModelId::LightingMapsEmission,
];

/// `functions` (a function file of `model`, possibly rewritten) inside `model`'s frame.
/// `None` for a model without a frame (`gouraud`, `blinn_phong`).
#[must_use]
pub fn complete_with(model: ModelId, functions: &str) -> Option<String> {
    let frame = frame(model)?;
    Some(format!("#version 330 core\n{functions}\n{frame}"))
}

/// The complete shader of `model` with its verified function file: a correct solution.
#[must_use]
pub fn reference(model: ModelId) -> Option<String> {
    complete_with(model, model.shader()?.functions())
}

/// The complete shader of `model` with `mistake` applied: a learner's shader with exactly
/// that mistake.
///
/// Errors: [`MutateError::NotApplicable`] when the mistake does not apply to the model or
/// the model has no frame.
pub fn with_mistake(model: ModelId, mistake: &Mistake) -> Result<String, MutateError> {
    let functions = mistake.mutate(model)?;
    complete_with(model, &functions).ok_or(MutateError::NotApplicable { id: mistake.id, model })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_models_with_a_frame_are_listed() {
        let framed: Vec<ModelId> = ModelId::ALL.into_iter().filter(|&m| frame(m).is_some()).collect();
        assert_eq!(framed, MODELS);
    }
}
