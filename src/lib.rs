//! lightlab

/// Figures for the book: SVG diagrams rasterized with resvg, line charts drawn with plotters.
#[cfg(feature = "book")]
pub mod figures;

/// The book build: generate figures and tables, then render the HTML with mdBook + KaTeX.
#[cfg(feature = "book")]
pub mod book;
