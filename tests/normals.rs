//! Normals: the normal matrix (inverse-transpose, cofactor) and vertex normals.
use crate::common;

use common::{close, close3, config, invertible_mat3, normal_and_tangent, rotation, unit_vec3, vec3_in};
use glam::{DMat3, DVec3, Mat3, Vec3};
use lightlab::normals::{
    model_matrix_normal_error_deg, normal_matrix_cofactor, normal_matrix_inverse_transpose, transform_normal,
    triangle_area_vector, triangle_normal_or_zero, try_triangle_normal, vertex_normals, VertexWeighting,
};
use lightlab::reference::{self, dmat3, dvec3};
use proptest::prelude::*;

const WEIGHTINGS: [VertexWeighting; 3] = [VertexWeighting::Unweighted, VertexWeighting::Area, VertexWeighting::Angle];

/// A fan around a centre vertex in one plane: a flat patch, counter-clockwise.
fn flat_fan() -> impl Strategy<Value = (Vec<Vec3>, Vec<[u32; 3]>, Vec3)> {
    (unit_vec3(), vec3_in(5.0), prop::collection::vec((0.2f32..1.0, 0.3f32..3.0), 3..8)).prop_map(
        |(n, centre, spokes)| {
            let (t, b) = n.any_orthonormal_pair();
            // Angles spread over a full turn, each step below π so every triangle is CCW.
            let k = spokes.len();
            let mut positions = vec![centre];
            for (i, &(jitter, r)) in spokes.iter().enumerate() {
                let a = (i as f32 + 0.4 * jitter) * std::f32::consts::TAU / k as f32;
                positions.push(centre + r * (a.cos() * t + a.sin() * b));
            }
            let tris = (0..k as u32).map(|i| [0, 1 + i, 1 + (i + 1) % k as u32]).collect();
            (positions, tris, n)
        },
    )
}

/// A random small mesh: 4–10 vertices, 1–12 triangles (degenerate ones allowed).
fn random_mesh() -> impl Strategy<Value = (Vec<Vec3>, Vec<[u32; 3]>)> {
    prop::collection::vec(vec3_in(3.0), 4..10).prop_flat_map(|p| {
        let n = p.len() as u32;
        (Just(p), prop::collection::vec(prop::array::uniform3(0..n), 1..12))
    })
}

proptest! {
    #![proptest_config(config())]

    /// No normal function panics on any `f32` input (NaN, ±∞ included); the
    /// cofactor matrix of a finite matrix is finite, and an inverse-transpose,
    /// when returned, is finite.
    #[test]
    fn normal_functions_never_panic(a in prop::array::uniform9(proptest::num::f32::ANY), n in prop::array::uniform3(proptest::num::f32::ANY)) {
        let m = Mat3::from_cols_array(&a);
        let n = Vec3::from_array(n);
        let c = normal_matrix_cofactor(m);
        if m.is_finite() && a.iter().all(|x| x.abs() < 1e12) { prop_assert!(c.is_finite(), "cofactor of {m} = {c}"); }
        if let Some(it) = normal_matrix_inverse_transpose(m) { prop_assert!(it.is_finite()); }
        let _ = transform_normal(c, n);
        let _ = model_matrix_normal_error_deg(m, n);
        let _ = lightlab::normals::condition_number(m);
        let _ = reference::normals::normal_matrix_inverse_transpose(dmat3(m));
        let _ = reference::normals::model_matrix_normal_error_deg(dmat3(m), dvec3(n));
        let p = [Vec3::ZERO, n, Vec3::from_slice(&a[..3]), Vec3::from_slice(&a[3..6])];
        for w in WEIGHTINGS {
            for v in vertex_normals(&p, &[[0, 1, 2], [1, 2, 3]], w).unwrap() {
                prop_assert!(v == Vec3::ZERO || (v.length() - 1.0).abs() < 1e-5, "{w:?}: {v}");
            }
        }
    }

    /// For any invertible model (non-uniform scale and shear included), a normal
    /// sent through the normal matrix stays perpendicular to every transformed tangent.
    #[test]
    fn normal_matrix_keeps_normals_perpendicular(m in invertible_mat3(), (n, t) in normal_and_tangent()) {
        let mt = (m * t).normalize();
        let inv_t = normal_matrix_inverse_transpose(m).expect("invertible");
        for (name, nm) in [("inverse-transpose", inv_t), ("cofactor", normal_matrix_cofactor(m))] {
            let n2 = transform_normal(nm, n);
            // Cosine of the angle between unit vectors; error grows with the
            // condition number κ < 200 of the f32 inverse: ~κ · 10U ≈ 1.2e-4.
            close(&format!("f32 {name}: n'·(M t)"), 0.0, n2.dot(mt) as f64, 2e-4)?;
        }
        let md = dmat3(m);
        let (nd, td) = (dvec3(n), dvec3(t));
        let mtd = (md * td).normalize();
        let inv_td = reference::normals::normal_matrix_inverse_transpose(md).expect("invertible");
        for (name, nm) in [("inverse-transpose", inv_td), ("cofactor", reference::normals::normal_matrix_cofactor(md))] {
            let n2 = reference::normals::transform_normal(nm, nd);
            // f64: κ · 10 · 2^-53 ≈ 2e-13, but n·t is only 0 to f32 precision (~4U): 1e-6.
            close(&format!("f64 {name}: n'·(M t)"), 0.0, n2.dot(mtd), 1e-6)?;
        }
    }

    /// Cofactor and inverse-transpose agree in direction when det > 0 and are
    /// opposite when det < 0; cof = det · M^{-T}.
    #[test]
    fn cofactor_and_inverse_transpose_agree(m in invertible_mat3(), n in unit_vec3()) {
        let det = m.determinant();
        let a = transform_normal(normal_matrix_cofactor(m), n);
        let b = transform_normal(normal_matrix_inverse_transpose(m).unwrap(), n);
        let expected = if det > 0.0 { 1.0 } else { -1.0 };
        // Two unit vectors from f32 products; κ < 200: 1 − cos ≤ 1e-5 comfortably.
        close("f32 cos(cofactor, inverse-transpose)", expected, a.dot(b) as f64, 1e-5)?;
        let md = dmat3(m);
        let cof = reference::normals::normal_matrix_cofactor(md);
        let inv_t = reference::normals::normal_matrix_inverse_transpose(md).unwrap();
        let det_d = reference::normals::determinant(md);
        for c in 0..3 {
            close3(&format!("f64 cof = det·M^-T, column {c}"), inv_t.col(c) * det_d, cof.col(c), 1e-12)?;
        }
        close("f64 det vs glam", md.determinant(), det_d, 1e-12)?;
    }

    /// Under rotation × uniform scale the model matrix itself maps normals
    /// correctly: the normal-matrix error is zero.
    #[test]
    fn uniform_scale_needs_no_normal_matrix(q in rotation(), s in 0.1f32..10.0, n in unit_vec3()) {
        let m = Mat3::from_quat(q) * s;
        let err = model_matrix_normal_error_deg(m, n).unwrap();
        // acos near 1 turns a cosine error of ~10U into sqrt(20U) rad ≈ 0.06°.
        prop_assert!(err < 0.1, "angle between M n and M^-T n = {err}°");
        let md = dmat3(m);
        let err_d = reference::normals::model_matrix_normal_error_deg(md, dvec3(n)).unwrap();
        // atan2 keeps small angles accurate: the only error is M's f32 non-orthogonality (~U): 1e-4°.
        prop_assert!(err_d < 1e-4, "reference angle = {err_d}°");
    }

    /// Vertex normals are unit length or exactly zero, under every weighting.
    #[test]
    fn vertex_normals_unit_or_zero((p, tris) in random_mesh()) {
        for w in WEIGHTINGS {
            for (i, v) in vertex_normals(&p, &tris, w).unwrap().into_iter().enumerate() {
                let len = v.length();
                prop_assert!(v == Vec3::ZERO || (len - 1.0).abs() < 1e-6, "{w:?} vertex {i}: {v} (length {len})");
            }
            let pd: Vec<DVec3> = p.iter().map(|&x| dvec3(x)).collect();
            for v in reference::normals::vertex_normals(&pd, &tris, w).unwrap() {
                prop_assert!(v == DVec3::ZERO || (v.length() - 1.0).abs() < 1e-14, "reference {w:?}: {v}");
            }
        }
    }

    /// On a flat fan every weighting gives the face normal at every used vertex.
    #[test]
    fn flat_fan_gives_face_normal((p, tris, n) in flat_fan()) {
        for w in WEIGHTINGS {
            for (i, v) in vertex_normals(&p, &tris, w).unwrap().into_iter().enumerate() {
                // Each face normal is n to ~κ·U of the cross product; 1e-5 with radii ≥ 0.3.
                close3(&format!("{w:?} vertex {i}"), dvec3(n), dvec3(v), 1e-5)?;
            }
        }
    }

    /// Area weighting equals the normalized sum of the raw cross products.
    #[test]
    fn area_weighting_is_sum_of_cross_products((p, tris) in random_mesh()) {
        let got = vertex_normals(&p, &tris, VertexWeighting::Area).unwrap();
        let mut sums = vec![Vec3::ZERO; p.len()];
        for t in &tris {
            let c = triangle_area_vector(p[t[0] as usize], p[t[1] as usize], p[t[2] as usize]);
            for &k in t { sums[k as usize] += c; }
        }
        for (i, (g, s)) in got.iter().zip(&sums).enumerate() {
            let expected = s.normalize_or_zero();
            // Near-cancelling sums lose relative precision; skip vertices whose sum is tiny vs its terms.
            if s.length() > 1e-3 {
                close3(&format!("vertex {i}"), dvec3(expected), dvec3(*g), 1e-4)?;
            }
        }
    }

    /// A triangle's normal is perpendicular to its edges and follows the CCW winding.
    #[test]
    fn triangle_normal_is_perpendicular(a in vec3_in(5.0), b in vec3_in(5.0), c in vec3_in(5.0)) {
        let area2 = triangle_area_vector(a, b, c).length();
        prop_assume!(area2 > 0.1);
        let n = try_triangle_normal(a, b, c).unwrap();
        // Edges up to ~17 long, n unit: dot error ~ 17 · 10U; relative to edge length, 1e-5.
        close("n·(b−a)/|b−a|", 0.0, (n.dot(b - a) / (b - a).length()) as f64, 1e-5)?;
        close("n·(c−a)/|c−a|", 0.0, (n.dot(c - a) / (c - a).length()) as f64, 1e-5)?;
        prop_assert!(n.dot(triangle_normal_or_zero(b, a, c)) < -0.999, "swapping two corners flips the normal");
        let nd = reference::normals::try_triangle_normal(dvec3(a), dvec3(b), dvec3(c)).unwrap();
        close3("reference normal", nd, dvec3(n), 1e-4)?;
    }
}

#[test]
fn singular_model_matrices() {
    // Scale to zero along x: singular.
    for m in [Mat3::from_diagonal(Vec3::new(0.0, 1.0, 2.0)), Mat3::ZERO, Mat3::from_cols(Vec3::X, Vec3::X, Vec3::Z)] {
        assert_eq!(normal_matrix_inverse_transpose(m), None, "{m}");
        let c = normal_matrix_cofactor(m);
        assert!(c.is_finite(), "cofactor of {m} = {c}");
        assert_eq!(reference::normals::normal_matrix_inverse_transpose(dmat3(m)), None);
        assert!(reference::normals::normal_matrix_cofactor(dmat3(m)).is_finite());
        let _ = model_matrix_normal_error_deg(m, Vec3::Y); // must not panic
    }
    // A flattened model (scale 0 in x): cofactor sends every normal to ±x, the surviving direction.
    let flat = Mat3::from_diagonal(Vec3::new(0.0, 1.0, 2.0));
    let n = transform_normal(normal_matrix_cofactor(flat), Vec3::new(0.3, 0.4, 0.5).normalize());
    assert!((n.x.abs() - 1.0).abs() < 1e-6, "{n}");
    // NaN matrices: no panic, None / NaN.
    let nan = Mat3::from_cols(Vec3::NAN, Vec3::Y, Vec3::Z);
    assert_eq!(normal_matrix_inverse_transpose(nan), None);
    assert_eq!(transform_normal(normal_matrix_cofactor(nan), Vec3::Z), Vec3::ZERO);
    assert_eq!(
        reference::normals::normal_matrix_inverse_transpose(DMat3::from_cols(DVec3::NAN, DVec3::Y, DVec3::Z)),
        None
    );
}

#[test]
fn zero_area_and_bad_index_triangles() {
    let (a, b) = (Vec3::ZERO, Vec3::X);
    assert_eq!(try_triangle_normal(a, b, 2.0 * b), None, "collinear");
    assert_eq!(try_triangle_normal(a, a, a), None, "point");
    assert_eq!(triangle_normal_or_zero(a, b, 2.0 * b), Vec3::ZERO);
    assert_eq!(try_triangle_normal(Vec3::NAN, b, Vec3::Y), None);
    // Tiny and huge triangles: |c|² under- or overflows in f32, but the normal is
    // still unit (before the fix: length 0.9996 for the tiny one, None for the huge one).
    for s in [1e-20f32, 1e18] {
        let n = try_triangle_normal(Vec3::ZERO, Vec3::X * s, Vec3::Y * s).unwrap_or(Vec3::ZERO);
        assert!((n - Vec3::Z).length() < 1e-6, "scale {s}: {n}");
        let v = vertex_normals(&[Vec3::ZERO, Vec3::X * s, Vec3::Y * s], &[[0, 1, 2]], VertexWeighting::Area).unwrap();
        assert!((v[0] - Vec3::Z).length() < 1e-6, "scale {s}: vertex normal {}", v[0]);
    }
    assert_eq!(reference::normals::try_triangle_normal(DVec3::ZERO, DVec3::X, DVec3::X * 2.0), None);
    // Vertex normals skip the degenerate triangle and give zero to untouched vertices.
    let p = [a, b, Vec3::Y, 2.0 * b, Vec3::NAN];
    let tris = [[0, 1, 2], [0, 1, 3], [1, 4, 2]];
    for w in WEIGHTINGS {
        let n = vertex_normals(&p, &tris, w).unwrap();
        assert_eq!(n[3], Vec3::ZERO, "{w:?}: vertex only in a zero-area triangle");
        assert_eq!(n[4], Vec3::ZERO, "{w:?}: NaN vertex");
        assert!((n[0] - Vec3::Z).length() < 1e-6, "{w:?}: {}", n[0]);
    }
    let err = vertex_normals(&p, &[[0, 1, 9]], VertexWeighting::Area).unwrap_err();
    assert_eq!((err.triangle, err.index, err.vertex_count), (0, 9, 5));
    assert!(err.to_string().contains("triangles[0]"), "{err}");
    let pd: Vec<DVec3> = p.iter().map(|&x| dvec3(x)).collect();
    assert!(reference::normals::vertex_normals(&pd, &[[0, 1, 9]], VertexWeighting::Area).is_err());
}
