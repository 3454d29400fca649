//! lightlab

// Headless OpenGL verification on Mesa llvmpipe (feature `gl`); documented in src/gl/mod.rs.
#[cfg(feature = "gl")]
pub mod gl;
