//! Clipping in clip space, before the perspective division.
//!
//! | plane | inside when |
//! | --- | --- |
//! | near | `z + w ≥ 0` |
//! | far | `w − z ≥ 0` |
//! | guard band | `G·w ± x ≥ 0`, `G·w ± y ≥ 0`, `G` = [`GUARD_BAND`] |
//!
//! Only triangles that cross a plane are cut; the x and y planes sit far
//! outside the screen (a guard band) so that on-screen edges are never moved
//! and the fixed-point edge functions stay in range. An edge shared by two
//! triangles is cut at the same point in both: the intersection is always
//! computed from the inside vertex toward the outside one.
//!
//! Source: Sutherland & Hodgman 1974; OpenGL 3.3 core §2.20 (clipping).

use glam::Vec4;

/// Most varyings a vertex can carry (position 3, normal 3, uv 2).
pub const MAX_VARYINGS: usize = 8;

/// The guard band: x and y are clipped at `±GUARD_BAND · w`.
pub const GUARD_BAND: f32 = 8.0;

/// A vertex after the vertex stage: clip-space position and varyings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// `gl_Position`.
    pub clip: Vec4,
    /// The outputs to interpolate (only the first `varying_count` of a draw are used).
    pub varyings: [f32; MAX_VARYINGS],
}

impl ClipVertex {
    fn lerp(&self, other: &ClipVertex, t: f32) -> ClipVertex {
        let mut varyings = [0.0; MAX_VARYINGS];
        for (k, v) in varyings.iter_mut().enumerate() {
            *v = self.varyings[k] + (other.varyings[k] - self.varyings[k]) * t;
        }
        ClipVertex { clip: self.clip + (other.clip - self.clip) * t, varyings }
    }
}

const PLANES: [Vec4; 6] = [
    Vec4::new(0.0, 0.0, 1.0, 1.0),
    Vec4::new(0.0, 0.0, -1.0, 1.0),
    Vec4::new(1.0, 0.0, 0.0, GUARD_BAND),
    Vec4::new(-1.0, 0.0, 0.0, GUARD_BAND),
    Vec4::new(0.0, 1.0, 0.0, GUARD_BAND),
    Vec4::new(0.0, -1.0, 0.0, GUARD_BAND),
];

/// Whether every corner is inside every plane (the common case: no clipping).
pub fn inside_all(tri: &[ClipVertex; 3]) -> bool {
    tri.iter().all(|v| PLANES.iter().all(|p| p.dot(v.clip) >= 0.0))
}

/// Clip a triangle to the near, far and guard-band planes.
///
/// Returns the clipped convex polygon (0 to 9 vertices, in the input's
/// winding order); fan it from vertex 0. Triangles with a non-finite
/// coordinate give an empty polygon (they are skipped, never a panic).
pub fn clip_triangle(tri: &[ClipVertex; 3]) -> Vec<ClipVertex> {
    if tri.iter().any(|v| !v.clip.is_finite()) {
        return Vec::new();
    }
    let mut poly: Vec<ClipVertex> = tri.to_vec();
    for plane in PLANES {
        if poly.is_empty() {
            break;
        }
        poly = clip_polygon(&poly, plane);
    }
    poly
}

fn clip_polygon(poly: &[ClipVertex], plane: Vec4) -> Vec<ClipVertex> {
    let mut out = Vec::with_capacity(poly.len() + 1);
    for (i, a) in poly.iter().enumerate() {
        let b = &poly[(i + 1) % poly.len()];
        let (da, db) = (plane.dot(a.clip), plane.dot(b.clip));
        if da >= 0.0 {
            out.push(*a);
        }
        if (da >= 0.0) != (db >= 0.0) {
            // from the inside vertex toward the outside one, so both triangles of a shared edge agree
            let (inside, outside, di, dout) = if da >= 0.0 { (a, b, da, db) } else { (b, a, db, da) };
            out.push(inside.lerp(outside, di / (di - dout)));
        }
    }
    out
}
