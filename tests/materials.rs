//! Chapter 3, Materials: the material shader and the classic materials table.
use crate::common;

use common::{close3, color, config, unit_vec3};
use glam::Vec3;
use lightlab::material::{classic_material, material_terms, LightProps, Material, CLASSIC_MATERIALS};
use lightlab::reference::{self, dvec3};
use proptest::prelude::*;

fn material() -> impl Strategy<Value = Material> {
    (color(), color(), color(), 1.0f32..128.0).prop_map(|(ambient, diffuse, specular, shininess)| Material {
        ambient,
        diffuse,
        specular,
        shininess,
    })
}

fn light_props() -> impl Strategy<Value = LightProps> {
    (color(), color(), color()).prop_map(|(ambient, diffuse, specular)| LightProps { ambient, diffuse, specular })
}

/// A name as a user might type it: random case, and `_`, `-` or space between words.
fn name_variant() -> impl Strategy<Value = (usize, String)> {
    (0..CLASSIC_MATERIALS.len(), prop::collection::vec(any::<bool>(), 16), 0..3usize, any::<bool>()).prop_map(
        |(i, upper, sep, pad)| {
            let sep = [' ', '_', '-'][sep];
            let name: String = CLASSIC_MATERIALS[i]
                .name
                .chars()
                .enumerate()
                .map(|(k, c)| {
                    if c == ' ' {
                        sep
                    } else if upper[k % 16] {
                        c.to_ascii_uppercase()
                    } else {
                        c
                    }
                })
                .collect();
            (i, if pad { format!("  {name} ") } else { name })
        },
    )
}

proptest! {
    #![proptest_config(config())]

    /// Every classic row has reflectances in [0, 1] and a shader exponent
    /// fraction × 128 in (0, 128].
    #[test]
    fn classic_rows_are_in_range(i in 0..CLASSIC_MATERIALS.len()) {
        let row = &CLASSIC_MATERIALS[i];
        for (what, c) in [("ambient", row.ambient), ("diffuse", row.diffuse), ("specular", row.specular)] {
            prop_assert!(c.iter().all(|x| (0.0..=1.0).contains(x)), "{}: {what} {c:?}", row.name);
        }
        let s = row.shininess();
        prop_assert!(s > 0.0 && s <= 128.0, "{}: shininess {s}", row.name);
        prop_assert_eq!(s, row.shininess_fraction * 128.0);
        prop_assert_eq!(row.material().shininess, s);
    }

    /// `classic_material` finds every row under case, separator and padding variants.
    #[test]
    fn classic_material_finds_every_naming_variant((i, name) in name_variant()) {
        let found = classic_material(&name);
        prop_assert!(found.is_some(), "{name:?} not found");
        prop_assert_eq!(found.unwrap().name, CLASSIC_MATERIALS[i].name);
    }

    /// With non-negative light and material, each term is bounded by
    /// light ⊙ material (diff, spec ∈ [0, 1]), and ambient ignores geometry.
    #[test]
    fn material_terms_are_bounded(m in material(), l in light_props(), n in unit_vec3(), ld in unit_vec3(), v in unit_vec3()) {
        let t = material_terms(&m, &l, n, ld, v);
        prop_assert_eq!(t.ambient, l.ambient * m.ambient);
        // diff, spec ≤ 1 + 1e-4 (see basic_lighting::specular_in_unit_interval).
        let slack = 1.0 + 1e-4;
        prop_assert!(t.diffuse.cmple(l.diffuse * m.diffuse * slack).all() && t.diffuse.cmpge(Vec3::ZERO).all(), "diffuse {}", t.diffuse);
        prop_assert!(t.specular.cmple(l.specular * m.specular * slack).all() && t.specular.cmpge(Vec3::ZERO).all(), "specular {}", t.specular);
        let r = reference::material::material_terms(
            &reference::material::Material::from_f32(&m), &reference::material::LightProps::from_f32(&l),
            dvec3(n), dvec3(ld), dvec3(v));
        close3("reference ambient", r.ambient, dvec3(t.ambient), 1e-7)?;
    }

    /// The chapter's time-varying light: ambient = 0.1 × light colour, and
    /// channels in [−0.5, 0.5] (negative light, errata E6).
    #[test]
    fn time_varying_light_relations(t in -100.0f32..100.0) {
        let p = LightProps::time_varying(t);
        close3("ambient = 0.2 · diffuse", dvec3(p.diffuse) * 0.2, dvec3(p.ambient), 1e-7)?;
        prop_assert!(p.diffuse.abs().cmple(Vec3::splat(0.5)).all(), "diffuse {}", p.diffuse);
        prop_assert_eq!(p.specular, Vec3::ONE);
    }
}

#[test]
fn classic_table_and_lookup_edges() {
    assert_eq!(CLASSIC_MATERIALS.len(), 24);
    assert_eq!(classic_material("unobtainium"), None);
    assert_eq!(classic_material(""), None);
    assert_eq!(classic_material("cyan_plastic").unwrap().name, "cyan plastic");
    // Published: the cyan plastic exercise row (LearnOpenGL, Materials; Kilgard's teapots).
    let cyan = classic_material("Cyan Plastic").unwrap();
    assert_eq!(cyan.shininess(), 32.0);
    // NaN geometry: ambient survives, no panic.
    let t = material_terms(&Material::coral(), &LightProps::white(), Vec3::NAN, Vec3::Z, Vec3::Z);
    assert_eq!(t.ambient, lightlab::color::CORAL);
    assert_eq!(t.diffuse, Vec3::ZERO);
    let p = LightProps::time_varying(f32::NAN);
    assert!(p.diffuse.is_nan());
}
