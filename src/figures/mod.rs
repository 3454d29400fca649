//! Figures for the book: diagrams drawn as SVG and rasterized with resvg, and line
//! charts drawn with plotters.
//!
//! Both back ends use one font, the vendored DejaVu Sans in `book/fonts/`, embedded
//! into the binary with `include_bytes!`. No system font is ever loaded, so a figure is
//! the same bytes on every machine.
//!
//! | module       | what it gives                                                    |
//! |--------------|------------------------------------------------------------------|
//! | [`artifact`] | [`artifact::Artifact`]: a generator and the files it writes; the registry checks |
//! | [`svg`]      | a small SVG writer in math coordinates and `SVG -> PNG`          |
//! | [`chart`]    | "several named line series over x" as a PNG, optional log axes   |
//! | [`diagrams`] | the book's diagrams, each an [`artifact::Artifact`]           |
//! | [`charts`]   | the book's charts, each an [`artifact::Artifact`]             |
//! | [`compare`]  | two renders side by side, a difference heat map, pixel statistics |
//! | [`book_data`] | the CSVs in `book/data/` the charts below are drawn from, read at build time |
//! | [`bench_charts`] | the benchmark scenes' roofline and scaling, from the committed CSVs |
//! | [`study_charts`] | the speed-against-accuracy charts and tables, from the committed CSVs |
//! | [`tables_md`] | the worked tables as generated Markdown, one file per chapter   |
//!
//! To add a figure: write a `fn my_figure() -> Result<Vec<u8>, FigureError>` in
//! [`diagrams`] or [`charts`] and add one [`artifact::Artifact::file`] line to that
//! module's `artifacts()` list. `lightlab book` writes it to
//! `book/src/generated/<path>`. Nothing here depends on the book module: the book
//! collects these lists.

pub mod artifact;
pub mod bench_charts;
pub mod book_data;
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

/// Why a figure, table or caption could not be made. Every message names the figure
/// or the field concerned.
#[derive(Debug, thiserror::Error)]
pub enum FigureError {
    /// An input the figure code refuses: a size, range, name or case it does not
    /// have, or data it cannot draw (the message names the field).
    #[error("{0}")]
    Invalid(String),
    /// A drawing back end (resvg, plotters, the PNG encoder) failed.
    #[error("{what}: {message}")]
    Backend {
        /// Which figure or step ("render_png", "LineChart: drawing failed", ...).
        what: String,
        /// The back end's message.
        message: String,
    },
    /// One of the study's committed CSVs does not parse.
    #[error("{}: {source}", path.display())]
    StudyCsv {
        /// The CSV's path.
        path: std::path::PathBuf,
        /// The parse error, with its line.
        source: crate::study::speed::StudyCsvError,
    },
}

impl FigureError {
    /// A back end error from `what`, with the back end's message.
    pub fn backend(what: impl Into<String>, message: impl std::fmt::Display) -> FigureError {
        FigureError::Backend { what: what.into(), message: message.to_string() }
    }
}

impl From<String> for FigureError {
    fn from(message: String) -> FigureError {
        FigureError::Invalid(message)
    }
}

impl From<&str> for FigureError {
    fn from(message: &str) -> FigureError {
        FigureError::Invalid(message.to_owned())
    }
}
