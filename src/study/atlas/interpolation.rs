//! What interpolation across a triangle loses: unnormalized normals (case 7) and Gouraud shading's lost highlights and Mach bands (case 8).
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::Vec3;

use super::super::advisor::{gouraud_edge_error, max_span_for_budget};
use super::super::{linspace, Curve, Figure, ONE_LEVEL};
use super::direction_from_angles;

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
        .map(|s| Curve::from_fn(format!("span {s}°"), linspace(0.0, 1.0, 40), move |t| case7_darkening(s, t) * 255.0))
        .collect();
    Figure::new("Unnormalized interpolated normals", "t", "darkening (8-bit levels)", series)
}

pub(super) fn case7_measure() -> (String, String) {
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
            Curve::from_fn(format!("s = {s}"), linspace(0.0, 30.0, 30), move |span| {
                gouraud_edge_error(1.0, 0.5, s, span) * 255.0
            })
        })
        .collect();
    Figure::new("Gouraud error across one edge", "normal span of the edge (°)", "worst error (8-bit levels)", series)
}

pub(super) fn case8_measure() -> (String, String) {
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
