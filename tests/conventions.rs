//! Three tutorials, three conventions: LearnOpenGL, opengl-tutorial 8, ogldev 19.
use crate::common;

use common::{close, config, unit_vec3, vec3_in};
use glam::Vec3;
use lightlab::glsl::reflect;
use lightlab::material::{material_terms, LightProps, Material};
use lightlab::models::{Ogldev, OpenGLTutorial, ShadingModel};
use lightlab::phong::{diffuse_factor, phong_specular_factor};
use lightlab::reference;
use proptest::prelude::*;

fn ogldev(direction: Vec3, power: f32) -> Ogldev {
    Ogldev {
        color: Vec3::ONE,
        ambient_intensity: 0.1,
        diffuse_intensity: 0.8,
        direction,
        specular_intensity: 1.0,
        specular_power: power,
        texture_color: Vec3::ONE,
    }
}

/// A unit light direction `depth_deg` below the horizon of `n`, at `azimuth` around it.
fn below_horizon(n: Vec3, azimuth: f32, depth_deg: f32) -> Vec3 {
    let (t, b) = n.any_orthonormal_pair();
    let tangent = azimuth.cos() * t + azimuth.sin() * b;
    (tangent * depth_deg.to_radians().cos() - n * depth_deg.to_radians().sin()).normalize()
}

proptest! {
    #![proptest_config(config())]

    /// ogldev gates the specular by n·l: whenever n·l ≤ 0 its specular is 0, for every view.
    #[test]
    fn ogldev_specular_is_zero_when_light_is_behind(n in unit_vec3(), l in unit_vec3(), frag in vec3_in(5.0), eye in vec3_in(10.0), power in 1.0f32..128.0) {
        prop_assume!(n.dot(l) <= 0.0);
        let t = ogldev(-l, power).terms(frag, n, eye);
        prop_assert_eq!(t.specular, Vec3::ZERO);
        prop_assert_eq!(t.diffuse, Vec3::ZERO);
        let r = reference::models::Ogldev::from_f32(&ogldev(-l, power)).terms(frag.as_dvec3(), n.as_dvec3(), eye.as_dvec3());
        prop_assert_eq!(r.specular, glam::DVec3::ZERO);
    }

    /// LearnOpenGL does not gate: for every light up to 26° below the horizon and
    /// the eye at −light_dir (above the surface), its specular is > 0 while its
    /// diffuse and ogldev's specular are 0. v·r = cos²δ − sin²δ = cos 2δ ≥ 0.6.
    #[test]
    fn learnopengl_specular_leaks_below_the_horizon(n in unit_vec3(), azimuth in 0.0f32..std::f32::consts::TAU, depth in 0.5f32..26.0, power in 1.0f32..128.0) {
        let l = below_horizon(n, azimuth, depth);
        let v = -l;
        prop_assert!(n.dot(l) < 0.0 && n.dot(v) > 0.0);
        let m = Material { shininess: power, ..Material::coral() };
        let t = material_terms(&m, &LightProps::white(), n, l, v);
        prop_assert_eq!(t.diffuse, Vec3::ZERO);
        // spec ≥ 0.6^128 ≈ 4e-29 > 0, no f32 underflow.
        prop_assert!(t.specular.min_element() > 0.0, "learnopengl specular {}", t.specular);
        let o = ogldev(-l, power).terms(Vec3::ZERO, n, v);
        prop_assert_eq!(o.specular, Vec3::ZERO);
    }

    /// Where both gates are open (n·l > 0, v·r > 0), ogldev's specular factor
    /// equals LearnOpenGL's for the same exponent.
    #[test]
    fn ogldev_and_learnopengl_agree_when_lit(n in unit_vec3(), l in unit_vec3(), v in unit_vec3(), power in 1.0f32..128.0) {
        prop_assume!(n.dot(l) > 0.01 && v.dot(reflect(-l, n)) > 0.01);
        let o = ogldev(-l, power).terms(Vec3::ZERO, n, v);
        let spec = phong_specular_factor(n, l, v, power);
        // ogldev renormalizes reflect_dir: base differs by ~4U, × power: 128 · 8U ≈ 6e-5.
        close("specular factor", spec as f64, o.specular.x as f64, 1e-4)?;
        close("diffuse factor", 0.8 * diffuse_factor(n, l) as f64, o.diffuse.x as f64, 1e-6)?;
    }

    /// opengl-tutorial's clamp(n·l, 0, 1) equals LearnOpenGL's max(n·l, 0) for
    /// unit vectors, so the two diffuse terms differ only by LightPower/d².
    #[test]
    fn opengl_tutorial_diffuse_is_inverse_square(light in vec3_in(10.0), frag in vec3_in(5.0), n in unit_vec3(), eye in vec3_in(10.0)) {
        prop_assume!(light.distance(frag) > 0.5);
        let m = OpenGLTutorial::with_defaults(light, Vec3::ONE);
        let t = m.terms(frag, n, eye);
        let l = (light - frag).normalize();
        let expected = diffuse_factor(n, l) * 50.0 / light.distance_squared(frag);
        close("diffuse", expected as f64, t.diffuse.x as f64, 1e-5 * (1.0 + expected as f64))?;
        prop_assert_eq!(t.ambient, Vec3::splat(0.1));
    }

    /// Shading model names round-trip.
    #[test]
    fn shading_model_names_round_trip(i in 0..4usize) {
        let m = ShadingModel::ALL[i];
        prop_assert_eq!(ShadingModel::from_name(m.name()), Some(m));
    }
}

#[test]
fn constructed_witness_learnopengl_leaks_ogldev_does_not() {
    // n = +z, light 10° below the horizon along +x, eye along −light_dir.
    let n = Vec3::Z;
    let l = below_horizon(n, 0.0, 10.0);
    let v = -l;
    let spec = phong_specular_factor(n, l, v, 32.0);
    // v·r = cos 20° = 0.9397; 0.9397^32 = 0.1363.
    assert!((spec - 20f32.to_radians().cos().powf(32.0)).abs() < 1e-5, "{spec}");
    assert!(spec > 0.13, "LearnOpenGL lights a surface facing away from the light: spec = {spec}");
    assert_eq!(ogldev(-l, 32.0).terms(Vec3::ZERO, n, v).specular, Vec3::ZERO);
}

#[test]
fn degenerate_models() {
    // opengl-tutorial: fragment at the light gives infinite diffuse (documented), zero normal gives ambient only.
    let m = OpenGLTutorial::with_defaults(Vec3::ONE, Vec3::ONE);
    let t = m.terms(Vec3::ZERO, Vec3::ZERO, Vec3::new(-1.0, -1.0, -1.0));
    assert_eq!(t.diffuse + t.specular, Vec3::ZERO, "zero normal: {t:?}");
    let r = reference::models::OpenGLTutorial::from_f32(&m).terms(
        glam::DVec3::ZERO,
        glam::DVec3::ZERO,
        glam::DVec3::splat(-1.0),
    );
    assert_eq!(r.diffuse + r.specular, glam::DVec3::ZERO);
    let _ = m.terms(Vec3::ONE, Vec3::Z, Vec3::ZERO); // d = 0: no panic
                                                     // ogldev with a NaN normal or a zero direction: ambient only.
    let o = ogldev(Vec3::ZERO, 32.0);
    assert_eq!(o.terms(Vec3::ZERO, Vec3::Z, Vec3::Z).diffuse, Vec3::ZERO);
    assert_eq!(ogldev(-Vec3::Z, 32.0).terms(Vec3::ZERO, Vec3::NAN, Vec3::Z).specular, Vec3::ZERO);
    assert_eq!(ShadingModel::from_name("phong"), None);
}
