//! `lightlab book --no-solutions`: the book without the exercises' reference solutions,
//! for a course that grades the exercises.
//!
//! A solution reaches the built book in two places, and both are withheld:
//! - the exercises appendix folds each one in a `<details>` block whose summary is
//!   `Reference solution` ([`crate::exercises::book_markdown`]): [`StripSolutions`], an
//!   mdBook preprocessor run before translation, removes those blocks from every
//!   chapter, so the pages, `print.html` and the search index of every language lack them;
//! - each in-page exercise's data (`generated/live/exercise-<id>.js`) carries `solution`,
//!   which `?selftest` runs through the checker: [`strip_page_data`] removes that key
//!   from the built copies (the generated files in `book/src/generated/` stay whole, so
//!   the cache serves both builds).
//!
//! What a determined student can still read: the in-page checker compares the reader's
//! shader with a complete reference shader, so the page data keeps `reference` (for a
//! shader exercise, the chapter's shader with the exercise's functions; for a variant,
//! with the exercise's change applied) and the mistake mutants. Those run in the
//! browser and can be read with its developer tools. The command-line check and the
//! grading need no page data. `?selftest` then checks each exercise with `reference`.

use std::fs;
use std::path::Path;

use mdbook_preprocessor::book::{Book, BookItem};
use mdbook_preprocessor::errors::Result as MdResult;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use super::{list_files, BookError};
use crate::live::exercises::{LINK_STATEMENT, LINK_WITH_SOLUTION};

/// Where a folded solution starts, as [`crate::exercises::book_markdown`] writes it.
pub const SOLUTION_START: &str = "<details><summary>Reference solution</summary>";
/// Where it ends.
const SOLUTION_END: &str = "</details>";

/// `markdown` with every exercise box's link text, in every language, saying
/// [`LINK_STATEMENT`] instead of [`LINK_WITH_SOLUTION`].
#[must_use]
pub fn relink(markdown: &str) -> String {
    use crate::i18n::{tr, translate::html_attr, Lang};
    let mut out = markdown.to_owned();
    for lang in Lang::ALL {
        let from = format!(">{}</a>", html_attr(&tr(lang, LINK_WITH_SOLUTION)));
        if out.contains(&from) {
            out = out.replace(&from, &format!(">{}</a>", html_attr(&tr(lang, LINK_STATEMENT))));
        }
    }
    out
}

/// `markdown` without its folded reference solutions: each block from
/// [`SOLUTION_START`] to the next `</details>` (and the line end after it) is removed.
/// An unterminated block is removed to the end of the text.
#[must_use]
pub fn strip(markdown: &str) -> String {
    let mut out = String::with_capacity(markdown.len());
    let mut rest = markdown;
    while let Some(start) = rest.find(SOLUTION_START) {
        out.push_str(&rest[..start]);
        let after = &rest[start..];
        rest = match after.find(SOLUTION_END) {
            Some(end) => {
                let tail = &after[end + SOLUTION_END.len()..];
                tail.strip_prefix('\n').unwrap_or(tail)
            }
            None => "",
        };
    }
    out.push_str(rest);
    out
}

/// The preprocessor of `--no-solutions` ([`strip`] on every chapter), named
/// [`PREPROCESSOR`]; [`order`] puts it where it sees the included appendix in English.
pub struct StripSolutions;

/// The name of [`StripSolutions`] in the book's configuration.
pub const PREPROCESSOR: &str = "lightlab-no-solutions";

/// Declares [`StripSolutions`] in `config`, after `links` (which includes the generated
/// appendix) and before `gettext` (which translates the `Reference solution` summary):
/// mdBook orders preprocessors by the configuration, and [`mdbook_driver::MDBook::with_preprocessor`]
/// then puts the in-process one in the declared place.
///
/// Errors: mdBook's, if the configuration cannot take the table.
pub fn order(config: &mut mdbook_driver::config::Config) -> Result<(), mdbook_driver::errors::Error> {
    config.set(format!("preprocessor.{PREPROCESSOR}.after"), ["links"])?;
    config.set(format!("preprocessor.{PREPROCESSOR}.before"), ["gettext"])
}

impl Preprocessor for StripSolutions {
    fn name(&self) -> &str {
        PREPROCESSOR
    }

    fn run(&self, _ctx: &PreprocessorContext, mut book: Book) -> MdResult<Book> {
        book.for_each_mut(|item| {
            if let BookItem::Chapter(ch) = item {
                if ch.content.contains(SOLUTION_START) {
                    ch.content = strip(&ch.content);
                }
                ch.content = relink(&ch.content);
            }
        });
        Ok(book)
    }
}

/// The exercise data script `js` (`(...)[<id>] = {...};`) without its `solution` key;
/// `None` when it is not such a script.
fn strip_script(js: &str) -> Option<String> {
    let at = js.find("] = ")? + "] = ".len();
    let body = js[at..].trim_end().strip_suffix(';')?;
    let mut data: serde_json::Value = serde_json::from_str(body).ok()?;
    data.as_object_mut()?.remove("solution");
    Some(format!("{}{};\n", &js[..at], data))
}

/// Removes `solution` from every built exercise data script under `dir` (every
/// language's `generated/live/exercise-*.js`). Returns how many scripts were rewritten.
///
/// Errors: [`BookError::Io`] naming the file that cannot be read or written.
pub fn strip_page_data(dir: &Path) -> Result<usize, BookError> {
    let mut n = 0;
    for file in list_files(dir)? {
        let name = file.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        let in_live = file.parent().is_some_and(|p| p.ends_with("generated/live"));
        if !(in_live && name.starts_with("exercise-") && name.ends_with(".js")) {
            continue;
        }
        let js = fs::read_to_string(&file).map_err(BookError::io("reading", &file))?;
        if let Some(stripped) = strip_script(&js) {
            fs::write(&file, stripped).map_err(BookError::io("writing", &file))?;
            n += 1;
        }
    }
    Ok(n)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn folded_solutions_are_removed_and_the_rest_kept() {
        let md = format!(
            "### A\n\nStatement.\n\n{SOLUTION_START}\n\n```glsl\nvoid main() {{}}\n```\n\n</details>\n\n### B\n\n\
             <details><summary>Other</summary>kept</details>\n{SOLUTION_START}\nunterminated"
        );
        let out = strip(&md);
        assert_eq!(out, "### A\n\nStatement.\n\n\n### B\n\n<details><summary>Other</summary>kept</details>\n");
    }

    #[test]
    fn the_exercise_boxes_link_says_statement_in_every_language() {
        use crate::i18n::{tr, Lang};
        for lang in Lang::ALL {
            let with = tr(lang, LINK_WITH_SOLUTION);
            let md = format!("(<a href=\"12-exercises.html#x\">{with}</a>; on the command line)");
            let out = relink(&md);
            assert!(out.contains(&format!(">{}</a>", tr(lang, LINK_STATEMENT))), "{lang}: {out}");
            assert!(!out.contains(&*with), "{lang}: {out}");
        }
    }

    #[test]
    fn the_page_data_loses_its_solution_only() {
        let js =
            "(window.D = window.D || {})[\"x\"] = {\"id\":\"x\",\"solution\":\"void main(){}\",\"reference\":\"r\"};\n";
        let out = strip_script(js).unwrap();
        assert!(out.starts_with("(window.D = window.D || {})[\"x\"] = {"), "{out}");
        assert!(!out.contains("solution") && out.contains("\"reference\":\"r\"") && out.ends_with("};\n"), "{out}");
        assert_eq!(strip_script("not a script"), None);
    }
}
