//! Normals in `f64`: triangle and vertex normals, and the normal matrix by cofactors.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `a`, `b`, `c` | triangle corners, counter-clockwise seen from the front |
//! | `m(r, c)` | entry of `mat3(model)` in row `r`, column `c` |
//! | `C(r, c)` | cofactor `(−1)^(r+c) · minor(r, c)` |
//!
//! A normal must satisfy `n' · (M t) = 0` for every tangent `t` with `n · t = 0`,
//! which `n' = M^{-T} n` (or any positive multiple, such as the cofactor
//! matrix `C = det(M) M^{-T}`) guarantees.
//! Sources: LearnOpenGL, Basic lighting; opengl-tutorial 8; Lengyel §3.4.

use glam::{DMat3, DVec3};

use crate::normals::{IndexOutOfRange, VertexWeighting};

/// The area vector `(b − a) × (c − a)`, whose length is twice the area.
///
/// Zero for a zero-area triangle; NaN propagates. Source: opengl-tutorial 8.
pub fn triangle_area_vector(a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    let (u, v) = (b - a, c - a);
    DVec3::new(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x)
}

/// The unit normal of a triangle, `None` when its area is zero or not finite.
///
/// Source: opengl-tutorial 8, triangle normals.
pub fn try_triangle_normal(a: DVec3, b: DVec3, c: DVec3) -> Option<DVec3> {
    let v = triangle_area_vector(a, b, c);
    let len = v.length();
    (len > 0.0 && len.is_finite()).then(|| v / len)
}

/// [`try_triangle_normal`], or zero for a degenerate triangle.
pub fn triangle_normal_or_zero(a: DVec3, b: DVec3, c: DVec3) -> DVec3 {
    try_triangle_normal(a, b, c).unwrap_or(DVec3::ZERO)
}

/// Per-vertex normals, summing weighted face normals, then normalizing.
///
/// ```text
/// Unweighted: Σ n_f
/// Area:       Σ (b − a) × (c − a)           (area vectors: weight ∝ area, no normalize per face)
/// Angle:      Σ angle_f(v) · n_f,  angle_f(v) = atan2(‖e1 × e2‖, e1 · e2)
/// n_v = sum / ‖sum‖, or zero
/// ```
///
/// Degenerate triangles (zero or non-finite area) are skipped; a vertex in no
/// valid triangle gets zero; an out-of-range index is an error naming the
/// triangle. The weighting tag and the error type are shared with
/// [`crate::normals`].
///
/// Source: opengl-tutorial 8, vertex normals; Thürmer & Wüthrich 1998 (angle).
pub fn vertex_normals(
    positions: &[DVec3],
    triangles: &[[u32; 3]],
    weighting: VertexWeighting,
) -> Result<Vec<DVec3>, IndexOutOfRange> {
    let mut sums = vec![DVec3::ZERO; positions.len()];
    for (t, tri) in triangles.iter().enumerate() {
        let mut p = [DVec3::ZERO; 3];
        for k in 0..3 {
            p[k] = *positions.get(tri[k] as usize).ok_or(IndexOutOfRange {
                triangle: t,
                index: tri[k],
                vertex_count: positions.len(),
            })?;
        }
        let area_vector = triangle_area_vector(p[0], p[1], p[2]);
        let Some(unit) = try_triangle_normal(p[0], p[1], p[2]) else {
            continue;
        };
        for k in 0..3 {
            let contribution = match weighting {
                VertexWeighting::Unweighted => unit,
                VertexWeighting::Area => area_vector,
                VertexWeighting::Angle => unit * corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]),
            };
            sums[tri[k] as usize] += contribution;
        }
    }
    Ok(sums.into_iter().map(super::glsl::normalize_or_zero).collect())
}

/// The interior angle at `p` of the triangle `p, q, r`, in radians.
fn corner_angle(p: DVec3, q: DVec3, r: DVec3) -> f64 {
    super::angle_between(q - p, r - p)
}

/// Entry `(row, col)` of a column-major `DMat3`.
fn m(mat: &DMat3, row: usize, col: usize) -> f64 {
    mat.col(col)[row]
}

/// The determinant by expansion along the first row.
///
/// ```text
/// det M = m00 C00 + m01 C01 + m02 C02
/// ```
pub fn determinant(mat: DMat3) -> f64 {
    let c = normal_matrix_cofactor(mat);
    m(&mat, 0, 0) * m(&c, 0, 0) + m(&mat, 0, 1) * m(&c, 0, 1) + m(&mat, 0, 2) * m(&c, 0, 2)
}

/// The cofactor matrix, each entry written out.
///
/// ```text
/// C(r, c) = (−1)^(r+c) · det(M without row r and column c)
/// C = det(M) · M^{-T}
/// ```
///
/// Maps normals to the same directions as the inverse-transpose when
/// `det M > 0` (opposite when `det M < 0`). Always finite for finite `M`;
/// for singular `M` it maps every normal to the surviving direction or to zero.
///
/// Source: Lengyel, "Mathematics for 3D Game Programming", §3.4.
pub fn normal_matrix_cofactor(mat: DMat3) -> DMat3 {
    let e = |r, c| m(&mat, r, c);
    let c00 = e(1, 1) * e(2, 2) - e(1, 2) * e(2, 1);
    let c01 = -(e(1, 0) * e(2, 2) - e(1, 2) * e(2, 0));
    let c02 = e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0);
    let c10 = -(e(0, 1) * e(2, 2) - e(0, 2) * e(2, 1));
    let c11 = e(0, 0) * e(2, 2) - e(0, 2) * e(2, 0);
    let c12 = -(e(0, 0) * e(2, 1) - e(0, 1) * e(2, 0));
    let c20 = e(0, 1) * e(1, 2) - e(0, 2) * e(1, 1);
    let c21 = -(e(0, 0) * e(1, 2) - e(0, 2) * e(1, 0));
    let c22 = e(0, 0) * e(1, 1) - e(0, 1) * e(1, 0);
    // from_cols takes columns: column c holds C(0, c), C(1, c), C(2, c).
    DMat3::from_cols(DVec3::new(c00, c10, c20), DVec3::new(c01, c11, c21), DVec3::new(c02, c12, c22))
}

/// `transpose(inverse(mat3(model)))`, computed as `C / det M`.
///
/// `None` when `det M = 0` or the result is not finite.
///
/// Source: LearnOpenGL, Basic lighting, normal matrix.
pub fn normal_matrix_inverse_transpose(mat: DMat3) -> Option<DMat3> {
    let det = determinant(mat);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    let r = normal_matrix_cofactor(mat) * (1.0 / det);
    r.is_finite().then_some(r)
}

/// `normalize(normal_matrix · n)`, or zero when the product is zero or not finite.
pub fn transform_normal(normal_matrix: DMat3, n: DVec3) -> DVec3 {
    super::glsl::normalize_or_zero(normal_matrix * n)
}

/// The angle in degrees between `normalize(M n)` (the bug) and the correct
/// `normalize(M^{-T} n)`, through [`super::angle_between`]. `None` when
/// either is zero, not finite, or `M` is singular.
///
/// Source: LearnOpenGL, Basic lighting, non-uniform scale.
pub fn model_matrix_normal_error_deg(mat: DMat3, n: DVec3) -> Option<f64> {
    let right = normal_matrix_inverse_transpose(mat)? * n;
    let wrong = mat * n;
    if right.length() == 0.0 || wrong.length() == 0.0 || !(right.is_finite() && wrong.is_finite()) {
        return None;
    }
    Some(super::angle_between(wrong, right).to_degrees())
}
