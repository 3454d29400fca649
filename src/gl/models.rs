//! The tutorials' shaders, written as GLSL function files, and their batch harnesses.
//!
//! Each [`ShaderModel`] pairs a function file (`src/gl/shaders/<name>.glsl`, reusable in a
//! real fragment shader) with a harness (`<name>.harness.glsl`) that unpacks the batch's
//! `vec4` inputs into the function's uniforms and varyings. The GLSL is written for lightlab
//! from the chapters' text (names and constants as in the tutorials), not copied.
//!
//! The packed layouts are listed in [`ShaderModel::inputs`] and [`ShaderModel::outputs`];
//! `-` marks an unused component.

use super::batch::{Batch, Uniform};
use super::context::{GlContext, GlError};

/// One tutorial shader: its GLSL function file, its harness and the packed layout.
#[derive(Debug, Clone, Copy)]
pub struct ShaderModel {
    /// Short name, also the file stem under `src/gl/shaders/`.
    pub name: &'static str,
    /// The chapter the function follows.
    pub source: &'static str,
    /// The function file.
    pub functions: &'static str,
    /// The harness defining `batch_main`.
    pub harness: &'static str,
    /// Meaning of each `vec4` input, in order.
    pub inputs: &'static [&'static str],
    /// Meaning of each `vec4` output, in order.
    pub outputs: &'static [&'static str],
    /// Uniforms shared by all cases, set by [`ShaderModel::batch`] (the chapter's values).
    pub uniforms: &'static [(&'static str, Uniform)],
}

impl ShaderModel {
    /// The batch body: function file then harness. Compile errors number its lines.
    pub fn body(&self) -> String {
        format!("{}\n{}", self.functions, self.harness)
    }

    /// Compiles the model into a [`Batch`] and sets its default uniforms.
    pub fn batch<'a>(&self, ctx: &'a GlContext) -> Result<Batch<'a>, GlError> {
        let batch = Batch::new(ctx, &self.body(), self.inputs.len(), self.outputs.len())?;
        for (name, value) in self.uniforms {
            batch.set_uniform(name, *value)?;
        }
        Ok(batch)
    }

    /// Looks a model up by name; `None` if there is none.
    pub fn by_name(name: &str) -> Option<&'static ShaderModel> {
        MODELS.iter().find(|m| m.name == name)
    }
}

/// LearnOpenGL, Basic lighting: Phong per fragment.
pub const BASIC_LIGHTING: ShaderModel = ShaderModel {
    name: "basic_lighting",
    source: "LearnOpenGL, Lighting > Basic lighting",
    functions: include_str!("shaders/basic_lighting.glsl"),
    harness: include_str!("shaders/basic_lighting.harness.glsl"),
    inputs: &[
        "FragPos.xyz, ambientStrength",
        "Normal.xyz, specularStrength",
        "lightPos.xyz, shininess",
        "viewPos.xyz, -",
        "lightColor.rgb, -",
        "objectColor.rgb, -",
    ],
    outputs: &["result.rgb, 1", "diff, spec, 0, 0"],
    uniforms: &[],
};

/// Every model, in chapter order.
pub const MODELS: &[ShaderModel] = &[BASIC_LIGHTING];
