//! The book's charts, each computed here from the formula it shows, through the
//! crate's core functions (or the study's data series for the failure atlas).
//!
//! | chart | shows | chapter |
//! | --- | --- | --- |
//! | `specular-falloff` | `cos^s α` for several shininess values | Basic lighting |
//! | `phong-blinn` | Phong against Blinn-Phong lobes, the 4× rule and the matched exponent | Basic lighting |
//! | `attenuation-short`, `attenuation-long` | the 12 rows of the range table | Light casters |
//! | `spot-intensity` | hard against soft spot edges | Light casters |
//! | `gouraud-edge` | per-vertex against per-fragment lighting along one edge | Basic lighting |
//! | `tessellation-error` | Gouraud and Phong error against sphere tessellation | Speed against accuracy |
//! | `range-window` | LearnOpenGL's range-7 attenuation against it with the range window at 7 and 30 | Speed against accuracy |
//! | `atlas-caseN` | the failure atlas's figures | Where methods fail |

use super::artifact::Artifact;
use super::chart::{Legend, LineChart, Series};
use super::FigureError;
use crate::casters::{hard_spot, spot_intensity, RANGE_TABLE};
use crate::phong::{
    blinn_exponent_matching_half_width, blinn_exponent_rule_of_thumb, blinn_specular_factor, phong_specular_factor,
};
use crate::study::{atlas, ONE_LEVEL};
use glam::Vec3;

/// The charts this module contributes to the book (paths under `book/src/generated/`).
pub fn artifacts() -> Vec<Artifact> {
    let mut all = Vec::new();
    all.extend(chart_artifact("specular-falloff", specular_falloff_chart));
    all.extend(chart_artifact("phong-blinn", phong_blinn_chart));
    all.extend(chart_artifact("attenuation-short", || attenuation_chart(0..6, Legend::UpperRight)));
    all.extend(chart_artifact("attenuation-long", || attenuation_chart(6..12, Legend::LowerLeft)));
    all.extend(chart_artifact("spot-intensity", spot_intensity_chart));
    all.extend(chart_artifact("tessellation-error", tessellation_error_chart));
    all.extend(chart_artifact("gouraud-edge", gouraud_edge_chart));
    all.extend(chart_artifact("range-window", range_window_chart));
    // One chart per atlas case that the chapter draws (see `atlas_style`).
    for case in atlas::CASES.iter().map(|c| c.number).filter(|&n| atlas_style(n).is_some()) {
        all.extend(chart_artifact(&format!("atlas-case{case}"), move || atlas_chart(case)));
    }
    all
}

/// The artifacts writing chart `name` as `charts/<name>.png` and `charts/<name>.svg`
/// from one [`LineChart`], once per language ([`Artifact::localized`]).
fn chart_artifact(
    name: &str,
    chart: impl Fn() -> Result<LineChart, FigureError> + Send + Sync + 'static,
) -> Vec<Artifact> {
    let (png, svg) = (format!("charts/{name}.png"), format!("charts/{name}.svg"));
    Artifact::localized(vec![png, svg], move |lang| {
        let c = chart()?.in_lang(lang);
        Ok::<_, FigureError>(vec![c.to_png()?, c.to_svg()?.into_bytes()])
    })
}

/// The y range of charts of values in [0, 1]: a little room below 0 and above 1, so a
/// line at 0 is not hidden by the axis and a line at 1 not by the frame.
const UNIT_RANGE: (f64, f64) = (-0.03, 1.05);

/// Size of the book's charts, pixels: modest, so the whole book builds fast.
const SIZE: (u32, u32) = (760, 440);

/// Shininess exponents drawn in the specular falloff chart (LearnOpenGL, Basic
/// Lighting, shows 2 to 256).
pub const SPECULAR_FALLOFF_SHININESS: [f64; 5] = [2.0, 8.0, 32.0, 128.0, 256.0];

/// `spec = pow(cos(alpha), shininess)` for `alpha` from 0 to 90 degrees in steps of
/// 0.25 degree, one line per shininess in [`SPECULAR_FALLOFF_SHININESS`].
///
/// ```text
/// spec(alpha) = max(cos alpha, 0)^shininess,   alpha = angle(reflect_dir, view_dir)
/// ```
/// LearnOpenGL, Basic Lighting, "Specular lighting" (the Phong specular term).
pub fn specular_falloff_chart() -> Result<LineChart, FigureError> {
    // 0.25 degree steps resolve the s = 256 peak (half width about 4 degrees).
    let alphas: Vec<f64> = (0..=360).map(|i| f64::from(i) * 0.25).collect();
    let mut chart = LineChart::new("angle between R and V, α (degrees)", "pow(cos α, s)")
        .x_range(0.0, 90.0)
        .y_range(UNIT_RANGE.0, UNIT_RANGE.1)
        .size(SIZE.0, SIZE.1);
    for s in SPECULAR_FALLOFF_SHININESS {
        chart = chart.series(Series::from_fn(&format!("s = {s}"), &alphas, |a| a.to_radians().cos().max(0.0).powf(s)));
    }
    Ok(chart)
}

/// The Phong exponent of the Phong-against-Blinn chart (LearnOpenGL's 32).
pub const PHONG_BLINN_SHININESS: f32 = 32.0;

/// The view direction at `alpha_deg` from the normal `+y` in the plane z = 0.
fn view_at(alpha_deg: f32) -> Vec3 {
    let a = alpha_deg.to_radians();
    Vec3::new(a.sin(), a.cos(), 0.0)
}

/// Phong and Blinn-Phong lobes with the light along the normal, so `reflect_dir =
/// n`, `α = angle(view_dir, n)` and `halfway` is `α/2` from `n`:
///
/// ```text
/// Phong               cos(α)^s             s = 32
/// Blinn, same s       cos(α/2)^s           much wider
/// Blinn, 4s           cos(α/2)^(4s)        the rule of thumb
/// Blinn, matched      cos(α/2)^s'          s' with the Phong half-width
/// ```
///
/// Every value comes from [`phong_specular_factor`] and [`blinn_specular_factor`] on
/// real vectors; the exponents from [`blinn_exponent_rule_of_thumb`] and
/// [`blinn_exponent_matching_half_width`]. LearnOpenGL, Advanced lighting.
pub fn phong_blinn_chart() -> Result<LineChart, FigureError> {
    let s = PHONG_BLINN_SHININESS;
    let four = blinn_exponent_rule_of_thumb(s);
    let matched =
        blinn_exponent_matching_half_width(s).ok_or_else(|| format!("no matched Blinn exponent for shininess {s}"))?;
    let alphas: Vec<f64> = (0..=360).map(|i| f64::from(i) * 0.25).collect();
    let n = Vec3::Y;
    let phong = |a: f64| f64::from(phong_specular_factor(n, n, view_at(a as f32), s));
    let blinn = |exp: f32| move |a: f64| f64::from(blinn_specular_factor(n, n, view_at(a as f32), exp));
    Ok(LineChart::new("angle between R and V, α (degrees); light along the normal", "specular factor")
        .x_range(0.0, 90.0)
        .y_range(UNIT_RANGE.0, UNIT_RANGE.1)
        .size(SIZE.0, SIZE.1)
        // Phong, 4s and the matched exponent almost coincide: Phong is drawn wide
        // underneath, the two Blinn lobes dashed on top, so all three stay visible.
        .series(Series::from_fn(&format!("Phong, s = {s}"), &alphas, phong).width(6))
        .series(Series::from_fn(&format!("Blinn, s = {s}"), &alphas, blinn(s)))
        .series(Series::from_fn(&format!("Blinn, 4s = {four}"), &alphas, blinn(four)).dashed(10, 6))
        .series(
            Series::from_fn(&format!("Blinn, matched half-width s = {matched:.1}"), &alphas, blinn(matched))
                .dashed(3, 5),
        ))
}

/// `n` distances from `lo` to `hi`, evenly spaced in log scale.
fn log_space(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| lo * (hi / lo).powf(i as f64 / n as f64)).collect()
}

/// The attenuation curves `1/(Kc + Kl·d + Kq·d²)` of range-table rows `rows`, each
/// drawn out to twice its range on a log distance axis.
///
/// The legend goes in the corner `legend`, chosen where the panel's curves leave room.
///
/// Source: LearnOpenGL, Light casters, the range table ([`RANGE_TABLE`]). Returns an
/// error for an empty or out-of-bounds row range.
pub fn attenuation_chart(rows: std::ops::Range<usize>, legend: Legend) -> Result<LineChart, FigureError> {
    let table = RANGE_TABLE.get(rows.clone()).filter(|t| !t.is_empty()).ok_or_else(|| format!("rows {rows:?}"))?;
    let hi = f64::from(table[table.len() - 1].range) * 2.0;
    let lo = 0.1;
    let ds = log_space(lo, hi, 300);
    let mut chart = LineChart::new("distance d (world units, log scale)", "attenuation")
        .x_log()
        .x_range(lo, hi)
        .y_range(UNIT_RANGE.0, UNIT_RANGE.1)
        .size(SIZE.0, SIZE.1)
        .legend(legend);
    for row in table {
        let a = row.attenuation;
        let name = format!("range {}: Kl {}, Kq {}", row.range, a.linear, a.quadratic);
        chart = chart.series(Series::from_fn(&name, &ds, |d| f64::from(a.at(d as f32))));
    }
    Ok(chart)
}

/// LearnOpenGL's range-7 attenuation (1, 0.7, 1.8) against the same attenuation times the
/// range window ([`crate::casters::range_window`]) at the nominal range 7 and at 30 (the
/// smallest range that keeps the 256-light floor within a level of LearnOpenGL,
/// [`crate::study::window`]), on a log scale down to 10⁻⁵, with half an 8-bit level
/// (`0.5/255`) for reference.
pub fn range_window_chart() -> Result<LineChart, FigureError> {
    let a = RANGE_TABLE[0].attenuation;
    let ds: Vec<f64> = (0..=640).map(|i| f64::from(i) * 0.05).collect();
    let windowed = |r: f32| move |d: f64| f64::from(a.windowed_at(d as f32, r)).max(1e-6);
    Ok(LineChart::new("distance d (world units)", "attenuation (log scale)")
        .y_log()
        .x_range(0.0, 32.0)
        .y_range(1e-5, 1.2)
        .size(SIZE.0, SIZE.1)
        .legend(Legend::UpperRight)
        .series(Series::from_fn("LearnOpenGL, range 7: 1/(1 + 0.7d + 1.8d²)", &ds, |d| f64::from(a.at(d as f32))))
        .series(Series::from_fn("times the range window at 7", &ds, windowed(7.0)).dashed(6, 4))
        .series(Series::from_fn("times the range window at 30", &ds, windowed(30.0)).dashed(2, 3))
        .series(Series::from_fn("half an 8-bit level", &ds, |_| 0.5 * f64::from(ONE_LEVEL)).width(1)))
}

/// The inner and outer cut-offs of the Light casters chapter (12.5°, 17.5°) and the
/// outer cut-off of the Multiple lights flashlight (15°).
pub const SPOT_CUT_OFFS_DEG: (f32, f32, f32) = (12.5, 17.5, 15.0);

/// Spot intensity against the angle off the axis: the hard test
/// `theta > cos(12.5°)` ([`hard_spot`]) and the soft edges of the Light casters
/// (12.5°/17.5°) and Multiple lights (12.5°/15°) chapters ([`spot_intensity`]).
pub fn spot_intensity_chart() -> Result<LineChart, FigureError> {
    let (inner, outer, flash) = SPOT_CUT_OFFS_DEG;
    let cos = |deg: f32| deg.to_radians().cos();
    let angles: Vec<f64> = (0..=500).map(|i| f64::from(i) * 0.05).collect();
    let theta = |a: f64| cos(a as f32);
    Ok(LineChart::new("angle from the spot axis (degrees)", "intensity")
        .x_range(0.0, 25.0)
        .y_range(UNIT_RANGE.0, UNIT_RANGE.1)
        .size(SIZE.0, SIZE.1)
        .series(Series::from_fn(&format!("hard, cut-off {inner}°"), &angles, |a| {
            f64::from(hard_spot(theta(a), cos(inner)))
        }))
        .series(Series::from_fn(&format!("soft, {inner}° to {outer}°"), &angles, |a| {
            f64::from(spot_intensity(theta(a), cos(inner), cos(outer)))
        }))
        .series(Series::from_fn(&format!("soft, {inner}° to {flash}° (flashlight)"), &angles, |a| {
            f64::from(spot_intensity(theta(a), cos(inner), cos(flash)))
        })))
}

/// Gouraud and Phong error against the number of triangles of the study's UV spheres,
/// in 8-bit levels on log axes, with the one-level budget; the numbers of
/// [`super::tables_md::tessellation_rows`].
pub fn tessellation_error_chart() -> Result<LineChart, FigureError> {
    let rows = super::tables_md::tessellation_rows()?;
    let levels = |e: f32| f64::from(e / ONE_LEVEL);
    let line = |name: &str, pick: &dyn Fn(&super::tables_md::TessellationRow) -> f32| {
        Series::new(name, rows.iter().map(|r| (f64::from(r.2), levels(pick(r)))).filter(|p| p.1 > 0.0).collect())
    };
    let tris: Vec<f64> = rows.iter().map(|r| f64::from(r.2)).collect();
    Ok(LineChart::new("triangles in the UV sphere (log scale)", "largest error (8-bit levels, log)")
        .x_log()
        .y_log()
        .size(SIZE.0, SIZE.1)
        .legend(Legend::LowerLeft)
        .series(line("Gouraud, measured", &|r| r.4))
        .series(line("Gouraud, worst-case bound", &|r| r.5))
        .series(line("Phong, measured", &|r| r.6))
        .series(Series::from_fn("one level", &tris, |_| 1.0)))
}

/// The normal span of the edge in the Gouraud chart, degrees: the widest edge of the
/// 8 × 16 UV sphere is about this wide.
pub const GOURAUD_EDGE_SPAN_DEG: f32 = 22.5;

/// Lighting along one triangle edge whose end normals are `GOURAUD_EDGE_SPAN_DEG`
/// apart, with the light and the eye both along the normal at the edge's middle (so
/// the highlight peaks there):
///
/// ```text
/// n(t)        = normalize(lerp(n0, n1, t))
/// c(n)        = diff(n) + 0.5 · spec(n),  s = 32       (one channel, white light and surface)
/// per-fragment: c(n(t))
/// per-vertex:   lerp(c(n0), c(n1), t)
/// ```
///
/// Through [`crate::phong::diffuse_factor`] and [`phong_specular_factor`].
/// LearnOpenGL, Basic lighting, the Gouraud exercise; the failure atlas, case 8.
pub fn gouraud_edge_chart() -> Result<LineChart, FigureError> {
    let half = 0.5 * GOURAUD_EDGE_SPAN_DEG;
    let (n0, n1) = (view_at(-half), view_at(half));
    let peak = view_at(0.0);
    let color = |n: Vec3| {
        let n = n.normalize_or_zero();
        f64::from(crate::phong::diffuse_factor(n, peak) + 0.5 * phong_specular_factor(n, peak, peak, 32.0))
    };
    let (c0, c1) = (color(n0), color(n1));
    let ts: Vec<f64> = (0..=200).map(|i| f64::from(i) / 200.0).collect();
    Ok(LineChart::new("position along the edge, t", "diffuse + 0.5 · specular (s = 32)")
        .x_range(0.0, 1.0)
        .y_range(0.0, 1.6)
        .size(SIZE.0, SIZE.1)
        .legend(Legend::LowerRight)
        .series(Series::from_fn("per fragment (Phong shading)", &ts, |t| color(n0.lerp(n1, t as f32))))
        .series(Series::from_fn("per vertex (Gouraud shading)", &ts, |t| c0 + (c1 - c0) * t)))
}

/// How each atlas figure is drawn: log y axis and legend corner, chosen for its data;
/// `None` for case 13, whose chapter section shows its table only (the figure is a
/// scatter of grid indices, which says less than the table's counts).
fn atlas_style(case: u8) -> Option<(bool, Legend)> {
    Some(match case {
        13 => return None,
        9 | 11 => (true, Legend::UpperLeft),
        10 => (true, Legend::UpperRight),
        2 => (false, Legend::LowerRight),
        3 | 4 => (false, Legend::LowerLeft),
        5 | 6 | 8 | 12 | 14 => (false, Legend::UpperLeft),
        _ => (false, Legend::UpperRight),
    })
}

/// The failure atlas's figure for `case`, from [`atlas::figure`], as a PNG.
///
/// Returns an error for a case without a figure, or one the chapter does not draw. On a log axis, points at or below
/// zero are left out (the atlas already leaves out points a method cannot produce).
pub fn atlas_chart(case: u8) -> Result<LineChart, FigureError> {
    let no_figure = || format!("the atlas has no figure for case {case}");
    let (y_log, legend) = atlas_style(case).ok_or_else(no_figure)?;
    let figure = atlas::figure(case).ok_or_else(no_figure)?;
    let mut chart = LineChart::new(&figure.x_label, &figure.y_label)
        .title(&format!("Case {case}: {}", figure.title))
        .size(SIZE.0, SIZE.1)
        .legend(legend);
    if y_log {
        chart = chart.y_log();
    }
    if case == 15 {
        // percentages reach 100: room above them for the legend
        chart = chart.y_range(-5.0, 135.0);
    }
    for s in &figure.series {
        let points: Vec<(f64, f64)> =
            s.points.iter().map(|&(x, y)| (f64::from(x), f64::from(y))).filter(|&(_, y)| !y_log || y > 0.0).collect();
        if !points.is_empty() {
            // The first line solid and wide, the others dashed on top of it: where
            // two methods give the same values (case 4 at normal sizes, case 11's
            // world space and f32 view matrix) both stay visible.
            let series = Series::new(&s.label, points);
            let i = chart.series.len() as u32;
            chart = chart.series(if i == 0 { series.width(5) } else { series.dashed(6 + 4 * i, 5) });
        }
    }
    Ok(chart)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_rows_and_cases_are_errors() {
        assert!(attenuation_chart(12..13, Legend::Hidden).is_err());
        assert!(attenuation_chart(3..3, Legend::Hidden).is_err());
        assert!(atlas_chart(99).unwrap_err().to_string().contains("99"));
    }

    #[test]
    fn matched_blinn_exponent_is_near_the_rule_of_thumb() {
        // The half-width match and the 4x rule agree to second order in the angle;
        // at s = 32 (half-width 11.8 degrees) they differ by well under 1%.
        let matched = blinn_exponent_matching_half_width(32.0).unwrap();
        assert!((matched / blinn_exponent_rule_of_thumb(32.0) - 1.0).abs() < 0.01, "{matched}");
    }
}
