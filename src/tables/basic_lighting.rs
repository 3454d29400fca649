//! Chapter 2, Basic lighting: ambient, diffuse and specular at sample fragments.
//!
//! Source: LearnOpenGL, Basic lighting: light at (1.2, 1, 2), eye at (0, 0, 3),
//! white light, coral object, ambient 0.1, specular strength 0.5, shininess 32.

use super::{num32, rgb8, vec3, Table, CUBE_FRAGMENTS};
use crate::color::to_rgb8;
use crate::glsl::reflect;
use crate::phong::{diffuse_factor, phong_specular_factor, BasicLighting};

/// The chapter's tables: the scalar factors, then the colored terms.
pub fn tables() -> Vec<Table> {
    let scene = BasicLighting::learnopengl();
    let mut factors = Table::new(
        "Basic lighting: factors at sample fragments",
        "Unit cube at the origin, light at (1.2, 1, 2), eye at (0, 0, 3). diff = max(n·l, 0); \
         spec = pow(max(v·r, 0), 32) with r = reflect(−l, n). The back face gets a specular factor although \
         n·l < 0: the chapter's shader does not gate specular by n·l.",
        &["fragment", "frag_pos", "n", "distance to light", "n·l", "diff", "v·r", "spec"],
    );
    let mut terms = Table::new(
        "Basic lighting: terms at sample fragments",
        "ambient = 0.1 · light ⊙ coral; diffuse = diff · light ⊙ coral; specular = 0.5 · spec · light ⊙ coral. \
         Sum unclamped; 8-bit after clamping to [0, 1].",
        &["fragment", "ambient", "diffuse", "specular", "sum", "8-bit"],
    );
    for f in CUBE_FRAGMENTS {
        let n = f.normal.normalize_or_zero();
        let light_dir = (scene.light_pos - f.frag_pos).normalize_or_zero();
        let view_dir = (scene.view_pos - f.frag_pos).normalize_or_zero();
        let v_dot_r = view_dir.dot(reflect(-light_dir, n));
        factors.push(vec![
            f.name.to_string(),
            vec3(f.frag_pos, 1),
            vec3(n, 0),
            num32(scene.light_pos.distance(f.frag_pos), 4),
            num32(n.dot(light_dir), 4),
            num32(diffuse_factor(n, light_dir), 4),
            num32(v_dot_r, 4),
            num32(phong_specular_factor(n, light_dir, view_dir, scene.shininess), 4),
        ]);
        let t = scene.terms(f.frag_pos, f.normal);
        terms.push(vec![
            f.name.to_string(),
            vec3(t.ambient, 4),
            vec3(t.diffuse, 4),
            vec3(t.specular, 4),
            vec3(t.sum(), 4),
            rgb8(to_rgb8(t.sum())),
        ]);
    }
    vec![factors, terms]
}
