//! Specular that goes wrong: the ungated lobe (case 1), `pow` outside its domain (cases 2 and 3), and Phong's lobe cut off beyond 90° (case 14).
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::Vec3;

use crate::casters::ParamError;
use crate::glsl::{pow_or_zero, reflect};
use crate::models::ogldev_specular_glsl;
use crate::phong::{blinn_exponent_rule_of_thumb, blinn_specular_factor, phong_specular_factor};

use super::super::{linspace, Curve, Figure, ONE_LEVEL};
use super::direction_from_angles;

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
        .map(|s| Curve::from_fn(format!("s = {s}"), linspace(0.0, 30.0, 30), |d| case1_ghost_peak(d, s)))
        .collect();
    Figure::new("Ghost highlight of ungated specular", "light below horizon (°)", "peak specular factor", series)
}

pub(super) fn case1_measure() -> (String, String) {
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

/// Case 2 figure: C `powf(v·r, y)` over v·r ∈ [−1, 1] for y = 32, 31, 31.5.
/// NaN points (31.5 below 0) are left out.
pub fn case2_figure() -> Figure {
    let series = [32.0, 31.0, 31.5]
        .into_iter()
        .map(|y| Curve::from_fn(format!("C powf, y = {y}"), linspace(-1.0, 1.0, 80), move |x| x.powf(y)))
        .chain(std::iter::once(Curve::from_fn("GLSL / llvmpipe, then > 0", linspace(-1.0, 1.0, 80), |x| {
            ogldev_specular_glsl(x, 32.0)
        })))
        .collect();
    Figure::new("pow of a negative base", "v · r", "specular factor", series)
}

pub(super) fn case2_measure() -> (String, String) {
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
            Curve::from_fn(format!("s = {s}"), linspace(0.0, 120.0, 120), move |a| c_specular(a.to_radians().cos(), s))
        })
        .collect();
    Figure::new("Shininess 0 and below 1 with C powf", "angle between v and r (°)", "specular factor", series)
}

pub(super) fn case3_measure() -> (String, String) {
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
        Curve::from_fn("Phong, s = 1", xs(), |a| case14_specular(15.0, a, 1.0).0),
        Curve::from_fn("Blinn-Phong, 4s = 4", xs(), |a| case14_specular(15.0, a, 1.0).1),
    ];
    Figure::new(
        "Phong's lobe cut at 90°, light 15° above the surface",
        "view angle from n (°, − = light side)",
        "specular factor",
        series,
    )
}

pub(super) fn case14_measure() -> (String, String) {
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
