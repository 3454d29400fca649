//! The page's guards against a reader's shader: the limits `book/theme/live/lightlab-gl.js`
//! applies in the exercise checker and the live-figure editor, emitted here once (under
//! `guard` in each figure's and exercise's data) so that the page retypes no number.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | loop cap | loop iterations one fragment may run before every loop condition turns false |
//! | loop mark | the alpha (rgb for a `vec3` output) a fragment writes when the cap stopped one of its loops |
//! | expansion | an upper bound of the tokens one `#define` expands to (lightlab-gl.js `macroRefusal`) |
//! | chunk | cases drawn between two waits for the GPU; sizes grow 1, 2, 4, … |
//! | budget | the most a reader's cases 1..=b may take: the floor plus the ratio times the reference's time on the same cases |
//!
//! Chromium draws WebGL in SwiftShader when it has no GPU, and runs no GPU watchdog there
//! (measured in `tests/browser.rs`, `an_endless_loop_in_the_editor_leaves_the_tab_responsive`:
//! without the cap an endless loop held the GPU process, and the tab, for minutes with no
//! context loss). A draw cannot be interrupted from JavaScript, so the cap is what makes
//! every draw end; the budget then stops a shader that is slow on any case.

use serde_json::{json, Value};

/// Loop iterations per fragment, and the mark a capped fragment writes: the command line's
/// loop guard's ([`crate::checker::check::loops`]), so the page and `exercise check` stop the
/// same loops. 10⁵ iterations of a `sin` loop took about 16 ms per fragment in SwiftShader
/// on this project's 2-core machine under load (10⁸ took 15.7 s), so one case capped at
/// fewer cannot hold the GPU long. The page writes the mark in the alpha of a `vec4`
/// output (all three channels of a `vec3` one); the checker compares rgb only and the
/// tutorials' shaders write alpha 1, so the mark cannot be a reader's value by accident.
pub use crate::checker::check::loops::{LOOP_CAP, LOOP_MARK};
/// The most `#define`s a source may hold: the tutorials' shaders have one
/// (`NR_POINT_LIGHTS`); a thousand leaves room for any hand-written shader.
pub const MAX_DEFINES: u32 = 1000;
/// The most tokens one macro may expand to (by the page's bound). The audit's bomb, a
/// 1.3 KB shader of nested `#define`s, took Chromium's GPU process past 2 GB; 10⁵ tokens is
/// about a megabyte of text, far beyond any shader and far below the memory of a tab.
pub const MAX_EXPANSION: u32 = 100_000;
/// The checker's absolute floor: a reader's cases are never stopped before they took this
/// long in total, whatever the ratio (a loaded machine can pause a draw for hundreds of
/// milliseconds; one warm case of the tutorials' shaders draws in about 1 ms in SwiftShader).
pub const CHUNK_FLOOR_MS: f64 = 1000.0;
/// The checker's ratio to the reference's time on the same cases: a correct shader written
/// less efficiently is a few times slower than the reference, not ten, and the two are timed
/// moments apart, so a load slows both.
pub const CHUNK_RATIO: f64 = 10.0;
/// The longest a live figure's draw of the reader's edited shader may take before the
/// figure goes back to the verified shader: a figure draws at every slider move, and the
/// verified shaders draw a figure in tens of milliseconds in SwiftShader.
pub const LIVE_DRAW_MS: f64 = 1000.0;

/// The guard's limits as the page reads them.
#[must_use]
pub fn guard_json() -> Value {
    json!({
        "loop_cap": LOOP_CAP,
        "loop_mark": LOOP_MARK,
        "max_defines": MAX_DEFINES,
        "max_expansion": MAX_EXPANSION,
        "chunk_floor_ms": CHUNK_FLOOR_MS,
        "chunk_ratio": CHUNK_RATIO,
        "live_draw_ms": LIVE_DRAW_MS,
    })
}
