//! Chapter 1, Colors: the coral toy under colored lights.
//!
//! Source: LearnOpenGL, Colors (white, green and olive lights; the chapter
//! prints the olive result rounded to two decimals).

use glam::Vec3;

use super::{constant3, rgb8, vec3, Table};
use crate::color::{modulate, to_rgb8, CORAL};

/// (name, light color, the chapter's printed result if it prints one).
const LIGHTS: [(&str, Vec3, Option<&str>); 8] = [
    ("white", Vec3::ONE, Some("(1.0, 0.5, 0.31)")),
    ("green", Vec3::new(0.0, 1.0, 0.0), Some("(0.0, 0.5, 0.0)")),
    ("olive", Vec3::new(0.33, 0.42, 0.18), Some("(0.33, 0.21, 0.06)")),
    ("red", Vec3::new(1.0, 0.0, 0.0), None),
    ("blue", Vec3::new(0.0, 0.0, 1.0), None),
    ("half grey", Vec3::splat(0.5), None),
    ("warm white", Vec3::new(1.0, 0.9, 0.7), None),
    ("coral itself", CORAL, None),
];

/// The chapter's tables: coral under each light, published against exact.
pub fn tables() -> Vec<Table> {
    let mut t = Table::new(
        "Coral (1, 0.5, 0.31) under colored lights",
        "result = light ⊙ object, component-wise, linear RGB. \"published\" is what LearnOpenGL, Colors prints; \
         the olive row's blue 0.06 is 0.18 × 0.31 = 0.0558 rounded to two decimals. 8-bit = round(clamp(c) × 255).",
        &["light", "light color", "published", "recomputed (4 dp)", "8-bit"],
    );
    for (name, light, published) in LIGHTS {
        let result = modulate(light, CORAL);
        t.push(vec![
            name.to_string(),
            constant3(light),
            published.unwrap_or("—").to_string(),
            vec3(result, 4),
            rgb8(to_rgb8(result)),
        ]);
    }
    vec![t]
}
