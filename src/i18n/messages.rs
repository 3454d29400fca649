//! The Rust strings a reader sees, listed for the template: the checker's sentences, the
//! grading's feedback labels, the mistake catalogue's titles and explanations, and the
//! exercises' titles and statements.
//! Each stays where it is defined, as an English msgid; [`super::tr`] looks it up at run time.

/// Every listed string with the file that defines it.
#[must_use]
pub fn all() -> Vec<(String, &'static str)> {
    #[allow(unused_mut)]
    let mut out: Vec<(String, &'static str)> = Vec::new();
    #[cfg(feature = "gl")]
    {
        use crate::gl::check::report::{
            REPORT_AGREES, REPORT_CASES, REPORT_COUNTEREXAMPLE, REPORT_DISAGREES, REPORT_ERROR,
        };
        use crate::gl::mistakes::{CATALOGUE, VERTEX_CATALOGUE};
        use crate::gl::texts::{AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, EVIDENCE, SEE_THE_BOOK};
        for s in [AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, SEE_THE_BOOK, EVIDENCE] {
            out.push((s.to_owned(), "src/gl/texts.rs"));
        }
        for s in [REPORT_AGREES, REPORT_DISAGREES, REPORT_CASES, REPORT_ERROR, REPORT_COUNTEREXAMPLE] {
            out.push((s.to_owned(), "src/gl/check/report.rs"));
        }
        for s in [crate::cli::exercise::SHOW_CHAPTER, crate::cli::exercise::SHOW_MODEL] {
            out.push((s.to_owned(), "src/cli/exercise.rs"));
        }
        use crate::cli::child::{CRASHED, OUT_OF_MEMORY, TIMED_OUT, VERDICTS, VERDICT_LINE};
        for s in [TIMED_OUT, OUT_OF_MEMORY, CRASHED, VERDICT_LINE].into_iter().chain(VERDICTS) {
            out.push((s.to_owned(), "src/cli/child.rs"));
        }
        for s in crate::cli::grade::texts::ALL {
            out.push(((*s).to_owned(), "src/cli/grade/texts.rs"));
        }
        for m in CATALOGUE.iter().chain(VERTEX_CATALOGUE) {
            out.push((m.title.to_owned(), "src/gl/mistakes.rs"));
            out.push((m.why.to_owned(), "src/gl/mistakes.rs"));
        }
        out.push((crate::gl::hints::HINT.to_owned(), "src/gl/hints.rs"));
        for (_, hints) in crate::gl::hints::HINTS {
            out.extend(hints.iter().map(|h| ((*h).to_owned(), "src/gl/hints.rs")));
        }
        for e in crate::exercises::EXERCISES {
            out.push((e.title.to_owned(), "src/exercises/catalogue.rs"));
            out.push((e.statement.to_owned(), "src/exercises/catalogue.rs"));
        }
    }
    out
}
