//! Figures for the book: diagrams drawn as SVG and rasterized with resvg, and line
//! charts drawn with plotters.
//!
//! Both back ends use one font, the vendored DejaVu Sans in `book/fonts/`, embedded
//! into the binary with `include_bytes!`. No system font is ever loaded, so a figure is
//! the same bytes on every machine.
//!
//! | module       | what it gives                                                    |
//! |--------------|------------------------------------------------------------------|
//! | [`svg`]      | a small SVG writer in math coordinates and `SVG -> PNG`          |
//! | [`chart`]    | "several named line series over x" as a PNG, optional log axes   |
//! | [`diagrams`] | the book's diagrams, each an [`crate::book::Artifact`]           |
//! | [`charts`]   | the book's charts, each an [`crate::book::Artifact`]             |
//! | [`compare`]  | two renders side by side, a difference heat map, pixel statistics |
//! | [`study_charts`] | the speed-against-accuracy charts and tables, from the committed CSVs |
//! | [`tables_md`] | the worked tables as generated Markdown, one file per chapter   |
//!
//! To add a figure: write a `fn my_figure() -> Result<Vec<u8>, String>` in
//! [`diagrams`] or [`charts`] and add one `Artifact` line to that module's
//! `artifacts()` list. `lightlab book` writes it to `book/src/generated/<path>`.

pub mod chart;
pub mod charts;
pub mod compare;
pub mod diagrams;
pub mod renders;
pub mod study_charts;
pub mod svg;
pub mod tables_md;

/// The bytes of the vendored DejaVu Sans (Debian `fonts-dejavu-core` 2.37;
/// Bitstream Vera licence, see `book/fonts/LICENSE`).
pub const FONT_DATA: &[u8] = include_bytes!("../../book/fonts/DejaVuSans.ttf");

/// The family name inside [`FONT_DATA`]; figures name this family (or a generic
/// family, which maps to it).
pub const FONT_FAMILY: &str = "DejaVu Sans";
