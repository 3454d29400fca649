//! Chapter 3, Materials: the 24 classic materials and how each looks at one fragment.
//!
//! Source: LearnOpenGL, Materials, and the devernay.free.fr table it links
//! (values from Kilgard's `teapots.c`, shininess as a fraction of 128).

use glam::Vec3;

use crate::color::to_rgb8;
use crate::material::{material_terms, LightProps, CLASSIC_MATERIALS};
use crate::table::{constant3, num32, rgb8, terms_row, vec3, Table};

/// The reference fragment: the origin with normal +z, light at the chapter's
/// (1.2, 1, 2), eye at (0, 0, 3).
pub const REFERENCE_LIGHT_POS: Vec3 = Vec3::new(1.2, 1.0, 2.0);

/// The chapter's tables: the values, then the shaded color under the exercise's white light
/// at [`REFERENCE_LIGHT_POS`].
pub fn tables() -> Vec<Table> {
    tables_for(REFERENCE_LIGHT_POS, &LightProps::white())
}

/// The same tables for a light of your own: its position and its ambient, diffuse and
/// specular intensities (`light.ambient`, `light.diffuse`, `light.specular`); the shaded
/// table's note prints the values used. A light at the fragment (zero direction) gives
/// `n·l = 0` and no highlight, as `normalize` of a zero vector is taken as zero here.
pub fn tables_for(light_pos: Vec3, light: &LightProps) -> Vec<Table> {
    let mut values = Table::new(
        "The 24 classic OpenGL materials",
        "Reflectances per channel, linear RGB, as the table prints them; the shader's exponent is the table's \
         shininess × 128.",
        &["material", "ambient", "diffuse", "specular", "shininess", "× 128"],
    );
    for m in &CLASSIC_MATERIALS {
        values.push(vec![
            m.name.to_string(),
            vec3(Vec3::from_array(m.ambient), 6),
            vec3(Vec3::from_array(m.diffuse), 6),
            vec3(Vec3::from_array(m.specular), 6),
            format!("{}", m.shininess_fraction),
            num32(m.shininess(), 2),
        ]);
    }
    let n = Vec3::Z;
    let light_dir = light_pos.normalize_or_zero();
    let view_dir = Vec3::Z;
    let v_dot_r = view_dir.dot(crate::glsl::reflect(-light_dir, n));
    let mut shaded = Table::new(
        "Classic materials shaded at one reference fragment",
        format!(
            "Fragment at the origin, normal +z, light at {} with {}, eye at (0, 0, 3): n·l = {}, v·r = {}. Sum \
             unclamped; 8-bit after clamping.",
            constant3(light_pos),
            light_words(light),
            num32(n.dot(light_dir), 4),
            num32(v_dot_r, 4)
        ),
        &["material", "ambient", "diffuse", "specular", "sum", "8-bit"],
    );
    for m in &CLASSIC_MATERIALS {
        let t = material_terms(&m.material(), light, n, light_dir, view_dir);
        shaded.push(terms_row(&[m.name], &t, &[rgb8(to_rgb8(t.sum()))]));
    }
    vec![values, shaded]
}

/// How the note names the light: the exercise's white light in its own words, any other by
/// its three intensities.
fn light_words(light: &LightProps) -> String {
    if *light == LightProps::white() {
        "ambient = diffuse = specular = 1 (the exercise's vec3(1.0))".to_string()
    } else {
        format!(
            "ambient {}, diffuse {}, specular {}",
            constant3(light.ambient),
            constant3(light.diffuse),
            constant3(light.specular)
        )
    }
}
