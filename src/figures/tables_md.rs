//! The book's worked tables as generated Markdown files, one per chapter of
//! [`crate::tables::chapters`], plus the study's tables (the failure atlas, the
//! light-culling range table and the tessellation study).
//!
//! Every file is rendered by [`crate::tables::render`] with [`Format::Markdown`], the
//! same code the examples run with `--format markdown`, so the book shows exactly what
//! `cargo run --example <chapter> -- --format markdown` prints. A chapter includes a
//! file with `{{#include generated/tables/<name>.md}}`.

use crate::book::Artifact;
use crate::study::advisor::{self, Method, SphereScene};
use crate::study::{atlas, culling};
use crate::tables::{self, num, render, Format, Table};

/// The generated table files (paths under `book/src/generated/`).
///
/// One `tables/<chapter>.md` per entry of [`tables::chapters`], then
/// `tables/atlas.md` (one line per case) and `tables/atlas-caseN.md` (one case's repro
/// and measurements), `tables/culling-range.md` and `tables/tessellation.md`.
pub fn artifacts() -> Vec<Artifact> {
    vec![
        Artifact { path: "tables/colors.md", make: || chapter_md("colors") },
        Artifact { path: "tables/basic_lighting.md", make: || chapter_md("basic_lighting") },
        Artifact { path: "tables/specular.md", make: || chapter_md("specular") },
        Artifact { path: "tables/normal_matrix.md", make: || chapter_md("normal_matrix") },
        Artifact { path: "tables/materials.md", make: || chapter_md("materials") },
        Artifact { path: "tables/lighting_maps.md", make: || chapter_md("lighting_maps") },
        Artifact { path: "tables/attenuation.md", make: || chapter_md("attenuation") },
        Artifact { path: "tables/spotlight.md", make: || chapter_md("spotlight") },
        Artifact { path: "tables/multiple_lights.md", make: || chapter_md("multiple_lights") },
        Artifact { path: "tables/conventions.md", make: || chapter_md("conventions") },
        Artifact { path: "tables/errata.md", make: || chapter_md("errata") },
        Artifact { path: "tables/atlas.md", make: atlas_summary_md },
        Artifact { path: "tables/atlas-case1.md", make: || atlas_case_md(1) },
        Artifact { path: "tables/atlas-case2.md", make: || atlas_case_md(2) },
        Artifact { path: "tables/atlas-case3.md", make: || atlas_case_md(3) },
        Artifact { path: "tables/atlas-case4.md", make: || atlas_case_md(4) },
        Artifact { path: "tables/atlas-case5.md", make: || atlas_case_md(5) },
        Artifact { path: "tables/atlas-case6.md", make: || atlas_case_md(6) },
        Artifact { path: "tables/atlas-case7.md", make: || atlas_case_md(7) },
        Artifact { path: "tables/atlas-case8.md", make: || atlas_case_md(8) },
        Artifact { path: "tables/atlas-case9.md", make: || atlas_case_md(9) },
        Artifact { path: "tables/atlas-case10.md", make: || atlas_case_md(10) },
        Artifact { path: "tables/atlas-case11.md", make: || atlas_case_md(11) },
        Artifact { path: "tables/atlas-case12.md", make: || atlas_case_md(12) },
        Artifact { path: "tables/atlas-case13.md", make: || atlas_case_md(13) },
        Artifact { path: "tables/atlas-case14.md", make: || atlas_case_md(14) },
        Artifact { path: "tables/culling-range.md", make: || study_md(&culling::range_table()) },
        Artifact { path: "tables/tessellation.md", make: tessellation_md },
    ]
}

/// The Markdown of chapter `name`'s tables, as its example prints them.
///
/// Returns an error when [`tables::chapters`] has no chapter of that name (a
/// registry entry out of date).
pub fn chapter_md(name: &str) -> Result<Vec<u8>, String> {
    let (_, tables_fn) = tables::chapters()
        .into_iter()
        .find(|(n, _)| *n == name)
        .ok_or_else(|| format!("tables::chapters() has no chapter '{name}'"))?;
    Ok(render(&tables_fn(), Format::Markdown).into_bytes())
}

/// A study table (header in `rows[0]`) converted to a [`Table`] and rendered as
/// Markdown. Returns an error for a table without a header row.
pub fn study_md(study: &crate::study::Table) -> Result<Vec<u8>, String> {
    Ok(from_study(study)?.render(Format::Markdown).into_bytes())
}

/// The failure atlas in three columns (number, case, fix), narrow enough for a page;
/// the measurements of each case are in [`atlas_case_md`].
pub fn atlas_summary_md() -> Result<Vec<u8>, String> {
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
/// measured, the fix and the measurement after it (cells as the atlas computes them).
///
/// Returns an error for a case number the atlas table does not have.
pub fn atlas_case_md(case: u8) -> Result<Vec<u8>, String> {
    let table = atlas::table();
    let row = table
        .rows
        .iter()
        .skip(1)
        .find(|r| r.first().is_some_and(|n| *n == case.to_string()))
        .ok_or_else(|| format!("the atlas table has no case {case}"))?;
    let cell = |i: usize| row.get(i).map_or("", String::as_str);
    let md = format!(
        "- *Minimal repro (found by shrinking):* {}\n- *Measured:* {}\n- *Fix:* {}\n- *After the fix:* {}\n",
        cell(2),
        cell(3),
        cell(4),
        cell(5)
    );
    Ok(md.into_bytes())
}

/// The same cells in a [`Table`], with no note.
fn from_study(study: &crate::study::Table) -> Result<Table, String> {
    let (header, rows) =
        study.rows.split_first().ok_or_else(|| format!("study table '{}' has no header", study.title))?;
    let headers: Vec<&str> = header.iter().map(String::as_str).collect();
    let mut t = Table::new(study.title.clone(), "", &headers);
    for r in rows {
        t.push(r.clone());
    }
    Ok(t)
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
pub fn tessellation_rows() -> Result<Vec<TessellationRow>, String> {
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
pub fn tessellation_md() -> Result<Vec<u8>, String> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_chapter_of_the_tables_registry_has_a_file() {
        let paths: Vec<&str> = artifacts().iter().map(|a| a.path).collect();
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
        assert!(chapter_md("no-such-chapter").unwrap_err().contains("no-such-chapter"));
    }

    #[test]
    fn study_table_keeps_its_cells() {
        let study = crate::study::Table { title: "T".into(), rows: vec![vec!["a".into()], vec!["1".into()]] };
        let md = String::from_utf8(study_md(&study).unwrap()).unwrap();
        assert!(md.starts_with("### T") && md.contains("| a |") && md.contains("| 1 |"), "{md}");
        let empty = crate::study::Table { title: "E".into(), rows: vec![] };
        assert!(study_md(&empty).is_err());
    }
}
