//! mdBook's own words in a translated book: the menu bar's buttons, the theme menu, the
//! search box and its result line, the keyboard help, the code blocks' buttons and the 404
//! page. mdBook writes them in English into every page and into its scripts; they are not
//! part of any chapter, so gettext never sees them.
//!
//! Each is listed here once, with the exact text around it in mdBook 0.5's output
//! ([`PAGE`] for the HTML pages, [`SCRIPT`] for `book-*.js` and `searcher-*.js`). They join
//! the translation template as English msgids, and a translated build replaces each
//! occurrence of its context by the same context around the translation
//! ([`translate_page`], [`translate_script`]). A string whose context is not found is left
//! as it is: a newer mdBook that changed its words shows them in English, never broken.
//!
//! The theme names Rust, Coal, Navy and Ayu are names and stay as they are; "Auto" and
//! "Light" describe the theme and are translated.

use super::{tr, Lang};

/// An mdBook string in its context: `{}` stands for the words.
pub struct Chrome {
    /// The text around the words, with `{}` where they stand.
    pub context: &'static str,
    /// The English words (a msgid of the template).
    pub words: &'static str,
}

const fn c(context: &'static str, words: &'static str) -> Chrome {
    Chrome { context, words }
}

/// mdBook's words in its HTML pages.
pub const PAGE: &[Chrome] = &[
    c("title=\"{}\"", "Toggle Table of Contents"),
    c("aria-label=\"{}\"", "Toggle Table of Contents"),
    c("aria-label=\"{}\"", "Table of contents"),
    c("title=\"{}\"", "Change theme"),
    c("aria-label=\"{}\"", "Change theme"),
    c("aria-label=\"{}\"", "Themes"),
    c("title=\"{}\"", "Search (`/`)"),
    c("aria-label=\"{}\"", "Toggle Searchbar"),
    c("placeholder=\"{}\"", "Search this book ..."),
    c("title=\"{}\"", "Print this book"),
    c("aria-label=\"{}\"", "Print this book"),
    c("title=\"{}\"", "Previous chapter"),
    c("aria-label=\"{}\"", "Previous chapter"),
    c("title=\"{}\"", "Next chapter"),
    c("aria-label=\"{}\"", "Next chapter"),
    c("aria-label=\"{}\"", "Page navigation"),
    c("\">{}</button>", "Auto"),
    c("\">{}</button>", "Light"),
    c(">{}</h2>", "Keyboard shortcuts"),
    c("<p>{}</p>", "Press <kbd>←</kbd> or <kbd>→</kbd> to navigate between chapters"),
    c("<p>{}</p>", "Press <kbd>S</kbd> or <kbd>/</kbd> to search in the book"),
    c("<p>{}</p>", "Press <kbd>?</kbd> to show this help"),
    c("<p>{}</p>", "Press <kbd>Esc</kbd> to hide this help"),
    c("\">{}</a></h1>", "Document not found (404)"),
    c("<p>{}</p>", "This URL is invalid, sorry. Please use the navigation bar or search to continue."),
];

/// mdBook's words in its scripts (string literals).
pub const SCRIPT: &[Chrome] = &[
    c("'{}'", "Copy to clipboard"),
    c("'{}'", "Copied!"),
    c("'{}'", "Clipboard error!"),
    c("'{}'", "Show hidden lines"),
    c("title=\"{}\"", "Show hidden lines"),
    c("aria-label=\"{}\"", "Show hidden lines"),
    c("'{}'", "Hide lines"),
    c("'{}'", "Run this code"),
    c("'{}'", "Undo changes"),
    c("'{}'", "Running..."),
    c("'{}'", "No output"),
    c("' {} \\''", "search result for"),
    c("' {} \\''", "search results for"),
    c("'{} \\''", "No search results for"),
];

/// Every listed English string, once each (for the template).
pub fn words() -> impl Iterator<Item = &'static str> {
    let mut seen = Vec::new();
    PAGE.iter().chain(SCRIPT).map(|c| c.words).filter(move |w| {
        let new = !seen.contains(w);
        seen.push(w);
        new
    })
}

impl Chrome {
    /// `words` written into this context: escaped for an attribute (`="{}"`) or a string
    /// literal (`'{}'`); an element's text is the translators' HTML, kept as it is
    /// (the PO check keeps its tags equal to the English ones).
    #[must_use]
    pub fn fill(&self, words: &str) -> String {
        let words = if self.context.contains("=\"{}\"") {
            super::translate::html_attr(words)
        } else if self.context.starts_with('\'') {
            words.replace('\\', "\\\\").replace('\'', "\\'")
        } else {
            words.to_owned()
        };
        self.context.replace("{}", &words)
    }
}

/// `text` with each listed context's words translated into `lang`.
fn translate(text: &str, lang: Lang, list: &[Chrome]) -> String {
    let mut out = text.to_owned();
    for c in list {
        let translated = tr(lang, c.words);
        if translated != c.words {
            out = out.replace(&c.fill(c.words), &c.fill(&translated));
        }
    }
    out
}

/// A page of mdBook's HTML with mdBook's words in `lang`.
#[must_use]
pub fn translate_page(html: &str, lang: Lang) -> String {
    translate(html, lang, PAGE)
}

/// One of mdBook's scripts with its words in `lang`.
#[must_use]
pub fn translate_script(js: &str, lang: Lang) -> String {
    translate(js, lang, SCRIPT)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn contexts_hold_their_words_once() {
        for c in PAGE.iter().chain(SCRIPT) {
            assert_eq!(c.context.matches("{}").count(), 1, "{}", c.context);
        }
        assert_eq!(words().filter(|w| *w == "Show hidden lines").count(), 1);
    }

    #[test]
    fn english_is_left_alone_and_only_the_context_changes() {
        let html = "<button title=\"Next chapter\">Next chapter</button>";
        assert_eq!(translate_page(html, Lang::En), html);
        let fr = translate_page(html, Lang::Fr);
        assert!(fr.starts_with("<button title=\"") && fr.ends_with("\">Next chapter</button>"), "{fr}");
        assert_ne!(fr, html, "po/fr.po translates \"Next chapter\"");
    }

    #[test]
    fn words_are_escaped_for_their_context() {
        let attr = c("title=\"{}\"", "x");
        assert_eq!(attr.fill("a \"b\" <c>"), "title=\"a &quot;b&quot; &lt;c&gt;\"");
        assert_eq!(c("'{}'", "x").fill("l'aide"), "'l\\'aide'");
        assert_eq!(c("<p>{}</p>", "x").fill("<kbd>S</kbd>"), "<p><kbd>S</kbd></p>");
    }
}
