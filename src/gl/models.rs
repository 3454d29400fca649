//! The tutorials' shaders, written as GLSL function files, and their batch harnesses.
//!
//! Each [`ShaderModel`] pairs a function file (`src/gl/shaders/<name>.glsl`, reusable in a
//! real fragment shader; [`ShaderModel::functions`]) with a harness (`<name>.harness.glsl`) that passes the batch's
//! `vec4` inputs to the function through `IN_<quantity>` macros generated from the
//! model's layout ([`Layout::glsl_defines`]), so no harness spells an input position. The GLSL is written for lightlab
//! from the chapters' text (names and constants as in the tutorials), not copied.
//!
//! A model whose shader is another's with a term added has no file of its own: its text is
//! the other's file edited as the checker's mistakes edit one ([`crate::gl::edit`]), so the
//! shared lines are written once. `lighting_maps_emission` is `lighting_maps.glsl` with the
//! emission texel ([`LIGHTING_MAPS_EMISSION`]).
//!
//! The packed layouts are described once, in [`crate::gl::layout`]; [`ShaderModel::inputs`]
//! and [`ShaderModel::outputs`] read them (`-` marks an unused component).

use super::batch::{Batch, Uniform};
use super::context::{GlContext, GlError};
use super::edit::{apply_steps, Edit};
use super::layout::Layout;
use super::model_id::ModelId;

/// One tutorial shader: its GLSL function file, its harness and its packed layout.
#[derive(Debug, Clone, Copy)]
pub struct ShaderModel {
    /// The model; its name is the file stem under `src/gl/shaders/`.
    pub id: ModelId,
    /// The function file, or how it is made from another model's ([`ShaderModel::functions`]).
    text: FunctionText,
    /// The harness file defining `batch_main`; it reads its inputs through the layout's
    /// `IN_` macros ([`ShaderModel::harness`] puts them in front).
    harness_file: &'static str,
    /// The packed inputs and outputs.
    pub layout: &'static Layout,
}

/// Where a model's function text comes from.
#[derive(Debug, Clone, Copy)]
enum FunctionText {
    /// Its own file, `src/gl/shaders/<name>.glsl`.
    File(&'static str),
    /// `base`'s function text with its opening comment lines replaced by `header` and
    /// `steps` applied ([`apply_steps`]).
    Edited { base: &'static ShaderModel, header: &'static str, steps: &'static [&'static [Edit]] },
}

impl ShaderModel {
    const fn new(id: ModelId, functions: &'static str, harness: &'static str) -> ShaderModel {
        ShaderModel { id, text: FunctionText::File(functions), harness_file: harness, layout: id.layout() }
    }

    /// The GLSL function text: the model's function file, or for a model made from another
    /// (see the module docs) that model's text, edited, made once per process.
    ///
    /// # Panics
    /// When the base text no longer holds a line the edits replace (an edit of
    /// `src/gl/shaders/` that forgot the model made from it); `functions_of_every_model_are_made`
    /// below fails on it first.
    pub fn functions(&self) -> &'static str {
        match self.text {
            FunctionText::File(text) => text,
            FunctionText::Edited { base, header, steps } => {
                static MADE: [std::sync::OnceLock<String>; super::model_id::N_MODELS] =
                    [const { std::sync::OnceLock::new() }; super::model_id::N_MODELS];
                let slot = ModelId::ALL.iter().position(|&m| m == self.id).expect("every model is in ModelId::ALL");
                MADE[slot].get_or_init(|| {
                    let body = without_opening_comment(base.functions());
                    let edited = apply_steps(steps, body).unwrap_or_else(|pattern| {
                        panic!("{} is made from {}.glsl, which no longer holds `{pattern}`", self.id, base.id)
                    });
                    format!("{header}{edited}")
                })
            }
        }
    }

    /// The chapter the function follows.
    pub fn source(&self) -> &'static str {
        self.layout.source
    }

    /// Meaning of each `vec4` input, in order ([`Layout::input_labels`]).
    pub fn inputs(&self) -> Vec<String> {
        self.layout.input_labels()
    }

    /// Meaning of each `vec4` output, in order.
    pub fn outputs(&self) -> &'static [&'static str] {
        self.layout.outputs
    }

    /// Uniforms shared by all cases, set by [`ShaderModel::batch`]: the chapter's scene for
    /// `multiple_lights` ([`Layout::chapter_uniforms`]), none for the others.
    pub fn uniforms(&self) -> Vec<(String, Uniform)> {
        self.layout.chapter_uniforms()
    }

    /// The harness defining `batch_main`: the layout's input macros
    /// ([`Layout::glsl_defines`]) then the harness file.
    pub fn harness(&self) -> String {
        format!("{}{}", self.layout.glsl_defines(), self.harness_file)
    }

    /// The batch body: function file then harness. Compile errors number its lines.
    pub fn body(&self) -> String {
        format!("{}\n{}", self.functions(), self.harness())
    }

    /// Compiles the model into a [`Batch`] and sets its default uniforms.
    pub fn batch<'a>(&self, ctx: &'a GlContext) -> Result<Batch<'a>, GlError> {
        let batch = Batch::new(ctx, &self.body(), self.layout.n_inputs(), self.layout.n_outputs())?;
        for (name, value) in self.uniforms() {
            batch.set_uniform(&name, value)?;
        }
        Ok(batch)
    }
}

macro_rules! shader_model {
    ($(#[$doc:meta])* $name:ident, $id:ident, $file:literal) => {
        $(#[$doc])*
        pub const $name: ShaderModel = ShaderModel::new(
            ModelId::$id,
            include_str!(concat!("shaders/", $file, ".glsl")),
            include_str!(concat!("shaders/", $file, ".harness.glsl")),
        );
    };
}

shader_model!(
    /// LearnOpenGL, Basic lighting: Phong per fragment.
    BASIC_LIGHTING, BasicLighting, "basic_lighting");
shader_model!(
    /// LearnOpenGL, Basic lighting, Gouraud exercise: the lighting per vertex.
    GOURAUD, Gouraud, "gouraud");
shader_model!(
    /// LearnOpenGL, Materials: material and light colors per component.
    MATERIALS, Materials, "materials");
shader_model!(
    /// LearnOpenGL, Lighting maps: diffuse and specular colors sampled from textures.
    LIGHTING_MAPS, LightingMaps, "lighting_maps");
shader_model!(
    /// LearnOpenGL, Light casters: directional light.
    DIRECTIONAL, Directional, "directional");
shader_model!(
    /// LearnOpenGL, Light casters: point light with attenuation.
    POINT, Point, "point");
shader_model!(
    /// LearnOpenGL, Light casters: spotlight, soft edges (and the first, hard-edged version).
    SPOT, Spot, "spot");
shader_model!(
    /// LearnOpenGL, Multiple lights: directional + 4 point lights + flashlight, lights as
    /// uniforms (the chapter's scene by default: [`crate::scene::Scene::learnopengl_default`]).
    MULTIPLE_LIGHTS, MultipleLights, "multiple_lights");
shader_model!(
    /// opengl-tutorial.org tutorial 8: inverse-square point light, camera-space vectors.
    OPENGL_TUTORIAL8, OpenGLTutorial8, "opengl_tutorial8");
shader_model!(
    /// ogldev tutorial 19: directional light with specular intensity and power.
    OGLDEV19, Ogldev19, "ogldev19");
shader_model!(
    /// LearnOpenGL, Advanced Lighting: Blinn-Phong on the basic-lighting inputs (checked by
    /// `check-shader`; not in the oracle's table).
    BLINN_PHONG, BlinnPhong, "blinn_phong");
shader_model!(
    /// lightlab's normal-matrix exercise: Basic lighting with the normal in object space and
    /// the model matrix, moved by the normal matrix in the fragment shader (checked by
    /// `check-shader`; not in the oracle's table). Its function file is what the catalogue's
    /// normal-matrix mistakes rewrite.
    NORMAL_MATRIX, NormalMatrix, "normal_matrix");
/// LearnOpenGL, Lighting maps, exercise 4: Lighting maps plus an emission map added
/// without lighting (checked by `check-shader`; not in the oracle's table). Its text is
/// `lighting_maps.glsl` with the emission texel as an argument and added to the result.
pub const LIGHTING_MAPS_EMISSION: ShaderModel = ShaderModel {
    id: ModelId::LightingMapsEmission,
    text: FunctionText::Edited { base: &LIGHTING_MAPS, header: EMISSION_HEADER, steps: EMISSION_STEPS },
    harness_file: include_str!("shaders/lighting_maps_emission.harness.glsl"),
    layout: ModelId::LightingMapsEmission.layout(),
};

/// The opening comment of `lighting_maps_emission`'s text.
const EMISSION_HEADER: &str = "\
// LearnOpenGL, Lighting > Lighting maps, exercise 4: an emission map. The shader is
// lighting_maps' with a third texel, vec3(texture(material.emission, TexCoords)), added
// to the result as it is: the emission is light the surface gives off itself, so no
// light's colour, no diffuse factor and no attenuation touches it. As in lighting_maps,
// the caller samples the maps and passes the texels.
";

/// `lighting_maps` to `lighting_maps_emission`: the function's name and the emission texel
/// argument, then the emission added unlit.
const EMISSION_STEPS: &[&[Edit]] = &[
    &[(
        "vec3 lighting_maps(vec3 diffuseTexel, vec3 specularTexel, float shininess, Light light,
                   vec3 FragPos, vec3 Normal, vec3 viewPos, out float diff, out float spec)",
        "vec3 lighting_maps_emission(vec3 diffuseTexel, vec3 specularTexel, vec3 emissionTexel, float shininess,
                            Light light, vec3 FragPos, vec3 Normal, vec3 viewPos, out float diff, out float spec)",
    )],
    &[(
        "    return ambient + diffuse + specular;",
        "    vec3 emission = emissionTexel;

    return ambient + diffuse + specular + emission;",
    )],
];

/// `text` after its opening `//` comment lines.
fn without_opening_comment(text: &str) -> &str {
    let mut rest = text;
    while rest.starts_with("//") {
        rest = rest.split_once('\n').map_or("", |(_, after)| after);
    }
    rest
}

impl ModelId {
    /// The model's tutorial shader (function file and harness).
    #[must_use]
    pub const fn shader(self) -> Option<&'static ShaderModel> {
        match self {
            ModelId::BasicLighting => Some(&BASIC_LIGHTING),
            ModelId::Gouraud => Some(&GOURAUD),
            ModelId::Materials => Some(&MATERIALS),
            ModelId::LightingMaps => Some(&LIGHTING_MAPS),
            ModelId::Directional => Some(&DIRECTIONAL),
            ModelId::Point => Some(&POINT),
            ModelId::Spot => Some(&SPOT),
            ModelId::MultipleLights => Some(&MULTIPLE_LIGHTS),
            ModelId::OpenGLTutorial8 => Some(&OPENGL_TUTORIAL8),
            ModelId::Ogldev19 => Some(&OGLDEV19),
            ModelId::NormalMatrix => Some(&NORMAL_MATRIX),
            ModelId::BlinnPhong => Some(&BLINN_PHONG),
            ModelId::LightingMapsEmission => Some(&LIGHTING_MAPS_EMISSION),
        }
    }
}

/// Every model, in chapter order, then `blinn_phong` and `lighting_maps_emission`.
pub const MODELS: &[ShaderModel] = &[
    BASIC_LIGHTING,
    GOURAUD,
    MATERIALS,
    LIGHTING_MAPS,
    DIRECTIONAL,
    POINT,
    SPOT,
    MULTIPLE_LIGHTS,
    OPENGL_TUTORIAL8,
    OGLDEV19,
    BLINN_PHONG,
    LIGHTING_MAPS_EMISSION,
];

/// Complete fragment shaders as a user would write them, for `lightlab check-shader`:
/// `(file name, source)`. `basic_lighting.frag`, `normal_matrix.frag` and
/// `renamed_uniforms.frag` (with `renamed_uniforms.toml`) and `blinn_phong.frag` (model
/// `blinn_phong`) are correct; the `bug_*` files and
/// `ot8_printed_semicolon.frag` each carry one documented mistake (see their header).
pub const EXAMPLE_SHADERS: &[(&str, &str)] = &[
    ("basic_lighting.frag", include_str!("shaders/examples/basic_lighting.frag")),
    ("bug_reflect_sign.frag", include_str!("shaders/examples/bug_reflect_sign.frag")),
    ("bug_unnormalized_normal.frag", include_str!("shaders/examples/bug_unnormalized_normal.frag")),
    ("bug_spot_degrees.frag", include_str!("shaders/examples/bug_spot_degrees.frag")),
    ("ot8_printed_semicolon.frag", include_str!("shaders/examples/ot8_printed_semicolon.frag")),
    ("normal_matrix.frag", include_str!("shaders/examples/normal_matrix.frag")),
    ("bug_model_matrix_normal.frag", include_str!("shaders/examples/bug_model_matrix_normal.frag")),
    ("renamed_uniforms.frag", include_str!("shaders/examples/renamed_uniforms.frag")),
    ("blinn_phong.frag", include_str!("shaders/examples/blinn_phong.frag")),
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn functions_of_every_model_are_made() {
        for m in MODELS {
            assert!(m.functions().contains("\n{\n"), "{}: no function body", m.id);
        }
    }

    #[test]
    fn the_emission_model_is_lighting_maps_with_the_emission_added() {
        let (base, emission) = (LIGHTING_MAPS.functions(), LIGHTING_MAPS_EMISSION.functions());
        // from the body's opening brace to the return: the same lines, and the emission texel
        let body = |t: &str| t[t.find("\n{\n").unwrap()..t.find("    return").unwrap()].to_owned();
        assert_eq!(body(emission).replace("    vec3 emission = emissionTexel;\n\n", ""), body(base));
        assert!(emission.starts_with(EMISSION_HEADER) && emission.contains("+ specular + emission;\n}"));
        assert!(
            emission.contains("vec3 lighting_maps_emission(vec3 diffuseTexel, vec3 specularTexel, vec3 emissionTexel,")
        );
    }
}
