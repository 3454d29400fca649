//! Chapter 1, Colors: the coral toy under colored lights.
//!
//! Source: LearnOpenGL, Colors (white, green and olive lights; the chapter
//! prints the olive result rounded to two decimals).

use glam::Vec3;

use crate::color::{modulate, to_rgb8, CORAL};
use crate::table::{constant3, rgb8, vec3, Table};

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
    tables_for(CORAL, None)
}

/// The same table for any `toyColor` (`object`), with `extra` (a `lightColor`
/// of your own) as a last row named "yours". Published values are shown only
/// for coral, the object the chapter prints them for.
pub fn tables_for(object: Vec3, extra: Option<Vec3>) -> Vec<Table> {
    let (title, note) = if object == CORAL {
        (
            "Coral (1, 0.5, 0.31) under colored lights".to_string(),
            "result = light ⊙ object, component-wise, linear RGB. \"published\" is what LearnOpenGL, Colors prints; \
             the olive row's blue 0.06 is 0.18 × 0.31 = 0.0558 rounded to two decimals. 8-bit = round(clamp(c) × 255)."
                .to_string(),
        )
    } else {
        (
            format!("Object ({}, {}, {}) under colored lights", object.x, object.y, object.z),
            "result = light ⊙ object, component-wise, linear RGB. LearnOpenGL, Colors prints results for coral \
             only, so \"published\" is empty. 8-bit = round(clamp(c) × 255)."
                .to_string(),
        )
    };
    let mut t = Table::new(title, note, &["light", "light color", "published", "recomputed (4 dp)", "8-bit"]);
    let yours = extra.map(|light| ("yours", light, None));
    for (name, light, published) in LIGHTS.into_iter().chain(yours) {
        let published = if object == CORAL { published } else { None };
        let result = modulate(light, object);
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
