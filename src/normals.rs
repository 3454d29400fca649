//! Normals: triangle and vertex normals, and the normal matrix.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `a`, `b`, `c` | triangle corners, counter-clockwise seen from the front |
//! | `n` | unit normal |
//! | `model` | the upper-left 3×3 of the model matrix, `mat3(model)` |
//! | `normal_matrix` | `transpose(inverse(mat3(model)))`, or its scaled twin the cofactor matrix |
//!
//! A normal is a covector: under a linear map `M` a tangent `t` becomes `M t`,
//! and a normal must become `M^{-T} n` so that `n · t = 0` still holds.
//! Sources: LearnOpenGL, Basic lighting ("One last thing", normal matrix);
//! opengl-tutorial 8 (triangle and vertex normals).

use glam::{Mat3, Vec3};

/// The unnormalized triangle normal, whose length is twice the area.
///
/// ```text
/// (b - a) × (c - a)
/// ```
///
/// Points toward the viewer for a counter-clockwise triangle. Zero for a
/// degenerate (zero-area) triangle; NaN propagates.
///
/// Source: opengl-tutorial 8, triangle normals.
// ANCHOR: triangle_area_vector
pub fn triangle_area_vector(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    (b - a).cross(c - a)
}
// ANCHOR_END: triangle_area_vector

/// The unit normal of a triangle.
///
/// ```text
/// n = normalize((b - a) × (c - a))
/// ```
///
/// Precondition: the triangle has non-zero area (checked by `debug_assert!`).
/// Use [`try_triangle_normal`] or [`triangle_normal_or_zero`] for untrusted input.
///
/// Source: opengl-tutorial 8, triangle normals.
pub fn triangle_normal(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    let n = try_triangle_normal(a, b, c);
    debug_assert!(n.is_some(), "degenerate triangle {a} {b} {c}");
    n.unwrap_or(Vec3::NAN)
}

/// [`triangle_normal`], or `None` for a zero-area or non-finite triangle.
pub fn try_triangle_normal(a: Vec3, b: Vec3, c: Vec3) -> Option<Vec3> {
    try_normalize_scaled(triangle_area_vector(a, b, c))
}

/// `normalize(v)` computed as `normalize(v / max|v_k|)`, so that `|v|²` neither
/// underflows (tiny triangles: glam's `try_normalize` then returns a vector of
/// length 0.9996, found by a property test) nor overflows. `None` for a zero
/// or non-finite `v`.
fn try_normalize_scaled(v: Vec3) -> Option<Vec3> {
    let m = v.abs().max_element();
    if !(m > 0.0 && m.is_finite() && v.is_finite()) {
        return None;
    }
    (v / m).try_normalize()
}

/// [`triangle_normal`], or the zero vector for a zero-area or non-finite triangle.
pub fn triangle_normal_or_zero(a: Vec3, b: Vec3, c: Vec3) -> Vec3 {
    try_triangle_normal(a, b, c).unwrap_or(Vec3::ZERO)
}

/// How the face normals around a vertex are weighted when averaged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VertexWeighting {
    /// Every adjacent face counts once (opengl-tutorial 8's description).
    Unweighted,
    /// Each face by its area: the sum of unnormalized cross products.
    Area,
    /// Each face by its interior angle at the vertex (Thürmer & Wüthrich 1998).
    Angle,
}

/// An index that points outside the vertex list.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct IndexOutOfRange {
    /// Which triangle (position in the index list).
    pub triangle: usize,
    /// The bad vertex index.
    pub index: u32,
    /// How many vertices there are.
    pub vertex_count: usize,
}

impl std::fmt::Display for IndexOutOfRange {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "triangles[{}]: vertex index {} out of range (vertex count {})",
            self.triangle, self.index, self.vertex_count
        )
    }
}

impl std::error::Error for IndexOutOfRange {}

/// Per-vertex normals averaged from the adjacent faces.
///
/// ```text
/// n_v = normalize( Σ_faces w_f · n_f )
/// w_f = 1 (Unweighted), area_f (Area), interior angle at v (Angle)
/// ```
///
/// - Degenerate triangles (zero area, NaN corners) are skipped.
/// - A vertex touched by no valid triangle gets the zero vector.
/// - An index out of range is an error naming the triangle.
///
/// Source: opengl-tutorial 8, vertex normals ("the average of the normals of
/// the neighbouring triangles").
// ANCHOR: vertex_normals
pub fn vertex_normals(
    positions: &[Vec3],
    triangles: &[[u32; 3]],
    weighting: VertexWeighting,
) -> Result<Vec<Vec3>, IndexOutOfRange> {
    let mut sums = vec![Vec3::ZERO; positions.len()];
    for (t, tri) in triangles.iter().enumerate() {
        let corners = corner_positions(positions, t, tri)?;
        let area_vector = triangle_area_vector(corners[0], corners[1], corners[2]);
        let Some(n) = try_normalize_scaled(area_vector) else {
            continue;
        };
        for k in 0..3 {
            // Area: `area · n` is `½ (b − a) × (c − a)` itself; using it directly avoids
            // `length()` underflowing to 0 for tiny triangles (found by a property test).
            sums[tri[k] as usize] += match weighting {
                VertexWeighting::Unweighted => n,
                VertexWeighting::Area => 0.5 * area_vector,
                VertexWeighting::Angle => interior_angle(corners, k) * n,
            };
        }
    }
    Ok(sums.into_iter().map(|s| try_normalize_scaled(s).unwrap_or(Vec3::ZERO)).collect())
}
// ANCHOR_END: vertex_normals

fn corner_positions(positions: &[Vec3], triangle: usize, tri: &[u32; 3]) -> Result<[Vec3; 3], IndexOutOfRange> {
    let get = |index: u32| {
        positions.get(index as usize).copied().ok_or(IndexOutOfRange { triangle, index, vertex_count: positions.len() })
    };
    Ok([get(tri[0])?, get(tri[1])?, get(tri[2])?])
}

/// The interior angle of a triangle at corner `k`, in radians.
fn interior_angle(corners: [Vec3; 3], k: usize) -> f32 {
    let p = corners[k];
    let e1 = (corners[(k + 1) % 3] - p).normalize_or_zero();
    let e2 = (corners[(k + 2) % 3] - p).normalize_or_zero();
    e1.dot(e2).clamp(-1.0, 1.0).acos()
}

/// The normal matrix as the tutorials write it.
///
/// ```text
/// normal_matrix = transpose(inverse(mat3(model)))
/// ```
///
/// Returns `None` when `model` is singular (determinant 0) or the inverse is
/// not finite. Near-singular matrices return large entries; prefer
/// [`normal_matrix_cofactor`], which gives the same directions and stays finite.
///
/// Source: LearnOpenGL, Basic lighting, "Normal = mat3(transpose(inverse(model))) * aNormal".
// ANCHOR: normal_matrix_inverse_transpose
pub fn normal_matrix_inverse_transpose(model: Mat3) -> Option<Mat3> {
    let det = model.determinant();
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let m = model.inverse().transpose();
    m.is_finite().then_some(m)
}
// ANCHOR_END: normal_matrix_inverse_transpose

/// The cofactor (adjugate-transpose) normal matrix.
///
/// ```text
/// cof(M) = [c1 × c2, c2 × c0, c0 × c1]   (columns; c_i are M's columns)
///        = det(M) · transpose(inverse(M))
/// ```
///
/// It maps normals to the same directions as the inverse-transpose when
/// `det(M) > 0` (and to the opposite directions when `det(M) < 0`, a
/// mirroring model matrix), needs no division, and stays finite for singular
/// `M`. For a singular `M` it maps normals to the one direction that survives
/// (or to zero).
///
/// Source: Lengyel, "Mathematics for 3D Game Programming", §3.4 (normal
/// transformation by the adjugate).
// ANCHOR: normal_matrix_cofactor
pub fn normal_matrix_cofactor(model: Mat3) -> Mat3 {
    let [c0, c1, c2] = [model.x_axis, model.y_axis, model.z_axis];
    Mat3::from_cols(c1.cross(c2), c2.cross(c0), c0.cross(c1))
}
// ANCHOR_END: normal_matrix_cofactor

/// Transform a normal by a normal matrix and renormalize.
///
/// ```text
/// n' = normalize(normal_matrix · n)
/// ```
///
/// Returns the zero vector when the product is zero or not finite.
pub fn transform_normal(normal_matrix: Mat3, n: Vec3) -> Vec3 {
    (normal_matrix * n).normalize_or_zero()
}

/// The angle in degrees between a normal sent through `model` itself (the bug)
/// and the correct transformed normal.
///
/// ```text
/// error = angle( normalize(M n), normalize(M^{-T} n) )
/// ```
///
/// Zero for rotations and uniform scale. `None` when either transformed
/// normal is zero or not finite.
///
/// Source: LearnOpenGL, Basic lighting, non-uniform scale figure.
// ANCHOR: model_matrix_normal_error_deg
pub fn model_matrix_normal_error_deg(model: Mat3, n: Vec3) -> Option<f32> {
    let wrong = (model * n).try_normalize()?;
    let right = (normal_matrix_cofactor(model) * n).try_normalize()?;
    let right = if model.determinant() < 0.0 { -right } else { right };
    Some(wrong.dot(right).clamp(-1.0, 1.0).acos().to_degrees())
}
// ANCHOR_END: model_matrix_normal_error_deg

/// The condition number of a 3×3 matrix in the Frobenius norm.
///
/// ```text
/// κ_F(M) = ‖M‖_F · ‖M^{-1}‖_F
/// ```
///
/// Infinite for a singular matrix. It bounds how much relative error the
/// inverse-transpose amplifies.
pub fn condition_number(model: Mat3) -> f32 {
    match normal_matrix_inverse_transpose(model) {
        Some(inv_t) => frobenius(model) * frobenius(inv_t),
        None => f32::INFINITY,
    }
}

fn frobenius(m: Mat3) -> f32 {
    (m.x_axis.length_squared() + m.y_axis.length_squared() + m.z_axis.length_squared()).sqrt()
}
