//! Diagrams as SVG text, rasterized to PNG with resvg (tiny-skia) and the vendored font.
//!
//! A [`Canvas`] takes coordinates in *math* units (x right, y up, as on a blackboard),
//! maps them to pixels with one origin and one scale, and writes SVG elements. A diagram
//! author computes vectors with glam and hands them over; nothing is typed in pixels.
//!
//! | symbol      | meaning                                                   |
//! |-------------|-----------------------------------------------------------|
//! | `origin_px` | pixel position of the math origin (SVG pixels, y down)    |
//! | `scale`     | pixels per math unit                                      |
//! | `p`         | a point in math units; pixel = `origin_px + scale*(p.x, -p.y)` |
//!
//! [`render_png`] loads only [`super::FONT_DATA`] into the font database and maps every
//! generic family (serif, sans-serif, monospace, ...) to it, so text never depends on
//! the fonts of the machine, and the same SVG gives the same PNG bytes every time.

use super::FigureError;
use glam::Vec2;
use resvg::{tiny_skia, usvg};
use std::fmt::Write as _;
use std::sync::{Arc, OnceLock};

/// Length of an arrow head, in pixels.
const HEAD_LEN_PX: f32 = 11.0;
/// Half the width of an arrow head at its base, in pixels.
const HEAD_HALF_WIDTH_PX: f32 = 4.5;
/// Gap between an arrow tip (or an arc) and its label, in pixels.
const LABEL_GAP_PX: f32 = 13.0;
/// Font size of labels drawn by [`Canvas::arrow`] and [`Canvas::arc`], in pixels.
const LABEL_SIZE_PX: f32 = 18.0;

/// How a line is stroked: an SVG color (`"#1f77b4"`, `"black"`), a width in pixels and
/// whether it is dashed.
#[derive(Clone, Debug, PartialEq)]
pub struct Pen {
    /// Any SVG color string.
    pub color: String,
    /// Stroke width in pixels.
    pub width: f32,
    /// Dashed (6 px on, 4 px off) instead of solid.
    pub dashed: bool,
}

impl Pen {
    /// A solid pen of `color` and `width` pixels.
    pub fn solid(color: &str, width: f32) -> Pen {
        Pen { color: color.to_owned(), width, dashed: false }
    }

    /// The same pen, dashed.
    pub fn dashed(mut self) -> Pen {
        self.dashed = true;
        self
    }

    fn attrs(&self) -> String {
        let dash = if self.dashed { " stroke-dasharray=\"6 4\"" } else { "" };
        format!("stroke=\"{}\" stroke-width=\"{}\"{dash}", escape(&self.color), num(self.width))
    }
}

/// Horizontal placement of text relative to its anchor point.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// The text starts at the point.
    Start,
    /// The text is centred on the point.
    Middle,
    /// The text ends at the point.
    End,
}

impl Anchor {
    fn as_str(self) -> &'static str {
        match self {
            Anchor::Start => "start",
            Anchor::Middle => "middle",
            Anchor::End => "end",
        }
    }

    /// The anchor that keeps a label placed in direction `dir` (pixels, y down) away
    /// from the thing it labels: text to the right starts there, text to the left ends
    /// there, text above or below is centred.
    fn away_from(dir: Vec2) -> Anchor {
        if dir.x > 0.35 {
            Anchor::Start
        } else if dir.x < -0.35 {
            Anchor::End
        } else {
            Anchor::Middle
        }
    }
}

/// An SVG document under construction, in math coordinates (see the module docs).
#[derive(Clone, Debug)]
pub struct Canvas {
    width: u32,
    height: u32,
    origin_px: Vec2,
    scale: f32,
    body: String,
    /// The language of the words drawn ([`Canvas::in_lang`]).
    lang: crate::i18n::Lang,
}

impl Canvas {
    /// A white canvas of `width` x `height` pixels whose math origin sits at pixel
    /// `origin_px` and whose unit is `scale` pixels long.
    ///
    /// Returns an error naming the field when `width` or `height` is zero, or when
    /// `scale` is not a finite positive number, or `origin_px` is not finite.
    pub fn new(width: u32, height: u32, origin_px: Vec2, scale: f32) -> Result<Canvas, FigureError> {
        if width == 0 || height == 0 {
            return Err(FigureError::Invalid(format!("Canvas: width and height must be > 0, got {width}x{height}")));
        }
        if !(scale.is_finite() && scale > 0.0) {
            return Err(FigureError::Invalid(format!("Canvas: scale must be finite and > 0, got {scale}")));
        }
        if !origin_px.is_finite() {
            return Err(FigureError::Invalid(format!("Canvas: origin_px must be finite, got {origin_px}")));
        }
        let mut body = String::new();
        let _ = writeln!(body, "<rect x=\"0\" y=\"0\" width=\"{width}\" height=\"{height}\" fill=\"white\"/>");
        Ok(Canvas { width, height, origin_px, scale, body, lang: crate::i18n::Lang::En })
    }

    /// The canvas drawing its words in `lang`: every text goes through
    /// [`crate::i18n::tr`], the English being the msgid.
    #[must_use]
    pub fn in_lang(mut self, lang: crate::i18n::Lang) -> Canvas {
        self.lang = lang;
        self
    }

    /// Pixel position of math point `p`: `origin_px + scale * (p.x, -p.y)`.
    pub fn to_px(&self, p: Vec2) -> Vec2 {
        self.origin_px + self.scale * Vec2::new(p.x, -p.y)
    }

    /// A straight segment from `from` to `to` (math units).
    pub fn line(&mut self, from: Vec2, to: Vec2, pen: &Pen) -> &mut Self {
        let (a, b) = (self.to_px(from), self.to_px(to));
        let _ = writeln!(
            self.body,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {} stroke-linecap=\"round\"/>",
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y),
            pen.attrs()
        );
        self
    }

    /// Text at math point `at`, `size` pixels high, in `color`, placed by `anchor`.
    /// The point is the text's vertical centre. Characters `& < > "` are escaped.
    pub fn text(&mut self, at: Vec2, text: &str, size: f32, color: &str, anchor: Anchor) -> &mut Self {
        let p = self.to_px(at);
        self.text_px(p, text, size, color, anchor);
        self
    }

    /// [`Canvas::text`] for a label that has `max_width` pixels: a translation keeps its size
    /// while it fits there (estimated at [`EM_WIDTH`] per character), and shrinks to fit
    /// otherwise, never below [`MIN_FIT_SCALE`].
    pub fn text_within(
        &mut self,
        at: Vec2,
        text: &str,
        size: f32,
        color: &str,
        anchor: Anchor,
        max_width: f32,
    ) -> &mut Self {
        let p = self.to_px(at);
        self.text_fitted(p, text, size, color, anchor, Some(max_width));
        self
    }

    fn text_px(&mut self, p: Vec2, text: &str, size: f32, color: &str, anchor: Anchor) {
        self.text_fitted(p, text, size, color, anchor, None);
    }

    /// Draw `text` translated; a translation shrinks to `max_width` pixels when given, else to
    /// the English label's length ([`fit_scale`]).
    fn text_fitted(&mut self, p: Vec2, text: &str, size: f32, color: &str, anchor: Anchor, max_width: Option<f32>) {
        // Shift the baseline down by 0.35 em so that `p` is the visual centre of the
        // capitals (DejaVu Sans cap height is 0.73 em).
        let baseline = p.y + 0.35 * size;
        let english = text;
        let text = if text.is_empty() { text.into() } else { crate::i18n::tr(self.lang, text) };
        let scale = match max_width {
            _ if text == english => 1.0,
            Some(w) => (w / (EM_WIDTH * size * text.chars().count().max(1) as f32)).clamp(MIN_FIT_SCALE, 1.0),
            None => fit_scale(english, &text),
        };
        let size = size * scale;
        let _ = writeln!(
            self.body,
            "<text x=\"{}\" y=\"{}\" font-family=\"{}\" font-size=\"{}\" fill=\"{}\" text-anchor=\"{}\">{}</text>",
            num(p.x),
            num(baseline),
            super::FONT_FAMILY,
            num(size),
            escape(color),
            anchor.as_str(),
            escape(&text)
        );
    }

    /// An arrow from `from` to `to` (math units) with a filled head at `to`, and
    /// `label` just beyond the tip (nothing when `label` is empty).
    ///
    /// Returns an error when the arrow is shorter than its head (including a zero
    /// vector), since its direction could not be seen.
    pub fn arrow(&mut self, from: Vec2, to: Vec2, pen: &Pen, label: &str) -> Result<&mut Self, FigureError> {
        let (a, b) = (self.to_px(from), self.to_px(to));
        let len = a.distance(b);
        if len.is_nan() || len <= HEAD_LEN_PX {
            return Err(FigureError::Invalid(format!(
                "Canvas::arrow '{label}': length {len:.1} px is not longer than the head ({HEAD_LEN_PX} px)"
            )));
        }
        let dir = (b - a) / len;
        let normal = dir.perp();
        let head_len = HEAD_LEN_PX + pen.width;
        let half = HEAD_HALF_WIDTH_PX + 0.5 * pen.width;
        let base = b - dir * head_len;
        // Stop the shaft inside the head so its square end does not poke out of the tip.
        let shaft_end = b - dir * (0.5 * head_len);
        let _ = writeln!(
            self.body,
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" {}/>",
            num(a.x),
            num(a.y),
            num(shaft_end.x),
            num(shaft_end.y),
            pen.attrs()
        );
        let (l, r) = (base + normal * half, base - normal * half);
        let _ = writeln!(
            self.body,
            "<path d=\"M {} {} L {} {} L {} {} Z\" fill=\"{}\"/>",
            num(b.x),
            num(b.y),
            num(l.x),
            num(l.y),
            num(r.x),
            num(r.y),
            escape(&pen.color)
        );
        if !label.is_empty() {
            let at = b + dir * LABEL_GAP_PX;
            self.text_px(at, label, LABEL_SIZE_PX, &pen.color, Anchor::away_from(dir));
        }
        Ok(self)
    }

    /// The arc of radius `radius` (math units) around `center`, swept the short way
    /// from direction `from_dir` to direction `to_dir`, with `label` centred just
    /// outside its middle (keep it short, one symbol, so it fits the wedge).
    /// Directions need not be unit length.
    ///
    /// Returns an error when a direction is zero or not finite, or `radius` is not
    /// positive. Opposite directions (a 180 degree arc) sweep counter-clockwise.
    pub fn arc(
        &mut self,
        center: Vec2,
        radius: f32,
        from_dir: Vec2,
        to_dir: Vec2,
        pen: &Pen,
        label: &str,
    ) -> Result<&mut Self, FigureError> {
        let (Some(u), Some(v)) = (from_dir.try_normalize(), to_dir.try_normalize()) else {
            return Err(FigureError::Invalid(format!(
                "Canvas::arc '{label}': from_dir {from_dir} and to_dir {to_dir} must be non-zero"
            )));
        };
        if !(radius.is_finite() && radius > 0.0) {
            return Err(FigureError::Invalid(format!("Canvas::arc '{label}': radius must be > 0, got {radius}")));
        }
        let cross = u.perp_dot(v);
        // SVG's sweep flag 1 turns toward +y of the pixel grid, which is clockwise on
        // screen; counter-clockwise in math coordinates (y up) is therefore flag 0.
        let ccw = cross >= 0.0;
        let sweep = if ccw { 0 } else { 1 };
        let (a, b) = (self.to_px(center + u * radius), self.to_px(center + v * radius));
        let r_px = radius * self.scale;
        let _ = writeln!(
            self.body,
            "<path d=\"M {} {} A {} {} 0 0 {sweep} {} {}\" fill=\"none\" {}/>",
            num(a.x),
            num(a.y),
            num(r_px),
            num(r_px),
            num(b.x),
            num(b.y),
            pen.attrs()
        );
        if !label.is_empty() {
            let mid = (u + v).try_normalize().unwrap_or_else(|| if ccw { u.perp() } else { -u.perp() });
            let mid_px = Vec2::new(mid.x, -mid.y);
            let at = self.to_px(center) + mid_px * (r_px + LABEL_GAP_PX);
            self.text_px(at, label, LABEL_SIZE_PX, &pen.color, Anchor::Middle);
        }
        Ok(self)
    }

    /// The finished SVG document.
    pub fn finish(&self) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n{}</svg>\n",
            self.body,
            w = self.width,
            h = self.height
        )
    }

    /// Shortcut for `render_png(&self.finish(), scale)`.
    pub fn to_png(&self, scale: f32) -> Result<Vec<u8>, FigureError> {
        render_png(&self.finish(), scale)
    }
}

/// A number as SVG text: two decimals, enough for sub-pixel placement, and the same
/// text for the same `f32` on every platform.
fn num(x: f32) -> String {
    let s = format!("{x:.2}");
    if s == "-0.00" {
        "0.00".to_owned()
    } else {
        s
    }
}

/// Escape the XML special characters of `s`.
fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            _ => out.push(c),
        }
    }
    out
}

/// The font database shared by all renders: the vendored font alone.
fn font_db() -> Arc<usvg::fontdb::Database> {
    static DB: OnceLock<Arc<usvg::fontdb::Database>> = OnceLock::new();
    DB.get_or_init(|| {
        let mut db = usvg::fontdb::Database::new();
        db.load_font_data(super::FONT_DATA.to_vec());
        db.set_serif_family(super::FONT_FAMILY);
        db.set_sans_serif_family(super::FONT_FAMILY);
        db.set_monospace_family(super::FONT_FAMILY);
        db.set_cursive_family(super::FONT_FAMILY);
        db.set_fantasy_family(super::FONT_FAMILY);
        Arc::new(db)
    })
    .clone()
}

/// How much a translated label shrinks to fit where the English one was laid out: the
/// ratio of their lengths in characters, for a translation longer than the English, never
/// below [`MIN_FIT_SCALE`] (a diagram is drawn around its English labels).
#[must_use]
pub fn fit_scale(english: &str, shown: &str) -> f32 {
    let (e, s) = (english.chars().count(), shown.chars().count());
    if s <= e || e == 0 {
        1.0
    } else {
        (e as f32 / s as f32).max(MIN_FIT_SCALE)
    }
}

/// The smallest [`fit_scale`]: below it a label would be too small to read.
pub const MIN_FIT_SCALE: f32 = 0.7;

/// The mean advance of a DejaVu Sans character, in em (Latin and Cyrillic lower case with
/// spaces average about 0.55 em; 0.6 leaves a margin), for [`Canvas::text_within`].
pub const EM_WIDTH: f32 = 0.6;

/// Rasterize SVG text to PNG bytes, `scale` output pixels per SVG pixel, on the
/// document's own background (transparent where it draws nothing).
///
/// Text uses only the vendored font (see the module docs); external files and images
/// are not resolved. Returns an error when the SVG does not parse, when `scale` is not
/// finite and positive, or when the scaled size is zero or too large for tiny-skia.
pub fn render_png(svg: &str, scale: f32) -> Result<Vec<u8>, FigureError> {
    if !(scale.is_finite() && scale > 0.0) {
        return Err(FigureError::Invalid(format!("render_png: scale must be finite and > 0, got {scale}")));
    }
    let options =
        usvg::Options { font_family: super::FONT_FAMILY.to_owned(), fontdb: font_db(), ..usvg::Options::default() };
    let tree = usvg::Tree::from_str(svg, &options).map_err(|e| format!("render_png: {e}"))?;
    let size = tree.size();
    let (w, h) = ((size.width() * scale).ceil() as u32, (size.height() * scale).ceil() as u32);
    let mut pixmap = tiny_skia::Pixmap::new(w, h).ok_or_else(|| format!("render_png: cannot make a {w}x{h} pixmap"))?;
    resvg::render(&tree, tiny_skia::Transform::from_scale(scale, scale), &mut pixmap.as_mut());
    pixmap.encode_png().map_err(|e| FigureError::backend("render_png", e))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_longer_translation_shrinks_to_the_english_width_within_a_floor() {
        assert_eq!(fit_scale("spot", "spot"), 1.0);
        assert_eq!(fit_scale("point: rings", "short"), 1.0);
        assert_eq!(fit_scale("abcdefgh", "abcdefghij"), 0.8);
        assert_eq!(fit_scale("ab", "abcdefghij"), MIN_FIT_SCALE);
    }

    #[test]
    fn canvas_rejects_bad_sizes() {
        assert!(Canvas::new(0, 10, Vec2::ZERO, 1.0).is_err());
        assert!(Canvas::new(10, 10, Vec2::ZERO, 0.0).is_err());
        assert!(Canvas::new(10, 10, Vec2::ZERO, f32::NAN).is_err());
    }

    #[test]
    fn math_y_points_up() {
        let c = Canvas::new(100, 100, Vec2::new(50.0, 50.0), 10.0).unwrap();
        assert_eq!(c.to_px(Vec2::new(1.0, 1.0)), Vec2::new(60.0, 40.0));
    }

    #[test]
    fn zero_arrow_and_zero_arc_are_errors() {
        let mut c = Canvas::new(100, 100, Vec2::new(50.0, 50.0), 10.0).unwrap();
        let pen = Pen::solid("black", 2.0);
        assert!(c.arrow(Vec2::ZERO, Vec2::ZERO, &pen, "N").is_err());
        assert!(c.arc(Vec2::ZERO, 1.0, Vec2::ZERO, Vec2::X, &pen, "a").is_err());
    }

    #[test]
    fn arcs_bulge_away_from_their_centre() {
        // A quarter arc from +x to +y around the origin must pass through the
        // first quadrant: counter-clockwise in math coordinates is sweep flag 0.
        let mut c = Canvas::new(100, 100, Vec2::new(50.0, 50.0), 10.0).unwrap();
        c.arc(Vec2::ZERO, 1.0, Vec2::X, Vec2::Y, &Pen::solid("black", 1.0), "").unwrap();
        assert!(c.finish().contains("A 10.00 10.00 0 0 0 50.00 40.00"), "{}", c.finish());
        let mut c = Canvas::new(100, 100, Vec2::new(50.0, 50.0), 10.0).unwrap();
        c.arc(Vec2::ZERO, 1.0, Vec2::Y, Vec2::X, &Pen::solid("black", 1.0), "").unwrap();
        assert!(c.finish().contains("A 10.00 10.00 0 0 1 60.00 50.00"), "{}", c.finish());
    }

    #[test]
    fn text_is_escaped() {
        let mut c = Canvas::new(10, 10, Vec2::ZERO, 1.0).unwrap();
        c.text(Vec2::ZERO, "a<b & \"c\"", 10.0, "black", Anchor::Start);
        assert!(c.finish().contains("a&lt;b &amp; &quot;c&quot;"));
    }

    #[test]
    fn text_draws_pixels_with_the_vendored_font() {
        // A blank canvas and the same canvas with one letter must differ: if the font
        // were not found, resvg would silently drop the text.
        let blank = Canvas::new(40, 40, Vec2::new(20.0, 20.0), 1.0).unwrap();
        let mut lettered = blank.clone();
        lettered.text(Vec2::ZERO, "N", 24.0, "black", Anchor::Middle);
        assert_ne!(blank.to_png(1.0).unwrap(), lettered.to_png(1.0).unwrap());
    }

    #[test]
    fn bad_svg_is_an_error() {
        assert!(render_png("<svg", 1.0).is_err());
        assert!(render_png("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"0\" height=\"0\"/>", 1.0).is_err());
    }
}
