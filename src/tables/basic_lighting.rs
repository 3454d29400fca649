//! Chapter 2, Basic lighting: ambient, diffuse and specular at sample fragments.
//!
//! Source: LearnOpenGL, Basic lighting: light at (1.2, 1, 2), eye at (0, 0, 3),
//! white light, coral object, ambient 0.1, specular strength 0.5, shininess 32.

use glam::Vec3;

use super::CUBE_FRAGMENTS;
use crate::color::{to_rgb8, CORAL};
use crate::glsl::reflect;
use crate::phong::{diffuse_factor, phong_specular_factor, BasicLighting};
use crate::table::{num32, rgb8, terms_row, vec3, Table};

/// The chapter's tables: the scalar factors, then the colored terms.
pub fn tables() -> Vec<Table> {
    tables_for(&BasicLighting::learnopengl())
}

/// `(x, y, z)` with each number in its shortest form (`(1.2, 1, 2)`).
fn short3(v: Vec3) -> String {
    format!("({}, {}, {})", v.x, v.y, v.z)
}

/// The same tables for any values of the chapter's uniforms (`lightPos`,
/// `viewPos`, `lightColor`, `objectColor`, `ambientStrength`,
/// `specularStrength` and the exponent); the notes print the values used.
pub fn tables_for(scene: &BasicLighting) -> Vec<Table> {
    let light = if scene.light_color == Vec3::ONE {
        "light".to_string()
    } else {
        format!("light {}", short3(scene.light_color))
    };
    let object = if scene.object_color == CORAL { "coral".to_string() } else { short3(scene.object_color) };
    let mut factors = Table::new(
        "Basic lighting: factors at sample fragments",
        format!(
            "Unit cube at the origin, light at {}, eye at {}. diff = max(n·l, 0); \
             spec = pow(max(v·r, 0), {}) with r = reflect(−l, n).",
            short3(scene.light_pos),
            short3(scene.view_pos),
            scene.shininess
        ),
        &["fragment", "frag_pos", "n", "distance to light", "n·l", "diff", "v·r", "spec"],
    );
    let mut terms = Table::new(
        "Basic lighting: terms at sample fragments",
        format!(
            "ambient = {a} · {light} ⊙ {object}; diffuse = diff · {light} ⊙ {object}; \
             specular = {s} · spec · {light} ⊙ {object}. Sum unclamped; 8-bit after clamping to [0, 1].",
            a = scene.ambient_strength,
            s = scene.specular_strength,
        ),
        &["fragment", "ambient", "diffuse", "specular", "sum", "8-bit"],
    );
    let mut ungated = Vec::new();
    for f in CUBE_FRAGMENTS {
        let n = f.normal.normalize_or_zero();
        let light_dir = (scene.light_pos - f.frag_pos).normalize_or_zero();
        let view_dir = (scene.view_pos - f.frag_pos).normalize_or_zero();
        let v_dot_r = view_dir.dot(reflect(-light_dir, n));
        let spec = phong_specular_factor(n, light_dir, view_dir, scene.shininess);
        if n.dot(light_dir) < 0.0 && spec > 0.0 {
            ungated.push(f.name);
        }
        factors.push(vec![
            f.name.to_string(),
            vec3(f.frag_pos, 1),
            vec3(n, 0),
            num32(scene.light_pos.distance(f.frag_pos), 4),
            num32(n.dot(light_dir), 4),
            num32(diffuse_factor(n, light_dir), 4),
            num32(v_dot_r, 4),
            num32(spec, 4),
        ]);
        let t = scene.terms(f.frag_pos, f.normal);
        terms.push(terms_row(&[f.name], &t, &[rgb8(to_rgb8(t.sum()))]));
    }
    let who = match ungated.as_slice() {
        [] => None,
        ["back centre"] => Some("The back face gets".to_string()),
        names => Some(format!("The fragments {} get", names.join(", "))),
    };
    if let Some(who) = who {
        factors.note.push_str(&format!(
            " {who} a specular factor although n·l < 0: the chapter's shader does not gate specular by n·l."
        ));
    }
    vec![factors, terms]
}
