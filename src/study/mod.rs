//! Where methods fail, and no more than a scene needs.
//!
//! | module | what it holds |
//! | --- | --- |
//! | [`atlas`] | the failure atlas: 14 cases, each measured, fixed and re-measured |
//! | [`culling`] | light culling with a proven bound on the skipped light |
//! | [`advisor`] | shading-frequency and tessellation advisors at the formula level |
//! | `speed` | the timed speed-against-accuracy study on rendered scenes (feature `book`) |
//! | `bench` | the benchmark scenes' roofline and scaling, and their timing on llvmpipe (feature `book`) |
//!
//! # Dependencies
//!
//! - [`atlas`], [`culling`] and [`advisor`] work at the formula level: they use glam
//!   and the crate's core modules ([`crate::casters`], [`crate::color`],
//!   [`crate::glsl`], [`crate::material`], [`crate::normals`], [`crate::phong`],
//!   [`crate::scene`]) and build without any feature. Their results are plain data
//!   ([`crate::table::Table`], [`Figure`]), so the book, the CLI and the charts render
//!   the same numbers.
//! - `speed` and `bench` (feature `book`) render scenes: it uses the rasterizer and the ray
//!   caster ([`crate::raster`]), rayon for the frame's parallelism, nv-flip for the
//!   FLIP metric, and the `csv` crate (with serde) for its files; `bench` also draws the
//!   scenes through OpenGL (`crate::gl`, which the `book` feature brings).
//!
//! Nothing here depends on the figures or the book; they depend on this module.

pub mod advisor;
pub mod atlas;
#[cfg(feature = "book")]
pub mod bench;
pub mod culling;
#[cfg(feature = "book")]
pub mod speed;
#[cfg(feature = "book")]
pub mod window;

/// One 8-bit output level in linear units: `1/255`.
///
/// The error budgets below are stated in these units: a change smaller than
/// half a level cannot move a value across more than one rounding boundary of
/// [`crate::color::to_rgb8`].
pub const ONE_LEVEL: f32 = 1.0 / 255.0;

/// One named line of a figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
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
    pub series: Vec<Curve>,
}

impl Figure {
    fn new(title: &str, x_label: &str, y_label: &str, series: Vec<Curve>) -> Figure {
        Figure { title: title.into(), x_label: x_label.into(), y_label: y_label.into(), series }
    }
}

impl Curve {
    fn from_fn(label: impl Into<String>, xs: impl IntoIterator<Item = f32>, f: impl Fn(f32) -> f32) -> Curve {
        let points = xs.into_iter().map(|x| (x, f(x))).filter(|(_, y)| y.is_finite()).collect();
        Curve { label: label.into(), points }
    }
}

/// `n + 1` evenly spaced values from `a` to `b` inclusive.
fn linspace(a: f32, b: f32, n: usize) -> impl Iterator<Item = f32> {
    (0..=n).map(move |i| a + (b - a) * i as f32 / n as f32)
}
