//! Chapter 6, Multiple lights: per-light sums, monotonicity, presets.
use crate::common;

use common::{color, config, unit_vec3, vec3_in};
use glam::Vec3;
use lightlab::casters::{Attenuation, DirLight, PointLight, SpotLight};
use lightlab::material::{LightProps, Material};
use lightlab::scene::{Atmosphere, LightId, Scene};
use proptest::prelude::*;

fn props() -> impl Strategy<Value = LightProps> {
    (color(), color(), color()).prop_map(|(ambient, diffuse, specular)| LightProps { ambient, diffuse, specular })
}

fn point_light() -> impl Strategy<Value = PointLight> {
    (vec3_in(10.0), props(), 0.0f32..0.5, 0.0f32..0.1).prop_map(|(position, props, l, q)| PointLight {
        position,
        attenuation: Attenuation::new(1.0, l, q).unwrap(),
        props,
    })
}

fn spot_light() -> impl Strategy<Value = SpotLight> {
    (vec3_in(10.0), unit_vec3(), 1.0f32..40.0, 0.0f32..10.0, props()).prop_map(|(p, d, inner, gap, props)| {
        SpotLight::new(p, d, inner, inner + gap, Attenuation::LEARNOPENGL, props).unwrap()
    })
}

fn scene() -> impl Strategy<Value = Scene> {
    (
        prop::option::of((unit_vec3(), props()).prop_map(|(direction, props)| DirLight { direction, props })),
        prop::collection::vec(point_light(), 0..5),
        prop::option::of(spot_light()),
    )
        .prop_map(|(dir_light, point_lights, spot_light)| Scene {
            dir_light,
            point_lights,
            spot_light,
            clear_color: Vec3::ZERO,
        })
}

fn material() -> impl Strategy<Value = Material> {
    (color(), color(), color(), 1.0f32..128.0).prop_map(|(ambient, diffuse, specular, shininess)| Material {
        ambient,
        diffuse,
        specular,
        shininess,
    })
}

proptest! {
    #![proptest_config(config())]

    /// Shading the chapter's scene never panics for any `f32` fragment and
    /// normal (NaN, ±∞ included), in both paths; finite inputs give finite output.
    #[test]
    fn shading_any_input_never_panics(f in prop::array::uniform3(proptest::num::f32::ANY), n in prop::array::uniform3(proptest::num::f32::ANY)) {
        let s = Scene::learnopengl_default();
        let (frag, normal) = (Vec3::from_array(f), Vec3::from_array(n));
        let eye = Vec3::new(0.0, 0.0, 3.0);
        let rgb = s.shade(&Material::coral(), frag, normal, eye).rgb();
        let sd = lightlab::reference::scene::Scene::from_f32(&s);
        let md = lightlab::reference::material::Material::from_f32(&Material::coral());
        let rgb_d = sd.shade(&md, frag.as_dvec3(), normal.as_dvec3(), eye.as_dvec3()).rgb();
        // Finite, moderate inputs away from the lights: finite output.
        let near_light = s.point_lights.iter().any(|p| p.position.distance(frag) < 1e-3) || eye.distance(frag) < 1e-3;
        if frag.is_finite() && frag.abs().max_element() < 1e6 && normal.is_finite() && !near_light {
            prop_assert!(rgb.is_finite() && rgb_d.is_finite(), "frag {frag} normal {normal}: {rgb} / {rgb_d}");
        }
    }

    /// The sum of the per-light terms is `rgb()`, and the lights come in shader order.
    #[test]
    fn per_light_terms_sum_to_rgb(s in scene(), m in material(), frag in vec3_in(5.0), normal in unit_vec3(), eye in vec3_in(10.0)) {
        let shaded = s.shade(&m, frag, normal, eye);
        let expected = s.dir_light.is_some() as usize + s.point_lights.len() + s.spot_light.is_some() as usize;
        prop_assert_eq!(shaded.lights.len(), expected);
        let mut total = Vec3::ZERO;
        for (_, t) in &shaded.lights { total += t.ambient + t.diffuse + t.specular; }
        // Same additions in a different grouping: ≤ (number of terms) · U · |total| ≲ 1e-5 for totals ≲ 20.
        prop_assert!((total - shaded.rgb()).abs().max_element() <= 1e-5, "sum {total} vs rgb {}", shaded.rgb());
        if let Some((id, _)) = shaded.lights.first() {
            prop_assert_eq!(*id, if s.dir_light.is_some() { LightId::Dir } else if s.point_lights.is_empty() { LightId::Spot } else { LightId::Point(0) });
        }
    }

    /// Adding a light with non-negative properties never darkens any channel.
    #[test]
    fn adding_a_light_never_darkens(s in scene(), extra in point_light(), m in material(), frag in vec3_in(5.0), normal in unit_vec3(), eye in vec3_in(10.0)) {
        let before = s.shade(&m, frag, normal, eye).rgb();
        let mut more = s.clone();
        more.point_lights.push(extra);
        let after = more.shade(&m, frag, normal, eye).rgb();
        // f32 summation order changes by one term: allow U · |before| rounding.
        prop_assert!(after.cmpge(before - before.abs() * 1e-6).all(), "before {before}, after {after}");
    }

    /// Every term of every light is non-negative when all inputs are.
    #[test]
    fn terms_are_non_negative(s in scene(), m in material(), frag in vec3_in(5.0), normal in unit_vec3(), eye in vec3_in(10.0)) {
        for (id, t) in s.shade(&m, frag, normal, eye).lights {
            prop_assert!(t.ambient.min(t.diffuse).min(t.specular).min_element() >= 0.0, "{id}: {t:?}");
        }
    }

    /// A scene with one directional light shades like the light alone.
    #[test]
    fn single_light_scene_is_that_light(direction in unit_vec3(), p in props(), m in material(), frag in vec3_in(5.0), normal in unit_vec3(), eye in vec3_in(10.0)) {
        prop_assume!(eye.distance(frag) > 1e-3);
        let d = DirLight { direction, props: p };
        let s = Scene { dir_light: Some(d), point_lights: vec![], spot_light: None, clear_color: Vec3::ZERO };
        let got = s.shade(&m, frag, normal, eye);
        prop_assert_eq!(got.lights[0].1, d.terms(&m, normal.normalize(), (eye - frag).normalize()));
    }
}

#[test]
fn presets_are_complete() {
    let s = Scene::learnopengl_default();
    assert_eq!(s.point_lights.len(), 4);
    assert!(s.dir_light.is_some() && s.spot_light.is_some());
    for a in Atmosphere::ALL {
        let s = a.scene();
        assert_eq!(s.point_lights.len(), 4, "{}", a.name());
        assert!(s.spot_light.is_some(), "{}: spot light rejected", a.name());
        assert_eq!(Atmosphere::from_name(a.name()), Some(a));
    }
}

#[test]
fn degenerate_fragments() {
    let s = Scene::learnopengl_default();
    let m = Material::coral();
    // At the eye (which holds the flashlight), a zero normal, a NaN position: no panic.
    for (frag, normal) in [(Vec3::new(0.0, 0.0, 3.0), Vec3::Z), (Vec3::ZERO, Vec3::ZERO), (Vec3::NAN, Vec3::Z)] {
        let _ = s.shade(&m, frag, normal, Vec3::new(0.0, 0.0, 3.0)).rgb();
    }
    let z = s.shade(&m, Vec3::ZERO, Vec3::ZERO, Vec3::new(0.0, 0.0, 3.0));
    for (id, t) in &z.lights {
        assert_eq!(t.diffuse + t.specular, Vec3::ZERO, "{id}: zero normal must give ambient only");
    }
}
