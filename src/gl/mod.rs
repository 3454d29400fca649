//! Real OpenGL: Mesa llvmpipe through a headless EGL context, and the tutorials' shaders
//! that run on it.
//!
//! - [`context`]: create an OpenGL 3.3 core context without a window ([`GlContext`]).
//! - [`batch`]: evaluate a GLSL function over many cases in one draw ([`Batch`]).
//! - [`layout`]: the packed inputs of every model, described once (also as JSON,
//!   `lightlab oracle --layouts`); `tables` holds the layouts, `json` the export.
//! - [`model_id`]: [`ModelId`], the one typed name of a model (strings only at the edges).
//! - [`edit`]: text edits of a function file (the checker's mistakes, derived models).
//! - [`models`]: the tutorials' shaders as GLSL function files and harnesses
//!   (`src/gl/shaders/`), and the example shaders of `check-shader`
//!   (`src/gl/shaders/examples/`).
//!
//! Two modules run on this one: [`crate::oracle`] (the randomized comparison of llvmpipe,
//! the `f32` core and the `f64` reference) and [`crate::checker`] (a learner's shader
//! checked against a model, its mistake named). Nothing here depends on either. The
//! benchmark scenes drawn through OpenGL are in `crate::study::bench` (feature `book`).
//!
//! Everything returns [`GlError`] when OpenGL is missing; nothing panics. The system needs
//! `libegl1 libegl-mesa0 libgl1-mesa-dri` (Debian names).
//!
//! # What llvmpipe returns where GLSL leaves the result undefined
//! Measured on Mesa 22.3.6, llvmpipe (LLVM 15.0.6, 256 bits), by the test
//! `undefined_builtins_on_llvmpipe` in `tests/gl_smoke.rs`, which prints the table again.
//! Inputs come from textures, so the compiler cannot fold them.
//!
//! | expression | GLSL 3.30 says | llvmpipe returns |
//! | --- | --- | --- |
//! | `pow(-2, 2)`, `pow(-2, 0.5)`, `pow(-0.5, 32)` | undefined for x < 0 | NaN (even for even integer y: it computes `exp2(y * log2(x))`) |
//! | `pow(0, 0)` | undefined for x = 0, y <= 0 | 0 (C's `pow` gives 1) |
//! | `pow(0, 32)` | 0 | 0 |
//! | `pow(1e-19, 2)` = 1e-38, below the smallest normal f32 | denormals may be flushed | 0 (flushed) |
//! | an input texel of 1e-40 (denormal): `clamp(x, 0, 1)`, `pow(x, 1)` | denormals may be flushed | 0, 0 (flushed on read) |
//! | `normalize(vec3(0))` | undefined (division by zero) | NaN in every component |
//! | `normalize(vec3(1e-30, 0, 0))` | defined (a unit vector) | (inf, NaN, NaN): the squared length underflows to 0 |
//! | `normalize(vec3(1e30, 0, 0))` | defined (a unit vector) | (0, 0, 0): the squared length overflows to inf |
//! | `clamp(NaN, 0, 1)` | undefined | 0 |
//! | `clamp(-inf, 0, 1)`, `clamp(inf, 0, 1)` | 0, 1 | 0, 1 |
//!
//! Consequences for the tutorials: ogldev 19 computes `pow(dot, power)` before testing the
//! dot's sign, and gets NaN for a negative dot; `NaN > 0` is false, so the term is dropped and
//! the image is right by accident. A shader that clamps after `pow` would turn the NaN into 0
//! as well. A Rust reference must not use `f32::powf` semantics (`powf(0, 0) = 1`,
//! `powf(-2, 2) = 4`) where it claims to match the GPU.
//!
//! # Throughput
//! `Batch::run` on 10^6 cases of a two-input shader (`max(dot(normalize(a), normalize(b)), 0)`),
//! release build, 2 shared cores: 20 to 35 million cases per second including upload
//! (about 18 ms for two 16 MB textures), draw (5 to 11 ms) and read-back (3 to 8 ms).

pub mod batch;
pub mod context;
pub mod edit;
pub mod layout;
pub mod model_id;
pub mod models;

pub use batch::{Batch, BatchTiming, Outputs, Uniform};
pub use context::{GlContext, GlError, GlInfo};
pub use model_id::{ModelId, UnknownModel};
pub use models::{ShaderModel, EXAMPLE_SHADERS, MODELS};
