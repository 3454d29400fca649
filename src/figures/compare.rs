//! Comparison figures for two renders of the same scene: the two images side by side,
//! a heat map of their difference with a color bar, and the difference statistics a
//! caption quotes.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `a`, `b` | two 8-bit RGB images of the same size (a reference and a method under test) |
//! | `d(p)` | the difference at pixel `p`: the largest of the three channel differences, in 8-bit levels |
//! | `full_scale` | the difference (levels) drawn at the hot end of the color map; larger ones saturate |
//!
//! Nothing here depends on how the images were made; [`super::renders`] calls it with
//! the rasterizer's images. [`DiffStats`] gives the plain pixel statistics and
//! [`flip_mean`] the perceptual FLIP score (NVIDIA's reference C++ through the `nv-flip`
//! crate). [`labelled_grid`] and [`labelled_comparison`] put a caption line above each
//! panel.

use super::FigureError;
use image::{ImageEncoder as _, Rgb, RgbImage};

use super::svg::{Anchor, Canvas};

/// Width of the color bar, pixels.
const BAR_WIDTH: u32 = 18;
/// Room for the color bar's tick labels, pixels.
const BAR_LABELS: u32 = 46;
/// White gap between the panels of a comparison, pixels.
const GAP: u32 = 10;

/// Statistics of the per-pixel difference `d(p)` between two images.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiffStats {
    /// The largest `d(p)`, levels.
    pub max_levels: u8,
    /// The mean of `d(p)` over all pixels, levels.
    pub mean_levels: f64,
    /// Pixels with `d(p) > 1` (a difference beyond rounding of one level).
    pub beyond_one_level: usize,
    /// All pixels.
    pub pixels: usize,
}

/// `d(p)` at one pixel: the largest channel difference, levels.
fn pixel_difference(a: &Rgb<u8>, b: &Rgb<u8>) -> u8 {
    (0..3).map(|c| a.0[c].abs_diff(b.0[c])).max().unwrap_or(0)
}

/// An error naming the mismatch when `a` and `b` cannot be compared.
fn check_sizes(a: &RgbImage, b: &RgbImage) -> Result<(), FigureError> {
    if a.dimensions() != b.dimensions() {
        return Err(FigureError::Invalid(format!(
            "compare: image b is {:?}, image a is {:?}; sizes must match",
            b.dimensions(),
            a.dimensions()
        )));
    }
    if a.width() == 0 || a.height() == 0 {
        return Err(FigureError::Invalid("compare: images are empty".to_owned()));
    }
    Ok(())
}

/// The difference statistics of `a` and `b`.
///
/// ```text
/// d(p) = max_c |a_c(p) − b_c(p)|          (levels)
/// max = max_p d(p);  mean = Σ_p d(p) / pixels;  beyond_one_level = #{p : d(p) > 1}
/// ```
///
/// Returns an error when the sizes differ or the images are empty.
pub fn diff_stats(a: &RgbImage, b: &RgbImage) -> Result<DiffStats, FigureError> {
    check_sizes(a, b)?;
    let (mut max, mut sum, mut beyond) = (0u8, 0u64, 0usize);
    for (pa, pb) in a.pixels().zip(b.pixels()) {
        let d = pixel_difference(pa, pb);
        max = max.max(d);
        sum += u64::from(d);
        beyond += usize::from(d > 1);
    }
    let pixels = a.pixels().len();
    Ok(DiffStats { max_levels: max, mean_levels: sum as f64 / pixels as f64, beyond_one_level: beyond, pixels })
}

/// The heat map's color at `t` in [0, 1] (clamped; NaN is 0): black, through deep
/// blue, purple, red and orange, to pale yellow, brightening monotonically so the map
/// also reads in grey.
pub fn heat_color(t: f32) -> [u8; 3] {
    const STOPS: [[f32; 3]; 6] = [
        [0.0, 0.0, 0.0],
        [0.10, 0.05, 0.45],
        [0.55, 0.10, 0.55],
        [0.90, 0.25, 0.20],
        [1.0, 0.65, 0.05],
        [1.0, 1.0, 0.75],
    ];
    let t = crate::glsl::saturate(t) * (STOPS.len() - 1) as f32;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f32;
    let (lo, hi) = (STOPS[i], STOPS[i + 1]);
    let mix = |c: usize| ((lo[c] + (hi[c] - lo[c]) * f) * 255.0).round() as u8;
    [mix(0), mix(1), mix(2)]
}

/// The heat map of `d(p)`, with `full_scale` levels (at least 1) at the hot end.
///
/// Returns an error when the sizes differ or the images are empty.
pub fn heat_map(a: &RgbImage, b: &RgbImage, full_scale: u8) -> Result<RgbImage, FigureError> {
    check_sizes(a, b)?;
    let scale = f32::from(full_scale.max(1));
    let mut out = RgbImage::new(a.width(), a.height());
    for ((pa, pb), po) in a.pixels().zip(b.pixels()).zip(out.pixels_mut()) {
        *po = Rgb(heat_color(f32::from(pixel_difference(pa, pb)) / scale));
    }
    Ok(out)
}

/// A vertical color bar `height` pixels tall for a heat map of `full_scale` levels, with
/// tick labels at 0, half and full scale (the top label reads `≥ full_scale`).
///
/// Returns an error when `height` is too small for the labels (under 40 pixels) or the
/// labels cannot be drawn.
pub fn color_bar(height: u32, full_scale: u8) -> Result<RgbImage, FigureError> {
    if height < 40 {
        return Err(FigureError::Invalid(format!("color_bar: height {height} is below 40 pixels")));
    }
    let width = BAR_WIDTH + BAR_LABELS;
    // Labels: a canvas in pixel units with y up from the bottom edge.
    let mut c = Canvas::new(width, height, glam::Vec2::new(0.0, height as f32), 1.0)?;
    let full = full_scale.max(1);
    let ticks = [(0.0, "0".to_owned()), (0.5, format!("{}", f32::from(full) / 2.0)), (1.0, format!("≥{full}"))];
    for (at, text) in &ticks {
        let y = (6.0 + at * (height as f32 - 12.0)).round();
        c.text(glam::Vec2::new(BAR_WIDTH as f32 + 4.0, y), text, 12.0, "#333333", Anchor::Start);
    }
    let labels = image::load_from_memory(&c.to_png(1.0)?).map_err(|e| format!("color_bar: {e}"))?.to_rgb8();
    let mut out = labels;
    for y in 0..height {
        let t = 1.0 - y as f32 / (height - 1) as f32;
        for x in 0..BAR_WIDTH {
            out.put_pixel(x, y, Rgb(heat_color(t)));
        }
    }
    Ok(out)
}

/// Images placed left to right on white, `GAP` pixels apart, top-aligned.
pub fn side_by_side(images: &[&RgbImage]) -> RgbImage {
    let width = images.iter().map(|i| i.width()).sum::<u32>() + GAP * images.len().saturating_sub(1) as u32;
    let height = images.iter().map(|i| i.height()).max().unwrap_or(0);
    let mut out = RgbImage::from_pixel(width.max(1), height.max(1), Rgb([255, 255, 255]));
    let mut x0 = 0;
    for img in images {
        for (x, y, p) in img.enumerate_pixels() {
            out.put_pixel(x0 + x, y, *p);
        }
        x0 += img.width() + GAP;
    }
    out
}

/// The comparison figure: `a`, `b`, the heat map of their difference and its color
/// bar, left to right, as PNG bytes, with the statistics for the caption.
///
/// Returns an error when the sizes differ, the images are empty or shorter than 40
/// pixels, or encoding fails.
pub fn comparison_png(a: &RgbImage, b: &RgbImage, full_scale: u8) -> Result<(Vec<u8>, DiffStats), FigureError> {
    let stats = diff_stats(a, b)?;
    let heat = heat_map(a, b, full_scale)?;
    let bar = color_bar(a.height(), full_scale)?;
    let all = side_by_side(&[a, b, &heat, &bar]);
    Ok((encode_png(&all)?, stats))
}

/// Height of the label line above each panel of a labelled figure, pixels.
pub const LABEL_HEIGHT: u32 = 22;
/// Font size of the panel labels, pixels.
const LABEL_SIZE: f32 = 13.0;

/// Panels in a grid of `cols` columns (left to right, then top to bottom) on white,
/// each cell as large as the largest panel, `GAP` pixels apart, with its label centred
/// in a [`LABEL_HEIGHT`] line above it. All labels are drawn in one SVG pass.
///
/// Returns an error when there are no panels, `cols` is 0, or the labels cannot be drawn.
pub fn labelled_grid(panels: &[(&RgbImage, &str)], cols: usize) -> Result<RgbImage, FigureError> {
    labelled_grid_in(panels, cols, crate::i18n::Lang::En)
}

/// [`labelled_grid`] with its labels in `lang` (the English labels are msgids).
pub fn labelled_grid_in(
    panels: &[(&RgbImage, &str)],
    cols: usize,
    lang: crate::i18n::Lang,
) -> Result<RgbImage, FigureError> {
    if panels.is_empty() || cols == 0 {
        return Err(FigureError::Invalid(format!(
            "labelled_grid: {} panels in {cols} columns; both must be > 0",
            panels.len()
        )));
    }
    let cols = cols.min(panels.len());
    let rows = panels.len().div_ceil(cols);
    let cell_w = panels.iter().map(|(i, _)| i.width()).max().unwrap_or(1);
    let cell_h = panels.iter().map(|(i, _)| i.height()).max().unwrap_or(1) + LABEL_HEIGHT;
    let width = cols as u32 * cell_w + (cols as u32 - 1) * GAP;
    let height = rows as u32 * cell_h + (rows as u32 - 1) * GAP;
    // Pixel coordinates: math (x, −y) with the origin at the top-left corner.
    let mut c = Canvas::new(width, height, glam::Vec2::ZERO, 1.0)?.in_lang(lang);
    let origin = |k: usize| ((k % cols) as u32 * (cell_w + GAP), (k / cols) as u32 * (cell_h + GAP));
    for (k, (_, label)) in panels.iter().enumerate() {
        let (x0, y0) = origin(k);
        let at = glam::Vec2::new((x0 + cell_w / 2) as f32, -((y0 + LABEL_HEIGHT / 2) as f32));
        c.text_within(at, label, LABEL_SIZE, "#222222", Anchor::Middle, cell_w as f32 - 8.0);
    }
    let mut out = image::load_from_memory(&c.to_png(1.0)?).map_err(|e| format!("labelled_grid: {e}"))?.to_rgb8();
    for (k, (img, _)) in panels.iter().enumerate() {
        let (x0, y0) = origin(k);
        let dx = x0 + (cell_w - img.width()) / 2;
        for (x, y, p) in img.enumerate_pixels() {
            out.put_pixel(dx + x, y0 + LABEL_HEIGHT + y, *p);
        }
    }
    Ok(out)
}

/// PNG bytes of an RGB image; an error if encoding fails.
pub fn encode_png(img: &RgbImage) -> Result<Vec<u8>, FigureError> {
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(img.as_raw(), img.width(), img.height(), image::ExtendedColorType::Rgb8)
        .map_err(|e| format!("encode_png: {e}"))?;
    Ok(png)
}

/// The mean FLIP error of `test` against `reference` (LDR-FLIP, Andersson et al. 2020,
/// "FLIP: A Difference Evaluator for Alternating Images"), computed by NVIDIA's
/// reference implementation through the `nv-flip` crate at its default 67 pixels per
/// degree (a 0.7 m viewing distance from a 24-inch 4K monitor).
///
/// ```text
/// flip_mean = (1 / pixels) Σ_p FLIP(reference, test)(p),   each FLIP(p) in [0, 1]
/// ```
///
/// 0 means indistinguishable; the score is not symmetric in its two arguments.
/// Returns an error when the sizes differ or the images are empty.
pub fn flip_mean(reference: &RgbImage, test: &RgbImage) -> Result<f32, FigureError> {
    check_sizes(reference, test)?;
    let (w, h) = reference.dimensions();
    let r = nv_flip::FlipImageRgb8::with_data(w, h, reference.as_raw());
    let t = nv_flip::FlipImageRgb8::with_data(w, h, test.as_raw());
    let error_map = nv_flip::flip(r, t, nv_flip::DEFAULT_PIXELS_PER_DEGREE);
    Ok(nv_flip::FlipPool::from_image(&error_map).mean())
}

/// A labelled comparison figure and the numbers its caption quotes.
#[derive(Clone, Debug)]
pub struct Comparison {
    /// The figure as PNG bytes.
    pub png: Vec<u8>,
    /// Pixel statistics of the difference.
    pub stats: DiffStats,
    /// Mean FLIP of the test image against the reference ([`flip_mean`]).
    pub flip: f32,
    /// The heat map's full scale, levels.
    pub full_scale: u8,
    /// The three panels (reference, test, heat map) with their English labels, and the
    /// color bar's column: what [`Comparison::png_in`] draws again with other labels.
    panels: Vec<(RgbImage, String)>,
    bar_cell: RgbImage,
}

impl Comparison {
    /// The figure with its labels in `lang` ([`Comparison::png`] is the English one). The
    /// labels are drawn on every call, in English too, so that the translation template
    /// hears them even when the comparison was rendered earlier (see `i18n::catalog::record`).
    pub fn png_in(&self, lang: crate::i18n::Lang) -> Result<Vec<u8>, FigureError> {
        let borrowed: Vec<(&RgbImage, &str)> = self.panels.iter().map(|(i, l)| (i, l.as_str())).collect();
        let grid = labelled_grid_in(&borrowed, 3, lang)?;
        encode_png(&side_by_side(&[&grid, &self.bar_cell]))
    }
}

/// The heat map's label in a comparison (a msgid).
const HEAT_LABEL: &str = "difference (8-bit levels)";

/// The labelled comparison figure: `reference`, `test`, the heat map of their
/// difference (`full_scale` levels at the hot end) and its color bar, left to right,
/// each under its label, with the statistics and the FLIP score.
///
/// Returns an error when the sizes differ, the images are empty or shorter than 40
/// pixels, or drawing or encoding fails.
pub fn labelled_comparison(
    reference: (&RgbImage, &str),
    test: (&RgbImage, &str),
    full_scale: u8,
) -> Result<Comparison, FigureError> {
    let (a, b) = (reference.0, test.0);
    let stats = diff_stats(a, b)?;
    let flip = flip_mean(a, b)?;
    let heat = heat_map(a, b, full_scale)?;
    let grid = labelled_grid(&[reference, test, (&heat, HEAT_LABEL)], 3)?;
    let bar = color_bar(a.height(), full_scale)?;
    let mut bar_cell = RgbImage::from_pixel(bar.width(), grid.height(), Rgb([255, 255, 255]));
    for (x, y, p) in bar.enumerate_pixels() {
        bar_cell.put_pixel(x, y + LABEL_HEIGHT, *p);
    }
    let png = encode_png(&side_by_side(&[&grid, &bar_cell]))?;
    let panels =
        vec![(a.clone(), reference.1.to_owned()), (b.clone(), test.1.to_owned()), (heat, HEAT_LABEL.to_owned())];
    Ok(Comparison { png, stats, flip, full_scale: full_scale.max(1), panels, bar_cell })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(w: u32, h: u32, v: u8) -> RgbImage {
        RgbImage::from_pixel(w, h, Rgb([v, v, v]))
    }

    #[test]
    fn a_comparison_draws_its_labels_again_in_english_for_the_template() {
        let (a, b) = (flat(48, 48, 100), flat(48, 48, 110));
        let c = labelled_comparison((&a, "left label"), (&b, "right label"), 16).unwrap();
        let (png, heard) = crate::i18n::catalog::record(|| c.png_in(crate::i18n::Lang::En).unwrap());
        assert_eq!(png, c.png, "the English redraw is the first drawing");
        for label in ["left label", "right label", HEAT_LABEL] {
            assert!(heard.contains(label), "{label} not heard: {heard:?}");
        }
    }

    #[test]
    fn identical_images_do_not_differ() {
        let a = flat(8, 8, 100);
        let s = diff_stats(&a, &a).unwrap();
        assert_eq!((s.max_levels, s.beyond_one_level, s.pixels), (0, 0, 64));
        assert_eq!(s.mean_levels, 0.0);
    }

    #[test]
    fn stats_take_the_largest_channel() {
        let a = flat(4, 4, 100);
        let mut b = a.clone();
        b.put_pixel(1, 2, Rgb([100, 107, 99]));
        b.put_pixel(3, 3, Rgb([101, 100, 100]));
        let s = diff_stats(&a, &b).unwrap();
        assert_eq!((s.max_levels, s.beyond_one_level), (7, 1));
        assert!((s.mean_levels - 8.0 / 16.0).abs() < 1e-12, "{}", s.mean_levels);
    }

    #[test]
    fn size_mismatch_is_an_error() {
        let e = diff_stats(&flat(4, 4, 0), &flat(4, 5, 0)).unwrap_err();
        assert!(e.to_string().contains("sizes"), "{e}");
        assert!(heat_map(&flat(0, 0, 0), &flat(0, 0, 0), 4).is_err());
    }

    #[test]
    fn color_map_runs_from_black_to_pale_yellow_and_brightens() {
        assert_eq!(heat_color(0.0), [0, 0, 0]);
        assert_eq!(heat_color(1.0), heat_color(7.0));
        assert_eq!(heat_color(f32::NAN), [0, 0, 0]);
        let luma = |c: [u8; 3]| 0.3 * f32::from(c[0]) + 0.59 * f32::from(c[1]) + 0.11 * f32::from(c[2]);
        let mut last = -1.0;
        for i in 0..=100 {
            let l = luma(heat_color(i as f32 / 100.0));
            assert!(l >= last, "luma falls at {i}: {l} < {last}");
            last = l;
        }
    }

    #[test]
    fn comparison_renders_deterministically() {
        let a = flat(48, 48, 120);
        let mut b = a.clone();
        b.put_pixel(10, 10, Rgb([140, 120, 120]));
        let (png, stats) = comparison_png(&a, &b, 8).unwrap();
        assert_eq!(&png[1..4], b"PNG");
        assert_eq!(stats.max_levels, 20);
        assert_eq!(png, comparison_png(&a, &b, 8).unwrap().0);
        assert!(color_bar(20, 8).is_err());
    }

    #[test]
    fn flip_is_zero_for_identical_images_and_grows_with_the_difference() {
        let a = RgbImage::from_fn(32, 32, |x, y| Rgb([(x * 8) as u8, (y * 8) as u8, 90]));
        assert_eq!(flip_mean(&a, &a).unwrap(), 0.0);
        let small = RgbImage::from_fn(32, 32, |x, y| Rgb([(x * 8) as u8 + 4, (y * 8) as u8, 90]));
        let large = RgbImage::from_fn(32, 32, |x, y| Rgb([255 - (x * 8) as u8, (y * 8) as u8, 90]));
        let (fs, fl) = (flip_mean(&a, &small).unwrap(), flip_mean(&a, &large).unwrap());
        assert!(0.0 < fs && fs < fl && fl <= 1.0, "small {fs}, large {fl}");
        assert!(flip_mean(&a, &flat(8, 8, 0)).is_err());
    }

    #[test]
    fn labelled_grid_places_panels_below_their_labels() {
        let (red, blue) =
            (RgbImage::from_pixel(40, 30, Rgb([255, 0, 0])), RgbImage::from_pixel(40, 30, Rgb([0, 0, 255])));
        let g = labelled_grid(&[(&red, "red"), (&blue, "blue"), (&red, "red again")], 2).unwrap();
        assert_eq!(g.dimensions(), (2 * 40 + GAP, 2 * (30 + LABEL_HEIGHT) + GAP));
        assert_eq!(g.get_pixel(5, LABEL_HEIGHT + 5), &Rgb([255, 0, 0]));
        assert_eq!(g.get_pixel(40 + GAP + 5, LABEL_HEIGHT + 5), &Rgb([0, 0, 255]));
        assert_eq!(g.get_pixel(45, LABEL_HEIGHT + 5), &Rgb([255, 255, 255]), "the gap stays white");
        assert!(labelled_grid(&[], 2).is_err());
        assert!(labelled_grid(&[(&red, "x")], 0).is_err());
    }
}
