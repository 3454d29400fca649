//! The failure atlas: 14 ways the tutorials' lighting math goes wrong, each
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
//! | symbol | meaning |
//! | --- | --- |
//! | `n` | unit normal, +z in the planar cases |
//! | `light_dir`, `view_dir` | unit vectors toward the light and the eye |
//! | `s` | shininess |
//! | level | one 8-bit output step, `1/255` in linear units ([`ONE_LEVEL`]) |
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

use glam::{DMat3, DVec3, Mat3, Mat4, Vec3, Vec4};

use crate::casters::{classify_light_vector, spot_intensity, Attenuation, LightVector, ParamError, SpotLight};
use crate::glsl::{pow, pow_or_zero, reflect, saturate};
use crate::material::LightProps;
use crate::normals::{
    model_matrix_normal_error_deg, normal_matrix_cofactor, normal_matrix_inverse_transpose, triangle_normal_or_zero,
};
use crate::phong::{blinn_exponent_rule_of_thumb, blinn_specular_factor, phong_specular_factor, BasicLighting};

use super::advisor::{gouraud_edge_error, max_span_for_budget};
use super::{linspace, Figure, Series, Table, ONE_LEVEL};

/// One case of the atlas: its name, source, fix and recorded minimal repro.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Case {
    /// Case number, 1 … 14, as issue 6 lists them.
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

/// The 14 cases, in issue 6's order, with the minimal repros the tests found.
pub const CASES: [Case; 14] = [
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
];

/// The case with `number` (1 … 14), or `None`.
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

// ---------------------------------------------------------------- case 1

/// Case 1, the failure: LearnOpenGL's specular, not gated by `n · light_dir`.
///
/// ```text
/// spec = pow(max(view_dir · reflect(−light_dir, n), 0), s)
/// ```
///
/// Inputs unit length, pointing away from the surface. With the light below
/// the surface (`n·l < 0`) and the eye low on the far side, `reflect_dir`
/// still meets `view_dir`: a highlight on an unlit face.
///
/// Source: LearnOpenGL, Basic lighting ([`phong_specular_factor`]).
pub fn ungated_specular(n: Vec3, light_dir: Vec3, view_dir: Vec3, shininess: f32) -> f32 {
    phong_specular_factor(n, light_dir, view_dir, shininess)
}

/// Case 1, the fix: specular only where the light reaches the front.
///
/// ```text
/// spec = n·l > 0 ? pow(max(v·r, 0), s) : 0
/// ```
///
/// ogldev 19 gates this way. NaN `n·l` gives 0.
pub fn gated_specular(n: Vec3, light_dir: Vec3, view_dir: Vec3, shininess: f32) -> f32 {
    if n.dot(light_dir) > 0.0 {
        phong_specular_factor(n, light_dir, view_dir, shininess)
    } else {
        0.0
    }
}

/// Case 1: the brightest ghost highlight with the light `below_horizon_deg`
/// under the surface, over every view above it.
///
/// The supremum is at the horizon opposite the light, where
/// `v·r = cos(below_horizon)`, so the ghost is `cos(δ)^s`; computed here
/// through [`ungated_specular`] with the view in the surface plane.
pub fn case1_ghost_peak(below_horizon_deg: f32, shininess: f32) -> f32 {
    let n = Vec3::Z;
    let light_dir = direction_from_angles(90.0 + below_horizon_deg, 0.0);
    let r = reflect(-light_dir, n);
    let view_dir = Vec3::new(r.x, r.y, 0.0).normalize_or_zero();
    ungated_specular(n, light_dir, view_dir, shininess)
}

/// Case 1 figure: the ghost's peak against the light's depth below the horizon.
pub fn case1_figure() -> Figure {
    let series = [8.0, 32.0, 128.0]
        .into_iter()
        .map(|s| Series::from_fn(format!("s = {s}"), linspace(0.0, 30.0, 30), |d| case1_ghost_peak(d, s)))
        .collect();
    Figure::new("Ghost highlight of ungated specular", "light below horizon (°)", "peak specular factor", series)
}

fn case1_measure() -> (String, String) {
    let ghost = case1_ghost_peak(5.0, 32.0);
    let n = Vec3::Z;
    let l = direction_from_angles(95.0, 0.0);
    let v = Vec3::new(-1.0, 0.0, 0.0);
    (
        format!(
            "light 5° below horizon, s = 32: ghost specular {ghost:.3} ({:.0} levels at strength 1)",
            ghost * 255.0
        ),
        format!("gated: {}", gated_specular(n, l, v, 32.0)),
    )
}

// ---------------------------------------------------------------- case 2

/// What three implementations of `pow(x, y)` return (case 2).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PowResults {
    /// C / Rust `powf`: defined for negative bases with integer exponents.
    pub c_powf: f32,
    /// GLSL 3.30 §8.2: undefined for `x < 0` (`None`).
    pub glsl: Option<f32>,
    /// llvmpipe's `exp2(y · log2(x))`: NaN for `x < 0`.
    pub llvmpipe: f32,
}

/// llvmpipe's `pow`: `exp2(y · log2 x)`.
///
/// NaN for `x < 0` (log2 of a negative), so a following `> 0` test is false.
/// Source: DESIGN (Mesa llvmpipe's lowering of `pow`).
pub fn llvmpipe_pow(x: f32, y: f32) -> f32 {
    (y * x.log2()).exp2()
}

/// Case 2: `pow(x, y)` by C, GLSL and llvmpipe.
///
/// For `x < 0`: C gives `|x|^y` for even integer `y` (a ghost highlight),
/// `−|x|^y` for odd integer `y` (negative light), NaN for non-integer `y`;
/// GLSL leaves it undefined; llvmpipe gives NaN.
pub fn case2_pow(x: f32, y: f32) -> PowResults {
    PowResults { c_powf: x.powf(y), glsl: crate::glsl::try_pow(x, y), llvmpipe: llvmpipe_pow(x, y) }
}

/// Case 2, the failure: ogldev's specular factor computed with C `powf`.
///
/// ```text
/// SpecularFactor = powf(dot(VertexToEye, LightReflect), SpecularPower)
/// specular = SpecularFactor > 0 ? SpecularFactor : 0
/// ```
///
/// `v_dot_r < 0` (eye behind the mirror direction) with an even power gives
/// a positive ghost; an odd power is caught by the `> 0` test here, but
/// without the test it is negative light ([`case2_pow`]).
///
/// Source: ogldev tutorial 19.
pub fn ogldev_specular_c_powf(v_dot_r: f32, power: f32) -> f32 {
    let factor = v_dot_r.powf(power);
    if factor > 0.0 {
        factor
    } else {
        0.0
    }
}

/// Case 2, the fix: the same test with GLSL's domain ([`crate::glsl::pow`]:
/// NaN for a negative base, so `> 0` is false), which is also llvmpipe's result.
/// Equal to `pow_or_zero(max(v_dot_r, 0), power)` for `power > 0`.
pub fn ogldev_specular_glsl(v_dot_r: f32, power: f32) -> f32 {
    let factor = pow(v_dot_r, power);
    if factor > 0.0 {
        factor
    } else {
        0.0
    }
}

/// Case 2 figure: C `powf(v·r, y)` over v·r ∈ [−1, 1] for y = 32, 31, 31.5.
/// NaN points (31.5 below 0) are left out.
pub fn case2_figure() -> Figure {
    let series = [32.0, 31.0, 31.5]
        .into_iter()
        .map(|y| Series::from_fn(format!("C powf, y = {y}"), linspace(-1.0, 1.0, 80), move |x| x.powf(y)))
        .chain(std::iter::once(Series::from_fn("GLSL / llvmpipe, then > 0", linspace(-1.0, 1.0, 80), |x| {
            ogldev_specular_glsl(x, 32.0)
        })))
        .collect();
    Figure::new("pow of a negative base", "v · r", "specular factor", series)
}

fn case2_measure() -> (String, String) {
    let grazing = -(10.0f32.to_radians().cos());
    let r = |y| case2_pow(grazing, y);
    (
        format!(
            "light 10° above horizon, eye at the opposite horizon (v·r = {grazing:.3}): powf y=32 → {:.3}, y=31 → {:.3}, y=31.5 → {}",
            r(32.0).c_powf,
            r(31.0).c_powf,
            r(31.5).c_powf
        ),
        format!("GLSL pow + test: {}, llvmpipe: {} → 0", ogldev_specular_glsl(grazing, 32.0), r(32.0).llvmpipe),
    )
}

// ---------------------------------------------------------------- case 3

/// Case 3, the failure: specular with C `powf` and any shininess.
///
/// ```text
/// spec = powf(max(v·r, 0), s)
/// ```
///
/// `powf(0, 0) = 1`: with `s = 0` every fragment outside the lobe gets full
/// specular. `0 < s < 1`: the lobe covers the hemisphere and ends in a step
/// (`x^s` has infinite slope at 0), a bright ring at `v·r = 0`.
pub fn c_specular(v_dot_r: f32, shininess: f32) -> f32 {
    v_dot_r.max(0.0).powf(shininess)
}

/// Case 3, the fix for user-supplied shininess: reject `s < 1`.
///
/// For `s ≥ 1`, `x^s ≤ x`, so the lobe fades continuously to 0 at its edge.
/// Errors name the field `shininess`: below 1, or not finite.
pub fn checked_shininess(shininess: f32) -> Result<f32, ParamError> {
    if shininess.is_finite() && shininess >= 1.0 {
        Ok(shininess)
    } else {
        Err(ParamError { field: "shininess", reason: format!("must be finite and >= 1, got {shininess}") })
    }
}

/// Case 3: the specular value 1° inside the lobe's edge (`v·r = cos 89°`).
pub fn case3_edge_step(shininess: f32) -> f32 {
    c_specular(89.0f32.to_radians().cos(), shininess)
}

/// Case 3 figure: `powf(max(cos α, 0), s)` against α for s = 0, 0.1, 0.5, 1, 4.
pub fn case3_figure() -> Figure {
    let series = [0.0, 0.1, 0.5, 1.0, 4.0]
        .into_iter()
        .map(|s| {
            Series::from_fn(format!("s = {s}"), linspace(0.0, 120.0, 120), move |a| c_specular(a.to_radians().cos(), s))
        })
        .collect();
    Figure::new("Shininess 0 and below 1 with C powf", "angle between v and r (°)", "specular factor", series)
}

fn case3_measure() -> (String, String) {
    (
        format!(
            "powf(0, 0) = {} (full specular outside the lobe); s = 0.5: step {:.3} ({:.0} levels) 1° inside the edge",
            c_specular(0.0, 0.0),
            case3_edge_step(0.5),
            case3_edge_step(0.5) * 255.0
        ),
        format!(
            "pow_or_zero(0, 0) = {}; checked_shininess(0.5) is an error; s = 1: step {:.4}",
            pow_or_zero(0.0, 0.0),
            case3_edge_step(1.0)
        ),
    )
}

// ---------------------------------------------------------------- case 4

/// Case 4, the failure: GLSL's `normalize`, `v · inversesqrt(dot(v, v))`.
///
/// NaN for the zero vector (0 · ∞), and for vectors so small that
/// `dot(v, v)` underflows to 0 (|v| < about 1e-23 in `f32`).
pub fn naive_normalize(v: Vec3) -> Vec3 {
    v * (1.0 / v.dot(v).sqrt())
}

/// Case 4, the failure: `normalize(cross(b − a, c − a))`.
pub fn naive_triangle_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    naive_normalize((b - a).cross(c - a))
}

/// Case 4, the fix for tiny triangles: scale each edge by its largest
/// component before the cross product, so no product underflows.
///
/// ```text
/// e1 = (b − a) / max|b − a|,  e2 = (c − a) / max|c − a|,  n = normalize(e1 × e2)
/// ```
///
/// The direction is unchanged (positive scale factors). `None` for a
/// zero-area, collinear or non-finite triangle (then
/// [`triangle_normal_or_zero`]'s zero vector is the shading fallback).
pub fn robust_triangle_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    let scaled = |e: Vec3| {
        let m = e.abs().max_element();
        (m > 0.0 && m.is_finite()).then(|| e / m)
    };
    scaled(b - a)?.cross(scaled(c - a)?).try_normalize()
}

/// Case 4: a right triangle with legs `size` at the origin in the xy plane.
pub fn tiny_triangle(size: f32) -> [Vec3; 3] {
    [Vec3::ZERO, Vec3::new(size, 0.0, 0.0), Vec3::new(0.0, size, 0.0)]
}

/// Case 4: the largest `k` in 0 … 45 for which the method still gives a unit
/// normal (within 1e-3) for a [`tiny_triangle`] of legs `10^-k`.
pub fn case4_smallest_exponent(method: fn(Vec3, Vec3, Vec3) -> Option<Vec3>) -> i32 {
    (0..=45)
        .take_while(|&k| {
            let [a, b, c] = tiny_triangle(10f32.powi(-k));
            method(a, b, c).is_some_and(|n| (n.length() - 1.0).abs() < 1e-3)
        })
        .last()
        .unwrap_or(-1)
}

fn naive_some(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    Some(naive_triangle_normal(a, b, c))
}

/// Case 4 figure: normal length from each method against triangle size 10^-k
/// (left out where NaN).
pub fn case4_figure() -> Figure {
    let length = |f: fn(Vec3, Vec3, Vec3) -> Option<Vec3>| {
        move |k: f32| {
            let [a, b, c] = tiny_triangle(10f32.powf(-k));
            f(a, b, c).map_or(0.0, |n| n.length())
        }
    };
    let series = vec![
        Series::from_fn("normalize(cross)", linspace(0.0, 45.0, 45), length(naive_some)),
        Series::from_fn(
            "try_normalize (zero fallback)",
            linspace(0.0, 45.0, 45),
            length(|a, b, c| Some(triangle_normal_or_zero(a, b, c))),
        ),
        Series::from_fn("pre-scaled edges", linspace(0.0, 45.0, 45), length(robust_triangle_normal)),
    ];
    Figure::new("Normals of tiny triangles", "leg length exponent k (legs 10^-k)", "length of the normal", series)
}

fn case4_measure() -> (String, String) {
    let zero = naive_triangle_normal(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO);
    (
        format!(
            "zero-area triangle: normal {zero}; naive unit normal down to legs 1e-{} only",
            case4_smallest_exponent(naive_some)
        ),
        format!(
            "normalize_or_zero: {} (ambient only); pre-scaled edges: unit normal down to legs 1e-{}",
            triangle_normal_or_zero(Vec3::ZERO, Vec3::ZERO, Vec3::ZERO),
            case4_smallest_exponent(robust_triangle_normal)
        ),
    )
}

// ---------------------------------------------------------------- case 5

/// Case 5: the largest angle error over normals in the xz plane when normals
/// go through `model = diag(ratio, 1, 1)` instead of the normal matrix.
///
/// ```text
/// error(θ) = angle(normalize(M n), normalize(M^-T n)),  n = (cos θ, 0, sin θ)
/// max over θ ∈ [0°, 90°] in 0.25° steps   ( = 2·atan(ratio) − 90° for ratio ≥ 1 )
/// ```
///
/// Uses [`model_matrix_normal_error_deg`]. Ratio ≤ 0 or non-finite gives NaN.
pub fn case5_max_angle_error_deg(ratio: f32) -> f32 {
    if !(ratio > 0.0 && ratio.is_finite()) {
        return f32::NAN;
    }
    let model = Mat3::from_diagonal(Vec3::new(ratio, 1.0, 1.0));
    (0..=360)
        .filter_map(|i| model_matrix_normal_error_deg(model, direction_from_angles(90.0 - i as f32 * 0.25, 0.0)))
        .fold(0.0, f32::max)
}

/// Case 5, the fix measured: the angle (degrees) between the cofactor-transformed
/// normal and the normal of the transformed tangent plane computed in `f64`.
///
/// ```text
/// t1, t2 ⟂ n (f64);  exact = normalize((M t1) × (M t2))
/// error = angle(normalize(cof(M) n), exact)     as atan2(|a × b|, a · b), accurate near 0
/// ```
///
/// `None` for a zero or non-finite result.
pub fn cofactor_normal_error_deg(model: Mat3, n: Vec3) -> Option<f64> {
    let m = DMat3::from_cols(model.x_axis.as_dvec3(), model.y_axis.as_dvec3(), model.z_axis.as_dvec3());
    let nd = n.as_dvec3().try_normalize()?;
    let t1 = nd.any_orthonormal_vector();
    let t2 = nd.cross(t1);
    let exact = ((m * t1).cross(m * t2)).try_normalize()?;
    let ours = (normal_matrix_cofactor(model) * n).try_normalize()?.as_dvec3();
    Some(ours.cross(exact).length().atan2(ours.dot(exact)).to_degrees())
}

/// Case 5 figure: the largest angle error against the scale ratio, model
/// matrix against cofactor.
pub fn case5_figure() -> Figure {
    let cof = |r: f32| {
        let model = Mat3::from_diagonal(Vec3::new(r, 1.0, 1.0));
        (0..=90)
            .filter_map(|i| cofactor_normal_error_deg(model, direction_from_angles(90.0 - i as f32, 0.0)))
            .fold(0.0, f64::max) as f32
    };
    let series = vec![
        Series::from_fn("mat3(model) · n", linspace(1.0, 16.0, 30), case5_max_angle_error_deg),
        Series::from_fn("cofactor · n", linspace(1.0, 16.0, 30), cof),
    ];
    Figure::new("Normals under non-uniform scale diag(r, 1, 1)", "scale ratio r", "largest angle error (°)", series)
}

fn case5_measure() -> (String, String) {
    let model = Mat3::from_diagonal(Vec3::new(2.0, 1.0, 1.0));
    let fixed = (0..=90)
        .filter_map(|i| cofactor_normal_error_deg(model, direction_from_angles(90.0 - i as f32, 0.0)))
        .fold(0.0, f64::max);
    (
        format!(
            "scale (2, 1, 1): up to {:.2}°; (4, 1, 1): {:.2}°",
            case5_max_angle_error_deg(2.0),
            case5_max_angle_error_deg(4.0)
        ),
        format!("cofactor at (2, 1, 1): {fixed:.1e}°"),
    )
}

// ---------------------------------------------------------------- case 6

/// Case 6: LearnOpenGL's cube rotation (50° about (1, 0.3, 0.5)) times `scale`.
pub fn case6_model(scale: Vec3) -> Mat3 {
    Mat3::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50.0f32.to_radians()) * Mat3::from_diagonal(scale)
}

/// The three ways case 6 compares of sending a normal through a model matrix.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalMatrixMethod {
    /// `transpose(inverse(M))`, then normalize.
    InverseTranspose,
    /// The cofactor matrix, then normalize.
    Cofactor,
    /// The cofactor of `M / max|M_ij|`, then normalize (same direction).
    ScaledCofactor,
}

/// Case 6: the unit normal by one method, or `None` if it is not finite and unit.
///
/// ```text
/// InverseTranspose: normalize(transpose(inverse(M)) n)
/// Cofactor:         normalize(cof(M) n)
/// ScaledCofactor:   normalize(cof(M / max_ij |M_ij|) n)
/// ```
pub fn transformed_normal(method: NormalMatrixMethod, model: Mat3, n: Vec3) -> Option<Vec3> {
    let matrix = match method {
        NormalMatrixMethod::InverseTranspose => normal_matrix_inverse_transpose(model)?,
        NormalMatrixMethod::Cofactor => normal_matrix_cofactor(model),
        NormalMatrixMethod::ScaledCofactor => {
            let m = model.abs().to_cols_array().into_iter().fold(0.0, f32::max);
            if !(m > 0.0 && m.is_finite()) {
                return None;
            }
            normal_matrix_cofactor(model * (1.0 / m))
        }
    };
    (matrix * n).try_normalize().filter(|v| (v.length() - 1.0).abs() < 1e-4)
}

/// Case 6: the first `k` in 0 … 149 for which `method` fails on the scale `family(2^-k)`.
///
/// Returns `None` if it never fails in that range.
pub fn case6_first_failure(method: NormalMatrixMethod, family: fn(f32) -> Vec3) -> Option<i32> {
    let n = Vec3::new(0.3, 0.4, 0.866).normalize();
    (0..=149).find(|&k| transformed_normal(method, case6_model(family(2f32.powi(-k))), n).is_none())
}

/// Case 6's flattening family: scale `(1, 1, s)`.
pub fn flatten(s: f32) -> Vec3 {
    Vec3::new(1.0, 1.0, s)
}

/// Case 6's shrinking family: uniform scale `s` (an object scaled to 0 to hide it).
pub fn shrink(s: f32) -> Vec3 {
    Vec3::splat(s)
}

/// Case 6 figure: log2 of the largest entry of each normal matrix against the
/// flattening exponent k (scale z = 2^-k); left out where not finite or zero.
pub fn case6_figure() -> Figure {
    let largest = |m: Mat3| {
        let v = m.abs().to_cols_array().into_iter().fold(0.0, f32::max);
        if v > 0.0 && v.is_finite() {
            v.log2()
        } else {
            f32::NAN
        }
    };
    let xs = || linspace(0.0, 140.0, 70);
    let series = vec![
        Series::from_fn("inverse-transpose", xs(), move |k| {
            normal_matrix_inverse_transpose(case6_model(flatten(2f32.powf(-k)))).map_or(f32::NAN, largest)
        }),
        Series::from_fn("cofactor", xs(), move |k| {
            largest(normal_matrix_cofactor(case6_model(flatten(2f32.powf(-k)))))
        }),
    ];
    Figure::new("Normal matrix of a flattening scale (1, 1, 2^-k)", "k", "log2 of the largest entry", series)
}

fn case6_measure() -> (String, String) {
    use NormalMatrixMethod::*;
    let show = |m, f| case6_first_failure(m, f).map_or("never".to_string(), |k| format!("2^-{k}"));
    (
        format!(
            "flatten (1,1,s): inverse-transpose fails at s = {}; uniform s: fails at {}",
            show(InverseTranspose, flatten),
            show(InverseTranspose, shrink)
        ),
        format!(
            "cofactor: flatten {}, uniform {}; pre-scaled cofactor: flatten {}, uniform {}",
            show(Cofactor, flatten),
            show(Cofactor, shrink),
            show(ScaledCofactor, flatten),
            show(ScaledCofactor, shrink)
        ),
    )
}

// ---------------------------------------------------------------- case 7

/// Case 7: two unit normals `span_deg` apart, interpolated linearly.
///
/// ```text
/// n0 = (−sin(span/2), 0, cos(span/2)),  n1 = (sin(span/2), 0, cos(span/2))
/// n(t) = lerp(n0, n1, t)        |n(0.5)| = cos(span/2)
/// ```
pub fn lerp_normal(span_deg: f32, t: f32) -> Vec3 {
    let half = 0.5 * span_deg;
    direction_from_angles(half, 180.0).lerp(direction_from_angles(half, 0.0), t)
}

/// Case 7: the diffuse darkening from not normalizing, light along the
/// interpolated normal's direction (the worst case).
///
/// ```text
/// darkening = max(normalize(n)·l, 0) − max(n·l, 0) = 1 − |n(t)|,  l = normalize(n(t))
/// ```
pub fn case7_darkening(span_deg: f32, t: f32) -> f32 {
    let n = lerp_normal(span_deg, t);
    let l = n.normalize_or_zero();
    l.dot(l).max(0.0) - n.dot(l).max(0.0)
}

/// Case 7, the fix measured: `1 − max(normalize(n)·l, 0)`, 0 up to rounding.
pub fn case7_darkening_fixed(span_deg: f32, t: f32) -> f32 {
    let n = lerp_normal(span_deg, t).normalize_or_zero();
    1.0 - n.dot(n).max(0.0)
}

/// Case 7: darkening at the centroid of a triangle with vertex normals `n`:
/// `1 − |(n0 + n1 + n2)/3|`.
pub fn case7_centroid_darkening(n: [Vec3; 3]) -> f32 {
    1.0 - ((n[0] + n[1] + n[2]) / 3.0).length()
}

/// Case 7 figure: darkening in 8-bit levels against t for spans 22.5°, 45°, 90°.
pub fn case7_figure() -> Figure {
    let series = [22.5, 45.0, 90.0]
        .into_iter()
        .map(|s| Series::from_fn(format!("span {s}°"), linspace(0.0, 1.0, 40), move |t| case7_darkening(s, t) * 255.0))
        .collect();
    Figure::new("Unnormalized interpolated normals", "t", "darkening (8-bit levels)", series)
}

fn case7_measure() -> (String, String) {
    use crate::study::advisor::TESSELLATIONS;
    let (stacks, _) = TESSELLATIONS[0];
    let span = 180.0 / stacks as f32;
    (
        format!(
            "8×16 sphere edge ({span}° span): {:.1} levels dark at the centre; 90° span: {:.0} levels",
            case7_darkening(span, 0.5) * 255.0,
            case7_darkening(90.0, 0.5) * 255.0
        ),
        format!("normalized: {:.1e} levels", case7_darkening_fixed(90.0, 0.5) * 255.0),
    )
}

// ---------------------------------------------------------------- case 8

/// Case 8, Mach bands: the jump in the slope of a Gouraud-shaded diffuse
/// gradient at a vertex, in 8-bit levels per degree.
///
/// ```text
/// vertices at normal angles a − Δ, a, a + Δ from the light;  c(x) = cos x
/// jump = |(c(a+Δ) − c(a))/Δ − (c(a) − c(a−Δ))/Δ| · 255
/// ```
///
/// Per-fragment shading has a continuous slope (jump 0); the eye amplifies
/// slope discontinuities into bright and dark bands. Angles in degrees.
pub fn case8_mach_slope_jump(a_deg: f32, span_deg: f32) -> f32 {
    let c = |x: f32| x.to_radians().cos().max(0.0);
    let right = (c(a_deg + span_deg) - c(a_deg)) / span_deg;
    let left = (c(a_deg) - c(a_deg - span_deg)) / span_deg;
    (right - left).abs() * 255.0
}

/// Case 8 figure: Gouraud's worst error (levels) against the edge's normal
/// span for s = 8, 32, 128 (DESIGN's material: diffuse 1, specular 0.5).
pub fn case8_figure() -> Figure {
    let series = [8.0, 32.0, 128.0]
        .into_iter()
        .map(|s| {
            Series::from_fn(format!("s = {s}"), linspace(0.0, 30.0, 30), move |span| {
                gouraud_edge_error(1.0, 0.5, s, span) * 255.0
            })
        })
        .collect();
    Figure::new("Gouraud error across one edge", "normal span of the edge (°)", "worst error (8-bit levels)", series)
}

fn case8_measure() -> (String, String) {
    let span = 22.5;
    let lost = gouraud_edge_error(1.0, 0.5, 32.0, span);
    let ok = max_span_for_budget(1.0, 0.5, 32.0, ONE_LEVEL);
    (
        format!(
            "22.5° edge, s = 32: {:.0} levels of highlight lost; Mach slope jump {:.2} levels/° at 45°",
            lost * 255.0,
            case8_mach_slope_jump(45.0, span)
        ),
        format!(
            "per-fragment: 0; Gouraud within 1 level needs spans ≤ {ok:.2}° (error {:.2} levels)",
            gouraud_edge_error(1.0, 0.5, 32.0, ok) * 255.0
        ),
    )
}

// ---------------------------------------------------------------- case 9

/// Case 9, the failure: the soft-edge formula with no guard on ε.
///
/// ```text
/// epsilon = cut_off − outer_cut_off;  intensity = clamp((theta − outer_cut_off) / epsilon, 0, 1)
/// ```
///
/// ε = 0 divides by zero (±∞, or NaN at `theta == outer_cut_off`, where GLSL's
/// clamp is undefined; Rust's gives 0). ε < 0 (inner > outer) inverts the
/// spot: dark inside, lit outside.
///
/// Source: LearnOpenGL, Light casters.
pub fn naive_spot_intensity(theta: f32, cut_off: f32, outer_cut_off: f32) -> f32 {
    let epsilon = cut_off - outer_cut_off;
    saturate((theta - outer_cut_off) / epsilon)
}

/// The raw ratio `(theta − outer_cut_off) / epsilon` before the clamp (case 9).
pub fn naive_spot_ratio(theta: f32, cut_off: f32, outer_cut_off: f32) -> f32 {
    (theta - outer_cut_off) / (cut_off - outer_cut_off)
}

/// How case 9 evaluates a spot's soft edge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EdgeForm {
    /// LearnOpenGL's ramp in cosines: `(cos α − cos γ) / (cos φ − cos γ)`.
    Cosine,
    /// The ramp in sines: `(sin γ − sin α) / (sin γ − sin φ)`, better
    /// conditioned near small angles (`d sin/dα = cos α ≈ 1`).
    Sine,
}

/// Case 9: a spot at the origin pointing −z lights the plane z = −5; the
/// fragment at `(x, 0, −5)`. The intensity by `form` in `f32`, as a shader does.
///
/// ```text
/// light_dir = normalize(−frag);  Cosine: theta = light_dir · (0, 0, 1)
/// Sine: sin α = |light_dir × (0, 0, 1)|;  cones from degrees in f32
/// ```
pub fn spot_edge_f32(form: EdgeForm, x: f32, inner_deg: f32, outer_deg: f32) -> f32 {
    let light_dir = (-Vec3::new(x, 0.0, -5.0)).normalize_or_zero();
    let (inner, outer) = (inner_deg.to_radians(), outer_deg.to_radians());
    match form {
        EdgeForm::Cosine => spot_intensity(light_dir.dot(Vec3::Z), inner.cos(), outer.cos()),
        EdgeForm::Sine => {
            let sin_a = light_dir.cross(Vec3::Z).length();
            let width = outer.sin() - inner.sin();
            if width > 0.0 {
                saturate((outer.sin() - sin_a) / width)
            } else {
                crate::casters::hard_spot(outer.sin(), sin_a)
            }
        }
    }
}

/// Case 9: the same intensity in `f64`, from the exact angle `atan(|x| / 5)`.
pub fn spot_edge_f64(form: EdgeForm, x: f32, inner_deg: f32, outer_deg: f32) -> f64 {
    let alpha = (x as f64).abs().atan2(5.0);
    let (inner, outer) = ((inner_deg as f64).to_radians(), (outer_deg as f64).to_radians());
    let ratio = match form {
        EdgeForm::Cosine => (alpha.cos() - outer.cos()) / (inner.cos() - outer.cos()),
        EdgeForm::Sine => (outer.sin() - alpha.sin()) / (outer.sin() - inner.sin()),
    };
    ratio.clamp(0.0, 1.0)
}

/// Case 9: the largest `|f32 − f64|` intensity across an edge from 12.5° to
/// 12.5° + `width_deg`, sampled at 401 angles over [inner − width, outer + width].
pub fn case9_max_error(form: EdgeForm, width_deg: f32) -> f32 {
    let inner = 12.5f32;
    let outer = inner + width_deg;
    (0..=400)
        .map(|i| {
            let a = (inner as f64 - width_deg as f64) + 3.0 * width_deg as f64 * i as f64 / 400.0;
            let x = (5.0 * a.to_radians().tan()) as f32;
            (spot_edge_f32(form, x, inner, outer) as f64 - spot_edge_f64(form, x, inner, outer)).abs() as f32
        })
        .fold(0.0, f32::max)
}

/// Case 9: the narrowest edge width (degrees, scanned as 10^-(k/20)) whose
/// f32 error stays within one level.
pub fn case9_narrowest_edge_deg(form: EdgeForm) -> f32 {
    (0..=120)
        .map(|k| 10f32.powf(-(k as f32) / 20.0))
        .take_while(|&w| case9_max_error(form, w) <= ONE_LEVEL)
        .fold(f32::NAN, |_, w| w)
}

/// Case 9 figure: f32 error (levels) against the edge width, cosine and sine forms.
pub fn case9_figure() -> Figure {
    let series = [EdgeForm::Cosine, EdgeForm::Sine]
        .into_iter()
        .map(|f| {
            Series::from_fn(format!("{f:?} ramp"), linspace(0.0, 5.0, 50), move |k| {
                case9_max_error(f, 10f32.powf(-k)) * 255.0
            })
        })
        .collect();
    Figure::new(
        "Spot soft edge in f32 (inner 12.5°)",
        "edge width exponent k (width 10^-k °)",
        "max error (8-bit levels)",
        series,
    )
}

fn case9_measure() -> (String, String) {
    let (c15, c12) = (15.0f32.to_radians().cos(), 12.5f32.to_radians().cos());
    let on_axis = naive_spot_intensity(1.0, c15, c12);
    let at_edge = naive_spot_ratio(c12, c12, c12);
    let props = LightProps::white();
    let rejected = SpotLight::new(Vec3::ZERO, Vec3::NEG_Z, 15.0, 12.5, Attenuation::LEARNOPENGL, props).is_err();
    (
        format!(
            "inner 15° > outer 12.5°: on-axis intensity {on_axis}; ε = 0 at the edge: ratio {at_edge}; 0.002° edge: f32 error {:.1} levels",
            case9_max_error(EdgeForm::Cosine, 0.002) * 255.0
        ),
        format!(
            "inverted cone rejected: {rejected}; ε = 0: hard edge {}; sine ramp at 0.002°: {:.2} levels; narrowest 1-level edge {:.2e}° (cos) vs {:.2e}° (sin)",
            spot_intensity(c12, c12, c12),
            case9_max_error(EdgeForm::Sine, 0.002) * 255.0,
            case9_narrowest_edge_deg(EdgeForm::Cosine),
            case9_narrowest_edge_deg(EdgeForm::Sine)
        ),
    )
}

// ---------------------------------------------------------------- case 10

/// Case 10, the fix for `Kc < 1`: attenuation clamped to 1 (never brighter
/// than the source). NaN distance gives NaN.
pub fn attenuation_clamped(attenuation: &Attenuation, distance: f32) -> f32 {
    let a = attenuation.at(distance);
    if a.is_nan() {
        a
    } else {
        a.min(1.0)
    }
}

/// Case 10, the fix for `1/d²`: distances below the light's radius count as the radius.
///
/// ```text
/// falloff = light_power / max(d, radius)²
/// ```
///
/// Bounded by `light_power / radius²`. `radius ≤ 0` or non-finite falls back
/// to the unbounded [`crate::casters::inverse_square_falloff`].
pub fn inverse_square_with_radius(light_power: f32, distance: f32, radius: f32) -> f32 {
    if radius > 0.0 && radius.is_finite() {
        let d = distance.max(radius);
        light_power / (d * d)
    } else {
        crate::casters::inverse_square_falloff(light_power, distance)
    }
}

/// Case 10 figure: attenuation against distance for Kc = 1, 0.5, 0.1
/// (Kl = 0.09, Kq = 0.032) and opengl-tutorial's 1/d² (power 1).
pub fn case10_figure() -> Figure {
    let mut series: Vec<Series> = [1.0, 0.5, 0.1]
        .into_iter()
        .map(|kc| {
            let a = Attenuation { constant: kc, ..Attenuation::LEARNOPENGL };
            Series::from_fn(format!("Kc = {kc}"), linspace(0.0, 5.0, 50), move |d| a.at(d))
        })
        .collect();
    series.push(Series::from_fn("1/d²", linspace(0.0, 5.0, 50), |d| crate::casters::inverse_square_falloff(1.0, d)));
    Figure::new("Attenuation near the light", "distance", "attenuation", series)
}

fn case10_measure() -> (String, String) {
    let a = Attenuation { constant: 0.1, ..Attenuation::LEARNOPENGL };
    let power = 50.0;
    (
        format!(
            "Kc = 0.1: {:.1}× the source at d = 0; opengl-tutorial power 50: {:.0} at d = 0.1, {} at d = 0",
            a.at(0.0),
            crate::casters::inverse_square_falloff(power, 0.1),
            crate::casters::inverse_square_falloff(power, 0.0)
        ),
        format!(
            "clamped: {}; radius 0.5: at most {}",
            attenuation_clamped(&a, 0.0),
            inverse_square_with_radius(power, 0.0, 0.5)
        ),
    )
}

// ---------------------------------------------------------------- case 11

/// The unit direction case 11 moves the scene along (a generic direction, so
/// all three coordinates grow).
pub fn case11_offset_direction() -> DVec3 {
    DVec3::new(1.0, 0.5, 0.25).normalize()
}

fn basic_lighting_f64(frag_pos: DVec3, normal: DVec3, light_pos: DVec3, view_pos: DVec3) -> DVec3 {
    let s = BasicLighting::learnopengl();
    let norm = normal.normalize();
    let light_dir = (light_pos - frag_pos).normalize();
    let view_dir = (view_pos - frag_pos).normalize();
    let diff = norm.dot(light_dir).max(0.0);
    let reflect_dir = -light_dir - 2.0 * norm.dot(-light_dir) * norm;
    let spec = view_dir.dot(reflect_dir).max(0.0).powf(s.shininess as f64);
    let k = s.ambient_strength as f64 + diff + s.specular_strength as f64 * spec;
    k * (s.light_color * s.object_color).as_dvec3()
}

/// The quad-single fragment at grid cell `(i, j)` of 11×11 over NDC [−1, 1]²:
/// `FragPos = (x·4/3, y, 0)`, `Normal = (x/2, y/2, 1)` (DESIGN).
pub fn quad_fragment(i: u32, j: u32) -> (DVec3, DVec3) {
    let x = -1.0 + 2.0 * (i.min(10) as f64) / 10.0;
    let y = -1.0 + 2.0 * (j.min(10) as f64) / 10.0;
    (DVec3::new(x * 4.0 / 3.0, y, 0.0), DVec3::new(x / 2.0, y / 2.0, 1.0))
}

/// Where case 11 does its `f32` arithmetic.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case11Space {
    /// World-space positions in `f32` (LearnOpenGL's shader).
    World,
    /// World-space positions in `f32`, moved to view space by an `f32` view
    /// matrix ([`BasicLighting::terms_in_view_space`]): the positions are
    /// rounded before the matrix sees them, so this does not help.
    ViewMatrix,
    /// Positions relative to the camera, the differences taken in `f64` on
    /// the CPU before anything becomes `f32`.
    CameraRelative,
}

/// Case 11: the `f32` error (in 8-bit levels, largest channel) of LearnOpenGL's
/// basic-lighting shader at quad fragment `(i, j)` when the whole scene sits
/// `distance` units from the origin.
///
/// ```text
/// O = distance · (1, 0.5, 0.25)/|…|;   exact = f64 shading of the scene at the origin
/// World:          f32(O + frag), f32(O + light), f32(O + eye)  →  BasicLighting::terms
/// ViewMatrix:     the same f32 positions, view = translate(−f32(O + eye)) → terms_in_view_space
/// CameraRelative: f32(frag − eye), f32(light − eye), eye = 0   (differences in f64)
/// ```
///
/// Colors unclamped. Source: LearnOpenGL, Basic lighting; DESIGN's quad-single.
pub fn case11_error_levels(distance: f64, i: u32, j: u32, space: Case11Space) -> f32 {
    let s = BasicLighting::learnopengl();
    let (frag, normal) = quad_fragment(i, j);
    let (light, eye) = (s.light_pos.as_dvec3(), s.view_pos.as_dvec3());
    let exact = basic_lighting_f64(frag, normal, light, eye);
    let origin = match space {
        Case11Space::CameraRelative => eye,
        _ => -distance * case11_offset_direction(),
    };
    let place = |p: DVec3| (p - origin).as_vec3();
    let shader = BasicLighting { light_pos: place(light), view_pos: place(eye), ..s };
    let got = match space {
        Case11Space::ViewMatrix => {
            let view = Mat4::from_translation(-place(eye));
            shader.terms_in_view_space(view, place(frag), normal.as_vec3())
        }
        _ => shader.terms(place(frag), normal.as_vec3()),
    }
    .sum();
    ((got.as_dvec3() - exact).abs().max_element() * 255.0) as f32
}

/// Case 11: the largest error over the 11×11 quad grid.
pub fn case11_max_error_levels(distance: f64, space: Case11Space) -> f32 {
    (0..=10).flat_map(|i| (0..=10).map(move |j| case11_error_levels(distance, i, j, space))).fold(0.0, f32::max)
}

/// Case 11 figure: largest error (levels) against log10(distance) from 10^0 to
/// 10^6 for the three spaces.
pub fn case11_figure() -> Figure {
    let series = [
        (Case11Space::World, "world space"),
        (Case11Space::ViewMatrix, "f32 view matrix"),
        (Case11Space::CameraRelative, "camera-relative"),
    ]
    .into_iter()
    .map(|(space, label)| {
        Series::from_fn(label, linspace(0.0, 6.0, 24), move |k| case11_max_error_levels(10f64.powf(k as f64), space))
    })
    .collect();
    Figure::new("f32 lighting far from the origin", "log10(distance from origin)", "max error (8-bit levels)", series)
}

fn case11_measure() -> (String, String) {
    let w = |k: i32| case11_max_error_levels(10f64.powi(k), Case11Space::World);
    (
        format!(
            "world space: {:.2} levels at 10^3, {:.2} at 10^4, {:.2} at 10^5, {:.2} at 10^6; f32 view matrix: {:.2} at 10^6",
            w(3),
            w(4),
            w(5),
            w(6),
            case11_max_error_levels(1e6, Case11Space::ViewMatrix)
        ),
        format!("camera-relative: {:.1e} levels at 10^6", case11_max_error_levels(1e6, Case11Space::CameraRelative)),
    )
}

// ---------------------------------------------------------------- case 12

/// How an unclamped color is brought into [0, 1] for output (case 12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClampStrategy {
    /// `clamp(c, 0, 1)` per channel: what an RGBA8 framebuffer does.
    PerChannel,
    /// Negative channels to 0, then divide by the largest channel if it exceeds 1.
    /// Keeps the ratios between channels, so the hue.
    ScaleByMax,
}

impl ClampStrategy {
    /// Apply the strategy. NaN channels become 0 first.
    ///
    /// ```text
    /// PerChannel: min(max(c, 0), 1)
    /// ScaleByMax: c' = max(c, 0); c' / max(1, max(c'))
    /// ```
    pub fn apply(self, c: Vec3) -> Vec3 {
        let c = Vec3::new(saturate_low(c.x), saturate_low(c.y), saturate_low(c.z));
        match self {
            ClampStrategy::PerChannel => c.min(Vec3::ONE),
            ClampStrategy::ScaleByMax => c / c.max_element().max(1.0),
        }
    }
}

fn saturate_low(x: f32) -> f32 {
    x.max(0.0)
}

/// The HSV hue of a non-negative color, degrees in [0, 360); `None` for a
/// grey (no hue) or non-finite color.
///
/// ```text
/// max = R: 60·((G − B)/(max − min) mod 6);  max = G: 60·((B − R)/(max − min) + 2);
/// max = B: 60·((R − G)/(max − min) + 4)
/// ```
pub fn hue_deg(c: Vec3) -> Option<f32> {
    let (max, min) = (c.max_element(), c.min_element());
    let chroma = max - min;
    if !(chroma > 0.0 && c.is_finite()) {
        return None;
    }
    let h = if max == c.x {
        ((c.y - c.z) / chroma).rem_euclid(6.0)
    } else if max == c.y {
        (c.z - c.x) / chroma + 2.0
    } else {
        (c.x - c.y) / chroma + 4.0
    };
    Some(60.0 * h)
}

/// The circular difference of two hues in degrees, in [0, 180]; `None` if
/// either color is grey.
pub fn hue_shift_deg(a: Vec3, b: Vec3) -> Option<f32> {
    let d = (hue_deg(a)? - hue_deg(b)?).rem_euclid(360.0);
    Some(d.min(360.0 - d))
}

/// Case 12: the hue shift of `lights` equal contributions `each` after `strategy`.
///
/// ```text
/// shift = hue_shift(strategy(lights · each), each)
/// ```
///
/// 0 when the sum stays below 1; `None` for a grey `each`.
pub fn case12_hue_shift(lights: u32, each: Vec3, strategy: ClampStrategy) -> Option<f32> {
    hue_shift_deg(strategy.apply(lights as f32 * each), each)
}

/// Case 12's contribution per light: coral lit at 0.3 (`0.3 · (1, 0.5, 0.31)`).
pub fn case12_contribution() -> Vec3 {
    0.3 * crate::color::CORAL
}

/// Case 12 figure: hue shift against the number of lights, both strategies.
pub fn case12_figure() -> Figure {
    let series = [ClampStrategy::PerChannel, ClampStrategy::ScaleByMax]
        .into_iter()
        .map(|st| {
            Series::from_fn(format!("{st:?}"), linspace(1.0, 16.0, 15), move |n| {
                case12_hue_shift(n as u32, case12_contribution(), st).unwrap_or(f32::NAN)
            })
        })
        .collect();
    Figure::new("Hue shift of coral under N lights of 0.3", "lights", "hue shift (°)", series)
}

fn case12_measure() -> (String, String) {
    let s = |n, st| case12_hue_shift(n, case12_contribution(), st).unwrap_or(f32::NAN);
    (
        format!(
            "coral × 0.3 per light: hue shift {:.1}° at 4 lights, {:.1}° at 8 (toward yellow)",
            s(4, ClampStrategy::PerChannel),
            s(8, ClampStrategy::PerChannel)
        ),
        format!("scale by max: {:.1e}° at 8 lights", s(8, ClampStrategy::ScaleByMax)),
    )
}

// ---------------------------------------------------------------- case 13

/// Case 13: a directional light `vec4(direction, 0)` taken to clip space and
/// back, as a deferred or clustered renderer does when it unprojects.
///
/// ```text
/// PV = perspective(45°, 4/3, 0.1, 100) · look_at(eye, 0, +y)
/// result = inverse(PV) · (PV · vec4(direction, 0))
/// ```
///
/// In exact arithmetic `w` stays 0; in `f32` it comes back as a few 1e-7.
/// `eye` must differ from the origin and not lie on the y axis (look_at's
/// precondition); otherwise the result is not finite.
pub fn unproject_round_trip(eye: Vec3, direction: Vec3) -> Vec4 {
    let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y);
    let proj = glam::camera::rh::proj::opengl::perspective(45f32.to_radians(), 4.0 / 3.0, 0.1, 100.0);
    let pv: Mat4 = proj * view;
    pv.inverse() * (pv * direction.extend(0.0))
}

/// Case 13, the failure: LearnOpenGL's exact test `lightVector.w == 0.0`.
pub fn is_directional_exact(v: Vec4) -> bool {
    v.w == 0.0
}

/// Case 13, the fix's tolerance for unit-length directions: `1e-4`.
///
/// More than 100× the largest `|w|` the round trip produces over
/// [`case13_grid`] (7.2e-7, checked by the tests), and 1e-4 of a positional
/// light's `w = 1`: a point light would have to sit 10^4 units away (in
/// homogeneous form with `|xyz| = 1`) to be taken for a direction.
pub const W_TOLERANCE: f32 = 1e-4;

/// Case 13, the fix: [`classify_light_vector`] with a tolerance relative to `|xyz|`.
///
/// ```text
/// |w| <= W_TOLERANCE · |xyz|  →  Direction
/// ```
pub fn is_directional_tolerant(v: Vec4) -> bool {
    matches!(classify_light_vector(v, W_TOLERANCE * v.truncate().length()), Some(LightVector::Direction(_)))
}

/// Case 13's grid: eyes at integer (x, y) in [−3, 3]², z = 5, and light
/// directions (dx, dy, −1) with integer dx, dy in [−2, 2].
pub fn case13_grid() -> impl Iterator<Item = (Vec3, Vec3)> {
    (-3..=3).flat_map(|ex| {
        (-3..=3).flat_map(move |ey| {
            (-2..=2).flat_map(move |dx| {
                (-2..=2).map(move |dy| {
                    (Vec3::new(ex as f32, ey as f32, 5.0), Vec3::new(dx as f32, dy as f32, -1.0).normalize())
                })
            })
        })
    })
}

/// Case 13 figure: the |w| of each round trip on the grid (index on x), on a log10 scale.
pub fn case13_figure() -> Figure {
    let points = case13_grid()
        .enumerate()
        .map(|(i, (eye, d))| (i as f32, unproject_round_trip(eye, d).w.abs().log10()))
        .filter(|(_, y)| y.is_finite())
        .collect();
    Figure::new(
        "w after an unproject round trip (w = 0 left out)",
        "grid case",
        "log10 |w|",
        vec![Series { label: "|w|".into(), points }],
    )
}

fn case13_measure() -> (String, String) {
    let results: Vec<Vec4> = case13_grid().map(|(e, d)| unproject_round_trip(e, d)).collect();
    let misread = results.iter().filter(|v| !is_directional_exact(**v)).count();
    let max_w = results.iter().map(|v| v.w.abs()).fold(0.0, f32::max);
    let fixed = results.iter().filter(|v| !is_directional_tolerant(**v)).count();
    let nearest =
        results.iter().filter(|v| v.w != 0.0).map(|v| (v.truncate() / v.w).length()).fold(f32::INFINITY, f32::min);
    (
        format!(
            "{misread}/{} unprojected directions fail w == 0 (|w| up to {max_w:.1e}); read as point lights ≥ {nearest:.1e} away, attenuation {:.1e}",
            results.len(),
            Attenuation::LEARNOPENGL.at(nearest)
        ),
        format!("tolerance {W_TOLERANCE}·|xyz|: {fixed} misread"),
    )
}

// ---------------------------------------------------------------- case 14

/// Case 14: light at `light_elevation_deg` above the surface (+x side) and the
/// eye at signed `view_angle_deg` from the normal, both in the xz plane
/// (negative: on the light's side). Returns `(n, light_dir, view_dir)`.
pub fn case14_vectors(light_elevation_deg: f32, view_angle_deg: f32) -> (Vec3, Vec3, Vec3) {
    let light_dir = direction_from_angles(90.0 - light_elevation_deg, 0.0);
    let view_dir = direction_from_angles(view_angle_deg, 180.0);
    (Vec3::Z, light_dir, view_dir)
}

/// Case 14: Phong's specular and Blinn-Phong's with the rule-of-thumb
/// exponent `4s`, at one in-plane view. Returns `(phong, blinn)`.
pub fn case14_specular(light_elevation_deg: f32, view_angle_deg: f32, shininess: f32) -> (f32, f32) {
    let (n, l, v) = case14_vectors(light_elevation_deg, view_angle_deg);
    (phong_specular_factor(n, l, v, shininess), blinn_specular_factor(n, l, v, blinn_exponent_rule_of_thumb(shininess)))
}

/// Case 14: the share of in-plane views (−89.5° … 89.5° in 0.5° steps) where
/// Phong is cut to 0 while Blinn(4s) still shows at least one level, and the
/// largest Blinn value there. Returns `(share, max_blinn)`.
pub fn case14_cut_region(light_elevation_deg: f32, shininess: f32) -> (f32, f32) {
    let views: Vec<f32> = (-179..=179).map(|i| i as f32 * 0.5).collect();
    let cut: Vec<f32> = views
        .iter()
        .map(|&a| case14_specular(light_elevation_deg, a, shininess))
        .filter(|&(p, b)| p == 0.0 && b >= ONE_LEVEL)
        .map(|(_, b)| b)
        .collect();
    (cut.len() as f32 / views.len() as f32, cut.iter().copied().fold(0.0, f32::max))
}

/// Case 14 figure: Phong (s = 1) and Blinn (4) against the view angle, light at 15°.
pub fn case14_figure() -> Figure {
    let xs = || linspace(-89.0, 89.0, 178);
    let series = vec![
        Series::from_fn("Phong, s = 1", xs(), |a| case14_specular(15.0, a, 1.0).0),
        Series::from_fn("Blinn-Phong, 4s = 4", xs(), |a| case14_specular(15.0, a, 1.0).1),
    ];
    Figure::new(
        "Phong's lobe cut at 90°, light 15° above the surface",
        "view angle from n (°, − = light side)",
        "specular factor",
        series,
    )
}

fn case14_measure() -> (String, String) {
    let (share, max_blinn) = case14_cut_region(15.0, 1.0);
    let min_n_dot_h = (-179..=179)
        .map(|i| {
            let (n, l, v) = case14_vectors(15.0, i as f32 * 0.5);
            n.dot(crate::phong::halfway(l, v))
        })
        .fold(f32::INFINITY, f32::min);
    (
        format!(
            "light 15° up, s = 1: Phong is 0 for {:.0}% of views where Blinn shows up to {max_blinn:.2}",
            share * 100.0
        ),
        format!("Blinn: n·h ≥ {min_n_dot_h:.3} > 0 for every view above the surface"),
    )
}

// ---------------------------------------------------------------- tables

/// The atlas table for the book: one row per case.
///
/// Columns: case number, name, minimal repro (recorded, checked by the
/// tests), symptom measured, fix, measured after the fix. Every number in the
/// measured columns is computed when this is called.
pub fn table() -> Table {
    let header = ["#", "case", "minimal repro", "symptom (measured)", "fix", "after the fix (measured)"];
    let mut rows = vec![header.iter().map(|s| s.to_string()).collect::<Vec<_>>()];
    for (c, (symptom, after)) in CASES.iter().zip(measures()) {
        rows.push(vec![
            c.number.to_string(),
            c.name.to_string(),
            c.repro.to_string(),
            symptom,
            c.fix.to_string(),
            after,
        ]);
    }
    Table { title: "The failure atlas".into(), rows }
}

/// [`table`] in a vector, for callers that render several tables.
pub fn tables() -> Vec<Table> {
    vec![table(), super::culling::range_table()]
}

fn measures() -> [(String, String); 14] {
    [
        case1_measure(),
        case2_measure(),
        case3_measure(),
        case4_measure(),
        case5_measure(),
        case6_measure(),
        case7_measure(),
        case8_measure(),
        case9_measure(),
        case10_measure(),
        case11_measure(),
        case12_measure(),
        case13_measure(),
        case14_measure(),
    ]
}

/// Every case's figure, numbered.
pub fn figures() -> Vec<(u8, Figure)> {
    vec![
        (1, case1_figure()),
        (2, case2_figure()),
        (3, case3_figure()),
        (4, case4_figure()),
        (5, case5_figure()),
        (6, case6_figure()),
        (7, case7_figure()),
        (8, case8_figure()),
        (9, case9_figure()),
        (10, case10_figure()),
        (11, case11_figure()),
        (12, case12_figure()),
        (13, case13_figure()),
        (14, case14_figure()),
    ]
}
