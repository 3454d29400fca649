//! GLSL built-ins: reflect, clamp, pow's domain (f32 path and f64 reference).
use crate::common;

use common::{close, close3, config, unit_vec3, vec3_in};
use glam::Vec3;
use lightlab::glsl::{homogeneous_kind, pow, pow_or_zero, reflect, saturate, try_pow, HomogeneousKind};
use lightlab::reference::{self, dvec3};
use proptest::prelude::*;

// Tolerance for reflect in f32: each output component is i_k − 2 (n·i) n_k,
// a dot product (3 products, 2 sums) then 2 more operations: about 7 roundings
// of quantities bounded by |i| ≤ 10, plus |n|² − 1 ≤ 3U from normalize.
// 16 U · 10 ≈ 1e-5; we use 2e-5.
const REFLECT_TOL_F32: f64 = 2e-5;

proptest! {
    #![proptest_config(config())]

    /// |reflect(i, n)| = |i| for unit n (a mirror is an isometry).
    #[test]
    fn reflect_preserves_length(i in vec3_in(10.0), n in unit_vec3()) {
        let r = reflect(i, n);
        close("f32 |r|", i.length() as f64, r.length() as f64, REFLECT_TOL_F32)?;
        let rd = reference::glsl::reflect(dvec3(i), dvec3(n));
        // f64: ~10 roundings of size 10 · 2^-53 ≈ 1e-14.
        close("f64 |r|", dvec3(i).length(), rd.length(), 1e-12)?;
    }

    /// r · n = −(i · n): the normal component flips, the tangent part stays.
    #[test]
    fn reflect_flips_normal_component(i in vec3_in(10.0), n in unit_vec3()) {
        let r = reflect(i, n);
        close("f32 r·n", -(i.dot(n) as f64), r.dot(n) as f64, REFLECT_TOL_F32)?;
        let (id, nd) = (dvec3(i), dvec3(n));
        let rd = reference::glsl::reflect(id, nd);
        close("f64 r·n", -id.dot(nd), rd.dot(nd), 1e-12)?;
        // Tangential part unchanged.
        close3("f64 tangent", id - nd * id.dot(nd) / nd.dot(nd), rd - nd * rd.dot(nd) / nd.dot(nd), 1e-12)?;
    }

    /// reflect(reflect(i, n), n) = i.
    #[test]
    fn reflect_is_an_involution(i in vec3_in(10.0), n in unit_vec3()) {
        // Two reflections: twice the single-reflection error bound.
        close3("f32 involution", dvec3(i), dvec3(reflect(reflect(i, n), n)), 2.0 * REFLECT_TOL_F32)?;
        let (id, nd) = (dvec3(i), dvec3(n));
        close3("f64 involution", id, reference::glsl::reflect(reference::glsl::reflect(id, nd), nd), 1e-12)?;
    }

    /// saturate lands in [0, 1], is idempotent, and is the identity on [0, 1].
    #[test]
    fn saturate_is_a_projection_onto_unit_interval(x in -10.0f32..10.0) {
        let s = saturate(x);
        prop_assert!((0.0..=1.0).contains(&s), "saturate({x}) = {s} outside [0, 1]");
        prop_assert_eq!(saturate(s), s);
        if (0.0..=1.0).contains(&x) { prop_assert_eq!(s, x); }
        prop_assert_eq!(reference::glsl::saturate(x as f64), s as f64, "reference saturate({})", x);
    }

    /// try_pow is None exactly on GLSL's undefined domain, and pow_or_zero ≥ 0 always.
    #[test]
    fn pow_domain_matches_glsl(x in -2.0f32..2.0, y in -4.0f32..64.0) {
        let undefined = x < 0.0 || (x == 0.0 && y <= 0.0);
        prop_assert_eq!(try_pow(x, y).is_none(), undefined, "try_pow({}, {})", x, y);
        prop_assert_eq!(pow(x, y).is_nan(), undefined, "pow({}, {}) = {}", x, y, pow(x, y));
        prop_assert!(pow_or_zero(x, y) >= 0.0, "pow_or_zero({x}, {y}) = {}", pow_or_zero(x, y));
        prop_assert_eq!(reference::glsl::try_pow(x as f64, y as f64).is_none(), undefined);
    }

    /// A w within the tolerance is a direction, anything else a position.
    #[test]
    fn homogeneous_kind_splits_at_tolerance(w in -1.0f32..1.0, tol in 0.0f32..0.5) {
        let kind = homogeneous_kind(w, tol).unwrap();
        let expected = if w.abs() <= tol { HomogeneousKind::Direction } else { HomogeneousKind::Position };
        prop_assert_eq!(kind, expected);
    }
}

#[test]
fn degenerate_inputs_do_not_panic() {
    // NaN propagates through reflect in both paths.
    assert!(reflect(Vec3::NAN, Vec3::Z).is_nan());
    assert!(reference::glsl::reflect(glam::DVec3::NAN, glam::DVec3::Z).is_nan());
    // Zero normal: f32 formula returns i (0 · i = 0), reference returns i (no line).
    let i = Vec3::new(1.0, -2.0, 3.0);
    assert_eq!(reflect(i, Vec3::ZERO), i);
    assert_eq!(reference::glsl::reflect(dvec3(i), glam::DVec3::ZERO), dvec3(i));
    // saturate(NaN) = 0 (documented choice).
    assert_eq!(saturate(f32::NAN), 0.0);
    assert_eq!(reference::glsl::saturate(f64::NAN), 0.0);
    // pow's undefined cases.
    assert!(pow(-1.0, 2.0).is_nan(), "GLSL pow(-1, 2) is undefined, lightlab gives NaN");
    assert!(pow(0.0, 0.0).is_nan());
    assert_eq!(pow_or_zero(0.0, 0.0), 0.0, "no highlight at grazing angle with shininess 0");
    assert_eq!(pow_or_zero(f32::NAN, 2.0), 0.0);
    assert!(reference::glsl::pow(-1.0, 2.0).is_nan());
    assert_eq!(reference::glsl::pow_or_zero(0.0, 0.0), 0.0);
    assert_eq!(homogeneous_kind(f32::NAN, 1e-6), None);
}
