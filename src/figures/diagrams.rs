//! The book's diagrams. Each is computed from vectors with glam and drawn with
//! [`super::svg::Canvas`]; nothing is placed by hand.
//!
//! Symbols follow the crate conventions (all unit length, pointing away from the
//! surface point): `n` normal, `light_dir` toward the light, `view_dir` toward the eye,
//! `reflect_dir = reflect(-light_dir, n)`.

use super::svg::{Anchor, Canvas, Pen};
use crate::book::Artifact;
use glam::{Vec2, Vec3};

/// The diagrams this module contributes to the book (paths under `book/src/generated/`).
pub fn artifacts() -> Vec<Artifact> {
    vec![Artifact { path: "diagrams/phong-vectors.png", make: phong_vectors_png }]
}

/// Angle between `n` and `light_dir` in the Phong vectors diagram, degrees.
pub const PHONG_VECTORS_THETA_DEG: f32 = 40.0;
/// Angle between `n` and `view_dir` in the Phong vectors diagram, degrees, on the
/// side of the reflection and beyond it, so the angle `alpha` between `reflect_dir`
/// and `view_dir` is this minus theta, 15 degrees.
pub const PHONG_VECTORS_VIEW_DEG: f32 = 55.0;

/// The four vectors of the Phong diagram, in the plane z = 0 (x right, y = normal):
/// `(n, light_dir, reflect_dir, view_dir)`.
///
/// ```text
/// n           = (0, 1, 0)
/// light_dir   = (-sin theta, cos theta, 0)
/// view_dir    = ( sin phi,   cos phi,   0)
/// reflect_dir = reflect(-light_dir, n) = -light_dir + 2 (n . light_dir) n
/// ```
/// with `theta` = [`PHONG_VECTORS_THETA_DEG`], `phi` = [`PHONG_VECTORS_VIEW_DEG`].
/// LearnOpenGL, Basic Lighting, "Specular lighting".
pub fn phong_vectors() -> (Vec3, Vec3, Vec3, Vec3) {
    let n = Vec3::Y;
    let theta = PHONG_VECTORS_THETA_DEG.to_radians();
    let phi = PHONG_VECTORS_VIEW_DEG.to_radians();
    let light_dir = Vec3::new(-theta.sin(), theta.cos(), 0.0);
    let view_dir = Vec3::new(phi.sin(), phi.cos(), 0.0);
    let reflect_dir = (-light_dir).reflect(n);
    (n, light_dir, reflect_dir, view_dir)
}

/// The vectors N, L, R, V at a surface point with the angles theta (N to L, N to R)
/// and alpha (R to V), as a PNG. See [`phong_vectors`] for the geometry.
pub fn phong_vectors_png() -> Result<Vec<u8>, String> {
    let (n, light_dir, reflect_dir, view_dir) = phong_vectors();
    let flat = |v: Vec3| Vec2::new(v.x, v.y);
    let (n, l, r, v) = (flat(n), flat(light_dir), flat(reflect_dir), flat(view_dir));

    let mut c = Canvas::new(560, 325, Vec2::new(280.0, 265.0), 220.0)?;
    let surface = Pen::solid("#444444", 3.0);
    c.line(Vec2::new(-1.2, 0.0), Vec2::new(1.2, 0.0), &surface);
    for i in 0..12 {
        // Hatching under the surface, one stroke every 0.2 units.
        let x = -1.1 + 0.2 * i as f32;
        c.line(Vec2::new(x, 0.0), Vec2::new(x - 0.07, -0.09), &Pen::solid("#888888", 1.5));
    }

    let arcs = Pen::solid("#555555", 1.5);
    c.arc(Vec2::ZERO, 0.30, l, n, &arcs, "θ")?;
    c.arc(Vec2::ZERO, 0.30, n, r, &arcs, "θ")?;
    c.arc(Vec2::ZERO, 0.62, r, v, &arcs, "α")?;

    let black = Pen::solid("#222222", 2.5);
    c.arrow(Vec2::ZERO, n, &black, "N")?;
    c.arrow(Vec2::ZERO, l, &Pen::solid("#d97706", 2.5), "L")?;
    c.arrow(Vec2::ZERO, r, &Pen::solid("#2563eb", 2.5), "R")?;
    c.arrow(Vec2::ZERO, v, &Pen::solid("#059669", 2.5), "V")?;

    // The key gives the angles measured from the computed vectors.
    let theta_deg = n.angle_to(l).abs().to_degrees();
    let alpha_deg = r.angle_to(v).abs().to_degrees();
    let key = format!("θ = {theta_deg:.0}°, α = {alpha_deg:.0}°");
    c.text(Vec2::new(-1.2, 1.1), &key, 17.0, "#333333", Anchor::Start);
    c.text(Vec2::new(0.0, -0.19), "surface point", 15.0, "#444444", Anchor::Middle);
    c.to_png(2.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reflection_mirrors_light_about_the_normal() {
        let (n, l, r, _) = phong_vectors();
        // Mirror image: same angle to n, opposite tangent component. 1e-6 is a few f32
        // ulps of values near 1.
        assert!((n.dot(l) - n.dot(r)).abs() < 1e-6, "n.l {} n.r {}", n.dot(l), n.dot(r));
        assert!((l.x + r.x).abs() < 1e-6, "l.x {} r.x {}", l.x, r.x);
        assert!((r.length() - 1.0).abs() < 1e-6, "|r| {}", r.length());
    }

    #[test]
    fn diagram_renders() {
        let png = phong_vectors_png().unwrap();
        assert_eq!(&png[1..4], b"PNG");
    }
}
