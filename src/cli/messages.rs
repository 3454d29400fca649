//! The Rust strings a reader sees, listed for the translation template: the book's own
//! words (the untranslated mark, the language picker, mdBook's menus), the checker's
//! sentences, the grading's feedback labels, the mistake catalogue's titles and
//! explanations, and the exercises' titles and statements.
//! Each stays where it is defined, as an English msgid; [`crate::i18n::tr`] looks it up at
//! run time. The list lives here, at the top of the crate, because it names strings from
//! every layer: `i18n` below takes it as a parameter ([`crate::i18n::extract::template`]).

use std::path::Path;

use crate::book::BookError;

/// Every Rust string a reader sees in a translated language, with where it is defined.
#[must_use]
pub fn rust_messages() -> Vec<(String, &'static str)> {
    let mut out: Vec<(String, &'static str)> = vec![
        (crate::i18n::translate::UNTRANSLATED_MARK.to_owned(), "src/i18n/translate.rs"),
        (crate::book::LANGUAGE_LABEL.to_owned(), "src/book.rs"),
        (crate::live::exercises::LINK_STATEMENT.to_owned(), "src/live/exercises.rs"),
    ];
    out.extend(crate::i18n::chrome::words().map(|w| (w.to_owned(), "src/i18n/chrome.rs")));
    out.extend(all());
    use clap::CommandFactory;
    let help = crate::cli::help::texts(&crate::cli::args::Cli::command());
    out.extend(help.into_iter().map(|h| (h, "src/cli/args.rs")));
    out
}

/// The translation template of the book at `root`: its messages, [`rust_messages`] and
/// the words its generated files draw ([`crate::book::drawn_words`]).
pub fn translation_template(root: &Path) -> Result<polib::catalog::Catalog, BookError> {
    crate::i18n::extract::template(root, &rust_messages(), &crate::book::drawn_words(root)?)
        .map_err(|message| BookError::MdBook { what: "extracting the messages of", root: root.to_path_buf(), message })
}

/// The checker's, the grading's and the exercises' strings, with the file that defines each.
#[must_use]
fn all() -> Vec<(String, &'static str)> {
    let mut out: Vec<(String, &'static str)> =
        crate::cli::input::TEXTS.iter().map(|s| ((*s).to_owned(), "src/cli/input.rs")).collect();
    #[cfg(feature = "gl")]
    {
        use crate::checker::check::report::{
            REPORT_AGREES, REPORT_CASES, REPORT_COUNTEREXAMPLE, REPORT_DISAGREES, REPORT_ERROR,
        };
        use crate::checker::mistakes::{CATALOGUE, VERTEX_CATALOGUE};
        for s in crate::checker::texts::ALL {
            out.push(((*s).to_owned(), "src/checker/texts.rs"));
        }
        for s in crate::checker::check::pair::MESSAGES {
            out.push(((*s).to_owned(), "src/checker/check/pair/diagnose.rs"));
        }
        use crate::checker::texts::{SOLUTION_SENTENCES, SOLUTION_VERDICT};
        for s in SOLUTION_SENTENCES.into_iter().chain(SOLUTION_VERDICT) {
            out.push((s.to_owned(), "src/checker/texts.rs"));
        }
        for s in crate::exercises::change::TEXTS {
            out.push((s.to_owned(), "src/exercises/change.rs"));
        }
        for s in [REPORT_AGREES, REPORT_DISAGREES, REPORT_CASES, REPORT_ERROR, REPORT_COUNTEREXAMPLE] {
            out.push((s.to_owned(), "src/checker/check/report.rs"));
        }
        out.push((crate::cli::check_shader::NOT_A_SHADER.to_owned(), "src/cli/check_shader.rs"));
        for s in crate::exercises::answer_text::TEXTS {
            out.push((s.to_owned(), "src/exercises/answer_text.rs"));
        }
        for s in crate::exercises::FILE_TEXTS {
            out.push((s.to_owned(), "src/exercises/check.rs"));
        }
        use crate::exercises::{STARTER_CHOICE, STARTER_NUMBER, STARTER_NUMBER_UNIT};
        for s in [STARTER_NUMBER, STARTER_NUMBER_UNIT, STARTER_CHOICE] {
            out.push((s.to_owned(), "src/exercises/mod.rs"));
        }
        for s in
            [crate::cli::exercise::SHOW_CHAPTER, crate::cli::exercise::SHOW_MODEL, crate::cli::exercise::ANSWER_COLUMN]
        {
            out.push((s.to_owned(), "src/cli/exercise.rs"));
        }
        out.push((crate::cli::exercise::UNKNOWN_EXERCISE.to_owned(), "src/cli/exercise.rs"));
        for s in [crate::cli::ERROR_LINE, crate::cli::INTERNAL_LINE, crate::cli::BOOK_FLAG_FIRST] {
            out.push((s.to_owned(), "src/cli/mod.rs"));
        }
        for s in crate::cli::usage_error::TEXTS {
            out.push((s.to_owned(), "src/cli/usage_error.rs"));
        }
        out.push((crate::gl::batch::VERSION_NOTE.to_owned(), "src/gl/batch.rs"));
        use crate::checker::check::{RULE_FORBIDDEN, RULE_REQUIRED};
        use crate::cli::child::{CRASHED, DOES_NOT_TERMINATE, OUT_OF_MEMORY, TIMED_OUT, VERDICTS, VERDICT_LINE};
        for s in [TIMED_OUT, OUT_OF_MEMORY, CRASHED, DOES_NOT_TERMINATE, VERDICT_LINE, RULE_FORBIDDEN, RULE_REQUIRED]
            .into_iter()
            .chain(VERDICTS)
        {
            out.push((s.to_owned(), "src/cli/child.rs"));
        }
        for s in crate::cli::grade::texts::ALL.iter().chain(crate::cli::grade::texts::TEACHER) {
            out.push(((*s).to_owned(), "src/cli/grade/texts.rs"));
        }
        for m in CATALOGUE.iter().chain(VERTEX_CATALOGUE) {
            out.push((m.title.to_owned(), "src/checker/mistakes.rs"));
            out.push((m.why.to_owned(), "src/checker/mistakes.rs"));
        }
        out.push((crate::checker::two_mistakes::TWO_MISTAKES.to_owned(), "src/checker/two_mistakes.rs"));
        for s in crate::checker::sites::Site::ALL {
            out.push((s.phrase().to_owned(), "src/checker/sites.rs"));
        }
        for s in crate::checker::isolation::ISOLATION_SEPARATORS {
            out.push((s.to_owned(), "src/checker/isolation.rs"));
        }
        for s in [crate::checker::hints::HINT_LINE, crate::checker::hints::HINT_NUMBERED] {
            out.push((s.to_owned(), "src/checker/hints.rs"));
        }
        for e in crate::checker::mistakes::EQUIVALENT {
            out.push((e.reason.to_owned(), "src/checker/mistakes.rs"));
        }
        for (_, hints) in crate::checker::hints::HINTS {
            out.extend(hints.iter().map(|h| ((*h).to_owned(), "src/checker/hints.rs")));
        }
        use crate::checker::hints::{
            EVERY_LIGHT_TERM_WHERE, KIND_HINTS, LIGHT_HINTS, NOWHERE_HINTS, TERM_HINTS, UNSWITCHED_HINTS, WHEN_HINTS,
        };
        let isolation_hints = TERM_HINTS.iter().flat_map(|(_, h)| h).chain(&LIGHT_HINTS).chain(&KIND_HINTS);
        let isolation_hints = isolation_hints.chain(&WHEN_HINTS).chain(&NOWHERE_HINTS).chain(&UNSWITCHED_HINTS);
        let isolation_hints = isolation_hints.chain([&EVERY_LIGHT_TERM_WHERE]);
        out.extend(isolation_hints.map(|h| ((*h).to_owned(), "src/checker/hints.rs")));
        for name in crate::checker::isolation::term_switch_names() {
            out.push((name, "src/checker/isolation.rs"));
        }
        for e in crate::exercises::EXERCISES {
            out.push((e.title.to_owned(), "src/exercises/catalogue.rs"));
            out.push((e.statement.to_owned(), "src/exercises/catalogue.rs"));
        }
    }
    out
}
