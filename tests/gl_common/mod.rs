//! Shared by the OpenGL test files: a context, or a printed reason to skip.
#![allow(dead_code)]

use lightlab::gl::GlContext;

/// A context for tests: `Some` when OpenGL works; `None` with the reason printed when it
/// does not, unless the environment sets `LIGHTLAB_REQUIRE_GL=1`, which turns a missing
/// OpenGL into a panic (CI installs Mesa and sets it).
pub fn context_or_skip() -> Option<GlContext> {
    match GlContext::new() {
        Ok(ctx) => Some(ctx),
        Err(e) if std::env::var("LIGHTLAB_REQUIRE_GL").as_deref() == Ok("1") => {
            panic!("LIGHTLAB_REQUIRE_GL=1 but no OpenGL context: {e}")
        }
        Err(e) => {
            println!("skipped: no OpenGL context: {e}");
            None
        }
    }
}
