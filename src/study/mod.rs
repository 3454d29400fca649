//! Where methods fail, and no more than a scene needs.
//!
//! | module | what it holds |
//! | --- | --- |
//! | [`atlas`] | the failure atlas: 14 cases, each measured, fixed and re-measured |
//! | [`culling`] | light culling with a proven bound on the skipped light |
//! | [`advisor`] | shading-mode and tessellation advisors at the formula level |
//! | `speed` | the timed speed-against-accuracy study on rendered scenes (feature `book`) |
//!
//! Everything here depends on glam and the crate's core modules only. Results
//! are plain data ([`Table`], [`Figure`]) so the book, the CLI and the charts
//! render the same numbers. The speed half of the study (timings on rendered
//! scenes) lives with the rasterizer; this module works at the formula level.
//!
//! Source: lightlab issue 6, "Speed against accuracy, where methods fail, and
//! no more than a scene needs".

pub mod advisor;
pub mod atlas;
pub mod culling;
#[cfg(feature = "book")]
pub mod speed;

/// One 8-bit output level in linear units: `1/255`.
///
/// The error budgets below are stated in these units: a change smaller than
/// half a level cannot move a value across more than one rounding boundary of
/// [`crate::color::to_rgb8`].
pub const ONE_LEVEL: f32 = 1.0 / 255.0;

/// A table as plain strings: `rows[0]` is the header.
#[derive(Clone, Debug, PartialEq)]
pub struct Table {
    /// Caption for the book.
    pub title: String,
    /// Header row first, then one row per entry; every row has the header's length.
    pub rows: Vec<Vec<String>>,
}

/// One named line of a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// `(x, y)` points in increasing `x`; a point the method cannot produce
    /// (NaN, overflow) is left out rather than drawn as a plausible value.
    pub points: Vec<(f32, f32)>,
}

/// The data of one chart: axes and lines, no styling.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Caption.
    pub title: String,
    /// X axis label, with unit.
    pub x_label: String,
    /// Y axis label, with unit.
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
}

impl Figure {
    fn new(title: &str, x_label: &str, y_label: &str, series: Vec<Series>) -> Figure {
        Figure { title: title.into(), x_label: x_label.into(), y_label: y_label.into(), series }
    }
}

impl Series {
    fn from_fn(label: impl Into<String>, xs: impl IntoIterator<Item = f32>, f: impl Fn(f32) -> f32) -> Series {
        let points = xs.into_iter().map(|x| (x, f(x))).filter(|(_, y)| y.is_finite()).collect();
        Series { label: label.into(), points }
    }
}

/// `n + 1` evenly spaced values from `a` to `b` inclusive.
fn linspace(a: f32, b: f32, n: usize) -> impl Iterator<Item = f32> {
    (0..=n).map(move |i| a + (b - a) * i as f32 / n as f32)
}
