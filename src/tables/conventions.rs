//! The three tutorials' conventions on the same fragments, with the cause of each difference.
//!
//! Sources: LearnOpenGL, Basic lighting; opengl-tutorial 8; ogldev 19.

use glam::Vec3;

use super::{Fragment, CUBE_FRAGMENTS};
use crate::color::CORAL;
use crate::table::{constant3, num32, terms_row, vec3, Table};
// Re-exported: the errata cite the ogldev light by this path (`errata::ogldev`, "power-32").
pub use crate::models::ogldev_comparable;
use crate::models::OpenGLTutorial;
use crate::phong::{BasicLighting, Terms};

/// The chapter's tables: the terms of each model, then the differences and their causes.
pub fn tables() -> Vec<Table> {
    tables_for(BasicLighting::learnopengl().light_pos)
}

/// The same tables with the light at `light_pos` for all three models (the ogldev light
/// travels from there toward the origin); the notes print the position used.
pub fn tables_for(light_pos: Vec3) -> Vec<Table> {
    let learn = BasicLighting { light_pos, ..BasicLighting::learnopengl() };
    let tutorial = OpenGLTutorial::with_defaults(learn.light_pos, CORAL);
    let ogldev = ogldev_comparable(learn.light_pos);
    let mut terms = Table::new(
        "Three conventions on the same fragments",
        format!(
            "Unit cube at the origin, eye at (0, 0, 3), coral surface, white light at {pos}. learnopengl: \
             Basic lighting (ambient 0.1, specular strength 0.5, shininess 32). opengl-tutorial: power {} / d², \
             ambient {} × diffuse, specular {} grey, exponent {}. ogldev: a directional light along \
             −normalize{pos}, ambient 0.1, diffuse 1, specular intensity 0.5, power 32, × texture (coral).",
            tutorial.light_power,
            tutorial.ambient_factor,
            tutorial.specular.x,
            tutorial.exponent,
            pos = constant3(light_pos)
        ),
        &["fragment", "model", "ambient", "diffuse", "specular", "sum"],
    );
    let mut causes = Table::new(
        "Why the conventions differ, fragment by fragment",
        "Difference = model sum − learnopengl sum (linear RGB); cause names what makes the difference largest here.",
        &["fragment", "model", "difference", "cause"],
    );
    for f in CUBE_FRAGMENTS {
        let l = learn.terms(f.frag_pos, f.normal);
        let o = tutorial.terms(f.frag_pos, f.normal, learn.view_pos);
        let g = ogldev.terms(f.frag_pos, f.normal, learn.view_pos);
        for (model, t) in [("learnopengl", l), ("opengl-tutorial", o), ("ogldev", g)] {
            terms.push(terms_row(&[f.name, model], &t, &[]));
        }
        causes.push(vec![
            f.name.to_string(),
            "opengl-tutorial".into(),
            vec3(o.sum() - l.sum(), 4),
            tutorial_cause(&f, &tutorial, &l, &o),
        ]);
        causes.push(vec![
            f.name.to_string(),
            "ogldev".into(),
            vec3(g.sum() - l.sum(), 4),
            ogldev_cause(&f, &learn, &l, &g),
        ]);
    }
    vec![terms, causes]
}

fn tutorial_cause(f: &Fragment, tutorial: &OpenGLTutorial, l: &Terms, o: &Terms) -> String {
    let d = tutorial.light_pos.distance(f.frag_pos);
    let falloff = tutorial.light_power / (d * d);
    let mut cause = format!("power/d² = {} scales diffuse and specular", num32(falloff, 3));
    if o.specular.max_element() > 0.0 || l.specular.max_element() > 0.0 {
        cause.push_str("; exponent 5 (not 32) widens the highlight, specular grey 0.3 not tinted");
    }
    if o.diffuse == Vec3::ZERO {
        cause = if o.specular.max_element() > 0.0 {
            format!(
                "n·l ≤ 0, no diffuse; but specular pow(clamp(E·R), 5) is not gated and power/d² = {} makes it bright",
                num32(falloff, 3)
            )
        } else {
            "n·l ≤ 0 and E·R ≤ 0: both give ambient only (0.1 × diffuse = 0.1 × coral here)".to_string()
        };
    }
    cause
}

fn ogldev_cause(f: &Fragment, learn: &BasicLighting, l: &Terms, g: &Terms) -> String {
    let n = f.normal.normalize_or_zero();
    let point_dir = (learn.light_pos - f.frag_pos).normalize_or_zero();
    let dir = learn.light_pos.normalize_or_zero();
    let angle = point_dir.dot(dir).clamp(-1.0, 1.0).acos().to_degrees();
    if n.dot(dir) <= 0.0 && l.specular.max_element() > 0.0 {
        return "n·l ≤ 0: ogldev skips specular, learnopengl keeps an ungated highlight".to_string();
    }
    if n.dot(dir) <= 0.0 {
        return "n·l ≤ 0: both give ambient only".to_string();
    }
    let mut cause = format!("directional light: light_dir differs from the point light's by {}°", num32(angle, 2));
    if g.specular == Vec3::ZERO && l.specular.max_element() > 0.0 {
        cause.push_str("; pow of a negative V·R is undefined, treated as no specular");
    }
    cause
}
