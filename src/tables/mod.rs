//! Every worked table, once: the numbers behind each chapter as aligned text,
//! Markdown and CSV.
//!
//! | item | meaning |
//! | --- | --- |
//! | `<chapter>::tables()` | the chapter's tables, the single source for the examples, the snapshots and the book |
//! | [`chapters`] | every chapter's name and table function, in book order |
//! | [`CUBE_FRAGMENTS`] | the sample fragments of the basic-lighting and conventions tables |
//!
//! The table type ([`crate::table::Table`]), its formats and the cell
//! formatting ([`crate::table::num`], [`crate::table::vec3`]) live one layer
//! down, in [`crate::table`], which the errata and the study use too.

use glam::Vec3;

use crate::table::Table;

pub mod attenuation;
pub mod basic_lighting;
pub mod colors;
pub mod conventions;
pub mod errata;
pub mod lighting_maps;
pub mod materials;
pub mod multiple_lights;
pub mod normal_matrix;
pub mod specular;
pub mod spotlight;

/// A chapter's table function.
pub type TablesFn = fn() -> Vec<Table>;

/// Every chapter's name (as its example and generated file are named) and its
/// `tables()` function, in book order. The book generator and the snapshot
/// tests iterate over this list.
pub fn chapters() -> Vec<(&'static str, TablesFn)> {
    vec![
        ("colors", colors::tables),
        ("basic_lighting", basic_lighting::tables),
        ("specular", specular::tables),
        ("normal_matrix", normal_matrix::tables),
        ("materials", materials::tables),
        ("lighting_maps", lighting_maps::tables),
        ("attenuation", attenuation::tables),
        ("spotlight", spotlight::tables),
        ("multiple_lights", multiple_lights::tables),
        ("conventions", conventions::tables),
        ("errata", errata::tables),
    ]
}

/// A named fragment: position and (not necessarily unit) normal, world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fragment {
    /// Short name for the table.
    pub name: &'static str,
    /// `FragPos`, world space.
    pub frag_pos: Vec3,
    /// `Normal`, world space; normalized by the shader.
    pub normal: Vec3,
}

/// The sample fragments of the basic-lighting and conventions tables: the
/// chapter's unit cube at the origin (faces at ±0.5), seen from (0, 0, 3)
/// with the light at (1.2, 1, 2).
pub const CUBE_FRAGMENTS: [Fragment; 6] = [
    Fragment { name: "front centre", frag_pos: Vec3::new(0.0, 0.0, 0.5), normal: Vec3::Z },
    Fragment { name: "front corner", frag_pos: Vec3::new(0.5, 0.5, 0.5), normal: Vec3::Z },
    Fragment { name: "right centre", frag_pos: Vec3::new(0.5, 0.0, 0.0), normal: Vec3::X },
    Fragment { name: "top centre", frag_pos: Vec3::new(0.0, 0.5, 0.0), normal: Vec3::Y },
    Fragment { name: "left centre", frag_pos: Vec3::new(-0.5, 0.0, 0.0), normal: Vec3::NEG_X },
    Fragment { name: "back centre", frag_pos: Vec3::new(0.0, 0.0, -0.5), normal: Vec3::NEG_Z },
];
