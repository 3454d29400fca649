//! The benchmark scenes' roofline, scaling and triangle-size sweep in the book: charts
//! and tables drawn from the committed CSVs in `book/data/bench/` (written by `lightlab
//! bench --roofline --csv`, `--scaling --csv` and `--sweep --llvmpipe --csv`).
//!
//! The CSVs are read from the book's data folder at build time ([`BookData`]), so the
//! book build times nothing, draws what `lightlab bench --csv` last wrote, and gives the
//! same bytes on every run with the same CSVs.

use plotters::prelude::*;

use super::artifact::Artifact;
use super::book_data::BookData;
use super::chart::{line_boxes, place_label, Legend, LineChart, Rect, Series};
use super::FigureError;
use crate::i18n::catalog::tr_fill;
use crate::i18n::{tr, Lang};
use crate::study::bench::roofline::{from_csv, RooflineRow};
use crate::study::bench::scaling::{amdahl_speedup, amdahl_table, ScalingRow, LIGHT_COUNTS, PIXEL_SCENES};
use crate::study::bench::specialisations::{SpecialisationRow, GENERAL, SPECIALISED};
use crate::study::bench::sweep::SweepRow;
use crate::study::speed::sig;
use crate::table::{Format, Table};

const ROOFLINE_CSV: &str = "bench/roofline.csv";
const SCALING_CSV: &str = "bench/scaling.csv";
const SPECIALISATIONS_CSV: &str = "bench/specialisations.csv";
const SWEEP_CSV: &str = "bench/sweep.csv";

/// A chart drawn in a language, as PNG bytes.
type LocalizedPng = fn(&BookData, Lang) -> Result<Vec<u8>, FigureError>;

/// The generated files (paths under `book/src/generated/`), drawn from `data`.
pub fn artifacts(data: &BookData) -> Vec<Artifact> {
    let with = |f: fn(&BookData) -> Result<Vec<u8>, FigureError>| {
        let data = data.clone();
        move || f(&data)
    };
    let mut all = vec![
        Artifact::file("tables/roofline.md", with(roofline_md)),
        Artifact::file("tables/scaling-threads.md", with(threads_md)),
        Artifact::file("tables/scaling-findings.md", with(scaling_findings_md)),
        Artifact::file("tables/specialisations.md", with(specialisations_md)),
    ];
    // the charts carry words: one copy per language (see Artifact::localized)
    let charts: [(&str, LocalizedPng); 4] = [
        ("charts/roofline.png", roofline_png),
        ("charts/scaling-lights.png", lights_png),
        ("charts/scaling-pixels.png", pixels_png),
        ("charts/sweep.png", sweep_png),
    ];
    for (path, chart) in charts {
        let data = data.clone();
        all.extend(Artifact::localized(vec![path.to_owned()], move |lang| chart(&data, lang).map(|png| vec![png])));
    }
    all
}

/// The roofline rows of `data`; an error names the file.
pub fn roofline_rows(data: &BookData) -> Result<Vec<RooflineRow>, FigureError> {
    let path = data.path(ROOFLINE_CSV);
    let rows: Vec<RooflineRow> =
        from_csv(&data.read(ROOFLINE_CSV)?).map_err(|e| FigureError::Invalid(format!("{}: {e}", path.display())))?;
    if rows.is_empty() {
        return Err(FigureError::Invalid(format!("{}: no rows", path.display())));
    }
    Ok(rows)
}

/// The scaling rows of `data`; an error names the file.
pub fn scaling_rows(data: &BookData) -> Result<Vec<ScalingRow>, FigureError> {
    let path = data.path(SCALING_CSV);
    from_csv(&data.read(SCALING_CSV)?).map_err(|e| FigureError::Invalid(format!("{}: {e}", path.display())))
}

/// Each scene's operations, bytes, bound and fraction of it.
pub fn roofline_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let rows = roofline_rows(data)?;
    let m = &rows[0];
    let mut t = Table::new(
        "How close each scene runs to the machine's limit",
        format!(
            "Measured by `lightlab bench --roofline` on {} ({} threads, {}): arithmetic peak P = {} GFLOP/s, store bandwidth β = {} GB/s. \
             Operations and bytes per fragment are counted from the code (lightlab::study::bench::roofline). \
             Fraction = max(F/P, B/β) / measured time.",
            m.cpu,
            m.threads,
            m.isa,
            sig(m.peak_gflops),
            sig(m.store_gbs)
        ),
        &["scene", "ms/frame", "flops/fragment", "bytes/fragment", "flops/byte", "GFLOP/s", "GB/s", "bound", "fraction"],
    );
    for r in &rows {
        let per = |x: f64| sig(x / r.fragments.max(1) as f64);
        t.push(vec![
            scene_cell(&r.scene),
            sig(r.ms),
            per(r.flops),
            per(r.bytes),
            sig(r.intensity()),
            sig(r.gflops()),
            sig(r.gbs()),
            r.bound().name().to_owned(),
            format!("{:.0} %", 100.0 * r.fraction()),
        ]);
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// A benchmark scene's cell in a table: its id, as `lightlab bench` takes it, in a code
/// span (the same in every language, not a word to translate).
fn scene_cell(id: &str) -> String {
    format!("`{id}`")
}

/// The roofline: achieved GFLOP/s against flops per byte, under `min(P, β·I)`.
pub fn roofline_png(data: &BookData, lang: Lang) -> Result<Vec<u8>, FigureError> {
    let rows = roofline_rows(data)?;
    let (p, beta) = (rows[0].peak_gflops, rows[0].store_gbs);
    let ridge = p / beta;
    let (mut x0, mut x1) = (ridge, ridge);
    let mut y0 = p;
    for r in &rows {
        if !(r.intensity() > 0.0 && r.gflops() > 0.0) {
            return Err(FigureError::Invalid(format!("roofline chart: {} has no positive rate", r.scene)));
        }
        x0 = x0.min(r.intensity());
        x1 = x1.max(r.intensity());
        y0 = y0.min(r.gflops());
    }
    let (x0, x1, y0, y1) = (x0 / 3.0, x1 * 3.0, y0 / 3.0, p * 2.0);
    super::chart::ensure_font()?;
    let (w, h, k) = (1000u32, 620u32, 2u32);
    let mut buf = vec![0u8; (w * k * h * k * 3) as usize];
    let err = |e: &dyn std::fmt::Debug| FigureError::Invalid(format!("roofline chart: {e:?}"));
    {
        let root = BitMapBackend::with_buffer(&mut buf, (w * k, h * k)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let font = |s: u32| ("sans-serif", f64::from(s * k));
        let mut chart = super::chart::log_log_chart(
            &root,
            &tr(lang, "The benchmark scenes on this machine's roofline"),
            x0..x1,
            y0..y1,
            &tr(lang, "arithmetic intensity (flops per framebuffer byte)"),
            &tr(lang, "GFLOP/s (both threads)"),
            &|v| lang.numbers_in(&sig(*v)),
            k,
        )?;
        let roof: Vec<(f64, f64)> = (0..=200)
            .map(|i| {
                let x = x0 * (x1 / x0).powf(f64::from(i) / 200.0);
                (x, p.min(beta * x))
            })
            .collect();
        let roof_line: Vec<(i32, i32)> = roof.iter().map(|p| chart.backend_coord(p)).collect();
        let grey = RGBColor(90, 90, 90);
        chart.draw_series(LineSeries::new(roof, grey.stroke_width(2 * k))).map_err(|e| err(&e))?;
        let roof_label =
            tr_fill(lang, "P = {} GFLOP/s; β = {} GB/s", &[&lang.numbers_in(&sig(p)), &lang.numbers_in(&sig(beta))]);
        chart
            .draw_series(std::iter::once(
                EmptyElement::at((ridge * 1.2, p))
                    + Text::new(roof_label, (0, 6 * k as i32), font(12).into_font().color(&grey)),
            ))
            .map_err(|e| err(&e))?;
        // every point first, so that no label covers one; then each label where it meets
        // no point and no label placed before it (the scenes crowd a few spots)
        let dot = 7 * k as i32;
        let area = super::chart::plot_box(&chart);
        let mut taken: Vec<Rect> = rows
            .iter()
            .map(|r| {
                let (x, y) = chart.backend_coord(&(r.intensity(), r.gflops()));
                [x - dot, y - dot, x + dot, y + dot]
            })
            .collect();
        // and the roof's line
        taken.extend(line_boxes(&roof_line, 2 * k as i32));
        for (i, r) in rows.iter().enumerate() {
            let color = super::chart::PALETTE[i % super::chart::PALETTE.len()];
            let (cx, cy) = (r.intensity(), r.gflops());
            chart.draw_series(std::iter::once(Circle::new((cx, cy), 5 * k, color.filled()))).map_err(|e| err(&e))?;
            let text = format!("{} ({:.0} %)", r.scene, 100.0 * r.fraction());
            // the label's box: EM_WIDTH per character of the 12 px font, and the font's
            // height with a pixel above and below
            let em = f64::from(super::svg::EM_WIDTH);
            let size = ((em * 12.0 * text.chars().count() as f64) as i32 * k as i32, 14 * k as i32);
            let at = chart.backend_coord(&(cx, cy));
            let (offset, leader) = place_label(at, size, &mut taken, 8 * k as i32, area);
            let label = Text::new(text, offset, font(12).into_font().color(&BLACK));
            // a label moved off its point's row is tied to it by a thin line
            let leader = PathElement::new(leader, grey.stroke_width(k));
            chart.draw_series(std::iter::once(EmptyElement::at((cx, cy)) + leader + label)).map_err(|e| err(&e))?;
        }
        root.present().map_err(|e| err(&e))?;
    }
    super::chart::downsample_to_png(buf, w, h, k, "roofline chart")
}

/// The lights axis, and `T(n) = a + b·n` fitted to it by least squares: `(rows, a, b)` in ms.
pub fn lights_fit(data: &BookData) -> Result<(Vec<ScalingRow>, f64, f64), FigureError> {
    let rows: Vec<ScalingRow> = scaling_rows(data)?.into_iter().filter(|r| r.axis == "lights").collect();
    if rows.len() < 2 {
        return Err(FigureError::Invalid("scaling.csv: fewer than two lights rows".into()));
    }
    let n = rows.len() as f64;
    let (sx, sy) = rows.iter().fold((0.0, 0.0), |(x, y), r| (x + r.lights as f64, y + r.ms_min));
    let (mx, my) = (sx / n, sy / n);
    let sxx: f64 = rows.iter().map(|r| (r.lights as f64 - mx).powi(2)).sum();
    let sxy: f64 = rows.iter().map(|r| (r.lights as f64 - mx) * (r.ms_min - my)).sum();
    let b = sxy / sxx;
    Ok((rows, my - b * mx, b))
}

/// ms per frame against the number of lights, with the fitted `a + b·n`.
pub fn lights_png(data: &BookData, lang: Lang) -> Result<Vec<u8>, FigureError> {
    let (rows, a, b) = lights_fit(data)?;
    let measured: Vec<(f64, f64)> = rows.iter().map(|r| (r.lights as f64, r.ms_min)).collect();
    let xs: Vec<f64> = LIGHT_COUNTS.iter().map(|&n| n as f64).collect();
    let fit = tr_fill(
        lang,
        "{} ms + {} ms per light (least squares)",
        &[&lang.numbers_in(&sig(a)), &lang.numbers_in(&sig(b))],
    );
    let size = [rows[0].width.to_string(), rows[0].height.to_string()];
    let mut chart = LineChart::new(&tr(lang, "point lights"), &tr(lang, "ms per frame (fastest run)"))
        .title(&tr_fill(lang, "Cost against lights: floor-lights256, {}×{}", &[&size[0], &size[1]]))
        .x_log()
        .y_log()
        .legend(Legend::UpperLeft)
        .series(Series::new(&tr(lang, "measured"), measured).width(3))
        .series(Series::from_fn(&fit, &xs, |n| a + b * n).dashed(8, 6));
    // the words are translated above (numbers from the CSV fill them); ticks follow the language
    chart.decimal_comma = lang.decimal_comma();
    chart.to_png()
}

/// ns per covered pixel against the frame's pixels.
pub fn pixels_png(data: &BookData, lang: Lang) -> Result<Vec<u8>, FigureError> {
    let rows: Vec<ScalingRow> = scaling_rows(data)?.into_iter().filter(|r| r.axis == "pixels").collect();
    if rows.is_empty() {
        return Err(FigureError::Invalid("scaling.csv: no pixels rows".into()));
    }
    let mut chart =
        LineChart::new(&tr(lang, "megapixels in the frame"), &tr(lang, "ns per covered pixel (fastest run)"))
            .title(&tr(lang, "Cost against resolution, 400×300 to 3840×2160"))
            .x_log()
            .legend(Legend::UpperRight);
    for scene in PIXEL_SCENES {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.scene == scene)
            .map(|r| (f64::from(r.width) * f64::from(r.height) / 1e6, r.ms_min * 1e6 / r.fragments.max(1) as f64))
            .collect();
        chart = chart.series(Series::new(scene, points).width(3));
    }
    chart.decimal_comma = lang.decimal_comma();
    chart.to_png()
}

/// The rows of `bench/sweep.csv`, each with its llvmpipe time, from the largest triangles
/// to the smallest; an error names the file.
pub fn sweep_rows(data: &BookData) -> Result<Vec<SweepRow>, FigureError> {
    let path = data.path(SWEEP_CSV);
    let mut rows: Vec<SweepRow> =
        from_csv(&data.read(SWEEP_CSV)?).map_err(|e| FigureError::Invalid(format!("{}: {e}", path.display())))?;
    if rows.is_empty() {
        return Err(FigureError::Invalid(format!("{}: no rows", path.display())));
    }
    for r in &rows {
        let positive = |ms: f64| ms.is_finite() && ms > 0.0;
        if !(positive(r.lightlab_ms) && r.llvmpipe_ms.is_some_and(positive) && r.fragments > 0) {
            return Err(FigureError::Invalid(format!(
                "{}: the row of {} triangles lacks a positive time or fragments (write it with `lightlab bench --sweep --llvmpipe --csv`)",
                path.display(),
                r.triangles
            )));
        }
    }
    rows.sort_by(|a, b| b.pixels_per_triangle().total_cmp(&a.pixels_per_triangle()));
    Ok(rows)
}

/// ms per frame of lightlab and of llvmpipe (same run) against covered pixels per
/// triangle, for the sphere tessellated from 256 to 262,144 triangles.
pub fn sweep_png(data: &BookData, lang: Lang) -> Result<Vec<u8>, FigureError> {
    let rows = sweep_rows(data)?;
    let points = |ms: fn(&SweepRow) -> f64| rows.iter().map(|r| (r.pixels_per_triangle(), ms(r))).collect();
    let mut chart = LineChart::new(&tr(lang, "covered pixels per triangle"), &tr(lang, "ms per frame (median run)"))
        .title(&tr(lang, "Cost against triangle size, 256 to 262,144 triangles"))
        .x_log()
        .y_log()
        .legend(Legend::UpperRight)
        .series(Series::new("lightlab", points(|r| r.lightlab_ms)).width(3))
        .series(Series::new("llvmpipe", points(|r| r.llvmpipe_ms.unwrap_or(f64::NAN))).width(3).dashed(8, 6));
    chart.decimal_comma = lang.decimal_comma();
    chart.to_png()
}

/// The rows of `bench/specialisations.csv`; an error names the file.
pub fn specialisation_rows(data: &BookData) -> Result<Vec<SpecialisationRow>, FigureError> {
    let path = data.path(SPECIALISATIONS_CSV);
    let rows: Vec<SpecialisationRow> = from_csv(&data.read(SPECIALISATIONS_CSV)?)
        .map_err(|e| FigureError::Invalid(format!("{}: {e}", path.display())))?;
    if rows.is_empty() {
        return Err(FigureError::Invalid(format!("{}: no rows", path.display())));
    }
    Ok(rows)
}

/// The general path against the specialised one, and what each specialisation alone
/// brings, from the fastest runs of `lightlab bench --specialisations`.
pub fn specialisations_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    use crate::raster::kernel::Specialisations;
    let rows = specialisation_rows(data)?;
    let m = &rows[0];
    let mut t = Table::new(
        "What each specialisation of the kernel brings",
        format!(
            "Fastest of the runs at 800×600, measured by `lightlab bench --specialisations` on {} ({} threads, {}). \
             Speed-up = the general path's time / the path's time; a specialisation alone is the general path with only it on. \
             Coloured lights have no grey path, so there it changes nothing; with all of them on, grey lights take the grey path rather than the folded material.",
            m.cpu, m.threads, m.isa
        ),
        &[
            "scene",
            "general (ms)",
            "specialised (ms)",
            "speed-up",
            "grey lights alone",
            "whole exponent alone",
            "R·V rewrite alone",
            "folded material alone",
        ],
    );
    let mut scenes: Vec<&str> = Vec::new();
    for r in &rows {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    for scene in scenes {
        let fastest = |path: &str| {
            rows.iter().find(|r| r.scene == scene && r.path == path).map(|r| r.ms_min).ok_or_else(|| {
                FigureError::Invalid(format!("{}: no {path} row for {scene}", data.path(SPECIALISATIONS_CSV).display()))
            })
        };
        let general = fastest(GENERAL)?;
        let specialised = fastest(SPECIALISED)?;
        let mut cells =
            vec![scene_cell(scene), sig(general), sig(specialised), format!("{}×", sig(general / specialised))];
        for (name, _) in Specialisations::EACH {
            cells.push(format!("{}×", sig(general / fastest(name)?)));
        }
        t.push(cells);
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// One and two threads, the parallel share and what Amdahl's law gives for more.
pub fn threads_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let rows = scaling_rows(data)?;
    let mut t = Table::new(
        "Threads: measured on two, extrapolated by Amdahl's law",
        "Fastest of the runs at 800×600 (`lightlab bench --scaling`). p = 2(1 − T₂/T₁), clamped to [0, 1]; \
         S(n) = 1/((1 − p) + p/n).",
        &["scene", "1 thread (ms)", "2 threads (ms)", "speed-up", "p", "S(4)", "S(8)", "S(∞)"],
    );
    for (scene, t1, t2, p) in amdahl_table(&rows) {
        t.push(vec![
            scene_cell(&scene),
            sig(t1),
            sig(t2),
            sig(t1 / t2),
            format!("{p:.2}"),
            sig(amdahl_speedup(p, 4.0)),
            sig(amdahl_speedup(p, 8.0)),
            if p < 1.0 { sig(1.0 / (1.0 - p)) } else { "unbounded".to_owned() },
        ]);
    }
    Ok(t.render(Format::Markdown).into_bytes())
}

/// The chapter's sentences on scaling, computed from the CSV so the prose never types a measured number.
pub fn scaling_findings_md(data: &BookData) -> Result<Vec<u8>, FigureError> {
    let rows = scaling_rows(data)?;
    let (lights, a, b) = lights_fit(data)?;
    let full = lights.last().map_or(f64::NAN, |r| r.ms_min);
    let amdahl = amdahl_table(&rows);
    let shares: Vec<f64> = amdahl.iter().map(|x| x.3).collect();
    let (lo, hi) = shares.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), &p| (l.min(p), h.max(p)));
    let mut lines = vec![
        format!(
            "- Lights: a frame of the floor costs about {} ms plus {} ms per light; at 256 lights the fixed part is {:.0} % of the frame, so the lights are nearly all of the cost.",
            sig(a),
            sig(b),
            100.0 * a / full
        ),
    ];
    for scene in PIXEL_SCENES {
        let ns: Vec<(u32, u32, f64)> = rows
            .iter()
            .filter(|r| r.axis == "pixels" && r.scene == scene)
            .map(|r| (r.width, r.height, r.ms_min * 1e6 / r.fragments.max(1) as f64))
            .collect();
        if let (Some(first), Some(last)) = (ns.first(), ns.last()) {
            lines.push(format!(
                "- Resolution, {scene}: {} ns per covered pixel at {}×{}, {} ns at {}×{}.",
                sig(first.2),
                first.0,
                first.1,
                sig(last.2),
                last.0,
                last.1
            ));
        }
    }
    if !shares.is_empty() {
        let s = |p: f64, n: f64| sig(amdahl_speedup(p, n));
        lines.push(format!(
            "- Threads: the measured parallel shares run from {lo:.2} to {hi:.2}. By Amdahl's law, four cores would make a frame {} to {} times faster than one, and eight cores {} to {} times; the serial part (the vertex stage, triangle setup before the bands start, the joins) is what limits it, and on a shared machine the two-thread measurement itself is noisy.",
            s(lo, 4.0),
            s(hi, 4.0),
            s(lo, 8.0),
            s(hi, 8.0)
        ));
    }
    Ok((lines.join("\n") + "\n").into_bytes())
}
