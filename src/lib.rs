//! lightlab

/// Headless OpenGL verification on Mesa llvmpipe (feature `gl`).
#[cfg(feature = "gl")]
pub mod gl;
