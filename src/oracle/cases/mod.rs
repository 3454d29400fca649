//! Random shading cases for the oracle and `check-shader`: proptest strategies with a fixed
//! seed, the packed layout of each model, and the Rust answers (the `f32` core and the `f64`
//! [`crate::reference`]) for every case.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | row | one case: the `vec4` inputs of a model, as its [`Layout`] describes them |
//! | group | cases that share uniforms (one draw each); only `multiple_lights` has several |
//! | channel | one compared output number (a color component) |
//! | `ε` | `2^-24`, the unit roundoff of `f32` |
//!
//! # What a case is
//! Positions are uniform in a box; the light and the eye are placed at a random direction and
//! a distance of at least 0.5 from the fragment (so `normalize` is well conditioned);
//! normals are random directions with lengths in [0.2, 5] (interpolated normals are not unit);
//! colors and intensities are uniform in [0, 1]; shininess is uniform in [1, 256] (ogldev and
//! opengl-tutorial 8: [1, 128]). A small share of cases is deliberately degenerate (zero
//! normal, light or eye at the fragment, shininess 0, equal spot cut-offs) so that GLSL's
//! undefined results show up in the report; [`Class`] sorts them out.
//!
//! The generator is `proptest`'s: `TestRunner::new_with_rng` with a `TestRng` seeded from
//! [`seed_bytes`], `strategy.new_tree(&mut runner)?.current()` per case. The same seed gives
//! the same cases on every machine. The RNG is proptest's XorShift rather than ChaCha: in an
//! unoptimized test build ChaCha made the generation of 10^5 cases take 15 s per model,
//! XorShift about 3 s (cryptographic quality is not needed here).

//!
//! | file | concern |
//! | --- | --- |
//! | [`strategies`] | the distributions of the cases, written through the layouts |
//! | [`bounds`] | the asserted error bound of each model, derived |
//! | `eval` | the `f32` core's and the `f64` reference's answer for a case |
//! | `classify` | which cases GLSL leaves undefined ([`Class`]) |

use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use crate::gl::batch::Uniform;
use crate::gl::context::GlError;
use crate::gl::layout::Layout;
use crate::gl::model_id::{ModelId, N_MODELS};
use crate::gl::models::ShaderModel;
use crate::reference as r64;
use crate::scene::Scene;

pub mod bounds;
mod classify;
mod eval;
mod fields;
pub mod strategies;

pub use crate::gl::layout::{scene_uniforms, QType, Quantity, Slot};
pub use classify::Class;
pub use eval::Channels;
pub use strategies::strategy;

/// The default seed of the oracle (any 64-bit value works; this one spells "lightlab").
pub const DEFAULT_SEED: u64 = 0x6c69_6768_746c_6162;

/// Most channels a model compares (spot: soft and hard edge, 3 each).
pub const MAX_CHANNELS: usize = 6;

/// The 16-byte XorShift seed for `seed` and a stream number (one stream per model and use).
pub fn seed_bytes(seed: u64, stream: u64) -> [u8; 16] {
    let mut bytes = [0u8; 16];
    bytes[..8].copy_from_slice(&seed.to_le_bytes());
    bytes[8..].copy_from_slice(&stream.to_le_bytes());
    bytes
}

/// Draws `n` values of `strategy` from a deterministic runner seeded with `seed`.
///
/// Errors: [`GlError::Input`] naming `strategy` if proptest rejects a value (the strategies
/// here have no filters, so this does not happen).
pub fn generate<S: Strategy>(strategy: &S, n: usize, seed: [u8; 16]) -> Result<Vec<S::Value>, GlError> {
    let rng = TestRng::from_seed(RngAlgorithm::XorShift, &seed);
    let mut runner = TestRunner::new_with_rng(Config::default(), rng);
    (0..n)
        .map(|_| {
            strategy
                .new_tree(&mut runner)
                .map(|tree| tree.current())
                .map_err(|reason| GlError::Input { field: "strategy".into(), reason: reason.to_string() })
        })
        .collect()
}

/// A model with random cases: its layout, names and asserted bound.
#[derive(Debug, Clone, Copy)]
pub struct CaseModel {
    /// Which model.
    pub id: ModelId,
    /// The model's own shader (`None` for `normal_matrix`).
    pub shader: Option<&'static ShaderModel>,
    /// Whether the oracle runs it and lists it in its report (`false` for the
    /// check-shader-only `normal_matrix`, `blinn_phong` and `lighting_maps_emission`).
    pub in_oracle: bool,
    /// The packed layout (the single description of the inputs).
    pub layout: &'static Layout,
    /// Number of `vec4` inputs per case (the layout's [`Layout::n_inputs`]).
    pub n_inputs: usize,
    /// Channels compared by the oracle (spot: 6, the others: 3).
    pub channels: usize,
    /// Named inputs (the layout's quantities), for `check-shader`.
    pub quantities: &'static [Quantity],
    /// The asserted bound on `|result - f64 reference|` per channel, derived in [`bounds`].
    pub bound: f64,
}

impl CaseModel {
    /// The model's name (`basic_lighting`, ..., `blinn_phong`): [`ModelId::name`].
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.id.name()
    }
}

impl ModelId {
    /// The model's random cases: layout, shader, channels and asserted bound.
    #[must_use]
    pub const fn case_model(self) -> &'static CaseModel {
        &CASE_MODELS[self as usize]
    }
}

/// Whether the oracle runs `id` and lists it in its report: every model with a tutorial
/// shader but the check-shader-only `blinn_phong` and `lighting_maps_emission`.
const fn in_oracle(id: ModelId) -> bool {
    match id {
        ModelId::BasicLighting
        | ModelId::Gouraud
        | ModelId::Materials
        | ModelId::LightingMaps
        | ModelId::Directional
        | ModelId::Point
        | ModelId::Spot
        | ModelId::MultipleLights
        | ModelId::OpenGLTutorial8
        | ModelId::Ogldev19 => true,
        ModelId::NormalMatrix | ModelId::BlinnPhong | ModelId::LightingMapsEmission => false,
    }
}

const fn case_model(id: ModelId, channels: usize, bound: f64) -> CaseModel {
    let layout = id.layout();
    CaseModel {
        id,
        shader: id.shader(),
        in_oracle: in_oracle(id),
        layout,
        n_inputs: layout.n_inputs(),
        channels,
        quantities: layout.quantities,
        bound,
    }
}

// Entry `i` of `CASE_MODELS` is `ModelId::ALL[i]`'s (checked at compile time).
const _: () = {
    let mut i = 0;
    while i < N_MODELS {
        assert!(CASE_MODELS[i].id as usize == i, "CASE_MODELS out of ModelId order");
        i += 1;
    }
};

/// Every model with random cases, in [`ModelId::ALL`] order: chapter order, then the
/// check-shader-only `normal_matrix`, `blinn_phong` and `lighting_maps_emission` (see [`CaseModel::in_oracle`]).
pub const CASE_MODELS: [CaseModel; N_MODELS] = [
    case_model(ModelId::BasicLighting, 3, bounds::BASIC_LIGHTING),
    case_model(ModelId::Gouraud, 3, bounds::GOURAUD),
    case_model(ModelId::Materials, 3, bounds::MATERIALS),
    case_model(ModelId::LightingMaps, 3, bounds::LIGHTING_MAPS),
    case_model(ModelId::Directional, 3, bounds::DIRECTIONAL),
    case_model(ModelId::Point, 3, bounds::POINT),
    case_model(ModelId::Spot, 6, bounds::SPOT),
    case_model(ModelId::MultipleLights, 3, bounds::MULTIPLE_LIGHTS),
    case_model(ModelId::OpenGLTutorial8, 3, bounds::OPENGL_TUTORIAL8),
    case_model(ModelId::Ogldev19, 3, bounds::OGLDEV19),
    case_model(ModelId::NormalMatrix, 3, bounds::GOURAUD),
    case_model(ModelId::BlinnPhong, 3, bounds::BLINN_PHONG),
    case_model(ModelId::LightingMapsEmission, 3, bounds::LIGHTING_MAPS_EMISSION),
];

/// The `f32` scene and its `f64` widening, shared by a group of `multiple_lights` cases.
#[derive(Debug, Clone)]
pub struct GroupScene {
    /// The scene the `f32` core shades with.
    pub f32: Scene,
    /// The same scene widened for the reference.
    pub f64: r64::scene::Scene,
}

/// Cases sharing uniforms: one draw.
#[derive(Debug, Clone)]
pub struct Group {
    /// Uniforms set before the draw (the scene's lights for `multiple_lights`).
    pub uniforms: Vec<(String, Uniform)>,
    /// The scene, for `multiple_lights`.
    pub scene: Option<GroupScene>,
    /// The cases, one packed row each.
    pub rows: Vec<Vec<[f32; 4]>>,
}

impl Group {
    /// The rows as the batch wants them: `inputs[k][i]`.
    pub fn columns(&self, n_inputs: usize) -> Vec<Vec<[f32; 4]>> {
        (0..n_inputs).map(|k| self.rows.iter().map(|r| r[k]).collect()).collect()
    }
}

/// Most cases one call of [`generate_cases`] makes, and every `--cases`' maximum: 10^6.
/// It fits a checking child's default address space (`--memory` 2048 MiB). Measured here
/// (peak resident set, llvmpipe on 2 cores): `check-shader` of 10^6 cases 450 MB in 4 s, a
/// `--vertex` pair of 10^6 cases 970 MB in 8 s; a pair at the old maximum of 10^7 needed
/// 8.2 GB and 194 s. Larger counts are refused before anything is allocated.
pub const MAX_CASES: usize = 1_000_000;

/// [`MAX_CASES`] as clap's ranges want it.
pub const MAX_CASES_U64: u64 = MAX_CASES as u64;

/// Most cases per model `exercise export` writes for the page (the book uses 256). Its
/// JSON holds every model's cases in this process (no child, no `--memory`): 10^6 aborted
/// at 4 GB; 10^4 peaks at 406 MB and writes 60 MB in 1.6 s here.
pub const MAX_EXPORT_CASES: u64 = 10_000;

/// Number of groups (draws) of `multiple_lights`: the chapter's scene and seven random ones.
pub const MULTIPLE_LIGHTS_GROUPS: usize = 8;

/// Generates `n` cases of `model` from `seed`, in groups (one draw each).
///
/// `fixed` overrides quantities by name (`check-shader` fixes what the user's shader
/// hard-codes); a `Float` takes the first component. Errors: [`GlError::Input`] naming
/// `fixed` for a name the model does not have, or `cases` when `n` is above [`MAX_CASES`].
pub fn generate_cases(
    model: &CaseModel,
    n: usize,
    seed: u64,
    fixed: &[(&str, [f32; 3])],
) -> Result<Vec<Group>, GlError> {
    if n > MAX_CASES {
        return Err(GlError::Input { field: "cases".into(), reason: format!("{n} is above the limit {MAX_CASES}") });
    }
    // The model's place in `ModelId::ALL` (reordering the models changes their cases).
    let stream = model.id as u64;
    let mut rows = generate(&strategy(model.id), n, seed_bytes(seed, stream))?;
    for (name, value) in fixed {
        let quantity = model.quantities.iter().find(|q| q.name == *name).ok_or_else(|| GlError::Input {
            field: "fixed".into(),
            reason: format!("model {} has no quantity {name}", model.id),
        })?;
        if let Slot::Case { input, offset } = quantity.slot {
            let width = if quantity.ty == QType::Float { 1 } else { 3 };
            for row in &mut rows {
                row[input][offset..offset + width].copy_from_slice(&value[..width]);
            }
        }
    }
    if !model.layout.has_groups() {
        return Ok(vec![Group { uniforms: Vec::new(), scene: None, rows }]);
    }
    let mut scenes = vec![Scene::learnopengl_default()];
    scenes.extend(generate(
        &strategies::scene_strategy(),
        MULTIPLE_LIGHTS_GROUPS - 1,
        seed_bytes(seed, 1000 + stream),
    )?);
    let per_group = n.div_ceil(MULTIPLE_LIGHTS_GROUPS).max(1);
    let mut groups = Vec::new();
    let mut rest = rows.into_iter();
    for scene in scenes {
        let chunk: Vec<Vec<[f32; 4]>> = rest.by_ref().take(per_group).collect();
        if chunk.is_empty() {
            break;
        }
        let f64_scene = r64::scene::Scene::from_f32(&scene);
        groups.push(Group {
            uniforms: scene_uniforms(&scene),
            scene: Some(GroupScene { f32: scene, f64: f64_scene }),
            rows: chunk,
        });
    }
    Ok(groups)
}
