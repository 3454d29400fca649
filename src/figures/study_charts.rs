//! The speed-against-accuracy study in the book: charts and tables drawn from the
//! committed CSVs in `book/data/study/` (written by `lightlab study`).
//!
//! The CSVs are read from the book's data folder at build time ([`BookData`]), so the
//! book build times nothing, draws what `lightlab study` last wrote, and gives the same
//! bytes on every run with the same CSVs. One chart per scene: cost (median ms/frame, min–max as error bars)
//! against mean error (8-bit levels) on log axes, every point labelled, the
//! Pareto front joined by a line and its points filled.

use super::book_data::BookData;
use super::chart::{line_boxes, place_label, Rect};
use super::FigureError;

use plotters::prelude::*;

use super::artifact::Artifact;
use crate::i18n::catalog::tr_fill;
use crate::i18n::{tr, Lang};
use crate::study::advisor::{self, Method, SphereScene};
use crate::study::speed::{self, from_csv, pareto, Machine, Row};
use crate::table::{Format, Table};

/// The committed CSVs, `(scene, path under the data folder)`.
const CSVS: [(&str, &str); 3] = [
    (speed::SPHERE, "study/sphere-multi.csv"),
    (speed::GBUFFER, "study/sphere-gbuffer.csv"),
    (speed::FLOOR, "study/floor-lights.csv"),
];

/// Errors below this many levels are drawn at it (a log axis has no zero).
pub const ERROR_FLOOR: f64 = 1e-7;

/// The study's generated files (paths under `book/src/generated/`).
pub fn artifacts(data: &BookData) -> Vec<Artifact> {
    let with = |f: fn(&BookData) -> Result<Vec<u8>, FigureError>| {
        let data = data.clone();
        move || f(&data)
    };
    let table = |scene: &'static str| {
        let data = data.clone();
        move || table_md(&data, scene)
    };
    let mut all = vec![
        Artifact::file("tables/study-sphere-multi.md", table(speed::SPHERE)),
        Artifact::file("tables/study-sphere-gbuffer.md", table(speed::GBUFFER)),
        Artifact::file("tables/study-floor-lights.md", table(speed::FLOOR)),
        Artifact::file("tables/study-pareto.md", with(pareto_md)),
        Artifact::file("tables/study-machine.md", with(machine_md)),
        Artifact::file("tables/study-advice.md", with(advice_md)),
        Artifact::file("tables/study-culling.md", culling_md),
        Artifact::file("tables/study-findings.md", with(findings_md)),
    ];
    // the charts carry words: one copy per language (see Artifact::localized)
    for (path, scene) in [
        ("charts/study-sphere-multi.png", speed::SPHERE),
        ("charts/study-sphere-gbuffer.png", speed::GBUFFER),
        ("charts/study-floor-lights.png", speed::FLOOR),
    ] {
        let data = data.clone();
        all.extend(Artifact::localized(vec![path.to_owned()], move |lang| {
            chart_png(&data, scene, lang).map(|png| vec![png])
        }));
    }
    all
}

/// The machine and rows of one scene's CSV in `data`; an error names the file.
pub fn scene_data(data: &BookData, scene: &str) -> Result<(Machine, Vec<Row>), FigureError> {
    let (_, rel) = CSVS.iter().find(|(s, _)| *s == scene).ok_or_else(|| format!("no study CSV for scene {scene:?}"))?;
    let text = data.read(rel)?;
    from_csv(&text).map_err(|source| FigureError::StudyCsv { path: data.path(rel), source })
}

/// One scene's table as Markdown.
pub fn table_md(data: &BookData, scene: &str) -> Result<Vec<u8>, FigureError> {
    let (m, rows) = scene_data(data, scene)?;
    let note = format!(
        "Measured by `lightlab study` on {} ({} threads, kernel ISA {}), frame {}. ● marks the Pareto front (median ms/frame against mean error).",
        m.cpu, m.cores, m.isa, m.frame
    );
    let mut t = speed::table(scene, &rows);
    t.note = note;
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The Pareto fronts of all scenes in one Markdown table.
pub fn pareto_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let mut t = Table::new(
        "The Pareto front of each scene",
        "No other method of the same scene is both cheaper and more accurate (median ms/frame, mean error).",
        &["scene", "method", "ms/frame", "ns/fragment", "max err (levels)", "mean err (levels)", "mean FLIP"],
    );
    for (scene, _) in CSVS {
        let (_, rows) = scene_data(data, scene)?;
        let front = pareto(&rows);
        let mut on: Vec<&Row> = rows.iter().zip(&front).filter(|(_, f)| **f).map(|(r, _)| r).collect();
        on.sort_by(|a, b| a.timing.ms_median.total_cmp(&b.timing.ms_median));
        for r in on {
            t.push(vec![
                scene.to_owned(),
                r.method.clone(),
                speed::sig(r.timing.ms_median),
                speed::sig(r.ns_per_fragment()),
                speed::sig(r.error.max_levels),
                speed::sig(r.error.mean_levels),
                speed::sig(r.error.flip),
            ]);
        }
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The machine the committed numbers come from.
pub fn machine_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let (m, _) = scene_data(data, speed::SPHERE)?;
    let mut t = Table::new("The machine", "As `lightlab study` recorded it in the CSV headers.", &["", ""]);
    t.push(vec!["CPU".into(), m.cpu]);
    t.push(vec!["threads used".into(), m.cores.to_string()]);
    t.push(vec!["kernel ISA".into(), m.isa]);
    t.push(vec!["frame".into(), m.frame]);
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The coarsest measured sphere meeting each budget, for Gouraud and Phong,
/// next to the formula-level tessellation advisor's answer.
pub fn advice_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let (_, rows) = scene_data(data, speed::SPHERE)?;
    let tess: Vec<&Row> = rows.iter().filter(|r| r.group == "tessellation").collect();
    let coarsest = |prefix: &str, ok: &dyn Fn(&Row) -> bool| {
        tess.iter().filter(|r| r.method.starts_with(prefix)).find(|r| ok(r)).map_or("none measured".to_owned(), |r| {
            format!("{} ({} ms)", &r.method[prefix.len()..], speed::sig(r.timing.ms_median))
        })
    };
    let mut t = Table::new(
        "Coarsest sphere within an error budget",
        "Measured: the first row of the tessellation sweep (8×16 … 256×512) meeting the budget on the sphere-multi scene. \
         Advisor: lightlab::study::advisor::advise_tessellation at one level, formula level (Gouraud: worst case over highlight placements).",
        &["budget", "Gouraud (measured)", "Phong (measured)"],
    );
    type Budget = (&'static str, Box<dyn Fn(&Row) -> bool>);
    let budgets: [Budget; 4] = [
        ("max err ≤ 1 level", Box::new(|r: &Row| r.error.max_levels <= 1.0)),
        ("mean err ≤ 0.5 level", Box::new(|r: &Row| r.error.mean_levels <= 0.5)),
        ("≤ 1 % of pixels off by > 1 level", Box::new(|r: &Row| r.error.over_one <= 0.01)),
        ("mean FLIP ≤ 0.01", Box::new(|r: &Row| r.error.flip <= 0.01)),
    ];
    for (name, ok) in &budgets {
        t.push(vec![name.to_string(), coarsest("Gouraud ", ok.as_ref()), coarsest("Phong ", ok.as_ref())]);
    }
    let candidates = advisor::TESSELLATIONS;
    let answer = |m: Method| {
        advisor::advise_tessellation(&SphereScene::design(), m, advisor::DEFAULT_BUDGET, &candidates)
            .map_or("none in the list".to_owned(), |a| format!("{}×{}", a.stacks, a.slices))
    };
    t.push(vec!["advisor, 1 level".into(), answer(Method::Gouraud), answer(Method::Phong)]);
    Ok(t.render(Format::Markdown).into_bytes())
}

/// A point's label in `lang`: the method's words translated, its tessellation
/// (`128×256`, the last word when it holds a `×`) kept: `normal matrix per vertex, 128×256`.
fn method_label(method: &str, lang: Lang) -> String {
    match method.rsplit_once(' ') {
        Some((words, size)) if size.contains('×') => {
            let (words, sep) = words.strip_suffix(',').map_or((words, " "), |w| (w, ", "));
            format!("{}{sep}{size}", tr(lang, words))
        }
        _ => tr(lang, method).into_owned(),
    }
}

/// The chart of one scene from the committed CSV: cost against error, log axes,
/// Pareto front, labels, error bars.
pub fn chart_png(data: &BookData, scene: &str, lang: Lang) -> Result<Vec<u8>, FigureError> {
    let (_, rows) = scene_data(data, scene)?;
    chart_png_of(scene, &rows, lang)
}

/// [`chart_png`] for rows just measured (what `lightlab study` writes beside its CSVs).
pub fn chart_png_of(scene: &str, rows: &[Row], lang: Lang) -> Result<Vec<u8>, FigureError> {
    let rows = rows.to_vec();
    if rows.is_empty() {
        return Err(FigureError::Invalid(format!("study chart {scene}: no rows")));
    }
    super::chart::ensure_font()?;
    let front = pareto(&rows);
    let y = |r: &Row| r.error.mean_levels.max(ERROR_FLOOR);
    let (mut x0, mut x1) = (f64::INFINITY, 0.0f64);
    let (mut y0, mut y1) = (f64::INFINITY, 0.0f64);
    for r in &rows {
        if !(r.timing.ms_min > 0.0 && r.timing.ms_max.is_finite()) {
            return Err(FigureError::Invalid(format!("study chart {scene}: {} has a non-positive time", r.method)));
        }
        x0 = x0.min(r.timing.ms_min);
        x1 = x1.max(r.timing.ms_max);
        y0 = y0.min(y(r));
        y1 = y1.max(y(r));
    }
    let (x0, x1, y0, y1) = (x0 / 1.5, x1 * 4.0, y0 / 8.0, y1 * 2.0);
    let (w, h, k) = (1000u32, 640u32, 2u32);
    let mut buf = vec![0u8; (w * k * h * k * 3) as usize];
    let err = |e: &dyn std::fmt::Debug| format!("study chart {scene}: {e:?}");
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w * k, h * k)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let font = |s: u32| ("sans-serif", f64::from(s * k));
        let mut chart = super::chart::log_log_chart(
            &root,
            &tr_fill(lang, "{}: cost against error", &[scene]),
            x0..x1,
            y0..y1,
            &tr(lang, "ms per frame (median; bars: min to max)"),
            &tr(lang, "mean error (8-bit levels)"),
            &|v| lang.numbers_in(&super::chart::tick_label(v)),
            k,
        )?;
        let blue = super::chart::PALETTE[0];
        let orange = super::chart::PALETTE[1];
        let mut on: Vec<(f64, f64)> =
            rows.iter().zip(&front).filter(|(_, f)| **f).map(|(r, _)| (r.timing.ms_median, y(r))).collect();
        on.sort_by(|a, b| a.0.total_cmp(&b.0));
        let front_line: Vec<(i32, i32)> = on.iter().map(|p| chart.backend_coord(p)).collect();
        chart.draw_series(LineSeries::new(on, orange.stroke_width(2 * k))).map_err(|e| err(&e))?;
        let points: Vec<(i32, i32)> = rows.iter().map(|r| chart.backend_coord(&(r.timing.ms_median, y(r)))).collect();
        for (r, f) in rows.iter().zip(&front) {
            let (cx, cy) = (r.timing.ms_median, y(r));
            let color = if *f { orange } else { blue };
            chart
                .draw_series(std::iter::once(PathElement::new(
                    vec![(r.timing.ms_min, cy), (r.timing.ms_max, cy)],
                    color.stroke_width(k),
                )))
                .map_err(|e| err(&e))?;
            let style = if *f { color.filled() } else { color.stroke_width(k) };
            chart.draw_series(std::iter::once(Circle::new((cx, cy), 4 * k, style))).map_err(|e| err(&e))?;
        }
        // every point and error bar first, so that no label covers one; then each label
        // where it meets none of them and no label placed before it, inside the plot, tied
        // to its point by a thin line when it had to move
        let area = super::chart::plot_box(&chart);
        let dot = 5 * k as i32;
        let mut taken: Vec<Rect> = points.iter().map(|&(x, y)| [x - dot, y - dot, x + dot, y + dot]).collect();
        for r in &rows {
            let (x0, py) = chart.backend_coord(&(r.timing.ms_min, y(r)));
            let (x1, _) = chart.backend_coord(&(r.timing.ms_max, y(r)));
            taken.push([x0, py - k as i32, x1, py + k as i32]);
        }
        // and the Pareto front's line
        taken.extend(line_boxes(&front_line, 2 * k as i32));
        let grey = RGBColor(90, 90, 90);
        for (r, &at) in rows.iter().zip(&points) {
            let text = method_label(&r.method, lang);
            // the label's box: EM_WIDTH per character of the 11 px font, and the font's
            // height with a pixel above and below
            let em = f64::from(super::svg::EM_WIDTH);
            let size = ((em * 11.0 * text.chars().count() as f64).ceil() as i32 * k as i32, 13 * k as i32);
            let gap = 6 * k as i32;
            let (offset, leader) = place_label(at, size, &mut taken, gap, area);
            let leader = PathElement::new(leader, grey.stroke_width(k));
            let label = Text::new(text, offset, font(11).into_font().color(&BLACK));
            chart
                .draw_series(std::iter::once(EmptyElement::at((r.timing.ms_median, y(r))) + leader + label))
                .map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    super::chart::downsample_to_png(buf, w, h, k, "study chart")
}

/// Why culling pays on the floor scene and not on the sphere: cull distances and
/// the share of light evaluations skipped (computed, not timed; 200 × 150 samples).
pub fn culling_md() -> Result<Vec<u8>, FigureError> {
    use crate::study::culling::{cull, threshold_for, MaterialBound};
    let material = speed::study_material();
    let bound = MaterialBound::of(&material);
    let mut t = Table::new(
        "Light culling on the two scenes",
        "Cull distance: beyond it a light changes no channel by more than τ = 1/(2·255·N) for N cullable lights \
         (lightlab::study::culling). Skipped: share of (fragment, light) evaluations culling skips over the visible fragments.",
        &["scene", "cullable lights", "attenuation (1, Kl, Kq)", "cull distance", "farthest light from the object", "skipped"],
    );
    let sphere = crate::scene::Scene::learnopengl_default();
    let n = sphere.point_lights.len() + 1;
    let c = cull(&sphere, &bound, threshold_for(n));
    let far = sphere.point_lights.iter().map(|p| p.position.length() - 1.0).fold(0.0f32, f32::max);
    let d = c.point_cull.iter().flatten().fold(f32::INFINITY, |a, &b| a.min(b));
    t.push(vec![
        speed::SPHERE.into(),
        n.to_string(),
        "(1, 0.09, 0.032)".into(),
        format!("{d:.0}"),
        format!("{far:.1}"),
        "0 % (every light is nearer than its cull distance)".into(),
    ]);
    let floor = speed::floor_scene();
    let c = cull(&floor, &bound, threshold_for(floor.point_lights.len()));
    let d = c.point_cull.iter().flatten().fold(f32::INFINITY, |a, &b| a.min(b));
    let share = speed::floor_skipped_share(200, 150);
    t.push(vec![
        speed::FLOOR.into(),
        floor.point_lights.len().to_string(),
        "(1, 0.7, 1.8)".into(),
        format!("{d:.0}"),
        "lights 100 apart".into(),
        format!("{:.0} %", 100.0 * share),
    ]);
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The chapter's key ratios, computed from the CSVs so the prose never types a measured number.
pub fn findings_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let get = |scene: &str, method: &str| -> Result<Row, FigureError> {
        let (_, rows) = scene_data(data, scene)?;
        rows.into_iter()
            .find(|r| r.method == method)
            .ok_or_else(|| FigureError::Invalid(format!("{scene}: no method {method:?} in the CSV")))
    };
    let ratio = |a: &Row, b: &Row| a.timing.ms_median / b.timing.ms_median;
    let (_, sphere) = scene_data(data, speed::SPHERE)?;
    let finest =
        |prefix: &str| sphere.iter().rfind(|r| r.group == "tessellation" && r.method.starts_with(prefix)).cloned();
    let (g, p) = (finest("Gouraud ").ok_or("no Gouraud rows")?, finest("Phong ").ok_or("no Phong rows")?);
    let simd = get(speed::GBUFFER, "16-lane kernel, Phong")?;
    let scalar = get(speed::GBUFFER, "Scene::shade (scalar core)")?;
    let on = get(speed::FLOOR, "culling on (scalar)")?;
    let off = get(speed::FLOOR, "culling off (scalar)")?;
    let floor_simd = get(speed::FLOOR, "16-lane kernel (no culling)")?;
    let lut = get(speed::GBUFFER, "LUT 256")?;
    let schlick = get(speed::GBUFFER, "Schlick x/(n−nx+x)")?;
    let rsqrt = get(speed::GBUFFER, "rsqrt + 1 Newton step")?;
    let lines = [
        format!(
            "- At the finest mesh measured ({}), Gouraud is still off by up to {} levels (mean {}), Phong by up to {} (mean {}).",
            &g.method["Gouraud ".len()..],
            speed::sig(g.error.max_levels),
            speed::sig(g.error.mean_levels),
            speed::sig(p.error.max_levels),
            speed::sig(p.error.mean_levels)
        ),
        format!(
            "- The 16-lane kernel shades the exact inputs {}× faster than the scalar `Scene::shade`, at the same error.",
            speed::sig(ratio(&scalar, &simd))
        ),
        format!(
            "- A 256-entry table is within {} levels of `powf`; Schlick's rational is off by up to {} levels, the magic-constant rsqrt with one Newton step by up to {}.",
            speed::sig(lut.error.max_levels),
            speed::sig(schlick.error.max_levels),
            speed::sig(rsqrt.error.max_levels)
        ),
        format!(
            "- On the floor under 25 short lights, culling makes scalar shading {}× faster and moves no channel by more than {} levels; the 16-lane kernel without culling is still {}× faster than scalar shading with it.",
            speed::sig(ratio(&off, &on)),
            speed::sig(on.error.max_levels),
            speed::sig(ratio(&on, &floor_simd))
        ),
    ];
    Ok((lines.join("\n") + "\n").into_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_points_label_keeps_its_tessellation_and_translates_its_words() {
        assert_eq!(method_label("normal matrix per vertex, 128×256", Lang::En), "normal matrix per vertex, 128×256");
        let fr = method_label("normal matrix per vertex, 128×256", Lang::Fr);
        assert!(fr.ends_with(", 128×256") && !fr.starts_with("normal matrix"), "{fr}");
        assert_eq!(method_label("Phong 8×16", Lang::Uk), format!("{} 8×16", tr(Lang::Uk, "Phong")));
        assert_eq!(method_label("culling on (scalar)", Lang::Fr), tr(Lang::Fr, "culling on (scalar)"));
    }
}
