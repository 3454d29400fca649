//! Verification on real OpenGL: Mesa llvmpipe through a headless EGL context.
//!
//! - [`context`]: create an OpenGL 3.3 core context without a window ([`GlContext`]).
//! - [`batch`]: evaluate a GLSL function over many cases in one draw ([`Batch`]).
//! - [`models`]: the tutorials' shaders as GLSL function files with their input layouts.
//!
//! Everything returns [`GlError`] when OpenGL is missing; nothing panics.

pub mod batch;
pub mod context;
pub mod models;

pub use batch::{Batch, BatchTiming, Uniform};
pub use context::{GlContext, GlError, GlInfo};
pub use models::{ShaderModel, MODELS};
