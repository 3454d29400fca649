//! Chapter 5, Light casters: attenuation, spot cones, the directional limit.
use crate::common;

use common::{close, config, unit_vec3, vec3_in};
use glam::{Vec3, Vec4};
use lightlab::casters::LocalLight as _;
use lightlab::casters::{
    classify_light_vector, spot_intensity, Attenuation, DirLight, LightVector, PointLight, SpotLight, RANGE_TABLE,
};
use lightlab::material::{LightProps, Material};
use lightlab::reference::casters::LocalLight as _;
use lightlab::reference::{self, dvec3};
use proptest::prelude::*;

/// Valid coefficients with Kc ≥ 1 (the chapter's advice) and Kl, Kq ≥ 0, not both zero.
fn attenuation() -> impl Strategy<Value = Attenuation> {
    (1.0f32..4.0, 0.0f32..1.0, 0.0f32..2.0)
        .prop_filter("falls off", |(_, l, q)| *l + *q > 1e-3)
        .prop_map(|(c, l, q)| Attenuation::new(c, l, q).unwrap())
}

/// Inner and outer cut-offs in degrees, inner < outer, both in (0, 90).
fn cones() -> impl Strategy<Value = (f32, f32)> {
    (0.5f32..60.0, 0.1f32..20.0).prop_map(|(inner, gap)| (inner, inner + gap))
}

fn white() -> LightProps {
    LightProps::white()
}

proptest! {
    #![proptest_config(config())]

    /// Attenuation is ≤ 1 and decreasing in distance when Kc ≥ 1.
    #[test]
    fn attenuation_is_decreasing_and_at_most_one(a in attenuation(), d1 in 0.0f32..1000.0, d2 in 0.0f32..1000.0) {
        let (near, far) = if d1 <= d2 { (d1, d2) } else { (d2, d1) };
        let (an, af) = (a.at(near), a.at(far));
        prop_assert!(an <= 1.0 && af <= 1.0 && af > 0.0, "at({near}) = {an}, at({far}) = {af}");
        prop_assert!(af <= an, "not decreasing: at({near}) = {an} < at({far}) = {af}");
        let r = reference::casters::Attenuation::from_f32(&a);
        prop_assert!(r.at(far as f64) <= r.at(near as f64) && r.at(near as f64) <= 1.0);
    }

    /// `distance_for` inverts `at`: at(distance_for(f)) = f for f ∈ (at(∞), 1/Kc).
    #[test]
    fn distance_for_inverts_at(a in attenuation(), fraction in 0.001f32..0.99) {
        let d = a.distance_for(fraction).unwrap();
        if fraction >= 1.0 / a.constant {
            prop_assert_eq!(d, 0.0);
        } else {
            // at() relative error ~4U; d from the cancellation-free root ~6U relative;
            // at'(d)·Δd relative to at is ≤ 2·6U: total 1e-5 relative is generous.
            close("at(distance_for(f))", fraction as f64, a.at(d) as f64, 1e-5 * fraction as f64)?;
        }
        let r = reference::casters::Attenuation::from_f32(&a);
        let dr = r.distance_for(fraction as f64).unwrap();
        if dr > 0.0 {
            // Bisection brackets the root to one f64 ulp of d: at changes by
            // |at'(d)| · ulp(d) ≤ 2 · at · 2^-52 relative, plus at's own 4 roundings.
            close("reference at(distance_for(f))", fraction as f64, r.at(dr), 1e-14 * fraction as f64)?;
        }
    }

    /// Spot intensity is in [0, 1], non-decreasing in theta, 1 inside the inner cone, 0 outside the outer.
    #[test]
    fn spot_intensity_ramp((inner, outer) in cones(), a1 in 0.0f32..180.0, a2 in 0.0f32..180.0) {
        let (cut_off, outer_cut_off) = (inner.to_radians().cos(), outer.to_radians().cos());
        let (t1, t2) = (a1.to_radians().cos(), a2.to_radians().cos());
        let (i1, i2) = (spot_intensity(t1, cut_off, outer_cut_off), spot_intensity(t2, cut_off, outer_cut_off));
        prop_assert!((0.0..=1.0).contains(&i1), "intensity {i1}");
        if t1 <= t2 { prop_assert!(i1 <= i2, "theta {t1} → {i1}, theta {t2} → {i2}"); }
        if t1 >= cut_off { prop_assert_eq!(i1, 1.0); }
        if t1 <= outer_cut_off { prop_assert_eq!(i1, 0.0); }
        let r = reference::casters::spot_intensity(t1 as f64, cut_off as f64, outer_cut_off as f64);
        prop_assert!((0.0..=1.0).contains(&r));
    }

    /// A spot light built from angles: inside the inner cone it lights like a
    /// point light, outside the outer cone only ambient (×0 in CalcSpotLight) remains.
    #[test]
    fn spot_light_cone_regions((inner, outer) in cones(), axis in unit_vec3(), off in 0.0f32..89.0, r in 0.5f32..20.0, n in unit_vec3(), v in unit_vec3()) {
        let spot = SpotLight::new(Vec3::ZERO, axis, inner, outer, Attenuation::LEARNOPENGL, white()).unwrap();
        prop_assert!(spot.cut_off >= spot.outer_cut_off);
        // A fragment at angle `off` from the axis, distance r.
        let (t, _) = axis.any_orthonormal_pair();
        let dir = (axis * off.to_radians().cos() + t * off.to_radians().sin()).normalize();
        let frag = dir * r;
        let m = Material::coral();
        let terms = spot.terms(&m, n, frag, v);
        let point = PointLight { position: Vec3::ZERO, attenuation: Attenuation::LEARNOPENGL, props: white() }.terms(&m, n, frag, v);
        // Stay 0.05° away from the edges: theta's f32 error (~1e-7) is far smaller.
        if off < inner - 0.05 {
            prop_assert!((terms.sum() - point.sum()).abs().max_element() <= 1e-6, "inside: spot {:?} point {:?}", terms, point);
        }
        if off > outer + 0.05 {
            prop_assert_eq!(terms.sum(), Vec3::ZERO);
            let keep = spot.terms_keep_ambient(&m, n, frag, v);
            prop_assert_eq!(keep.ambient, point.ambient);
            prop_assert_eq!(keep.diffuse + keep.specular, Vec3::ZERO);
        }
    }

    /// A directional light is the limit of a far point light: a point light at
    /// distance D along −direction, without attenuation (Kc = 1), differs from
    /// the directional light by O(R/D) for fragments within R of the origin.
    #[test]
    fn directional_is_limit_of_far_point_light(direction in unit_vec3(), frag in vec3_in(1.0), n in unit_vec3(), v in unit_vec3(), log_d in 2.0f32..4.0) {
        let d = 10f32.powf(log_d);
        let m = Material::coral();
        let dir = DirLight { direction, props: white() }.terms(&m, n, v);
        let none = Attenuation::new(1.0, 0.0, 0.0).unwrap();
        let point = PointLight { position: -direction * d, attenuation: none, props: white() }.terms(&m, n, frag, v);
        // |Δlight_dir| ≤ 2R/(D − R) with R = √3; diffuse changes by ≤ |Δl|,
        // specular by ≤ s·2|Δl| (pow's derivative ≤ s, reflect doubles): bound
        // (1 + 2s)·2R/(D − R) per channel (reflectances ≤ 1), plus f32 rounding of the
        // light position: ulp(D)/D ≈ 2U, negligible.
        let bound = (1.0 + 2.0 * m.shininess) * 2.0 * 3f32.sqrt() / (d - 3f32.sqrt());
        let diff = (dir.sum() - point.sum()).abs().max_element();
        prop_assert!(diff <= bound, "D = {d}: dir {:?}\npoint {:?}\ndifference {diff} > bound {bound}", dir, point);
        // Same in f64 with a larger D range, where f32 could not go.
        let rd = reference::casters::DirLight { direction: dvec3(direction), props: reference::material::LightProps::from_f32(&white()) };
        let rm = reference::material::Material::from_f32(&m);
        let dd = (d as f64) * 1e4;
        let rp = reference::casters::PointLight { position: -dvec3(direction) * dd, attenuation: reference::casters::Attenuation::from_f32(&none), props: rd.props };
        let diff_d = (rd.terms(&rm, dvec3(n), dvec3(v)).sum() - rp.terms(&rm, dvec3(n), dvec3(frag), dvec3(v)).sum()).abs().max_element();
        let bound_d = (1.0 + 2.0 * 32.0) * 2.0 * 3f64.sqrt() / (dd - 3f64.sqrt());
        prop_assert!(diff_d <= bound_d, "reference D = {dd}: difference {diff_d} > bound {bound_d}");
    }

    /// Point-light terms = attenuation(d) × the unattenuated material terms.
    #[test]
    fn point_light_scales_by_attenuation(a in attenuation(), pos in vec3_in(10.0), frag in vec3_in(10.0), n in unit_vec3(), v in unit_vec3()) {
        prop_assume!(pos.distance(frag) > 1e-3);
        let m = Material::coral();
        let t = PointLight { position: pos, attenuation: a, props: white() }.terms(&m, n, frag, v);
        let unit = lightlab::material::material_terms(&m, &white(), n, (pos - frag).normalize(), v);
        let expected = unit.sum() * a.at(pos.distance(frag));
        prop_assert!((t.sum() - expected).abs().max_element() <= 1e-6, "{} vs {}", t.sum(), expected);
    }

    /// A vec4 with w = 0 is a direction; any other w a position xyz / w.
    #[test]
    fn light_vector_classification(xyz in vec3_in(10.0), w in prop_oneof![Just(0.0f32), 0.5f32..2.0, -2.0f32..-0.5]) {
        match classify_light_vector(Vec4::from((xyz, w)), 1e-6).unwrap() {
            LightVector::Direction(d) => { prop_assert_eq!(w, 0.0); prop_assert_eq!(d, xyz); }
            LightVector::Position(p) => { prop_assert!(w != 0.0); prop_assert_eq!(p, xyz / w); }
        }
    }
}

#[test]
fn invalid_lights_are_errors_naming_the_field() {
    let props = white();
    let att = Attenuation::LEARNOPENGL;
    let e = SpotLight::new(Vec3::ZERO, Vec3::NEG_Z, 17.5, 12.5, att, props).unwrap_err();
    assert_eq!(e.field, "cut_off_deg", "{e}");
    assert!(e.to_string().starts_with("cut_off_deg"), "{e}");
    assert_eq!(SpotLight::new(Vec3::ZERO, Vec3::ZERO, 12.5, 17.5, att, props).unwrap_err().field, "direction");
    assert_eq!(SpotLight::new(Vec3::ZERO, Vec3::NAN, 12.5, 17.5, att, props).unwrap_err().field, "direction");
    assert_eq!(SpotLight::new(Vec3::ZERO, Vec3::Z, f32::NAN, 17.5, att, props).unwrap_err().field, "cut_off_deg");
    assert_eq!(SpotLight::new(Vec3::ZERO, Vec3::Z, 12.5, 95.0, att, props).unwrap_err().field, "outer_cut_off_deg");
    // Equal angles are a hard edge, accepted.
    let hard = SpotLight::new(Vec3::ZERO, Vec3::Z, 15.0, 15.0, att, props).unwrap();
    assert_eq!(spot_intensity(1.0, hard.cut_off, hard.outer_cut_off), 1.0);
    assert_eq!(spot_intensity(f32::NAN, 0.9, 0.8), 0.0);
    assert_eq!(reference::casters::spot_intensity(f64::NAN, 0.9, 0.8), 0.0);
    assert!(SpotLight::flashlight(Vec3::ZERO, Vec3::ZERO).is_none());
    for (args, field) in [
        ((-1.0, 0.0, 0.0), "constant"),
        ((1.0, -0.1, 0.0), "linear"),
        ((1.0, 0.0, -1e-9), "quadratic"),
        ((1.0, f32::NAN, 0.0), "linear"),
        ((1.0, 0.0, f32::INFINITY), "quadratic"),
        ((0.0, 0.0, 0.0), "constant"),
    ] {
        let e = Attenuation::new(args.0, args.1, args.2).unwrap_err();
        assert_eq!(e.field, field, "{args:?}: {e}");
    }
    // Degenerate evaluation: no panic.
    assert!(Attenuation::LEARNOPENGL.at(f32::NAN).is_nan());
    assert_eq!(Attenuation::new(0.0, 1.0, 0.0).unwrap().at(0.0), f32::INFINITY);
    assert_eq!(Attenuation::LEARNOPENGL.distance_for(0.0), None);
    assert_eq!(Attenuation::LEARNOPENGL.distance_for(f32::NAN), None);
    assert_eq!(Attenuation::new(1.0, 0.0, 0.0).unwrap().distance_for(0.5), None);
    assert_eq!(reference::casters::Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 }.distance_for(0.5), None);
    assert_eq!(classify_light_vector(Vec4::new(1.0, 2.0, 3.0, f32::NAN), 1e-6), None);
    // A fragment at the point light: ambient only, × 1/Kc, no NaN.
    let p = PointLight { position: Vec3::ONE, attenuation: att, props };
    let t = p.terms(&Material::coral(), Vec3::Z, Vec3::ONE, Vec3::Z);
    assert!(t.sum().is_finite());
    assert_eq!(t.diffuse, Vec3::ZERO);
}

#[test]
fn range_table_rows_fall_to_about_one_percent_at_their_range() {
    // research.md 1.1.a: every row falls to 1/77 … 1/95 of the source at its range.
    for row in RANGE_TABLE {
        let f = row.attenuation.at(row.range);
        assert!((1.0 / 95.0..=1.0 / 77.0).contains(&f), "range {}: attenuation {f}", row.range);
    }
    // Published: distance-50 row at d = 50 is 0.0116959064 (f32 relative error ≤ 4U).
    let f = Attenuation::LEARNOPENGL.at(50.0) as f64;
    assert!((f - 0.011_695_906_4).abs() < 1e-9, "{f}");
}

// ---------------------------------------------------------------- the range window

proptest! {
    #![proptest_config(config())]

    /// Zero at and beyond the range, whatever the attenuation: culling there is exact.
    #[test]
    fn the_windowed_falloff_is_zero_from_the_range_on(a in attenuation(), r in 0.1f32..1000.0, k in 1.0f32..100.0) {
        prop_assert_eq!(a.windowed_at(r, r), 0.0);
        prop_assert_eq!(a.windowed_at(r * k, r), 0.0);
        prop_assert_eq!(lightlab::casters::range_window(-r * k, r), 0.0);
    }

    /// Below the unwindowed falloff everywhere, equal to it at the light, non-increasing in d.
    #[test]
    fn the_window_only_lowers_and_keeps_the_falloff_monotone(
        a in attenuation(), r in 0.1f32..1000.0, t in 0.0f32..1.5, dt in 0.0f32..0.5,
    ) {
        let (d1, d2) = (t * r, (t + dt) * r);
        prop_assert!(a.windowed_at(d1, r) <= a.at(d1));
        prop_assert_eq!(a.windowed_at(0.0, r), a.at(0.0));
        prop_assert!(a.windowed_at(d2, r) <= a.windowed_at(d1, r), "{} > {}", a.windowed_at(d2, r), a.windowed_at(d1, r));
    }

    /// Continuous at the range: just inside it, the window is within `4·(1 − d/r)²·16`
    /// of zero (its slope is zero there: window ≈ (4·(1 − d/r))² for d near r).
    #[test]
    fn the_window_reaches_zero_smoothly(r in 0.1f32..1000.0, gap in 1e-4f32..1e-2) {
        let w = lightlab::casters::range_window(r * (1.0 - gap), r);
        prop_assert!(w <= 16.0 * gap * gap * 1.01 + 1e-6, "window {w} at 1 − {gap}");
    }

    /// The f32 window against the f64 reference, written independently: within 8 ulps of 1
    /// (a fourth power, a subtraction and a square, each rounding once, near 1).
    #[test]
    fn the_window_matches_its_reference(d in 0.0f32..2000.0, r in 0.1f32..1000.0) {
        let got = lightlab::casters::range_window(d, r) as f64;
        let want = reference::casters::range_window(d as f64, r as f64);
        prop_assert!((got - want).abs() <= 8.0 * f32::EPSILON as f64, "{got} vs {want}");
    }
}

#[test]
fn the_window_has_its_documented_values() {
    use lightlab::casters::range_window;
    // 1 at the light; (1 − 0.5⁴)² = 0.87890625 exactly at half the range; 0 at the range.
    assert_eq!(range_window(0.0, 7.0), 1.0);
    assert_eq!(range_window(3.5, 7.0), 0.878_906_25);
    assert_eq!(range_window(7.0, 7.0), 0.0);
    // above 0.99 up to about 0.22·r: (1 − 0.22⁴)² ≈ 0.99531
    assert!(range_window(0.22 * 7.0, 7.0) > 0.99);
    // no range, no light
    assert_eq!(range_window(1.0, 0.0), 0.0);
    assert_eq!(range_window(1.0, f32::NAN), 0.0);
    assert!(range_window(f32::NAN, 1.0).is_nan());
}
