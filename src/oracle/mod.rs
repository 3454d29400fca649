//! The randomized oracle: the tutorials' shaders on llvmpipe against the Rust `f32` core and
//! the `f64` reference, case by case (`lightlab oracle`).
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `got` | a result of llvmpipe or of the `f32` core |
//! | `want` | the `f64` reference's result for the same (exactly widened) inputs |
//! | abs error | `|got - want|`, per channel, the largest channel per case |
//! | ulps | `|got - want| / ulp(max(|want|, 2^-10))`, with `ulp(x)` the `f32` spacing at `x`: the floor keeps dark channels (below 1/1024, invisible after 8-bit output) from reporting huge ulp counts for tiny absolute errors |
//! | bound | the asserted bound on the abs error, derived in [`cases::bounds`] |
//!
//! For each model [`run_model`] draws the cases ([`cases`]), runs them through the
//! model's harness in one draw per group, evaluates the same cases with the `f32` core and
//! the reference, and sorts each case into a [`Class`](cases::Class). Defined cases enter
//! the statistics and the bound; the others are counted by class with what llvmpipe
//! returned. [`measure_pow`] measures llvmpipe's `pow` alone, the one built-in whose error
//! the bounds take from measurement.
//!
//! | file | what it holds |
//! | --- | --- |
//! | [`cases`] | random cases and the Rust answers for them: `strategies` (proptest, fixed seeds), `bounds` (the derived error bounds), `eval` (the `f32` core and the `f64` reference), `classify` (GLSL's undefined cases), `fields` (the layout places they read) |
//! | `stats` | distances in ulps and their summary ([`ErrorSummary`]) |
//! | `compare` | one run: [`run_model`], [`measure_pow`], [`run`] and their reports |
//! | `format` | the report as text and as Markdown ([`format_text`], [`format_markdown`]) |
//!
//! The oracle runs on [`crate::gl`] (context, batches, layouts, the tutorials' GLSL) and
//! depends on nothing above it; the checker ([`crate::checker`]) draws its cases and bounds
//! from [`cases`].
//!
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

pub mod cases;
mod compare;
mod format;
mod stats;

pub use compare::{
    measure_pow, run, run_model, CaseRecord, ExcludedReport, ModelReport, OracleReport, PowReport, DEFAULT_CASES,
};
pub use format::{describe_inputs, format_markdown, format_text, report_markdown};
pub(crate) use stats::ErrorAcc;
pub use stats::{ulp_f32, ulps, ErrorSummary, ULP_FLOOR};
