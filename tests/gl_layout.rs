//! The packed layouts are the single description of every model's inputs: the case
//! generators write through them, the reports label with them, and the JSON export says
//! the same. No OpenGL needed.
#![cfg(all(feature = "gl", feature = "book"))]

use lightlab::gl::layout::{self, Layout, LayoutId, Packed, QType, Row, Slot};
use lightlab::gl::{models, ModelId, Uniform};
use lightlab::oracle::cases::{self, CASE_MODELS};
use lightlab::scene::Scene;

/// Every component a quantity occupies in `row`.
fn components(layout: &Layout, q: &layout::Quantity, row: &[[f32; 4]]) -> Vec<f32> {
    let Slot::Case { input, offset } = q.slot else { return Vec::new() };
    assert!(input < layout.n_inputs());
    (0..q.components).map(|i| row[input + (offset + i) / 4][(offset + i) % 4]).collect()
}

#[test]
fn generated_cases_fit_the_layout_and_its_ranges() {
    for m in &CASE_MODELS {
        let rows = cases::generate(&cases::strategy(m.id), 3000, cases::seed_bytes(7, 0)).unwrap();
        for row in &rows {
            assert_eq!(row.len(), m.layout.n_inputs(), "{}: row length", m.id);
            for q in m.layout.quantities {
                let Some((lo, hi)) = q.range else { continue };
                for x in components(m.layout, q, row) {
                    assert!(x >= lo && x <= hi, "{}: {} = {x} outside [{lo}, {hi}]", m.id, q.name);
                }
            }
        }
        // No component outside every quantity is written (the unused ones stay 0).
        let mut used = vec![[false; 4]; m.layout.n_inputs()];
        for q in m.layout.quantities {
            if let Slot::Case { input, offset } = q.slot {
                for i in 0..q.components {
                    used[input + (offset + i) / 4][(offset + i) % 4] = true;
                }
            }
        }
        for row in &rows {
            for (k, v) in row.iter().enumerate() {
                for c in 0..4 {
                    assert!(used[k][c] || v[c] == 0.0, "{}: input {k}.{c} is written but no quantity owns it", m.id);
                }
            }
        }
    }
}

#[test]
fn quantities_do_not_overlap() {
    for l in layout::LAYOUTS {
        let mut owner = vec![[None::<&str>; 4]; l.n_inputs()];
        for q in l.quantities {
            if let Slot::Case { input, offset } = q.slot {
                for i in 0..q.components {
                    let cell = &mut owner[input + (offset + i) / 4][(offset + i) % 4];
                    assert!(cell.is_none(), "{}: {} overlaps {:?}", l.id, q.name, cell);
                    *cell = Some(q.name);
                }
            }
        }
    }
}

#[test]
fn the_labels_follow_the_quantities() {
    let labels = layout::BASIC_LIGHTING.input_labels();
    assert_eq!(labels[0], "FragPos.xyz, ambientStrength");
    assert_eq!(labels[3], "viewPos.xyz, -");
    assert_eq!(labels[4], "lightColor.rgb, -");
    assert_eq!(layout::GOURAUD.input_labels()[7], "model column 1");
    assert_eq!(layout::POINT.input_labels()[9], "light.constant, light.linear, light.quadratic, -");
    assert_eq!(layout::OGLDEV19.input_labels()[5], "sampled texel rgba");
    for m in models::MODELS {
        assert_eq!(m.inputs().len(), m.layout.n_inputs(), "{}", m.id);
        assert_eq!(m.outputs().len(), m.layout.n_outputs(), "{}", m.id);
    }
}

#[test]
fn packed_and_row_round_trip() {
    let l = &layout::SPOT;
    let pos = l.get("light.position");
    let cut = l.get("light.cutOff");
    let kq = l.get("light.quadratic");
    let row = Packed::new(l).vec3(pos, glam::Vec3::new(1.0, 2.0, 3.0)).float(cut, 0.9).float(kq, 0.25).into_row();
    let r = Row(&row);
    assert_eq!(r.vec3(pos), glam::Vec3::new(1.0, 2.0, 3.0));
    assert_eq!(r.float(cut), 0.9);
    assert_eq!(r.float(kq), 0.25);
    assert_eq!(row[5], [1.0, 2.0, 3.0, 0.9]);
    assert_eq!(row[10], [0.0, 0.0, 0.25, 0.0]);
}

#[test]
fn the_multiple_lights_uniforms_are_the_core_scene() {
    let u = models::MULTIPLE_LIGHTS.uniforms();
    // 4 + 4 × 7 + 10 uniforms: the directional light, four point lights, the flashlight.
    assert_eq!(u.len(), 42);
    let scene = Scene::learnopengl_default();
    assert_eq!(u, layout::scene_uniforms(&scene));
    let find = |name: &str| u.iter().find(|(n, _)| n == name).map(|(_, v)| *v);
    assert_eq!(find("pointLights[2].position"), Some(Uniform::Vec3([-4.0, 2.0, -12.0])));
    assert_eq!(find("spotLight.direction"), Some(Uniform::Vec3([0.0, 0.0, -1.0])));
    assert!(models::BASIC_LIGHTING.uniforms().is_empty());
}

#[test]
fn the_json_export_is_deterministic_and_says_what_the_layouts_say() {
    let text = layout::export_json();
    assert_eq!(text, layout::export_json());
    let json: serde_json::Value = serde_json::from_str(&text).expect("valid JSON");
    assert_eq!(json["schema"], 1);
    let models_json = json["models"].as_array().unwrap();
    assert_eq!(models_json.len(), CASE_MODELS.len());
    for (m, j) in CASE_MODELS.iter().zip(models_json) {
        assert_eq!(j["model"], m.name());
        assert_eq!(j["n_inputs"], m.n_inputs);
        assert_eq!(j["tutorial_shader"], m.shader.is_some());
        let labels: Vec<String> = j["inputs"].as_array().unwrap().iter().map(|s| s.as_str().unwrap().into()).collect();
        assert_eq!(labels, m.layout.input_labels());
        let qs = j["quantities"].as_array().unwrap();
        assert_eq!(qs.len(), m.quantities.len());
        for (q, jq) in m.quantities.iter().zip(qs) {
            assert_eq!(jq["name"], q.name);
            assert_eq!(jq["components"], q.components);
            match q.slot {
                Slot::Case { input, offset } => {
                    assert_eq!(
                        (jq["storage"].as_str(), jq["input"].as_u64(), jq["offset"].as_u64()),
                        (Some("case"), Some(input as u64), Some(offset as u64))
                    );
                }
                Slot::Group => assert_eq!(jq["storage"], "group"),
                Slot::Unused => assert_eq!(jq["storage"], "unused"),
            }
            let ty = match q.ty {
                QType::Float => "float",
                QType::Vec2 => "vec2",
                QType::Vec3 => "vec3",
                QType::Texel => "texel",
                QType::Mat4 => "mat4",
            };
            assert_eq!(jq["type"], ty);
        }
    }
    let multi = models_json.iter().find(|j| j["model"] == "multiple_lights").unwrap();
    assert_eq!(multi["uniforms"].as_array().unwrap().len(), 42);
    assert_eq!(multi["uniforms"][0]["name"], "dirLight.direction");
    let basic = models_json.iter().find(|j| j["model"] == "basic_lighting").unwrap();
    let shininess = basic["quantities"].as_array().unwrap().iter().find(|q| q["name"] == "shininess").unwrap();
    assert_eq!(shininess["default"], serde_json::json!([32.0, 32.0, 32.0]));
    assert_eq!(ModelId::NormalMatrix.case_model().layout.id, LayoutId::Model(ModelId::NormalMatrix));
    for m in ModelId::ALL {
        assert_eq!(m.layout().id, LayoutId::Model(m));
        assert_eq!(m.case_model().id, m);
        assert!(m.shader().is_none_or(|s| s.id == m && s.layout.id == LayoutId::Model(m)), "{m}");
    }
}

#[test]
fn the_cli_prints_the_layouts() {
    let out =
        std::process::Command::new(env!("CARGO_BIN_EXE_lightlab")).args(["oracle", "--layouts"]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(String::from_utf8(out.stdout).unwrap(), layout::export_json());
}

#[test]
fn no_harness_spells_an_input_position() {
    for m in models::MODELS {
        let harness = m.harness();
        let defines = m.layout.glsl_defines();
        let own = &harness[defines.len()..];
        let positional = own.match_indices("v[").any(|(i, _)| own[i + 2..].starts_with(|c: char| c.is_ascii_digit()));
        assert!(!positional, "{}: the harness reads v[k] directly instead of an IN_ macro", m.id);
        for q in m.layout.quantities.iter().filter(|q| matches!(q.slot, Slot::Case { .. })) {
            let name: String = q.name.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
            assert!(defines.contains(&format!("#define IN_{name} ")), "{}: no macro for {}", m.id, q.name);
        }
    }
}

#[test]
fn the_spot_chapter_cut_offs_are_the_cosines_of_its_angles() {
    let (inner, outer) = layout::SPOT_CUT_OFFS;
    assert_eq!(inner.to_bits(), 12.5f32.to_radians().cos().to_bits(), "{inner} vs {}", 12.5f32.to_radians().cos());
    assert_eq!(outer.to_bits(), 17.5f32.to_radians().cos().to_bits(), "{outer} vs {}", 17.5f32.to_radians().cos());
    let spot = ModelId::Spot.layout();
    assert_eq!(spot.find("light.cutOff").unwrap().default, Some([inner; 3]));
    assert_eq!(spot.find("light.quadratic").unwrap().default, Some([0.032; 3]));
}
