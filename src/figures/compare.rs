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
//! Nothing here depends on how the images were made; the book's render chapters will
//! call it once the rasterizer produces images. The perceptual FLIP score (nv-flip) is
//! not computed here yet: [`DiffStats`] gives the plain pixel statistics.

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
fn check_sizes(a: &RgbImage, b: &RgbImage) -> Result<(), String> {
    if a.dimensions() != b.dimensions() {
        return Err(format!(
            "compare: image b is {:?}, image a is {:?}; sizes must match",
            b.dimensions(),
            a.dimensions()
        ));
    }
    if a.width() == 0 || a.height() == 0 {
        return Err("compare: images are empty".to_owned());
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
pub fn diff_stats(a: &RgbImage, b: &RgbImage) -> Result<DiffStats, String> {
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
pub fn heat_map(a: &RgbImage, b: &RgbImage, full_scale: u8) -> Result<RgbImage, String> {
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
pub fn color_bar(height: u32, full_scale: u8) -> Result<RgbImage, String> {
    if height < 40 {
        return Err(format!("color_bar: height {height} is below 40 pixels"));
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
pub fn comparison_png(a: &RgbImage, b: &RgbImage, full_scale: u8) -> Result<(Vec<u8>, DiffStats), String> {
    let stats = diff_stats(a, b)?;
    let heat = heat_map(a, b, full_scale)?;
    let bar = color_bar(a.height(), full_scale)?;
    let all = side_by_side(&[a, b, &heat, &bar]);
    let mut png = Vec::new();
    image::codecs::png::PngEncoder::new(&mut png)
        .write_image(all.as_raw(), all.width(), all.height(), image::ExtendedColorType::Rgb8)
        .map_err(|e| format!("comparison_png: {e}"))?;
    Ok((png, stats))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn flat(w: u32, h: u32, v: u8) -> RgbImage {
        RgbImage::from_pixel(w, h, Rgb([v, v, v]))
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
        assert!(e.contains("sizes"), "{e}");
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
}
