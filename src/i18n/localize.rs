//! Generated files in the reader's language: a chart, a diagram or a live figure's markup
//! that carries words is generated once per language, the English at
//! `src/generated/<path>` and each translation at `src/generated/<code>/<path>`
//! ([`crate::figures::artifact::Artifact::localized`]). A translated chapter then points at
//! its language's copy:
//!
//! - before mdBook's `links`, the [`Localize`] preprocessor rewrites the paths inside
//!   `{{#include …}}` directives, so a chapter includes the French markup of a live figure;
//! - after translation, [`localize_paths`] rewrites every other path (images, scripts), in
//!   the translated text, so a msgstr keeps the English path as the PO checks demand.
//!
//! A path is rewritten only when the language's copy exists on disk: a render without words
//! has one copy, shared by every language.

use std::path::{Path, PathBuf};

use mdbook_preprocessor::book::{Book, BookItem};
use mdbook_preprocessor::errors::Result as MdResult;
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};

use super::Lang;

/// The directory of generated files, relative to the book's `src`.
pub const GENERATED: &str = "generated";

/// The characters a generated path is made of (`live/asset-sphere-4x8.js`, `x@2x.png`).
fn is_path_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || matches!(c, '/' | '.' | '-' | '_' | '@')
}

/// Every `generated/<path>` in `text` whose copy `generated_dir/<code>/<path>` exists,
/// rewritten to `generated/<code>/<path>`; English and other paths stay as they are. A
/// `generated/` that continues a longer path segment (`not-generated/x`) is not a match.
#[must_use]
pub fn localize_paths(text: &str, lang: Lang, generated_dir: &Path) -> String {
    if !lang.is_translation() {
        return text.to_owned();
    }
    let prefix = format!("{GENERATED}/");
    let mut out = String::with_capacity(text.len() + 64);
    let mut rest = text;
    while let Some(at) = rest.find(&prefix) {
        let starts_segment = rest[..at].chars().next_back().is_none_or(|c| !is_path_char(c) || c == '/');
        let after = &rest[at + prefix.len()..];
        let len = after.find(|c: char| !is_path_char(c)).unwrap_or(after.len());
        let path = &after[..len];
        out.push_str(&rest[..at + prefix.len()]);
        if starts_segment && !path.is_empty() && generated_dir.join(lang.code()).join(path).is_file() {
            out.push_str(lang.code());
            out.push('/');
        }
        out.push_str(path);
        rest = &after[len..];
    }
    out.push_str(rest);
    out
}

/// [`localize_paths`] applied only inside `{{#include …}}` directives (the rest of a
/// chapter is English text that gettext must still find in the template).
#[must_use]
pub fn localize_includes(text: &str, lang: Lang, generated_dir: &Path) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find("{{#include") {
        let Some(len) = rest[at..].find("}}") else { break };
        out.push_str(&rest[..at]);
        out.push_str(&localize_paths(&rest[at..at + len + 2], lang, generated_dir));
        rest = &rest[at + len + 2..];
    }
    out.push_str(rest);
    out
}

/// The book's generated directory, from a preprocessor's context.
#[must_use]
pub fn generated_dir(ctx: &PreprocessorContext) -> PathBuf {
    ctx.root.join(&ctx.config.book.src).join(GENERATED)
}

/// The preprocessor named `localize` (`before = ["links"]` in `book.toml`): a translated
/// chapter includes its language's copy of generated markup.
#[derive(Debug, Clone, Copy)]
pub struct Localize {
    lang: Lang,
}

impl Localize {
    /// The preprocessor for the book in `lang` (English passes chapters through).
    #[must_use]
    pub fn new(lang: Lang) -> Localize {
        Localize { lang }
    }
}

impl Preprocessor for Localize {
    fn name(&self) -> &str {
        "localize"
    }

    fn run(&self, ctx: &PreprocessorContext, mut book: Book) -> MdResult<Book> {
        if !self.lang.is_translation() {
            return Ok(book);
        }
        let dir = generated_dir(ctx);
        book.for_each_mut(|item| {
            if let BookItem::Chapter(ch) = item {
                ch.content = localize_includes(&ch.content, self.lang, &dir);
            }
        });
        Ok(book)
    }

    fn supports_renderer(&self, _renderer: &str) -> MdResult<bool> {
        Ok(true)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::scratch::Scratch;

    /// A generated directory with `fr/charts/a.png` and `charts/b.png` (English only).
    fn tree() -> Scratch {
        let d = Scratch::new("localize");
        for p in ["charts/a.png", "fr/charts/a.png", "charts/b.png", "live/f.md", "fr/live/f.md"] {
            let path = d.join(p);
            std::fs::create_dir_all(path.parent().unwrap()).unwrap();
            std::fs::write(path, b"x").unwrap();
        }
        d
    }

    #[test]
    fn only_paths_with_a_copy_in_the_language_are_rewritten() {
        let d = tree();
        let text = "![a](generated/charts/a.png) ![b](generated/charts/b.png) <img src=\"./generated/charts/a.png\">";
        assert_eq!(
            localize_paths(text, Lang::Fr, &d),
            "![a](generated/fr/charts/a.png) ![b](generated/charts/b.png) <img src=\"./generated/fr/charts/a.png\">"
        );
        // no Ukrainian copies, English never rewritten, a longer segment is not a match
        assert_eq!(localize_paths(text, Lang::Uk, &d), text);
        assert_eq!(localize_paths(text, Lang::En, &d), text);
        assert_eq!(localize_paths("not-generated/charts/a.png", Lang::Fr, &d), "not-generated/charts/a.png");
        // idempotent: a rewritten path has no copy of its own
        let once = localize_paths(text, Lang::Fr, &d);
        assert_eq!(localize_paths(&once, Lang::Fr, &d), once);
    }

    #[test]
    fn includes_are_rewritten_and_prose_is_not() {
        let d = tree();
        let text = "See generated/live/f.md.\n{{#include generated/live/f.md}}\n";
        assert_eq!(
            localize_includes(text, Lang::Fr, &d),
            "See generated/live/f.md.\n{{#include generated/fr/live/f.md}}\n"
        );
        assert_eq!(localize_includes("{{#include generated/live/f.md", Lang::Fr, &d), "{{#include generated/live/f.md");
    }
}
