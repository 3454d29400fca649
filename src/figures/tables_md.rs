//! The book's worked tables as generated Markdown files, one per chapter of
//! [`crate::tables::chapters`], plus the study's tables (the failure atlas, the
//! light-culling range table and the tessellation study).
//!
//! Every file is rendered by [`crate::table::render`] with [`Format::Markdown`], the
//! same code the examples run with `--format markdown`, so the book shows exactly what
//! `cargo run --release --example <chapter> -- --format markdown` prints. A chapter includes a
//! file with `{{#include generated/tables/<name>.md}}`.

use super::artifact::Artifact;
use super::FigureError;
use crate::study::advisor::{self, Method, SphereScene};
use crate::study::{atlas, culling};
use crate::table::{num, render, Format, Table};
use crate::tables;

/// The generated table files (paths under `book/src/generated/`).
///
/// One `tables/<chapter>.md` per entry of [`tables::chapters`], then
/// `tables/atlas.md` (one line per case) and `tables/atlas-caseN.md` (one case's repro
/// and measurements), `tables/culling-range.md` and `tables/tessellation.md`.
pub fn artifacts() -> Vec<Artifact> {
    let mut all = vec![
        Artifact::file("tables/colors.md", || chapter_md("colors")),
        Artifact::file("tables/basic_lighting.md", || chapter_md("basic_lighting")),
        Artifact::file("tables/specular.md", || chapter_md("specular")),
        Artifact::file("tables/normal_matrix.md", || chapter_md("normal_matrix")),
        Artifact::file("tables/materials.md", || chapter_md("materials")),
        Artifact::file("tables/lighting_maps.md", || chapter_md("lighting_maps")),
        Artifact::file("tables/attenuation.md", || chapter_md("attenuation")),
        Artifact::file("tables/spotlight.md", || chapter_md("spotlight")),
        Artifact::file("tables/multiple_lights.md", || chapter_md("multiple_lights")),
        Artifact::file("tables/conventions.md", || chapter_md("conventions")),
        Artifact::file("tables/errata.md", || chapter_md("errata")),
        Artifact::file("tables/atlas.md", atlas_summary_md),
        Artifact::file("tables/culling-range.md", || {
            Ok::<_, String>(culling::range_table().render(Format::Markdown).into_bytes())
        }),
        Artifact::file("tables/tessellation.md", tessellation_md),
        Artifact::file("tables/range-window.md", || {
            Ok::<_, String>(crate::study::window::table().render(Format::Markdown).into_bytes())
        }),
        Artifact::file("tables/multiple_lights-summary.md", multiple_lights_summary_md),
    ];
    for case in atlas::CASES.iter().map(|c| c.number) {
        all.push(Artifact::file(format!("tables/atlas-case{case}.md"), move || atlas_case_md(case)));
    }
    all
}

/// The Markdown of chapter `name`'s tables, as its example prints them.
///
/// Returns an error when [`tables::chapters`] has no chapter of that name (a
/// registry entry out of date).
pub fn chapter_md(name: &str) -> Result<Vec<u8>, FigureError> {
    let (_, tables_fn) = tables::chapters()
        .into_iter()
        .find(|(n, _)| *n == name)
        .ok_or_else(|| format!("tables::chapters() has no chapter '{name}'"))?;
    Ok(render(&tables_fn(), Format::Markdown).into_bytes())
}

/// The failure atlas in three columns (number, case, fix), narrow enough for a page;
/// the measurements of each case are in [`atlas_case_md`].
pub fn atlas_summary_md() -> Result<Vec<u8>, FigureError> {
    let mut t = Table::new(
        "The failure atlas",
        "Each case's minimal repro and measurements follow in its own section below.",
        &["#", "case", "where it comes from", "fix"],
    );
    for c in atlas::CASES {
        t.push(vec![c.number.to_string(), c.name.to_owned(), c.source.to_owned(), c.fix.to_owned()]);
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// One case of [`atlas::table`] as a Markdown list: minimal repro, the symptom
/// measured, the fix and the measurement after it (the cells of the case's row,
/// computed for this case alone).
///
/// Returns an error for a case number the atlas does not have.
pub fn atlas_case_md(case: u8) -> Result<Vec<u8>, FigureError> {
    let no_case = || format!("the atlas table has no case {case}");
    let c = atlas::case(case).ok_or_else(no_case)?;
    let (symptom, after) = atlas::measure(case).ok_or_else(no_case)?;
    let md = format!(
        "- *Minimal repro (found by shrinking):* {}\n- *Measured:* {symptom}\n- *Fix:* {}\n- *After the fix:* {after}\n",
        c.repro, c.fix
    );
    Ok(md.into_bytes())
}

/// One row of the tessellation study: `(stacks, slices, triangles, widest normal
/// span in degrees, Gouraud error, Gouraud worst-case bound, Phong error)`, errors
/// in linear units.
pub type TessellationRow = (u32, u32, u32, f32, f32, f32, f32);

/// The tessellation study on [`SphereScene::design`]: for each of
/// [`advisor::TESSELLATIONS`], the measured largest error of per-vertex (Gouraud)
/// and per-fragment (Phong) shading against the true sphere
/// ([`advisor::sphere_error`]), and the formula-level Gouraud worst case
/// ([`advisor::sphere_gouraud_worst_case`]). Triangles are `2 · stacks · slices`.
///
/// Returns an error naming the tessellation when the advisor rejects it.
pub fn tessellation_rows() -> Result<Vec<TessellationRow>, FigureError> {
    let scene = SphereScene::design();
    advisor::TESSELLATIONS
        .iter()
        .map(|&(stacks, slices)| {
            let bad = || format!("tessellation {stacks}x{slices} rejected by the advisor");
            let span = advisor::sphere_max_span_deg(stacks, slices).ok_or_else(bad)?;
            let gouraud = advisor::sphere_error(&scene, stacks, slices, Method::Gouraud).ok_or_else(bad)?;
            let bound = advisor::sphere_gouraud_worst_case(&scene, stacks, slices).ok_or_else(bad)?;
            let phong = advisor::sphere_error(&scene, stacks, slices, Method::Phong).ok_or_else(bad)?;
            Ok((stacks, slices, 2 * stacks * slices, span, gouraud, bound, phong))
        })
        .collect()
}

/// [`tessellation_rows`] as a Markdown table, errors also in 8-bit levels, with the
/// advisors' answers for a one-level budget in the note.
pub fn tessellation_md() -> Result<Vec<u8>, FigureError> {
    let scene = SphereScene::design();
    let budget = advisor::DEFAULT_BUDGET;
    let advice = |m: Method| {
        advisor::advise_tessellation(&scene, m, budget, &advisor::TESSELLATIONS)
            .map_or("none of the listed meshes".to_owned(), |a| format!("{}×{}", a.stacks, a.slices))
    };
    let note = format!(
        "Unit UV sphere, light at (1.2, 1, 2), eye at (0, 0, 3), coral material (shininess 32). \
         Error = largest channel difference from the lighting of the true sphere at 15 barycentric \
         samples per front-facing triangle, in 8-bit levels (linear error × 255). \
         \"Gouraud bound\" is the advisor's formula-level worst case over every highlight placement. \
         Coarsest mesh within one level: Gouraud (by the bound) {}; Phong (measured, 4 placements) {}.",
        advice(Method::Gouraud),
        advice(Method::Phong)
    );
    let mut t = Table::new(
        "Per-vertex against per-fragment error by sphere tessellation",
        note,
        &[
            "mesh (stacks × slices)",
            "triangles",
            "widest edge span (°)",
            "Gouraud (levels)",
            "Gouraud bound (levels)",
            "Phong (levels)",
        ],
    );
    for (stacks, slices, tris, span, g, bound, p) in tessellation_rows()? {
        let levels = |e: f32| num(f64::from(e) * 255.0, 3);
        t.push(vec![
            format!("{stacks} × {slices}"),
            tris.to_string(),
            num(f64::from(span), 2),
            levels(g),
            levels(bound),
            levels(p),
        ]);
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The Multiple lights chapter's tables in one line per scene and fragment: which
/// light gives the most, the unclamped sum, the clamped 8-bit color and the channels
/// the clamp cuts. Computed from the same scenes, fragments and material as
/// [`crate::tables::multiple_lights::tables`], whose full per-light rows the chapter
/// folds away behind this summary.
pub fn multiple_lights_summary_md() -> Result<Vec<u8>, FigureError> {
    use crate::material::Material;
    use crate::scene::{Atmosphere, Scene};
    use crate::table::{rgb8, vec3};
    use crate::tables::multiple_lights::{FRAGMENTS, VIEW_POS};
    let mut t = Table::new(
        "Multiple lights at a glance",
        "One line per scene and fragment (coral material, eye at (0, 0, 3)): the light whose terms add up to the \
         most, the unclamped sum of all lights, and the 8-bit color after clamping. \"clipped\" names the channels \
         above 1, where the clamp changes the hue.",
        &["scene", "fragment", "brightest light", "sum", "8-bit", "clipped"],
    );
    let material = Material::coral();
    let mut scenes = vec![("default".to_owned(), Scene::learnopengl_default())];
    scenes.extend(Atmosphere::ALL.iter().map(|a| (a.name().to_owned(), a.scene())));
    for (name, scene) in &scenes {
        for f in FRAGMENTS {
            let shaded = scene.shade(&material, f.frag_pos, f.normal, VIEW_POS);
            let total = |v: glam::Vec3| v.x + v.y + v.z;
            let brightest = shaded
                .lights
                .iter()
                .max_by(|a, b| total(a.1.sum()).total_cmp(&total(b.1.sum())))
                .map_or("none".to_owned(), |(id, _)| id.to_string());
            let sum = shaded.rgb();
            let clipped: Vec<&str> =
                ["R", "G", "B"].into_iter().zip(sum.to_array()).filter(|(_, c)| *c > 1.0).map(|(n, _)| n).collect();
            t.push(vec![
                name.clone(),
                f.name.to_owned(),
                brightest,
                vec3(sum, 3),
                rgb8(crate::color::to_rgb8(sum)),
                if clipped.is_empty() { "none".to_owned() } else { clipped.join(", ") },
            ]);
        }
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_chapter_of_the_tables_registry_has_a_file() {
        let all = artifacts();
        let paths: Vec<&str> = all.iter().flat_map(|a| a.paths()).map(String::as_str).collect();
        for (name, _) in tables::chapters() {
            let path = format!("tables/{name}.md");
            assert!(paths.contains(&path.as_str()), "{path} is not registered");
        }
    }

    #[test]
    fn every_atlas_case_has_its_file() {
        for c in atlas::CASES {
            let md = String::from_utf8(atlas_case_md(c.number).unwrap()).unwrap();
            assert!(md.contains(c.repro), "case {}: {md}", c.number);
        }
        assert!(atlas_case_md(0).is_err());
    }

    #[test]
    fn unknown_chapter_is_an_error() {
        assert!(chapter_md("no-such-chapter").unwrap_err().to_string().contains("no-such-chapter"));
    }
}
