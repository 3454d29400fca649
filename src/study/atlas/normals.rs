//! Normals that go wrong: degenerate triangles (case 4), non-uniform scale without the normal matrix (case 5), and a near-singular model matrix (case 6).
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::{DMat3, Mat3, Vec3};

use crate::normals::{
    model_matrix_normal_error_deg, normal_matrix_cofactor, normal_matrix_inverse_transpose, triangle_normal_or_zero,
};

use super::super::{linspace, Curve, Figure};
use super::direction_from_angles;

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
        Curve::from_fn("normalize(cross)", linspace(0.0, 45.0, 45), length(naive_some)),
        Curve::from_fn(
            "try_normalize (zero fallback)",
            linspace(0.0, 45.0, 45),
            length(|a, b, c| Some(triangle_normal_or_zero(a, b, c))),
        ),
        Curve::from_fn("pre-scaled edges", linspace(0.0, 45.0, 45), length(robust_triangle_normal)),
    ];
    Figure::new("Normals of tiny triangles", "leg length exponent k (legs 10^-k)", "length of the normal", series)
}

pub(super) fn case4_measure() -> (String, String) {
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
        Curve::from_fn("mat3(model) · n", linspace(1.0, 16.0, 30), case5_max_angle_error_deg),
        Curve::from_fn("cofactor · n", linspace(1.0, 16.0, 30), cof),
    ];
    Figure::new("Normals under non-uniform scale diag(r, 1, 1)", "scale ratio r", "largest angle error (°)", series)
}

pub(super) fn case5_measure() -> (String, String) {
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
        Curve::from_fn("inverse-transpose", xs(), move |k| {
            normal_matrix_inverse_transpose(case6_model(flatten(2f32.powf(-k)))).map_or(f32::NAN, largest)
        }),
        Curve::from_fn("cofactor", xs(), move |k| largest(normal_matrix_cofactor(case6_model(flatten(2f32.powf(-k)))))),
    ];
    Figure::new("Normal matrix of a flattening scale (1, 1, 2^-k)", "k", "log2 of the largest entry", series)
}

pub(super) fn case6_measure() -> (String, String) {
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
