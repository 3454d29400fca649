//! Verification on real OpenGL: Mesa llvmpipe through a headless EGL context.
//!
//! - [`context`]: create an OpenGL 3.3 core context without a window ([`GlContext`]).
//! - [`batch`]: evaluate a GLSL function over many cases in one draw ([`Batch`]).
//! - [`layout`]: the packed inputs of every model, described once (also as JSON,
//!   `lightlab oracle --layouts`); `tables` holds the layouts, `json` the export.
//! - [`model_id`]: [`ModelId`], the one typed name of a model (strings only at the edges).
//! - [`models`]: the tutorials' shaders as GLSL function files and harnesses.
//! - [`cases`]: random cases and the Rust answers for them: `strategies` (proptest, fixed
//!   seeds), `bounds` (the derived error bounds), `eval` (the `f32` core and the `f64`
//!   reference), `classify` (GLSL's undefined cases), `fields` (the layout places they read).
//! - [`check`]: `lightlab check-shader`, a user's fragment shader against a model:
//!   `glsl` (the scanner), `mapping` (the `--uniforms` file and name matching), `rewrite`
//!   (the shader turned into a batch body), `report` (the comparison).
//! - [`mistakes`]: the mistake catalogue, each mistake a rewrite of the function files.
//! - [`diagnose`]: naming the mistake of a shader that disagrees.
//! - [`complete`]: complete fragment shaders built from the function files.
//! - [`oracle`]: the randomized comparison of llvmpipe, the `f32` core and the `f64` reference.
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

//! # What the oracle measured
//! `lightlab oracle` (10^5 cases per model, seed `0x6c696768746c6162`, Mesa 22.3.6 llvmpipe)
//! finds llvmpipe and the Rust `f32` core both within their derived bounds on every model;
//! the largest distances from the `f64` reference are 1e-5 to 5e-5 on colors of order 1
//! (opengl-tutorial 8: 2e-4 on values up to 60), against bounds of 3e-4 to 2e-2. The
//! dominant error is the specular exponent carrying the base's rounding: about
//! `s·(a few ε)` relative, hence several hundred ulps at `s` near 256. llvmpipe's `pow`
//! alone has a relative error up to 2.9e-5 at `y = 253` (an absolute `log2` error of
//! about `3ε`, scaled by `y`). On GLSL's undefined inputs llvmpipe's `normalize(0)` gives
//! NaN, which `max(NaN, 0)` turns into 0, so the LearnOpenGL shaders show the `f32` core's
//! documented fallback (no diffuse or specular); opengl-tutorial 8 does too except when the
//! light sits on the fragment (`distance = 0`: NaN in 511 of its 2030 such cases);
//! ogldev 19's `pow` of a negative base is
//! NaN in all 24 596 such cases and drops the highlight. The oracle also caught a mistake
//! in this crate's first `multiple_lights.glsl` (the spotlight's ambient term not scaled
//! by its intensity, unlike the chapter's code and the core).

pub mod batch;
pub mod bench;
pub mod cases;
pub mod check;
pub mod complete;
pub mod context;
pub mod diagnose;
pub mod hints;
pub mod isolation;
pub mod layout;
pub mod mistakes;
pub mod model_id;
pub mod models;
pub mod oracle;
pub mod outputs;
pub mod sites;
pub mod texts;
pub mod two_mistakes;
pub mod verdict;

pub use batch::{Batch, BatchTiming, Outputs, Uniform};
pub use context::{GlContext, GlError, GlInfo};
pub use model_id::{ModelId, UnknownModel};
pub use models::{ShaderModel, EXAMPLE_SHADERS, MODELS};
