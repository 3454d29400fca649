//! `f32` far from the origin (case 11): world-space lighting loses levels that camera-relative positions keep.
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::{DVec3, Mat4};

use crate::phong::BasicLighting;

use super::super::{linspace, Curve, Figure};

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
        Curve::from_fn(label, linspace(0.0, 6.0, 24), move |k| case11_max_error_levels(10f64.powf(k as f64), space))
    })
    .collect();
    Figure::new("f32 lighting far from the origin", "log10(distance from origin)", "max error (8-bit levels)", series)
}

pub(super) fn case11_measure() -> (String, String) {
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
