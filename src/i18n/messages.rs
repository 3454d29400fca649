//! The Rust strings a reader sees, listed for the template: the checker's sentences, the
//! mistake catalogue's titles and explanations, and the exercises' titles and statements.
//! Each stays where it is defined, as an English msgid; [`super::tr`] looks it up at run time.

/// Every listed string with the file that defines it.
#[must_use]
pub fn all() -> Vec<(String, &'static str)> {
    #[allow(unused_mut)]
    let mut out: Vec<(String, &'static str)> = Vec::new();
    #[cfg(feature = "gl")]
    {
        use crate::gl::diagnose::{AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, SEE_THE_BOOK};
        use crate::gl::mistakes::{CATALOGUE, VERTEX_CATALOGUE};
        for s in [AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, SEE_THE_BOOK] {
            out.push((s.to_owned(), "src/gl/diagnose.rs"));
        }
        for m in CATALOGUE.iter().chain(VERTEX_CATALOGUE) {
            out.push((m.title.to_owned(), "src/gl/mistakes.rs"));
            out.push((m.why.to_owned(), "src/gl/mistakes.rs"));
        }
        for e in crate::exercises::EXERCISES {
            out.push((e.title.to_owned(), "src/exercises/catalogue.rs"));
            out.push((e.statement.to_owned(), "src/exercises/catalogue.rs"));
        }
    }
    out
}
