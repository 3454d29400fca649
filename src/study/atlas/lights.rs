//! Light casters that go wrong: spot cones with ε ≤ 0 or a narrow soft edge (case 9), attenuation above 1 and 1/d² at d = 0 (case 10), and the `w == 0.0` test (case 13).
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::{Mat4, Vec3, Vec4};

use crate::casters::{classify_light_vector, spot_intensity, Attenuation, LightVector, SpotLight};
use crate::glsl::saturate;
use crate::material::LightProps;

use super::super::{linspace, Curve, Figure, ONE_LEVEL};

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
            Curve::from_fn(format!("{f:?} ramp"), linspace(0.0, 5.0, 50), move |k| {
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

pub(super) fn case9_measure() -> (String, String) {
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
    let mut series: Vec<Curve> = [1.0, 0.5, 0.1]
        .into_iter()
        .map(|kc| {
            let a = Attenuation { constant: kc, ..Attenuation::LEARNOPENGL };
            Curve::from_fn(format!("Kc = {kc}"), linspace(0.0, 5.0, 50), move |d| a.at(d))
        })
        .collect();
    series.push(Curve::from_fn("1/d²", linspace(0.0, 5.0, 50), |d| crate::casters::inverse_square_falloff(1.0, d)));
    Figure::new("Attenuation near the light", "distance", "attenuation", series)
}

pub(super) fn case10_measure() -> (String, String) {
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
        vec![Curve { label: "|w|".into(), points }],
    )
}

pub(super) fn case13_measure() -> (String, String) {
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
