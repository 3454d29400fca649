//! Chapter 4, Lighting maps: sampled diffuse, specular and emission, nearest against bilinear.
//!
//! Source: LearnOpenGL, Lighting maps; sampling rules of OpenGL 3.3 §3.8.11.
//! The container maps are lightlab's procedural stand-ins (`maps::container`).

use glam::Vec2;

use crate::maps::{container, Filter, Wrap};
use crate::table::{num32, vec3, Table};

/// Texture size of the procedural container in these tables, in texels.
pub const SIZE: usize = 64;

/// Sample coordinates: plank centre, a texel corner on the wood, the steel
/// frame, the frame/wood boundary, and a coordinate outside [0, 1].
pub const UVS: [(&str, [f32; 2]); 6] = [
    ("centre", [0.5, 0.5]),
    ("wood, texel corner", [0.25, 0.75]),
    ("steel frame", [0.03, 0.5]),
    ("frame/wood edge", [0.09375, 0.5]),
    ("emission stroke", [0.45, 0.35]),
    ("outside (repeat)", [1.03, 0.5]),
];

/// The chapter's table: every sample UV through both filters.
pub fn tables() -> Vec<Table> {
    tables_for(None)
}

/// The same table with a sample of your own (`yours`, last) after the chapter's; any
/// finite UV works, as GL_REPEAT wraps it into [0, 1).
pub fn tables_for(yours: Option<Vec2>) -> Vec<Table> {
    let maps = match container(SIZE, true) {
        Ok(m) => m,
        Err(e) => return vec![Table::new("Lighting maps", format!("could not build the container: {e}"), &[])],
    };
    let mut t = Table::new(
        format!("Container maps sampled at sample UVs ({SIZE}×{SIZE} texels, GL_REPEAT)"),
        "Nearest takes texel floor(u·w); bilinear blends the four texels around u·w − ½, so at a texel corner and \
         on the frame/wood edge the two differ. The specular map is grey (one channel shown). Emission is added \
         unlit.",
        &["sample", "uv", "filter", "diffuse", "specular", "emission"],
    );
    let chapter = UVS.iter().map(|&(name, uv)| (name, Vec2::from_array(uv)));
    for (name, uv) in chapter.chain(yours.map(|uv| ("yours", uv))) {
        for (filter_name, filter) in [("nearest", Filter::Nearest), ("bilinear", Filter::Bilinear)] {
            let material = maps.material_at(uv, filter, Wrap::Repeat);
            t.push(vec![
                name.to_string(),
                format!("({}, {})", uv.x, uv.y),
                filter_name.to_string(),
                vec3(material.diffuse, 4),
                num32(material.specular.x, 4),
                vec3(maps.emission_at(uv, filter, Wrap::Repeat), 4),
            ]);
        }
    }
    vec![t]
}
