//! Random shading cases for the oracle and `check-shader`: proptest strategies with a fixed
//! seed, the packed layout of each model, and the Rust answers (the `f32` core and the `f64`
//! [`crate::reference`]) for every case.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | row | one case: the `vec4` inputs of a model, in [`crate::gl::ShaderModel::inputs`] order |
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

use glam::{DMat3, DVec3, Mat3, Mat4, Quat, Vec3};
use proptest::prelude::*;
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

use super::batch::Uniform;
use super::context::GlError;
use super::models::{self, ShaderModel};
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material};
use crate::reference as r64;
use crate::scene::Scene;

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

/// Why a case is left out of the asserted bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Class {
    /// Every operation is defined and the result is a continuous function of the inputs.
    Defined,
    /// `normalize` of a zero vector (zero normal, light or eye at the fragment, zero direction).
    /// GLSL's other undefined case, `clamp(NaN)`, only arises downstream of this one in the
    /// tutorials' shaders (opengl-tutorial 8 clamps a dot product with a NaN vector), so it
    /// is counted here.
    NormalizeZero,
    /// `pow(x, y)` with `x < 0` (ogldev 19 takes `pow` before testing the sign).
    PowNegative,
    /// `pow(0, y)` with `y <= 0`; the base is within 1e-4 of 0 with shininess 0.
    PowZeroNonPositive,
    /// A division by zero: a spot light with `cutOff == outerCutOff` (ε = 0).
    DivisionByZero,
    /// Within 1e-5 of a discontinuity (a `> 0` or `theta > cutOff` test), where rounding
    /// may take either branch. Defined, but not bounded by a rounding analysis.
    NearDiscontinuity,
}

impl Class {
    /// A short description for reports.
    pub fn describe(self) -> &'static str {
        match self {
            Class::Defined => "defined",
            Class::NormalizeZero => "normalize(0)",
            Class::PowNegative => "pow(x < 0, y)",
            Class::PowZeroNonPositive => "pow(0, y <= 0)",
            Class::DivisionByZero => "x / 0 (cutOff == outerCutOff)",
            Class::NearDiscontinuity => "within 1e-5 of a branch",
        }
    }
}

/// What a model quantity is, for `check-shader`'s generated loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum QType {
    /// `float`.
    Float,
    /// `vec2` (texture coordinates; not compared, always zero).
    Vec2,
    /// `vec3`.
    Vec3,
    /// A sampled texel, read by `texture(...)`: `vec4(rgb, 1)`.
    Texel,
    /// `mat4`, four consecutive inputs as columns.
    Mat4,
}

/// Where a model quantity lives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Slot {
    /// Per case: input `input`, starting at component `offset`.
    Case {
        /// Input index.
        input: usize,
        /// First component (0 = x).
        offset: usize,
    },
    /// Shared by a group of cases: a uniform of that name (multiple lights' scene).
    Group,
    /// Not an input of the model (texture coordinates): loaded as zero.
    Unused,
}

/// A named input of a model, as the tutorials name it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantity {
    /// The tutorial's name (`FragPos`, `light.position`, `pointLights[0].constant`, ...).
    pub name: &'static str,
    /// Its type.
    pub ty: QType,
    /// Where it is stored.
    pub slot: Slot,
    /// The chapter's value, used by `check-shader` when the user's shader does not declare
    /// the quantity (it then hard-codes it, as the tutorials do). `None`: random.
    pub default: Option<[f32; 3]>,
}

const fn q(name: &'static str, ty: QType, input: usize, offset: usize, default: Option<[f32; 3]>) -> Quantity {
    Quantity { name, ty, slot: Slot::Case { input, offset }, default }
}

const fn unused(name: &'static str) -> Quantity {
    Quantity { name, ty: QType::Vec2, slot: Slot::Unused, default: None }
}

use QType::{Float as F, Texel as T, Vec3 as V};

const BASIC_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("ambientStrength", F, 0, 3, Some([0.1; 3])),
    q("Normal", V, 1, 0, None),
    q("specularStrength", F, 1, 3, Some([0.5; 3])),
    q("lightPos", V, 2, 0, None),
    q("shininess", F, 2, 3, Some([32.0; 3])),
    q("viewPos", V, 3, 0, None),
    q("lightColor", V, 4, 0, None),
    q("objectColor", V, 5, 0, None),
];

const GOURAUD_Q: &[Quantity] = &[
    q("aPos", V, 0, 0, None),
    q("ambientStrength", F, 0, 3, Some([0.1; 3])),
    q("aNormal", V, 1, 0, None),
    q("specularStrength", F, 1, 3, Some([0.5; 3])),
    q("lightPos", V, 2, 0, None),
    q("shininess", F, 2, 3, Some([32.0; 3])),
    q("viewPos", V, 3, 0, None),
    q("lightColor", V, 4, 0, None),
    q("objectColor", V, 5, 0, None),
    q("model", QType::Mat4, 6, 0, None),
];

const NORMAL_MATRIX_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("ambientStrength", F, 0, 3, Some([0.1; 3])),
    q("aNormal", V, 1, 0, None),
    q("specularStrength", F, 1, 3, Some([0.5; 3])),
    q("lightPos", V, 2, 0, None),
    q("shininess", F, 2, 3, Some([32.0; 3])),
    q("viewPos", V, 3, 0, None),
    q("lightColor", V, 4, 0, None),
    q("objectColor", V, 5, 0, None),
    q("model", QType::Mat4, 6, 0, None),
];

const MATERIALS_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.ambient", V, 3, 0, None),
    q("material.shininess", F, 3, 3, None),
    q("material.diffuse", V, 4, 0, None),
    q("material.specular", V, 5, 0, None),
    q("light.position", V, 6, 0, None),
    q("light.ambient", V, 7, 0, None),
    q("light.diffuse", V, 8, 0, None),
    q("light.specular", V, 9, 0, None),
];

const MAPS_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("material.shininess", F, 0, 3, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.diffuse", T, 3, 0, None),
    q("material.specular", T, 4, 0, None),
    unused("TexCoords"),
    q("light.position", V, 5, 0, None),
    q("light.ambient", V, 6, 0, None),
    q("light.diffuse", V, 7, 0, None),
    q("light.specular", V, 8, 0, None),
];

const DIRECTIONAL_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("material.shininess", F, 0, 3, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.diffuse", T, 3, 0, None),
    q("material.specular", T, 4, 0, None),
    unused("TexCoords"),
    q("light.direction", V, 5, 0, None),
    q("light.ambient", V, 6, 0, None),
    q("light.diffuse", V, 7, 0, None),
    q("light.specular", V, 8, 0, None),
];

const POINT_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("material.shininess", F, 0, 3, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.diffuse", T, 3, 0, None),
    q("material.specular", T, 4, 0, None),
    unused("TexCoords"),
    q("light.position", V, 5, 0, None),
    q("light.ambient", V, 6, 0, None),
    q("light.diffuse", V, 7, 0, None),
    q("light.specular", V, 8, 0, None),
    q("light.constant", F, 9, 0, None),
    q("light.linear", F, 9, 1, None),
    q("light.quadratic", F, 9, 2, None),
];

const SPOT_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("material.shininess", F, 0, 3, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.diffuse", T, 3, 0, None),
    q("material.specular", T, 4, 0, None),
    unused("TexCoords"),
    q("light.position", V, 5, 0, None),
    q("light.cutOff", F, 5, 3, None),
    q("light.direction", V, 6, 0, None),
    q("light.outerCutOff", F, 6, 3, None),
    q("light.ambient", V, 7, 0, None),
    q("light.diffuse", V, 8, 0, None),
    q("light.specular", V, 9, 0, None),
    q("light.constant", F, 10, 0, None),
    q("light.linear", F, 10, 1, None),
    q("light.quadratic", F, 10, 2, None),
];

const MULTI_Q: &[Quantity] = &[
    q("FragPos", V, 0, 0, None),
    q("material.shininess", F, 0, 3, None),
    q("Normal", V, 1, 0, None),
    q("viewPos", V, 2, 0, None),
    q("material.diffuse", T, 3, 0, None),
    q("material.specular", T, 4, 0, None),
    unused("TexCoords"),
    Quantity { name: "dirLight", ty: V, slot: Slot::Group, default: None },
    Quantity { name: "pointLights", ty: V, slot: Slot::Group, default: None },
    Quantity { name: "spotLight", ty: V, slot: Slot::Group, default: None },
];

const OT8_Q: &[Quantity] = &[
    q("Position_worldspace", V, 0, 0, None),
    q("LightPower", F, 0, 3, Some([50.0; 3])),
    q("Normal_cameraspace", V, 1, 0, None),
    q("specularExponent", F, 1, 3, Some([5.0; 3])),
    q("EyeDirection_cameraspace", V, 2, 0, None),
    q("LightDirection_cameraspace", V, 3, 0, None),
    q("LightPosition_worldspace", V, 4, 0, None),
    q("MaterialDiffuseColor", V, 5, 0, None),
    q("MaterialSpecularColor", V, 6, 0, Some([0.3; 3])),
    q("LightColor", V, 7, 0, Some([1.0; 3])),
    q("MaterialAmbientFactor", V, 8, 0, Some([0.1; 3])),
];

const OGLDEV_Q: &[Quantity] = &[
    q("WorldPos0", V, 0, 0, None),
    q("gSpecularPower", F, 0, 3, None),
    q("Normal0", V, 1, 0, None),
    q("gMatSpecularIntensity", F, 1, 3, None),
    q("gEyeWorldPos", V, 2, 0, None),
    q("gDirectionalLight.Color", V, 3, 0, None),
    q("gDirectionalLight.AmbientIntensity", F, 3, 3, None),
    q("gDirectionalLight.Direction", V, 4, 0, None),
    q("gDirectionalLight.DiffuseIntensity", F, 4, 3, None),
    q("gSampler", T, 5, 0, None),
    unused("TexCoord0"),
];

/// The models with random cases: the ten tutorial shaders, plus `normal_matrix` (for
/// `check-shader` only: basic lighting whose normal arrives in object space with a `model`
/// matrix, so the shader must apply the normal matrix).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// LearnOpenGL, Basic lighting.
    BasicLighting,
    /// LearnOpenGL, Basic lighting, Gouraud exercise (per vertex).
    Gouraud,
    /// LearnOpenGL, Materials.
    Materials,
    /// LearnOpenGL, Lighting maps.
    LightingMaps,
    /// LearnOpenGL, Light casters, directional.
    Directional,
    /// LearnOpenGL, Light casters, point.
    Point,
    /// LearnOpenGL, Light casters, spot (soft edge and hard cut-off).
    Spot,
    /// LearnOpenGL, Multiple lights.
    MultipleLights,
    /// opengl-tutorial 8.
    OpenGLTutorial8,
    /// ogldev 19.
    Ogldev19,
    /// Basic lighting with an object-space normal and a `model` matrix (check-shader only).
    NormalMatrix,
}

/// A model with random cases: its layout, names and asserted bound.
#[derive(Debug, Clone, Copy)]
pub struct CaseModel {
    /// Name (the shader model's name; `normal_matrix` has no tutorial shader).
    pub name: &'static str,
    /// Which model.
    pub kind: Kind,
    /// The tutorial shader run by the oracle (`None` for `normal_matrix`).
    pub shader: Option<&'static ShaderModel>,
    /// Number of `vec4` inputs per case.
    pub n_inputs: usize,
    /// Channels compared by the oracle (spot: 6, the others: 3).
    pub channels: usize,
    /// Named inputs, for `check-shader`.
    pub quantities: &'static [Quantity],
    /// The asserted bound on `|result - f64 reference|` per channel, derived in [`bounds`].
    pub bound: f64,
}

/// The error bounds, derived from `f32` rounding (GLSL 3.30 §4.1.4 lets implementations
/// use IEEE single precision; llvmpipe does).
///
/// Error budget of one lit channel, with `ε = 2^-24` and unit vectors from `normalize`:
/// - `normalize(p - q)` of exact `f32` inputs: the subtraction is correctly rounded
///   (relative ε per component), the length and `inversesqrt` add a few ε: each component
///   of a normalized vector is off by at most `N = 4ε` (llvmpipe's `inversesqrt` refines
///   the hardware estimate with Newton steps; its error is in that budget).
/// - A cosine `dot(a, b)` of two such vectors: 3 products and 2 sums (3ε) plus the two
///   normalizations (2N): `COS = 11ε`.
/// - The specular base `dot(viewDir, reflect(-lightDir, norm))`: `reflect` adds a dot and
///   a scaled subtraction (`2·COS + 3ε` on each component of the reflected vector), then
///   the dot with `viewDir`: `BASE = 32ε`.
/// - `pow(x, s)` with x in [0, 1]: the base error is carried through the exponent,
///   `|d(x^s)| = s·x^(s-1)·|dx| <= s·BASE`; llvmpipe's own `exp2(s·log2 x)` adds a relative
///   error `ln2·s·η` for an absolute `log2` error `η` (measured by the oracle's `pow` row,
///   see [`bounds::LOG2_ABS`]).
/// - Products and sums of the terms: a few ε relative on values of order the coefficients.
///
/// Each model's bound is then `Σ coefficient × term error`, with the coefficients' maxima
/// from the case ranges in the module docs; the individual derivations are next to each
/// constant.
pub mod bounds {
    /// `2^-24`, the unit roundoff of `f32`.
    pub const EPS: f64 = 5.960_464_477_539_063e-8;
    /// Error of a cosine of two normalized vectors (`11ε`, see the module docs).
    pub const COS: f64 = 11.0 * EPS;
    /// Error of Phong's specular base (`32ε`).
    pub const BASE: f64 = 32.0 * EPS;
    /// Absolute error allowed for llvmpipe's `log2` inside `pow(x, s) = exp2(s·log2 x)`:
    /// `4ε`. Measured by [`crate::gl::oracle::measure_pow`]: at most about `3ε` on
    /// Mesa 22.3 / LLVM 15 (the `pow` row of the oracle report); `s·η` scales it into
    /// `log2` of the result, so `pow`'s relative error is about `ln2·s·η`: 2.9e-5 was
    /// measured at s = 256.
    pub const LOG2_ABS: f64 = 4.0 * EPS;
    /// Error of `spec = pow(base, s)` with `s <= s_max` and a result <= 1:
    /// `s_max·BASE` (the base's error through the exponent) + `ln2·s_max·LOG2_ABS`
    /// (llvmpipe's `exp2(s·log2 x)`) + `2ε` (rounding `s·log2 x`, whose `t·2^-t <= 0.53`
    /// keeps it below `ε` in absolute terms, and `exp2`'s own rounding).
    pub const fn spec(s_max: f64) -> f64 {
        s_max * BASE + std::f64::consts::LN_2 * s_max * LOG2_ABS + 2.0 * EPS
    }
    /// Error of a sum of `terms` products of factors in [0, 1] with values up to `scale`:
    /// `8ε` per term relative to the scale (the products, the sum and the final write).
    pub const fn arith(terms: f64, scale: f64) -> f64 {
        8.0 * EPS * terms * scale
    }

    /// basic lighting: `(a + diff + sS·spec)·lc·oc`, a, sS, colors in [0, 1], s <= 256:
    /// `COS` (diffuse) + `spec(256)` (specular) + arithmetic on a value <= 3.
    pub const BASIC_LIGHTING: f64 = COS + spec(256.0) + arith(3.0, 3.0);
    /// Gouraud: as basic lighting, plus the vertex transform. `model = T·R·S` with scales in
    /// [0.25, 4]: the inverse-transpose has condition number <= 16, so the normal's direction
    /// is off by `16·4ε` instead of `N`; the world position `model·aPos` (|aPos| <= √3,
    /// |T| <= 2√3, so |world| <= 6√3 ≈ 10.4) is off by `4ε·10.4`, which the light and eye
    /// directions (distance >= 1) carry as `4ε·10.4` absolute. Both enter every cosine:
    /// `COS_G = COS + 64ε + 42ε`, and the specular base twice: `BASE_G = BASE + 2·106ε`.
    pub const GOURAUD: f64 = (COS + 106.0 * EPS) + spec(256.0) + 256.0 * 212.0 * EPS + arith(3.0, 3.0);
    /// Materials: `La·Ka + Ld·diff·Kd + Ls·spec·Ks`, all colors in [0, 1]: like basic lighting.
    pub const MATERIALS: f64 = COS + spec(256.0) + arith(3.0, 3.0);
    /// Lighting maps: materials with `Ka = Kd` (the diffuse texel).
    pub const LIGHTING_MAPS: f64 = MATERIALS;
    /// Directional: materials with `lightDir = normalize(-direction)`.
    pub const DIRECTIONAL: f64 = MATERIALS;
    /// Point: materials times the attenuation `1/(Kc + Kl·d + Kq·d²)` with `Kc >= 0.5`, so
    /// attenuation <= 2, computed with a relative error of a few ε: `2·MATERIALS`.
    pub const POINT: f64 = 2.0 * MATERIALS;
    /// Spot (soft edge): point plus the intensity `clamp((θ - γ)/ε_s, 0, 1)` with the cone's
    /// `ε_s = cos φ - cos γ >= cos 60° - cos 62° ≈ 0.0302` (inner angles in [5°, 60°], the outer
    /// 2° to 15° wider): θ's error `COS` becomes `COS/0.0302 ≈ 33·COS` on the intensity,
    /// which multiplies diffuse + specular (<= 2) times the attenuation (<= 2).
    pub const SPOT: f64 = POINT + 4.0 * 33.2 * COS;
    /// Multiple lights: one directional light, four point lights and a spot, summed; each
    /// light's error as above with its own coefficients (<= 1 for the directional, <= 2 for
    /// the attenuated ones): `MATERIALS + 4·POINT + SPOT` plus the five sums.
    pub const MULTIPLE_LIGHTS: f64 = MATERIALS + 4.0 * POINT + SPOT + arith(5.0, 27.0);
    /// opengl-tutorial 8: `Kd·0.1·... + (Kd·cosθ + Ks·cosα^s)·LC·P/d²` with `P <= 60`,
    /// `d >= 1`, so `P/d² <= 60`; exponents <= 128; the division adds a few ε relative.
    pub const OPENGL_TUTORIAL8: f64 = 60.0 * (COS + spec(128.0)) + arith(4.0, 121.0);
    /// ogldev 19: `texel·(Color·(Ia + Id·DF + Is·SF))` with intensities in [0, 1], powers
    /// <= 128. `LightReflect` is normalized once more (another `N` on each component).
    pub const OGLDEV19: f64 = COS + spec(128.0) + 128.0 * 4.0 * EPS + arith(3.0, 3.0);
}

/// Every model of the oracle, in chapter order, then `normal_matrix`.
pub const CASE_MODELS: &[CaseModel] = &[
    CaseModel {
        name: "basic_lighting",
        kind: Kind::BasicLighting,
        shader: Some(&models::BASIC_LIGHTING),
        n_inputs: 6,
        channels: 3,
        quantities: BASIC_Q,
        bound: bounds::BASIC_LIGHTING,
    },
    CaseModel {
        name: "gouraud",
        kind: Kind::Gouraud,
        shader: Some(&models::GOURAUD),
        n_inputs: 10,
        channels: 3,
        quantities: GOURAUD_Q,
        bound: bounds::GOURAUD,
    },
    CaseModel {
        name: "materials",
        kind: Kind::Materials,
        shader: Some(&models::MATERIALS),
        n_inputs: 10,
        channels: 3,
        quantities: MATERIALS_Q,
        bound: bounds::MATERIALS,
    },
    CaseModel {
        name: "lighting_maps",
        kind: Kind::LightingMaps,
        shader: Some(&models::LIGHTING_MAPS),
        n_inputs: 9,
        channels: 3,
        quantities: MAPS_Q,
        bound: bounds::LIGHTING_MAPS,
    },
    CaseModel {
        name: "directional",
        kind: Kind::Directional,
        shader: Some(&models::DIRECTIONAL),
        n_inputs: 9,
        channels: 3,
        quantities: DIRECTIONAL_Q,
        bound: bounds::DIRECTIONAL,
    },
    CaseModel {
        name: "point",
        kind: Kind::Point,
        shader: Some(&models::POINT),
        n_inputs: 10,
        channels: 3,
        quantities: POINT_Q,
        bound: bounds::POINT,
    },
    CaseModel {
        name: "spot",
        kind: Kind::Spot,
        shader: Some(&models::SPOT),
        n_inputs: 11,
        channels: 6,
        quantities: SPOT_Q,
        bound: bounds::SPOT,
    },
    CaseModel {
        name: "multiple_lights",
        kind: Kind::MultipleLights,
        shader: Some(&models::MULTIPLE_LIGHTS),
        n_inputs: 5,
        channels: 3,
        quantities: MULTI_Q,
        bound: bounds::MULTIPLE_LIGHTS,
    },
    CaseModel {
        name: "opengl_tutorial8",
        kind: Kind::OpenGLTutorial8,
        shader: Some(&models::OPENGL_TUTORIAL8),
        n_inputs: 9,
        channels: 3,
        quantities: OT8_Q,
        bound: bounds::OPENGL_TUTORIAL8,
    },
    CaseModel {
        name: "ogldev19",
        kind: Kind::Ogldev19,
        shader: Some(&models::OGLDEV19),
        n_inputs: 6,
        channels: 3,
        quantities: OGLDEV_Q,
        bound: bounds::OGLDEV19,
    },
    CaseModel {
        name: "normal_matrix",
        kind: Kind::NormalMatrix,
        shader: None,
        n_inputs: 10,
        channels: 3,
        quantities: NORMAL_MATRIX_Q,
        bound: bounds::GOURAUD,
    },
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

fn v3(a: [f32; 4]) -> Vec3 {
    Vec3::new(a[0], a[1], a[2])
}

fn d3(a: [f32; 4]) -> DVec3 {
    DVec3::new(a[0] as f64, a[1] as f64, a[2] as f64)
}

fn p(v: Vec3, w: f32) -> [f32; 4] {
    [v.x, v.y, v.z, w]
}

// ---------------------------------------------------------------- strategies

/// A uniformly distributed unit direction (z uniform in [-1, 1], azimuth uniform).
fn direction() -> impl Strategy<Value = Vec3> {
    (-1.0f32..=1.0, 0.0f32..std::f32::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

fn color() -> impl Strategy<Value = Vec3> {
    (0.0f32..=1.0, 0.0f32..=1.0, 0.0f32..=1.0).prop_map(Vec3::from)
}

/// An interpolated normal: a direction of length in [0.2, 5]; 1 in 100 is zero.
fn normal() -> impl Strategy<Value = Vec3> {
    prop_oneof![99 => (direction(), 0.2f32..5.0).prop_map(|(d, l)| d * l), 1 => Just(Vec3::ZERO)]
}

/// An offset from the fragment to a light or the eye, length in [min, 20]; 1 in 200 is
/// zero (the point sits on the fragment).
fn offset(min: f32) -> impl Strategy<Value = Vec3> {
    prop_oneof![199 => (direction(), min..20.0f32).prop_map(|(d, l)| d * l), 1 => Just(Vec3::ZERO)]
}

fn position(half: f32) -> impl Strategy<Value = Vec3> {
    (-half..=half, -half..=half, -half..=half).prop_map(Vec3::from)
}

/// Shininess in [1, max]; 1 in 100 is 0 when `with_zero` (pow(0, 0) shows up).
fn shininess(max: f32, with_zero: bool) -> BoxedStrategy<f32> {
    if with_zero {
        prop_oneof![99 => 1.0f32..=max, 1 => Just(0.0f32)].boxed()
    } else {
        (1.0f32..=max).boxed()
    }
}

fn attenuation() -> impl Strategy<Value = [f32; 4]> {
    (0.5f32..=2.0, 0.0f32..=1.0, 0.0f32..=2.0).prop_map(|(c, l, q)| [c, l, q, 0.0])
}

/// Spot cone: (cutOff, outerCutOff) cosines; inner angle in [5°, 60°], outer 2° to 15° wider;
/// 1 in 100 has equal angles (ε = 0).
fn cone() -> impl Strategy<Value = (f32, f32)> {
    (5.0f32..=60.0, 2.0f32..=15.0, 0u32..100).prop_map(|(inner, extra, k)| {
        let outer = if k == 0 { inner } else { inner + extra };
        (inner.to_radians().cos(), outer.to_radians().cos())
    })
}

/// A spot axis around the ray from the light to the fragment: tilted by up to 1.5 times
/// the outer angle (so θ covers the inside, the soft edge and the outside), scaled by a
/// length in [0.2, 5] (the shader normalizes it); 1 in 200 is zero.
fn spot_axis(to_frag: Vec3, outer_cos: f32, tilt: (f32, Vec3, f32), zero: bool) -> Vec3 {
    if zero {
        return Vec3::ZERO;
    }
    let (fraction, axis_hint, len) = tilt;
    let ray = to_frag.normalize_or_zero();
    let axis = ray.cross(axis_hint).normalize_or_zero();
    let angle = fraction * 1.5 * outer_cos.clamp(-1.0, 1.0).acos();
    let dir = if axis == Vec3::ZERO { ray } else { Quat::from_axis_angle(axis, angle) * ray };
    dir * len
}

/// A model matrix `T·R·S`: translation in [-2, 2]³, a random rotation, scales in [0.25, 4].
fn model_matrix() -> impl Strategy<Value = Mat4> {
    (position(2.0), direction(), 0.0f32..std::f32::consts::TAU, (0.25f32..4.0, 0.25f32..4.0, 0.25f32..4.0)).prop_map(
        |(t, axis, angle, s)| {
            Mat4::from_scale_rotation_translation(Vec3::from(s), Quat::from_axis_angle(axis, angle), t)
        },
    )
}

fn cols(m: Mat4) -> [[f32; 4]; 4] {
    m.to_cols_array_2d()
}

/// The common surface: FragPos in [-5, 5]³, normal, eye offset, light offset.
fn surface() -> impl Strategy<Value = (Vec3, Vec3, Vec3, Vec3)> {
    (position(5.0), normal(), offset(0.5), offset(0.5))
}

type Row = Vec<[f32; 4]>;

fn basic_strategy() -> BoxedStrategy<Row> {
    (surface(), color(), color(), 0.0f32..=1.0, 0.0f32..=1.0, shininess(256.0, true))
        .prop_map(|((frag, n, eye, light), lc, oc, a, ss, s)| {
            vec![p(frag, a), p(n, ss), p(frag + light, s), p(frag + eye, 0.0), p(lc, 0.0), p(oc, 0.0)]
        })
        .boxed()
}

fn model_rows_strategy(world_space_frag: bool) -> BoxedStrategy<Row> {
    (
        position(1.0),
        normal(),
        (direction(), 1.0f32..20.0),
        (direction(), 1.0f32..20.0),
        (color(), color(), 0.0f32..=1.0, 0.0f32..=1.0, shininess(256.0, false)),
        model_matrix(),
    )
        .prop_map(move |(a_pos, a_normal, (ld, ll), (vd, vl), (lc, oc, a, ss, s), m)| {
            let world = if world_space_frag { a_pos * 5.0 } else { m.transform_point3(a_pos) };
            let [c0, c1, c2, c3] = cols(m);
            let frag = if world_space_frag { world } else { a_pos };
            vec![
                p(frag, a),
                p(a_normal, ss),
                p(world + ld * ll, s),
                p(world + vd * vl, 0.0),
                p(lc, 0.0),
                p(oc, 0.0),
                c0,
                c1,
                c2,
                c3,
            ]
        })
        .boxed()
}

fn materials_strategy() -> BoxedStrategy<Row> {
    (surface(), (color(), color(), color(), shininess(256.0, true)), (color(), color(), color()))
        .prop_map(|((frag, n, eye, light), (ka, kd, ks, s), (la, ld, ls))| {
            vec![
                p(frag, 0.0),
                p(n, 0.0),
                p(frag + eye, 0.0),
                p(ka, s),
                p(kd, 0.0),
                p(ks, 0.0),
                p(frag + light, 0.0),
                p(la, 0.0),
                p(ld, 0.0),
                p(ls, 0.0),
            ]
        })
        .boxed()
}

/// Lighting maps, directional and point share the mapped surface; `light` is the position
/// (or the direction for the directional light) and the attenuation row is appended for
/// the point light.
fn mapped_strategy(kind: Kind) -> BoxedStrategy<Row> {
    (surface(), (color(), color(), shininess(256.0, false)), (color(), color(), color()), normal(), attenuation())
        .prop_map(move |((frag, n, eye, light), (dt, st, s), (la, ld, ls), dir, att)| {
            let light_vec = if kind == Kind::Directional { dir } else { frag + light };
            let mut row = vec![
                p(frag, s),
                p(n, 0.0),
                p(frag + eye, 0.0),
                p(dt, 0.0),
                p(st, 0.0),
                p(light_vec, 0.0),
                p(la, 0.0),
                p(ld, 0.0),
                p(ls, 0.0),
            ];
            if kind == Kind::Point {
                row.push(att);
            }
            row
        })
        .boxed()
}

fn spot_strategy() -> BoxedStrategy<Row> {
    (
        surface(),
        (color(), color(), shininess(256.0, false)),
        (color(), color(), color()),
        cone(),
        ((0.0f32..=1.0, direction(), 0.2f32..5.0), 0u32..200),
        attenuation(),
    )
        .prop_map(|((frag, n, eye, light), (dt, st, s), (la, ld, ls), (cut, outer), (tilt, z), att)| {
            let pos = frag + light;
            let axis = spot_axis(frag - pos, outer, tilt, z == 0);
            vec![
                p(frag, s),
                p(n, 0.0),
                p(frag + eye, 0.0),
                p(dt, 0.0),
                p(st, 0.0),
                p(pos, cut),
                p(axis, outer),
                p(la, 0.0),
                p(ld, 0.0),
                p(ls, 0.0),
                att,
            ]
        })
        .boxed()
}

fn multiple_strategy() -> BoxedStrategy<Row> {
    // The eye and the fragment are placed in the chapter's scene volume.
    (position(5.0), normal(), offset(0.5), color(), color(), shininess(256.0, false))
        .prop_map(|(frag, n, eye, dt, st, s)| vec![p(frag, s), p(n, 0.0), p(frag + eye, 0.0), p(dt, 0.0), p(st, 0.0)])
        .boxed()
}

fn ot8_strategy() -> BoxedStrategy<Row> {
    // Camera at the origin (V = identity): camera space is world space, EyeDirection is
    // -Position and LightDirection is LightPosition - Position, both exact in f32 or one
    // rounding, the same operations as the Rust path. Fragments in [-5, 5]³; 1 in 200 sits
    // at the eye (EyeDirection = 0).
    (
        prop_oneof![199 => position(5.0), 1 => Just(Vec3::ZERO)],
        normal(),
        offset(1.0),
        (1.0f32..=60.0, shininess(128.0, true), 0.0f32..=1.0),
        (color(), color(), color()),
    )
        .prop_map(|(frag, n, light, (power, s, ambient), (kd, ks, lc))| {
            let light_pos = frag + light;
            vec![
                p(frag, power),
                p(n, s),
                p(-frag, 0.0),
                p(light_pos - frag, 0.0),
                p(light_pos, 0.0),
                p(kd, 0.0),
                p(ks, 0.0),
                p(lc, 0.0),
                p(Vec3::splat(ambient), 0.0),
            ]
        })
        .boxed()
}

fn ogldev_strategy() -> BoxedStrategy<Row> {
    (
        surface(),
        (shininess(128.0, true), 0.0f32..=1.0),
        (color(), 0.0f32..=1.0, 0.0f32..=1.0),
        direction(),
        (color(), 0.0f32..=1.0),
    )
        .prop_map(|((frag, n, eye, _), (power, si), (c, ia, id), dir, (texel, alpha))| {
            // The tutorial normalizes the direction on the CPU; the packed value is the
            // f32-normalized direction, used as given by every path.
            let dir = dir.normalize_or_zero();
            vec![p(frag, power), p(n, si), p(frag + eye, 0.0), p(c, ia), p(dir, id), p(texel, alpha)]
        })
        .boxed()
}

/// The case strategy of `kind`: one packed row per value.
pub fn strategy(kind: Kind) -> BoxedStrategy<Row> {
    match kind {
        Kind::BasicLighting => basic_strategy(),
        Kind::Gouraud => model_rows_strategy(false),
        Kind::NormalMatrix => model_rows_strategy(true),
        Kind::Materials => materials_strategy(),
        Kind::LightingMaps | Kind::Directional | Kind::Point => mapped_strategy(kind),
        Kind::Spot => spot_strategy(),
        Kind::MultipleLights => multiple_strategy(),
        Kind::OpenGLTutorial8 => ot8_strategy(),
        Kind::Ogldev19 => ogldev_strategy(),
    }
}

/// A random scene for `multiple_lights`: a directional light, four point lights in
/// [-6, 6]³ and a spot light pointing at the origin's neighbourhood, colors in [0, 1],
/// attenuation and cones as for the single casters.
fn scene_strategy() -> impl Strategy<Value = Scene> {
    let props = || {
        (color(), color(), color()).prop_map(|(ambient, diffuse, specular)| LightProps { ambient, diffuse, specular })
    };
    let point = move || {
        (position(6.0), attenuation(), props()).prop_map(|(position, a, props)| PointLight {
            position,
            attenuation: Attenuation { constant: a[0], linear: a[1], quadratic: a[2] },
            props,
        })
    };
    (
        (direction(), props()),
        [point(), point(), point(), point()],
        (position(6.0), position(1.0), cone(), attenuation(), props()),
    )
        .prop_map(|((dir, dprops), points, (pos, aim, (cut, outer), a, sprops))| Scene {
            dir_light: Some(DirLight { direction: dir, props: dprops }),
            point_lights: points.to_vec(),
            spot_light: Some(SpotLight {
                position: pos,
                direction: (aim - pos).normalize_or_zero(),
                cut_off: cut,
                // Equal cones are excluded here: the scene is shared by every case of the
                // group, and an undefined ε = 0 would void the whole group.
                outer_cut_off: if outer == cut { (cut.acos() + 0.05).cos() } else { outer },
                attenuation: Attenuation { constant: a[0], linear: a[1], quadratic: a[2] },
                props: sprops,
            }),
            clear_color: Vec3::ZERO,
        })
}

/// The uniforms that give the shader `scene` (names as in the chapter's shader).
pub fn scene_uniforms(scene: &Scene) -> Vec<(String, Uniform)> {
    let v = |x: Vec3| Uniform::Vec3(x.to_array());
    let mut u = Vec::new();
    if let Some(d) = &scene.dir_light {
        u.push(("dirLight.direction".to_string(), v(d.direction)));
        u.push(("dirLight.ambient".to_string(), v(d.props.ambient)));
        u.push(("dirLight.diffuse".to_string(), v(d.props.diffuse)));
        u.push(("dirLight.specular".to_string(), v(d.props.specular)));
    }
    for (i, l) in scene.point_lights.iter().enumerate() {
        let f = |field: &str| format!("pointLights[{i}].{field}");
        u.push((f("position"), v(l.position)));
        u.push((f("constant"), Uniform::Float(l.attenuation.constant)));
        u.push((f("linear"), Uniform::Float(l.attenuation.linear)));
        u.push((f("quadratic"), Uniform::Float(l.attenuation.quadratic)));
        u.push((f("ambient"), v(l.props.ambient)));
        u.push((f("diffuse"), v(l.props.diffuse)));
        u.push((f("specular"), v(l.props.specular)));
    }
    if let Some(s) = &scene.spot_light {
        u.push(("spotLight.position".to_string(), v(s.position)));
        u.push(("spotLight.direction".to_string(), v(s.direction)));
        u.push(("spotLight.cutOff".to_string(), Uniform::Float(s.cut_off)));
        u.push(("spotLight.outerCutOff".to_string(), Uniform::Float(s.outer_cut_off)));
        u.push(("spotLight.constant".to_string(), Uniform::Float(s.attenuation.constant)));
        u.push(("spotLight.linear".to_string(), Uniform::Float(s.attenuation.linear)));
        u.push(("spotLight.quadratic".to_string(), Uniform::Float(s.attenuation.quadratic)));
        u.push(("spotLight.ambient".to_string(), v(s.props.ambient)));
        u.push(("spotLight.diffuse".to_string(), v(s.props.diffuse)));
        u.push(("spotLight.specular".to_string(), v(s.props.specular)));
    }
    u
}

/// Number of groups (draws) of `multiple_lights`: the chapter's scene and seven random ones.
pub const MULTIPLE_LIGHTS_GROUPS: usize = 8;

/// Generates `n` cases of `model` from `seed`, in groups (one draw each).
///
/// `fixed` overrides quantities by name (`check-shader` fixes what the user's shader
/// hard-codes); a `Float` takes the first component. Errors: [`GlError::Input`] naming
/// `fixed` for a name the model does not have.
pub fn generate_cases(
    model: &CaseModel,
    n: usize,
    seed: u64,
    fixed: &[(&str, [f32; 3])],
) -> Result<Vec<Group>, GlError> {
    let stream = CASE_MODELS.iter().position(|m| m.name == model.name).unwrap_or(0) as u64;
    let mut rows = generate(&strategy(model.kind), n, seed_bytes(seed, stream))?;
    for (name, value) in fixed {
        let quantity = model.quantities.iter().find(|q| q.name == *name).ok_or_else(|| GlError::Input {
            field: "fixed".into(),
            reason: format!("model {} has no quantity {name}", model.name),
        })?;
        if let Slot::Case { input, offset } = quantity.slot {
            let width = if quantity.ty == QType::Float { 1 } else { 3 };
            for row in &mut rows {
                row[input][offset..offset + width].copy_from_slice(&value[..width]);
            }
        }
    }
    if model.kind != Kind::MultipleLights {
        return Ok(vec![Group { uniforms: Vec::new(), scene: None, rows }]);
    }
    let mut scenes = vec![Scene::learnopengl_default()];
    scenes.extend(generate(&scene_strategy(), MULTIPLE_LIGHTS_GROUPS - 1, seed_bytes(seed, 1000 + stream))?);
    let per_group = n.div_ceil(MULTIPLE_LIGHTS_GROUPS).max(1);
    let mut groups = Vec::new();
    let mut rest = rows.into_iter();
    for scene in scenes {
        let chunk: Vec<Row> = rest.by_ref().take(per_group).collect();
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

// ---------------------------------------------------------------- the Rust answers

/// Channels of one case: up to [`MAX_CHANNELS`] numbers.
pub type Channels<T> = [T; MAX_CHANNELS];

fn ch3<T: Copy + Default>(a: [T; 3]) -> Channels<T> {
    let mut c = [T::default(); MAX_CHANNELS];
    c[..3].copy_from_slice(&a);
    c
}

fn ch6<T: Copy + Default>(a: [T; 3], b: [T; 3]) -> Channels<T> {
    let mut c = [T::default(); MAX_CHANNELS];
    c[..3].copy_from_slice(&a);
    c[3..].copy_from_slice(&b);
    c
}

fn basic_f32(r: &[[f32; 4]], normal: Vec3, frag: Vec3) -> Vec3 {
    crate::phong::BasicLighting {
        light_pos: v3(r[2]),
        view_pos: v3(r[3]),
        light_color: v3(r[4]),
        object_color: v3(r[5]),
        ambient_strength: r[0][3],
        specular_strength: r[1][3],
        shininess: r[2][3],
    }
    .terms(frag, normal)
    .sum()
}

fn basic_f64(r: &[[f32; 4]], normal: DVec3, frag: DVec3) -> DVec3 {
    r64::phong::BasicLighting {
        light_pos: d3(r[2]),
        view_pos: d3(r[3]),
        light_color: d3(r[4]),
        object_color: d3(r[5]),
        ambient_strength: r[0][3] as f64,
        specular_strength: r[1][3] as f64,
        shininess: r[2][3] as f64,
    }
    .terms(frag, normal)
    .sum()
}

fn model_of(r: &[[f32; 4]]) -> Mat4 {
    Mat4::from_cols_array_2d(&[r[6], r[7], r[8], r[9]])
}

fn material(r: &[[f32; 4]], kind: Kind) -> Material {
    if kind == Kind::Materials {
        Material { ambient: v3(r[3]), diffuse: v3(r[4]), specular: v3(r[5]), shininess: r[3][3] }
    } else {
        Material { ambient: v3(r[3]), diffuse: v3(r[3]), specular: v3(r[4]), shininess: r[0][3] }
    }
}

fn material64(r: &[[f32; 4]], kind: Kind) -> r64::material::Material {
    r64::material::Material::from_f32(&material(r, kind))
}

fn props(r: &[[f32; 4]], first: usize) -> LightProps {
    LightProps { ambient: v3(r[first]), diffuse: v3(r[first + 1]), specular: v3(r[first + 2]) }
}

fn att(a: [f32; 4]) -> Attenuation {
    Attenuation { constant: a[0], linear: a[1], quadratic: a[2] }
}

fn spot_light(r: &[[f32; 4]]) -> SpotLight {
    SpotLight {
        position: v3(r[5]),
        direction: v3(r[6]),
        cut_off: r[5][3],
        outer_cut_off: r[6][3],
        attenuation: att(r[10]),
        props: props(r, 7),
    }
}

fn ot8(r: &[[f32; 4]]) -> crate::models::OpenGLTutorial {
    crate::models::OpenGLTutorial {
        light_pos: v3(r[4]),
        light_color: v3(r[7]),
        light_power: r[0][3],
        diffuse: v3(r[5]),
        specular: v3(r[6]),
        ambient_factor: r[8][0],
        exponent: r[1][3],
    }
}

fn ogldev(r: &[[f32; 4]]) -> crate::models::Ogldev {
    crate::models::Ogldev {
        color: v3(r[3]),
        ambient_intensity: r[3][3],
        diffuse_intensity: r[4][3],
        direction: v3(r[4]),
        specular_intensity: r[1][3],
        specular_power: r[0][3],
        texture_color: v3(r[5]),
    }
}

/// The surface vectors of the mapped models (`norm`, `viewDir`, and `lightDir` toward
/// `light_pos`), as the shaders compute them, with zero for a zero vector.
fn surface_dirs(r: &[[f32; 4]], light_pos: Vec3) -> (Vec3, Vec3, Vec3) {
    let frag = v3(r[0]);
    (v3(r[1]).normalize_or_zero(), (light_pos - frag).normalize_or_zero(), (v3(r[2]) - frag).normalize_or_zero())
}

fn surface_dirs64(r: &[[f32; 4]], light_pos: DVec3) -> (DVec3, DVec3, DVec3) {
    use r64::phong::normalize_or_zero as nz;
    let frag = d3(r[0]);
    (nz(d3(r[1])), nz(light_pos - frag), nz(d3(r[2]) - frag))
}

impl CaseModel {
    /// Looks a model up by name (`basic_lighting`, ..., `normal_matrix`).
    pub fn by_name(name: &str) -> Option<&'static CaseModel> {
        CASE_MODELS.iter().find(|m| m.name == name)
    }

    /// The `f32` core's answer for one case (`scene` for `multiple_lights`).
    ///
    /// Every formula is the core's ([`crate::phong`], [`crate::material`],
    /// [`crate::casters`], [`crate::scene`], [`crate::models`]); this function only unpacks.
    pub fn eval_f32(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Channels<f32> {
        let frag = v3(r[0]);
        match self.kind {
            Kind::BasicLighting => ch3(basic_f32(r, v3(r[1]), frag).to_array()),
            Kind::Gouraud | Kind::NormalMatrix => {
                let m = model_of(r);
                let world = if self.kind == Kind::Gouraud { m.transform_point3(frag) } else { frag };
                let nm = crate::normals::normal_matrix_inverse_transpose(Mat3::from_mat4(m));
                let n = nm.map_or(Vec3::ZERO, |nm| nm * v3(r[1]));
                ch3(basic_f32(r, n, world).to_array())
            }
            Kind::Materials => {
                let (n, l, v) = surface_dirs(r, v3(r[6]));
                let light = props(r, 7);
                ch3(crate::material::material_terms(&material(r, self.kind), &light, n, l, v).sum().to_array())
            }
            Kind::LightingMaps => {
                let (n, l, v) = surface_dirs(r, v3(r[5]));
                ch3(crate::material::material_terms(&material(r, self.kind), &props(r, 6), n, l, v).sum().to_array())
            }
            Kind::Directional => {
                let (n, _, v) = surface_dirs(r, frag);
                let light = DirLight { direction: v3(r[5]), props: props(r, 6) };
                ch3(light.terms(&material(r, self.kind), n, v).sum().to_array())
            }
            Kind::Point => {
                let (n, _, v) = surface_dirs(r, frag);
                let light = PointLight { position: v3(r[5]), attenuation: att(r[9]), props: props(r, 6) };
                ch3(light.terms(&material(r, self.kind), n, frag, v).sum().to_array())
            }
            Kind::Spot => {
                let (n, _, v) = surface_dirs(r, frag);
                let light = spot_light(r);
                let m = material(r, self.kind);
                let soft = light.terms_keep_ambient(&m, n, frag, v).sum();
                let hard = light.terms_hard_edge(&m, n, frag, v).sum();
                ch6(soft.to_array(), hard.to_array())
            }
            Kind::MultipleLights => match scene {
                Some(s) => ch3(s.f32.shade(&material(r, self.kind), frag, v3(r[1]), v3(r[2])).rgb().to_array()),
                None => [f32::NAN; MAX_CHANNELS],
            },
            Kind::OpenGLTutorial8 => ch3(ot8(r).terms(frag, v3(r[1]), Vec3::ZERO).sum().to_array()),
            Kind::Ogldev19 => ch3(ogldev(r).terms(frag, v3(r[1]), v3(r[2])).sum().to_array()),
        }
    }

    /// The `f64` reference's answer for one case ([`crate::reference`], inputs widened exactly).
    pub fn eval_f64(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Channels<f64> {
        let frag = d3(r[0]);
        match self.kind {
            Kind::BasicLighting => ch3(basic_f64(r, d3(r[1]), frag).to_array()),
            Kind::Gouraud | Kind::NormalMatrix => {
                let m = r64::dmat4(model_of(r));
                let world = if self.kind == Kind::Gouraud { m.transform_point3(frag) } else { frag };
                let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
                let n = nm.map_or(DVec3::ZERO, |nm| nm * d3(r[1]));
                ch3(basic_f64(r, n, world).to_array())
            }
            Kind::Materials => {
                let (n, l, v) = surface_dirs64(r, d3(r[6]));
                let light = r64::material::LightProps::from_f32(&props(r, 7));
                ch3(r64::material::material_terms(&material64(r, self.kind), &light, n, l, v).sum().to_array())
            }
            Kind::LightingMaps => {
                let (n, l, v) = surface_dirs64(r, d3(r[5]));
                let light = r64::material::LightProps::from_f32(&props(r, 6));
                ch3(r64::material::material_terms(&material64(r, self.kind), &light, n, l, v).sum().to_array())
            }
            Kind::Directional => {
                let (n, _, v) = surface_dirs64(r, frag);
                let light = r64::casters::DirLight::from_f32(&DirLight { direction: v3(r[5]), props: props(r, 6) });
                ch3(light.terms(&material64(r, self.kind), n, v).sum().to_array())
            }
            Kind::Point => {
                let (n, _, v) = surface_dirs64(r, frag);
                let light = r64::casters::PointLight::from_f32(&PointLight {
                    position: v3(r[5]),
                    attenuation: att(r[9]),
                    props: props(r, 6),
                });
                ch3(light.terms(&material64(r, self.kind), n, frag, v).sum().to_array())
            }
            Kind::Spot => {
                let (n, _, v) = surface_dirs64(r, frag);
                let light = r64::casters::SpotLight::from_f32(&spot_light(r));
                let m = material64(r, self.kind);
                let soft = light.terms_keep_ambient(&m, n, frag, v).sum();
                let hard = light.terms_hard_edge(&m, n, frag, v).sum();
                ch6(soft.to_array(), hard.to_array())
            }
            Kind::MultipleLights => match scene {
                Some(s) => ch3(s.f64.shade(&material64(r, self.kind), frag, d3(r[1]), d3(r[2])).rgb().to_array()),
                None => [f64::NAN; MAX_CHANNELS],
            },
            Kind::OpenGLTutorial8 => {
                ch3(r64::models::OpenGLTutorial::from_f32(&ot8(r)).terms(frag, d3(r[1]), DVec3::ZERO).sum().to_array())
            }
            Kind::Ogldev19 => {
                ch3(r64::models::Ogldev::from_f32(&ogldev(r)).terms(frag, d3(r[1]), d3(r[2])).sum().to_array())
            }
        }
    }

    /// The compared channels of the shader's outputs for one case (`outs[m]` = output `m`).
    pub fn gl_channels(&self, outs: &[[f32; 4]]) -> Channels<f32> {
        let rgb = |o: [f32; 4]| [o[0], o[1], o[2]];
        if self.kind == Kind::Spot && outs.len() > 1 {
            ch6(rgb(outs[0]), rgb(outs[1]))
        } else {
            ch3(rgb(outs[0]))
        }
    }

    /// Sorts a case into [`Class`]: defined, or which undefined operation it reaches.
    ///
    /// Decided in `f64` from the exact inputs; the bands (1e-4 for `pow(0, 0)`, 1e-5 for
    /// branches) are far wider than the `f32` errors, so no case near the edge of a class
    /// is counted as defined.
    pub fn classify(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Class {
        use r64::phong::normalize_or_zero as nz;
        let frag = d3(r[0]);
        let zero = |v: DVec3| v == DVec3::ZERO;
        // Phong's base for the light toward `l` (unit), the normal n and the eye v.
        let base = |n: DVec3, l: DVec3, v: DVec3| v.dot(r64::glsl::reflect(-l, n)).max(0.0);
        let pow_class = |s: f32, b: f64| if s <= 0.0 && b < 1e-4 { Class::PowZeroNonPositive } else { Class::Defined };
        match self.kind {
            Kind::BasicLighting | Kind::Gouraud | Kind::NormalMatrix => {
                let (frag, n) = match self.kind {
                    Kind::Gouraud => {
                        let m = r64::dmat4(model_of(r));
                        let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
                        (m.transform_point3(frag), nm.map_or(DVec3::ZERO, |nm| nm * d3(r[1])))
                    }
                    Kind::NormalMatrix => {
                        let m = r64::dmat4(model_of(r));
                        let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
                        (frag, nm.map_or(DVec3::ZERO, |nm| nm * d3(r[1])))
                    }
                    _ => (frag, d3(r[1])),
                };
                let (l, v) = (d3(r[2]) - frag, d3(r[3]) - frag);
                if zero(n) || zero(l) || zero(v) {
                    return Class::NormalizeZero;
                }
                pow_class(r[2][3], base(nz(n), nz(l), nz(v)))
            }
            Kind::Materials | Kind::LightingMaps | Kind::Point | Kind::Spot | Kind::Directional => {
                let light = match self.kind {
                    Kind::Materials => d3(r[6]) - frag,
                    Kind::Directional => -d3(r[5]),
                    _ => d3(r[5]) - frag,
                };
                let (n, v) = (d3(r[1]), d3(r[2]) - frag);
                if zero(n) || zero(light) || zero(v) || (self.kind == Kind::Spot && zero(d3(r[6]))) {
                    return Class::NormalizeZero;
                }
                if self.kind == Kind::Spot {
                    if r[5][3] == r[6][3] {
                        return Class::DivisionByZero;
                    }
                    let theta = nz(light).dot(nz(-d3(r[6])));
                    if (theta - r[5][3] as f64).abs() < 1e-5 {
                        return Class::NearDiscontinuity;
                    }
                }
                let s = if self.kind == Kind::Materials { r[3][3] } else { r[0][3] };
                pow_class(s, base(nz(n), nz(light), nz(v)))
            }
            Kind::MultipleLights => {
                if zero(d3(r[1])) || zero(d3(r[2]) - frag) {
                    return Class::NormalizeZero;
                }
                let at_a_light = scene.is_some_and(|s| {
                    s.f64.point_lights.iter().any(|l| l.position == frag)
                        || s.f64.spot_light.as_ref().is_some_and(|l| l.position == frag)
                });
                if at_a_light {
                    Class::NormalizeZero
                } else {
                    Class::Defined
                }
            }
            Kind::OpenGLTutorial8 => {
                let (n, l, e) = (d3(r[1]), d3(r[3]), d3(r[2]));
                if zero(n) || zero(l) || zero(e) {
                    return Class::NormalizeZero;
                }
                let cos_alpha = nz(e).dot(r64::glsl::reflect(-nz(l), nz(n))).clamp(0.0, 1.0);
                pow_class(r[1][3], cos_alpha)
            }
            Kind::Ogldev19 => {
                let (n, v) = (d3(r[1]), d3(r[2]) - frag);
                if zero(n) {
                    return Class::NormalizeZero;
                }
                let n = nz(n);
                let dir = d3(r[4]);
                let diffuse_factor = n.dot(-dir);
                if diffuse_factor.abs() < 1e-5 {
                    return Class::NearDiscontinuity;
                }
                if diffuse_factor < 0.0 {
                    return Class::Defined;
                }
                if zero(v) {
                    return Class::NormalizeZero;
                }
                let c = nz(v).dot(nz(r64::glsl::reflect(dir, n)));
                if c < 0.0 {
                    Class::PowNegative
                } else {
                    pow_class(r[0][3], c)
                }
            }
        }
    }
}
