//! The failure atlas: 15 ways the tutorials' lighting math goes wrong, each
//! measured, fixed and measured again.
//!
//! Every case has:
//! - functions here that compute the failure and the fix quantitatively;
//! - a test in `tests/failure_atlas.rs` that *finds* the failure with a
//!   deterministic proptest runner and shrinks it to the minimal repro
//!   recorded in [`CASES`] (the test fails if the repro changes);
//! - a property test that the fix holds;
//! - a row in [`table`] and a figure (`caseN_figure`, all in [`figures`]).
//!
//! The cases live in one module per family, re-exported here:
//!
//! | module | cases |
//! | --- | --- |
//! | `specular` | 1 ungated specular, 2 `pow` of a negative base, 3 `pow(0, 0)`, 14 Phong's cut lobe |
//! | `normals` | 4 degenerate triangles, 5 non-uniform scale, 6 near-singular model matrix |
//! | `interpolation` | 7 unnormalized interpolated normals, 8 Gouraud and Mach bands |
//! | `lights` | 9 spot edges, 10 attenuation near the light, 13 the `w == 0.0` test |
//! | `precision` | 11 `f32` far from the origin |
//! | `saturation` | 12 hue shift when lights saturate |
//! | `winding` | 15 the LearnOpenGL cube's mixed winding under back-face culling |
//!
//! [`CASES`] is the registry: [`figure`] and [`measure`] compute one case, and the
//! book's figure and table lists loop over it.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `n` | unit normal, +z in the planar cases |
//! | `light_dir`, `view_dir` | unit vectors toward the light and the eye |
//! | `s` | shininess |
//! | level | one 8-bit output step, `1/255` in linear units ([`super::ONE_LEVEL`]) |
//!
//! Minimal repros (found by shrinking with a fixed seed, recorded in [`CASES`]
//! and checked by the tests):
//!
//! | # | minimal repro |
//! | --- | --- |
//! | 1 | light 1° below the horizon, eye 18° from n at azimuth 125°, s = 1: specular 0.161 |
//! | 2 | v·r = -0.78, power 22: C powf ghost 0.0042 |
//! | 3 | v·r = 0, s = 0: specular 1 |
//! | 4 | a = [-2, -2, 0], b = [-2, -2, 0], c = [0, 0, 0]: normal [NaN, NaN, NaN]; legs 1e-11: normal [0, 0, 1.0096843] |
//! | 5 | scale (1.1, 1, 1), normal 6° from +x toward +z: error 1.14° |
//! | 6 | scale (1, 1, 2^-65): inverse-transpose normal fails |
//! | 7 | normals 13° apart, t = 0.19: 1.01 levels dark |
//! | 8 | span 2°, s = 13: 1.04 levels lost |
//! | 9 | inner 23°, outer 2°, fragment 0° off axis: intensity 0; edge width 5.01e-3°: f32 error 1.63 levels |
//! | 10 | Kc = 0.01, d = 0: attenuation 100; d = 0: 1/d² = inf |
//! | 11 | scene 10^5.1 from the origin: 1.98 levels (worst quad fragment) |
//! | 12 | 2 lights of [0, 0.54, 0.12]: hue shift 1.1° |
//! | 13 | eye (-1, 0, 5), direction (1, -2, -1): w = 2.3841858e-7 |
//! | 14 | light 1° up, eye -1° from n, s = 1: Phong 0, Blinn 0.250 |
//! | 15 | eye 0° up, azimuth 10°: 44 of 2128 pixels wrong |

use glam::Vec3;

use super::Figure;
use crate::table::Table;

mod interpolation;
mod lights;
mod normals;
mod precision;
mod saturation;
mod specular;
mod winding;

pub use interpolation::*;
pub use lights::*;
pub use normals::*;
pub use precision::*;
pub use saturation::*;
pub use specular::*;
pub use winding::*;

/// One case of the atlas: its name, source, fix and recorded minimal repro.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Case {
    /// Case number, 1 … 15.
    pub number: u8,
    /// Short name.
    pub name: &'static str,
    /// Where the failing code comes from.
    pub source: &'static str,
    /// The fix, in one line.
    pub fix: &'static str,
    /// The minimal repro that shrinking found, exactly as the test prints it.
    pub repro: &'static str,
}

/// The 15 cases, in the chapter's order, with the minimal repros the tests found.
pub const CASES: [Case; 15] = [
    Case {
        number: 1,
        name: "specular on surfaces facing away",
        source: "LearnOpenGL, Basic lighting (specular not gated by n·l)",
        fix: "gate specular by n·l > 0 (gated_specular)",
        repro: "light 1° below the horizon, eye 18° from n at azimuth 125°, s = 1: specular 0.161",
    },
    Case {
        number: 2,
        name: "pow of a negative base",
        source: "ogldev 19 (pow before the > 0 test)",
        fix: "GLSL-domain pow (NaN → test false → 0) or pow(max(x, 0), s)",
        repro: "v·r = -0.78, power 22: C powf ghost 0.0042",
    },
    Case {
        number: 3,
        name: "pow(0, 0) and shininess below 1",
        source: "any shader with user shininess; C powf(0, 0) = 1",
        fix: "pow_or_zero and checked_shininess (s >= 1)",
        repro: "v·r = 0, s = 0: specular 1",
    },
    Case {
        number: 4,
        name: "normalize of zero; degenerate triangle",
        source: "opengl-tutorial 8 (triangle normals)",
        fix: "normalize_or_zero; edges pre-scaled before the cross product",
        repro: "a = [-2, -2, 0], b = [-2, -2, 0], c = [0, 0, 0]: normal [NaN, NaN, NaN]; legs 1e-11: normal [0, 0, 1.0096843]",
    },
    Case {
        number: 5,
        name: "non-uniform scale without the normal matrix",
        source: "LearnOpenGL, Basic lighting (Normal = mat3(model) * aNormal)",
        fix: "cofactor normal matrix",
        repro: "scale (1.1, 1, 1), normal 6° from +x toward +z: error 1.14°",
    },
    Case {
        number: 6,
        name: "near-singular model matrix",
        source: "LearnOpenGL, Basic lighting (transpose(inverse(model)))",
        fix: "cofactor normal matrix (pre-scaled for tiny uniform scale)",
        repro: "scale (1, 1, 2^-65): inverse-transpose normal fails",
    },
    Case {
        number: 7,
        name: "interpolated normals left unnormalized",
        source: "a fragment shader without normalize(Normal)",
        fix: "normalize in the fragment shader",
        repro: "normals 13° apart, t = 0.19: 1.01 levels dark",
    },
    Case {
        number: 8,
        name: "Gouraud losing a highlight; Mach bands",
        source: "LearnOpenGL, Basic lighting, Gouraud exercise",
        fix: "per-fragment shading, or a span from the advisor",
        repro: "span 2°, s = 13: 1.04 levels lost",
    },
    Case {
        number: 9,
        name: "spot with ε <= 0; narrow soft edge in f32",
        source: "LearnOpenGL, Light casters (intensity = clamp((θ−γ)/ε))",
        fix: "validated cones (hard edge at ε = 0); sine-form ramp",
        repro: "inner 23°, outer 2°, fragment 0° off axis: intensity 0; edge width 5.01e-3°: f32 error 1.63 levels",
    },
    Case {
        number: 10,
        name: "Kc < 1 and 1/d² as d → 0",
        source: "LearnOpenGL, Light casters; opengl-tutorial 8",
        fix: "clamp attenuation to 1; 1/max(d, radius)²",
        repro: "Kc = 0.01, d = 0: attenuation 100; d = 0: 1/d² = inf",
    },
    Case {
        number: 11,
        name: "f32 far from the origin",
        source: "world-space lighting (LearnOpenGL, Basic lighting)",
        fix: "camera-relative positions, subtracted in f64 on the CPU (an f32 view matrix is not enough)",
        repro: "scene 10^5.1 from the origin: 1.98 levels (worst quad fragment)",
    },
    Case {
        number: 12,
        name: "hue shift when many lights saturate",
        source: "LearnOpenGL, Multiple lights (sum, then clamp per channel)",
        fix: "scale by the largest channel (hue-preserving clamp)",
        repro: "2 lights of [0, 0.54, 0.12]: hue shift 1.1°",
    },
    Case {
        number: 13,
        name: "w == 0.0 test for directional lights",
        source: "LearnOpenGL, Light casters (if (lightVector.w == 0.0))",
        fix: "classify_light_vector with a tolerance",
        repro: "eye (-1, 0, 5), direction (1, -2, -1): w = 2.3841858e-7",
    },
    Case {
        number: 14,
        name: "Phong's lobe cut off beyond 90°",
        source: "LearnOpenGL, Advanced lighting",
        fix: "Blinn-Phong (n·h >= 0 for every view above the surface)",
        repro: "light 1° up, eye -1° from n, s = 1: Phong 0, Blinn 0.250",
    },
    Case {
        number: 15,
        name: "mixed winding under back-face culling",
        source: "LearnOpenGL, Lighting maps (the cube's vertices[]: 6 of 12 triangles clockwise)",
        fix: "wind each triangle counter-clockwise against its face normal (Mesh::learnopengl_cube)",
        repro: "eye 0° up, azimuth 10°: 44 of 2128 pixels wrong",
    },
];

/// The case with `number` (1 … 15), or `None`.
pub fn case(number: u8) -> Option<&'static Case> {
    CASES.iter().find(|c| c.number == number)
}

/// A unit vector at `polar_deg` from +z and `azimuth_deg` around it from +x.
///
/// ```text
/// (sin p cos a, sin p sin a, cos p)
/// ```
///
/// The planar cases put the normal at +z; polar > 90° is below the surface.
pub fn direction_from_angles(polar_deg: f32, azimuth_deg: f32) -> Vec3 {
    let (p, a) = (polar_deg.to_radians(), azimuth_deg.to_radians());
    Vec3::new(p.sin() * a.cos(), p.sin() * a.sin(), p.cos())
}

// ---------------------------------------------------------------- tables

/// The atlas table for the book: one row per case.
///
/// Columns: case number, name, minimal repro (recorded, checked by the
/// tests), symptom measured, fix, measured after the fix. Every number in the
/// measured columns is computed when this is called.
pub fn table() -> Table {
    let header = ["#", "case", "minimal repro", "symptom (measured)", "fix", "after the fix (measured)"];
    let mut t = Table::new("The failure atlas", "", &header);
    for c in &CASES {
        let (symptom, after) = measure(c.number).unwrap_or_default();
        t.push(vec![c.number.to_string(), c.name.to_string(), c.repro.to_string(), symptom, c.fix.to_string(), after]);
    }
    t
}

/// [`table`] in a vector, for callers that render several tables.
pub fn tables() -> Vec<Table> {
    vec![table(), super::culling::range_table()]
}

/// A case's measurement: `(symptom, after the fix)`.
type MeasureFn = fn() -> (String, String);

/// The computed parts of one case: its figure and its measurements.
struct Computed {
    /// The case's figure.
    figure: fn() -> Figure,
    /// `(symptom, after the fix)`, both measured when called.
    measure: MeasureFn,
}

/// The computed parts of case `number` (1 … 15), in the order of [`CASES`].
fn computed(number: u8) -> Option<Computed> {
    let (figure, measure): (fn() -> Figure, MeasureFn) = match number {
        1 => (case1_figure, specular::case1_measure),
        2 => (case2_figure, specular::case2_measure),
        3 => (case3_figure, specular::case3_measure),
        4 => (case4_figure, normals::case4_measure),
        5 => (case5_figure, normals::case5_measure),
        6 => (case6_figure, normals::case6_measure),
        7 => (case7_figure, interpolation::case7_measure),
        8 => (case8_figure, interpolation::case8_measure),
        9 => (case9_figure, lights::case9_measure),
        10 => (case10_figure, lights::case10_measure),
        11 => (case11_figure, precision::case11_measure),
        12 => (case12_figure, saturation::case12_measure),
        13 => (case13_figure, lights::case13_measure),
        14 => (case14_figure, specular::case14_measure),
        15 => (case15_figure, winding::case15_measure),
        _ => return None,
    };
    Some(Computed { figure, measure })
}

/// Case `number`'s figure, or `None` for a number that is not a case.
pub fn figure(number: u8) -> Option<Figure> {
    computed(number).map(|c| (c.figure)())
}

/// Case `number`'s measurements, `(symptom, after the fix)`, as the table's two
/// measured columns show them; `None` for a number that is not a case.
pub fn measure(number: u8) -> Option<(String, String)> {
    computed(number).map(|c| (c.measure)())
}

/// Every case's figure, numbered.
pub fn figures() -> Vec<(u8, Figure)> {
    CASES.iter().filter_map(|c| Some((c.number, figure(c.number)?))).collect()
}
