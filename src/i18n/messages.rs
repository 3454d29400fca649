//! The Rust strings a reader sees, listed for the template: the mistake catalogue's titles
//! and explanations, the checker's sentences, and the exercises' titles and statements.
//! Each is an English msgid; [`super::tr`] looks it up at run time.

/// The checker's verdict sentences (`{}`: the model's name, then the finding's title).
pub const AGREES: &str = "Your shader agrees with the model {}.";
/// See [`AGREES`].
pub const DISAGREES: &str = "Your shader disagrees with the model {}.";
/// See [`AGREES`].
pub const DISAGREES_ISOLATED: &str = "Your shader disagrees with the model {}: {}.";
/// See [`AGREES`].
pub const DISAGREES_LIKELY: &str = "Your shader disagrees with the model {}. Most likely:";
/// See [`AGREES`].
pub const SEE_THE_BOOK: &str = "see the book: {}";

/// Every listed string with the file that defines it.
#[must_use]
pub fn all() -> Vec<(String, &'static str)> {
    let mut out: Vec<(String, &'static str)> = [AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, SEE_THE_BOOK]
        .iter()
        .map(|s| (s.to_string(), "src/i18n/messages.rs"))
        .collect();
    #[cfg(feature = "gl")]
    {
        use crate::gl::mistakes::{CATALOGUE, VERTEX_CATALOGUE};
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
