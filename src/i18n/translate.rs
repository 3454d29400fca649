//! The book's translating preprocessor: each chapter's Markdown is cut into messages by
//! mdbook-i18n-helpers (the same grouping its `xgettext` renderer uses to write
//! `po/messages.pot`), and each message is replaced by its translation from `po/<lang>.po`.
//!
//! It is mdbook-i18n-helpers' `Gettext` preprocessor with one change: a message with no
//! translation (new, changed in English, or fuzzy) is shown in English inside
//! `<span lang="en">`, followed by a visible mark ([`UNTRANSLATED_MARK`], itself translated),
//! where `Gettext` shows the English silently. A stale translation is never shown: a msgid
//! is the whole English text, so a changed paragraph no longer finds its old translation.
//!
//! The preprocessor is named `gettext` and `book.toml` orders it after `links` (so included
//! generated tables are translated) and before `katex` (so a msgid holds TeX, not HTML).

use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use mdbook_i18n_helpers::{extract_events, group_events, reconstruct_markdown, trim_paragraph, Group};
use mdbook_preprocessor::book::{Book, BookItem};
use mdbook_preprocessor::errors::{Error, Result as MdResult};
use mdbook_preprocessor::{Preprocessor, PreprocessorContext};
use polib::catalog::Catalog;
use pulldown_cmark::{CowStr, Event, Tag, TagEnd};

use super::catalog::lookup;
use super::Lang;

/// The English msgid of the mark after an untranslated paragraph (translated in the PO files).
pub const UNTRANSLATED_MARK: &str = "not yet translated";

/// How much of a language's book the catalog covered in one build.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Coverage {
    /// Messages shown translated.
    pub translated: usize,
    /// Messages shown in English with the mark, each with its chapter.
    pub untranslated: Vec<(String, String)>,
}

impl Coverage {
    /// Translated messages as a percentage of all (100 when there are none).
    #[must_use]
    pub fn percent(&self) -> f64 {
        let total = self.translated + self.untranslated.len();
        if total == 0 {
            100.0
        } else {
            100.0 * self.translated as f64 / total as f64
        }
    }
}

/// The preprocessor for one language. English passes through unchanged.
pub struct Translate {
    lang: Lang,
    catalog: Option<Catalog>,
    coverage: Arc<Mutex<Coverage>>,
}

/// Why the PO file of a language could not be used.
#[derive(Debug)]
pub struct PoError {
    /// The PO file.
    pub path: PathBuf,
    /// polib's message.
    pub message: String,
}

impl std::fmt::Display for PoError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "reading {}: {}", self.path.display(), self.message)
    }
}

impl std::error::Error for PoError {}

impl Translate {
    /// The preprocessor for `lang`, reading `po_dir/<code>.po` (nothing for English). A
    /// missing or unreadable PO file is an error naming it.
    pub fn new(lang: Lang, po_dir: &Path) -> Result<Translate, PoError> {
        let catalog = if lang.is_translation() {
            let path = po_dir.join(format!("{}.po", lang.code()));
            let catalog = super::catalog::parse_po_file(&path).map_err(|message| PoError { path, message })?;
            Some(catalog)
        } else {
            None
        };
        Ok(Translate { lang, catalog, coverage: Arc::default() })
    }

    /// The translation of the book's title (`book.title`), when the PO file has one.
    #[must_use]
    pub fn title(&self, english: &str) -> Option<String> {
        self.catalog.as_ref().and_then(|c| lookup(c, english)).map(str::to_owned)
    }

    /// The coverage of the builds this preprocessor ran (shared, read after the build).
    #[must_use]
    pub fn coverage(&self) -> Arc<Mutex<Coverage>> {
        Arc::clone(&self.coverage)
    }
}

impl Preprocessor for Translate {
    fn name(&self) -> &str {
        "gettext"
    }

    fn run(&self, ctx: &PreprocessorContext, mut book: Book) -> MdResult<Book> {
        if ctx.renderer == "xgettext" {
            // the template's messages hold the TeX as code spans (see `super::math`)
            book.for_each_mut(|item| {
                if let BookItem::Chapter(ch) = item {
                    ch.content = super::math::protect(&ch.content);
                }
            });
            return Ok(book);
        }
        let Some(catalog) = &self.catalog else { return Ok(book) };
        let mark = mark_html(catalog, self.lang);
        let generated = super::localize::generated_dir(ctx);
        let mut coverage = Coverage::default();
        let mut failure = None;
        book.for_each_mut(|item| {
            if failure.is_some() {
                return;
            }
            let BookItem::Chapter(ch) = item else { return };
            let chapter = ch.path.as_ref().map(|p| p.display().to_string()).unwrap_or_else(|| ch.name.clone());
            match translate_markdown(&ch.content, self.lang, catalog, &mark, &chapter, &mut coverage) {
                Ok(text) => ch.content = super::localize::localize_paths(&text, self.lang, &generated),
                Err(e) => failure = Some(Error::msg(format!("translating {chapter}: {e}"))),
            }
            // chapter names come from SUMMARY.md, whose messages are plain text
            if let Some(name) = lookup(catalog, &ch.name) {
                ch.name = name.to_owned();
            }
        });
        if let Some(e) = failure {
            return Err(e);
        }
        *self.coverage.lock().unwrap_or_else(|e| e.into_inner()) = coverage;
        Ok(book)
    }

    fn supports_renderer(&self, _renderer: &str) -> MdResult<bool> {
        Ok(true)
    }
}

/// The inline HTML that follows an untranslated message: the mark, in the book's language.
fn mark_html(catalog: &Catalog, lang: Lang) -> String {
    let text = lookup(catalog, UNTRANSLATED_MARK).unwrap_or(UNTRANSLATED_MARK);
    format!(
        "<sup class=\"lightlab-untranslated\" lang=\"{}\" title=\"{}\">[{}]</sup>",
        lang.code(),
        html_attr(text),
        html_attr(text)
    )
}

/// `text` escaped for an HTML attribute or text node.
#[must_use]
pub fn html_attr(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// `text` (one chapter's Markdown) with every message translated, or in English with the
/// mark; counts go to `coverage`.
///
/// A message with no words ([`super::extract::is_neutral`], a table cell `0.2857`) is its
/// own translation in the PO files, so that its numbers match by construction; on the page
/// its text (not its code, TeX or links) is written with the language's decimal sign
/// ([`Lang::numbers_in`]), as the figures and the live labels write theirs.
pub fn translate_markdown(
    text: &str,
    lang: Lang,
    catalog: &Catalog,
    mark: &str,
    chapter: &str,
    coverage: &mut Coverage,
) -> MdResult<String> {
    let protected = super::math::protect(text);
    let mut events = extract_events(&protected, None);
    keep_english_heading_ids(&mut events);
    let mut out: Vec<(usize, Event<'_>)> = Vec::with_capacity(events.len());
    let mut state = None;
    for group in group_events(&events)? {
        match group {
            Group::Translate { events: group, .. } => {
                let (msgid, next) = reconstruct_markdown(&group, state.clone())?;
                match lookup(catalog, &msgid) {
                    Some(msgstr) => {
                        let translated = extract_events(msgstr, state);
                        let events = trim_paragraph(&translated, &group);
                        if lang.decimal_comma() && super::extract::is_neutral(&msgid) {
                            out.extend(events.iter().map(|(line, event)| (*line, numbers_in_text(event, lang))));
                        } else {
                            out.extend_from_slice(events);
                        }
                        coverage.translated += 1;
                    }
                    None => {
                        out.extend(marked(&group, mark));
                        coverage.untranslated.push((chapter.to_owned(), msgid));
                    }
                }
                state = Some(next);
            }
            Group::Skip(group) => {
                let (_, next) = reconstruct_markdown(&group, state)?;
                out.extend(group.iter().map(|(line, event)| (*line, translate_html_event(event, catalog))));
                state = Some(next);
            }
        }
    }
    let out: Vec<(usize, Event<'_>)> =
        out.into_iter().map(|(l, e)| (l, super::math::unprotect_event(e, lang))).collect();
    Ok(reconstruct_markdown(&out, None)?.0)
}

/// A text event written with `lang`'s decimal sign ([`Lang::numbers_in`]); code, HTML and
/// every other event as it is.
fn numbers_in_text<'a>(event: &Event<'a>, lang: Lang) -> Event<'a> {
    match event {
        Event::Text(text) => Event::Text(CowStr::from(lang.numbers_in(text))),
        other => other.clone(),
    }
}

/// An HTML block's event with its words translated ([`translate_html`]); any other event
/// as it is.
fn translate_html_event<'a>(event: &Event<'a>, catalog: &Catalog) -> Event<'a> {
    match event {
        Event::Html(html) => Event::Html(CowStr::from(translate_html(html, catalog))),
        other => other.clone(),
    }
}

/// The byte ranges of the words a reader sees in the HTML fragment `html`: each run of text
/// between tags, trimmed, that holds a letter (a `<summary>`'s title, a link's text).
/// Tags, comments and the insides of `<script>` and `<style>` are not text.
///
/// mdbook-i18n-helpers leaves an HTML block out of the messages (it is markup, not
/// Markdown), so the words inside one would stay English on every page: these are added
/// to the template ([`crate::i18n::extract::template`]) and translated one by one.
#[must_use]
pub fn html_texts(html: &str) -> Vec<std::ops::Range<usize>> {
    let lower = html.to_ascii_lowercase();
    let mut out = Vec::new();
    let mut at = 0;
    while at < html.len() {
        let skip_to = |from: usize, end: &str| lower[from..].find(end).map_or(html.len(), |i| from + i + end.len());
        if lower[at..].starts_with("<!--") {
            at = skip_to(at, "-->");
        } else if lower[at..].starts_with("<script") {
            at = skip_to(at, "</script>");
        } else if lower[at..].starts_with("<style") {
            at = skip_to(at, "</style>");
        } else if html[at..].starts_with('<') {
            at = skip_to(at, ">");
        } else {
            let end = html[at..].find('<').map_or(html.len(), |i| at + i);
            let text = &html[at..end];
            let trimmed = text.trim();
            if trimmed.chars().any(char::is_alphabetic) {
                let start = at + (text.len() - text.trim_start().len());
                out.push(start..start + trimmed.len());
            }
            at = end;
        }
    }
    out
}

/// `html` with each of its [`html_texts`] replaced by its translation in `catalog`; a text
/// with none stays as it is. (A chapter's included figure markup is already in the page's
/// language, from its localized copy, so a miss is no error here; a chapter's own HTML
/// words are in the template, and `lightlab i18n check` reports an empty translation.)
#[must_use]
pub fn translate_html(html: &str, catalog: &Catalog) -> String {
    let mut out = String::with_capacity(html.len());
    let mut from = 0;
    for range in html_texts(html) {
        out.push_str(&html[from..range.start]);
        let english = &html[range.clone()];
        // a translation is plain text, never markup
        out.push_str(&lookup(catalog, english).map_or_else(|| english.to_owned(), html_attr));
        from = range.end;
    }
    out.push_str(&html[from..]);
    out
}

/// Give every heading without an explicit id the id mdBook derives from its English text,
/// so a translated heading keeps its anchor and links into it (`05-light-casters.md#spot`)
/// work in every language.
fn keep_english_heading_ids(events: &mut [(usize, Event<'_>)]) {
    let mut i = 0;
    while i < events.len() {
        if let Event::Start(Tag::Heading { id: None, .. }) = &events[i].1 {
            let mut text = String::new();
            for (_, e) in &events[i + 1..] {
                match e {
                    Event::End(TagEnd::Heading(_)) => break,
                    Event::Text(t) | Event::Code(t) => text.push_str(t),
                    _ => {}
                }
            }
            let anchor = id_from_content(&text);
            if let Event::Start(Tag::Heading { id, .. }) = &mut events[i].1 {
                *id = Some(CowStr::from(anchor));
            }
        }
        i += 1;
    }
}

/// mdBook's id of a heading's text (mdbook-html `id_from_content`): lower case; letters,
/// digits, `_` and `-` kept, white space turned into `-`, the rest dropped.
#[must_use]
pub fn id_from_content(content: &str) -> String {
    content
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            c if c.is_alphanumeric() || c == '_' || c == '-' => Some(c),
            c if c.is_whitespace() => Some('-'),
            _ => None,
        })
        .collect()
}

/// Block containers a message may open or close with (the span goes inside them).
fn is_block_start(tag: &Tag<'_>) -> bool {
    matches!(tag, Tag::Paragraph | Tag::Heading { .. } | Tag::Item | Tag::TableCell | Tag::BlockQuote(_))
}

fn is_block_end(tag: &TagEnd) -> bool {
    matches!(tag, TagEnd::Paragraph | TagEnd::Heading(_) | TagEnd::Item | TagEnd::TableCell | TagEnd::BlockQuote(_))
}

/// `group` wrapped in `<span lang="en">` and followed by the mark, inside its block
/// containers: `<p><span lang="en">text</span><sup>…</sup></p>`. A group that holds blocks
/// of its own (a list item with a code block) is kept as it is, the mark after it: a span
/// cannot cross blocks.
fn marked<'a>(group: &[(usize, Event<'a>)], mark: &str) -> Vec<(usize, Event<'a>)> {
    let lead = group.iter().take_while(|(_, e)| matches!(e, Event::Start(t) if is_block_start(t))).count();
    let trail = group[lead..].iter().rev().take_while(|(_, e)| matches!(e, Event::End(t) if is_block_end(t))).count();
    let inner = &group[lead..group.len() - trail];
    let line = group.first().map_or(0, |(l, _)| *l);
    let inline_only = inner.iter().all(|(_, e)| match e {
        Event::Start(t) => !is_block(t),
        Event::Html(_) | Event::Rule => false,
        _ => true,
    });
    let mut out = Vec::with_capacity(group.len() + 2);
    if !inline_only {
        out.extend_from_slice(group);
        out.push((line, Event::InlineHtml(CowStr::from(mark.to_owned()))));
        return out;
    }
    out.extend_from_slice(&group[..lead]);
    out.push((line, Event::InlineHtml(CowStr::Borrowed("<span lang=\"en\">"))));
    out.extend_from_slice(inner);
    out.push((line, Event::InlineHtml(CowStr::from(format!("</span>{mark}")))));
    out.extend_from_slice(&group[group.len() - trail..]);
    out
}

/// Tags that open a block (which a `<span>` must not cross).
fn is_block(tag: &Tag<'_>) -> bool {
    is_block_start(tag)
        || matches!(
            tag,
            Tag::CodeBlock(_) | Tag::List(_) | Tag::Table(_) | Tag::TableHead | Tag::TableRow | Tag::HtmlBlock
        )
}

#[cfg(test)]
mod tests {
    use super::*;
    use polib::message::{Message, MessageMutView};
    use polib::metadata::CatalogMetadata;

    fn catalog(pairs: &[(&str, &str)]) -> Catalog {
        let mut c = Catalog::new(CatalogMetadata::new());
        for (id, s) in pairs {
            c.append_or_update(Message::build_singular().with_msgid(id.to_string()).with_msgstr(s.to_string()).done());
        }
        c
    }

    #[test]
    fn the_words_inside_html_are_found_but_not_tags_comments_or_scripts() {
        let html = "<details><summary> Reference solution </summary><!-- a note --><script>let a = 1;</script>\
                    <p class=\"figure-links\"><a href=\"x@2x.png\">PNG at 2×</a> · <a>SVG</a></p><b>12</b>";
        let texts: Vec<&str> = html_texts(html).into_iter().map(|r| &html[r]).collect();
        assert_eq!(texts, ["Reference solution", "PNG at 2×", "SVG"]);
        // an unclosed tag or comment ends the scan without a panic
        assert!(html_texts("<summary>Open <!-- never closed")
            .iter()
            .map(|r| &"<summary>Open <!-- never closed"[r.clone()])
            .eq(["Open"]));
        assert!(html_texts("text <a href=").len() == 1);
        assert!(html_texts("<p>\n  \n</p>").is_empty(), "a run of white space is no text");
    }

    #[test]
    fn a_table_of_numbers_takes_the_languages_decimal_sign_but_its_code_does_not() {
        let md = "| k | value |\n| --- | --- |\n| 1 | 0.2857 |\n| 2 | `0.5` 1.25 |\n";
        let c = catalog(&[
            ("k", "k"),
            ("value", "valeur"),
            ("1", "1"),
            ("0.2857", "0.2857"),
            ("2", "2"),
            ("`0.5` 1.25", "`0.5` 1.25"),
        ]);
        let fr = translate_markdown(md, Lang::Fr, &c, "", "t", &mut Coverage::default()).unwrap();
        assert!(fr.contains("0,2857") && fr.contains("`0.5` 1,25") && fr.contains("valeur"), "{fr}");
        // a message with words is the translator's: its numbers are as written
        let c = catalog(&[("Pi is 3.14.", "Pi vaut 3.14.")]);
        let out = translate_markdown("Pi is 3.14.\n", Lang::Uk, &c, "", "t", &mut Coverage::default()).unwrap();
        assert!(out.contains("3.14"), "{out}");
    }

    #[test]
    fn html_words_are_translated_in_place_and_escaped_as_text() {
        let c = catalog(&[("Reference solution", "Solution de référence"), ("PNG at 2×", "PNG <2×> & co")]);
        let html =
            "<details><summary>Reference solution</summary>\n<a href=\"PNG at 2×\">PNG at 2×</a><i>other words</i>";
        assert_eq!(
            translate_html(html, &c),
            "<details><summary>Solution de référence</summary>\n<a href=\"PNG at 2×\">PNG &lt;2×&gt; &amp; co</a><i>other words</i>"
        );
        // through the whole chapter: the block's words translated, the markup kept
        let md = "Text.\n\n<details><summary>Reference solution</summary>\n\n```glsl\nx\n```\n\n</details>\n";
        let out = translate_markdown(md, Lang::Fr, &c, "", "ch", &mut Coverage::default()).unwrap();
        assert!(out.contains("<summary>Solution de référence</summary>"), "{out}");
    }

    #[test]
    fn translated_and_untranslated_paragraphs() {
        // msgids are as mdbook-i18n-helpers writes them back (`_` for emphasis)
        let c = catalog(&[("Hello _world_.", "Bonjour _le monde_."), ("Title", "Titre")]);
        let mut cov = Coverage::default();
        let text = "# Title\n\nHello *world*.\n\nA new sentence with `code`.\n\n```glsl\nvec3 x;\n```\n";
        let out = translate_markdown(text, Lang::Fr, &c, "<sup>MARK</sup>", "ch.md", &mut cov).unwrap();
        // the heading keeps the English anchor
        assert!(out.contains("# Titre { #title }"), "{out}");
        assert!(out.contains("Bonjour _le monde_."), "{out}");
        // the untranslated paragraph keeps its English, inside a span, with the mark
        assert!(out.contains("<span lang=\"en\">A new sentence with `code`.</span><sup>MARK</sup>"), "{out}");
        assert!(out.contains("vec3 x;"), "{out}");
        assert_eq!(cov.translated, 2);
        assert_eq!(cov.untranslated, vec![("ch.md".to_owned(), "A new sentence with `code`.".to_owned())]);
    }

    #[test]
    fn fuzzy_and_empty_translations_are_not_used() {
        let mut c = catalog(&[("One.", "")]);
        let mut fuzzy = Message::build_singular().with_msgid("Two.".into()).with_msgstr("Deux.".into()).done();
        fuzzy.flags_mut().add_flag("fuzzy");
        c.append_or_update(fuzzy);
        let mut cov = Coverage::default();
        let out = translate_markdown("One.\n\nTwo.\n", Lang::Fr, &c, "<sup>M</sup>", "x", &mut cov).unwrap();
        assert!(!out.contains("Deux"), "{out}");
        assert_eq!((cov.translated, cov.untranslated.len()), (0, 2));
    }
}
