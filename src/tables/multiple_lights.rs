//! Chapter 6, Multiple lights: per-light contributions at sample fragments, in
//! the chapter's scene and the four atmospheres.
//!
//! Source: LearnOpenGL, Multiple lights (and its exercise's atmospheres).

use glam::Vec3;

use super::Fragment;
use crate::color::to_rgb8;
use crate::material::Material;
use crate::scene::{Atmosphere, Scene};
use crate::table::{rgb8, terms_row, vec3, Table};

/// The camera (and flashlight) position of every scene.
pub const VIEW_POS: Vec3 = Vec3::new(0.0, 0.0, 3.0);

/// The sample fragments: on the cube at the origin (faces at ±0.5) and on
/// DESIGN.md's quad-multi quad (`FragPos = (x·4/3, y, 0)`, `Normal = (x/2, y/2, 1)`
/// at NDC (x, y)).
pub const FRAGMENTS: [Fragment; 4] = [
    Fragment { name: "cube front centre", frag_pos: Vec3::new(0.0, 0.0, 0.5), normal: Vec3::Z },
    Fragment { name: "cube top centre", frag_pos: Vec3::new(0.0, 0.5, 0.0), normal: Vec3::Y },
    Fragment {
        name: "quad NDC (0.5, 0.25)",
        frag_pos: Vec3::new(0.5 * 4.0 / 3.0, 0.25, 0.0),
        normal: Vec3::new(0.25, 0.125, 1.0),
    },
    Fragment {
        name: "quad NDC (-0.75, -0.5)",
        frag_pos: Vec3::new(-0.75 * 4.0 / 3.0, -0.5, 0.0),
        normal: Vec3::new(-0.375, -0.25, 1.0),
    },
];

/// The chapter's tables: the default scene, then each atmosphere.
pub fn tables() -> Vec<Table> {
    tables_for(None, None)
}

/// The same tables for one atmosphere only (`Some`: the default scene and that one) and
/// with a fragment of your own after the chapter's (its normal need not be unit length: it
/// is normalized as the shader does, a zero normal staying zero).
pub fn tables_for(only: Option<Atmosphere>, yours: Option<Fragment>) -> Vec<Table> {
    let mut fragments = FRAGMENTS.to_vec();
    fragments.extend(yours);
    let mut tables = vec![scene_table_at("default scene", &Scene::learnopengl_default(), &fragments)];
    for atmosphere in Atmosphere::ALL.into_iter().filter(|a| only.is_none_or(|o| o == *a)) {
        tables.push(scene_table_at(atmosphere.name(), &atmosphere.scene(), &fragments));
    }
    tables
}

/// One scene's table: every light's terms at every sample fragment, the sum, and the clamped 8-bit color.
pub fn scene_table(name: &str, scene: &Scene) -> Table {
    scene_table_at(name, scene, &FRAGMENTS)
}

/// [`scene_table`] at the given fragments.
fn scene_table_at(name: &str, scene: &Scene, fragments: &[Fragment]) -> Table {
    let material = Material::coral();
    let mut t = Table::new(
        format!("Multiple lights, {name}: per-light terms"),
        "Material: the coral material (ambient = diffuse = (1, 0.5, 0.31), specular 0.5, shininess 32) in place of \
         the chapter's container maps. Eye and flashlight at (0, 0, 3) looking down −z. Point and spot terms are \
         × attenuation, spot terms also × intensity; specular is not gated by n·l. \"sum\" is unclamped; \
         \"clamped\" is clamp(sum, 0, 1), with its 8-bit value.",
        &["fragment", "light", "ambient", "diffuse", "specular", "total", "8-bit"],
    );
    for f in fragments {
        let shaded = scene.shade(&material, f.frag_pos, f.normal, VIEW_POS);
        for (id, terms) in &shaded.lights {
            t.push(terms_row(&[f.name, &id.to_string()], terms, &[String::new()]));
        }
        let sum = shaded.rgb();
        let cell = |s: &str| s.to_string();
        t.push(vec![f.name.to_string(), cell("sum"), cell(""), cell(""), cell(""), vec3(sum, 4), cell("")]);
        let clamped = sum.clamp(Vec3::ZERO, Vec3::ONE);
        t.push(vec![
            f.name.to_string(),
            cell("clamped"),
            cell(""),
            cell(""),
            cell(""),
            vec3(clamped, 4),
            rgb8(to_rgb8(sum)),
        ]);
    }
    t
}
