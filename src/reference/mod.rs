//! The independent `f64` reference: every formula written again, in `DVec3`/`DMat3`,
//! with explicit projections, angles and cofactors. It never calls the `f32` code.
//!
//! | `f32` module | reference module | formulation used here |
//! | --- | --- | --- |
//! | [`crate::glsl`] | [`glsl`] | reflection by explicit projection `r = i − 2 proj_n(i)` |
//! | [`crate::color`] | [`color`] | per-channel products written out |
//! | [`crate::phong`] | [`phong`] | cosines from the angle `atan2(‖a×b‖, a·b)` |
//! | [`crate::normals`] | [`normals`] | cofactors written element by element |
//! | [`crate::material`] | [`material`] | the Materials chapter's three terms |
//! | [`crate::maps`] | [`maps`] | bilinear as a weighted sum of four `f64` texels |
//! | [`crate::casters`] | [`casters`] | Horner attenuation, bisection for `distance_for`, piecewise spot ramp |
//! | [`crate::scene`] | [`scene`] | the Multiple lights sum |
//! | [`crate::models`] | [`models`] | opengl-tutorial 8 and ogldev 19 with their gates made explicit |
//!
//! Independence rule: reference code may use the plain *tags and error types* of
//! the `f32` modules (enums such as [`crate::maps::Filter`], error structs such as
//! [`crate::casters::ParamError`]) and may *convert data* from them (`from_f32`),
//! but it never calls an `f32` formula. That way a property comparing the two
//! paths compares two derivations, not one derivation with itself.
//!
//! All vectors follow the crate conventions: unit length where stated, pointing
//! away from the surface (`n`, `light_dir`, `view_dir`).

use glam::{DMat3, DMat4, DVec2, DVec3, Mat3, Mat4, Vec2, Vec3};

pub mod casters;
pub mod color;
pub mod glsl;
pub mod maps;
pub mod material;
pub mod models;
pub mod normals;
pub mod phong;
pub mod scene;

/// Widen an `f32` vector to `f64` exactly (every `f32` is an `f64`).
pub fn dvec3(v: Vec3) -> DVec3 {
    v.as_dvec3()
}

/// Widen an `f32` 2-vector to `f64` exactly.
pub fn dvec2(v: Vec2) -> DVec2 {
    v.as_dvec2()
}

/// Widen an `f32` 3×3 matrix to `f64` exactly, column by column.
pub fn dmat3(m: Mat3) -> DMat3 {
    DMat3::from_cols(dvec3(m.x_axis), dvec3(m.y_axis), dvec3(m.z_axis))
}

/// Widen an `f32` 4×4 matrix to `f64` exactly, column by column.
pub fn dmat4(m: Mat4) -> DMat4 {
    DMat4::from_cols(m.x_axis.as_dvec4(), m.y_axis.as_dvec4(), m.z_axis.as_dvec4(), m.w_axis.as_dvec4())
}

/// The angle in radians between two vectors, in [0, π].
///
/// ```text
/// angle(a, b) = atan2(‖a × b‖, a · b)
/// ```
///
/// Accurate at every angle, unlike `acos` of a normalized dot product near 0
/// and π. No unit-length precondition. Degenerate input: a zero vector gives
/// `atan2(0, 0) = 0`; NaN propagates.
pub fn angle_between(a: DVec3, b: DVec3) -> f64 {
    a.cross(b).length().atan2(a.dot(b))
}

/// `‖a‖ ‖b‖ cos(angle(a, b))`: the dot product recomputed through the angle.
///
/// Equal to `a · b` in exact arithmetic for any vectors; the reference uses it
/// so that every cosine goes through [`angle_between`] rather than through
/// the `f32` code's plain dot product. A zero vector gives 0; NaN propagates.
pub fn cos_between_scaled(a: DVec3, b: DVec3) -> f64 {
    a.length() * b.length() * angle_between(a, b).cos()
}
