//! Translations checked like numbers: a PO file against the template.
//!
//! | check | fails when |
//! | --- | --- |
//! | complete | a msgid of the template is missing from the PO file, empty, or fuzzy |
//! | numbers | the msgstr's numbers differ from the msgid's (the same numbers in the same order; a decimal comma is allowed in French and Ukrainian: `45,28` for `45.28`) |
//! | spans | the msgstr's inline code, link targets, TeX and inline HTML differ from the msgid's (byte for byte, in any order, as many of each) |
//! | placeholders | the `{}` placeholders of a Rust string differ in number |
//!
//! Numbers are read from the text only, outside code, TeX and HTML, which the span check
//! covers byte for byte. The words of TeX's `\text{…}` may be translated: the span check
//! compares the TeX without them, and their numbers count with the text's. Each problem names the message by its source line (`book/src/…:12`)
//! and its first words.

use polib::catalog::Catalog;
use pulldown_cmark::{Event, Options, Parser, Tag};

use super::Lang;

/// One problem in a PO file.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// The message's source reference (`book/src/02-basic-lighting.md:12`).
    pub source: String,
    /// The msgid's first words.
    pub msgid: String,
    /// What is wrong.
    pub what: String,
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: \"{}\": {}", self.source, self.msgid, self.what)
    }
}

/// The first 60 characters of `s`, on one line.
fn short(s: &str) -> String {
    let one: String = s.split_whitespace().collect::<Vec<_>>().join(" ");
    match one.char_indices().nth(60) {
        Some((i, _)) => format!("{}…", &one[..i]),
        None => one,
    }
}

/// The spans a translation must keep byte for byte, and the numbers of its text.
#[derive(Debug, Default, PartialEq)]
pub struct Parts {
    /// Inline code, link and image targets, TeX, and HTML, sorted.
    pub spans: Vec<String>,
    /// The numbers of the text, in order, as written (a decimal comma turned into a point
    /// when `comma` is set).
    pub numbers: Vec<String>,
}

impl Parts {
    /// A TeX span: its frame is a span, the numbers of its `\text{}` words count with the
    /// text's ([`super::math::text_words`]).
    fn push_tex(&mut self, tex: String, comma: bool) {
        let (frame, words) = super::math::text_words(&tex);
        self.numbers.extend(words.iter().flat_map(|w| numbers(w, comma)));
        self.spans.push(frame);
    }
}

/// The [`Parts`] of one message. With `comma`, `45,28` in the text reads as `45.28`.
#[must_use]
pub fn parts(markdown: &str, comma: bool) -> Parts {
    let mut p = Parts::default();
    let options = Options::ENABLE_MATH | Options::ENABLE_TABLES | Options::ENABLE_STRIKETHROUGH;
    for event in Parser::new_ext(markdown, options) {
        match event {
            Event::Text(t) => p.numbers.extend(numbers(&t, comma)),
            Event::Code(c) if super::math::is_math(&c) => p.push_tex(format!("`{c}`"), comma),
            Event::Code(c) => p.spans.push(format!("`{c}`")),
            Event::InlineMath(m) => p.push_tex(format!("${m}$"), comma),
            Event::DisplayMath(m) => p.push_tex(format!("$${m}$$"), comma),
            Event::Html(h) | Event::InlineHtml(h) => p.spans.push(h.to_string()),
            Event::Start(Tag::Link { dest_url, .. }) | Event::Start(Tag::Image { dest_url, .. }) => {
                p.spans.push(format!("({dest_url})"))
            }
            Event::Start(Tag::Heading { id: Some(id), .. }) => p.spans.push(format!("{{#{id}}}")),
            _ => {}
        }
    }
    p.spans.sort();
    p
}

/// The numbers in `text`, in order: digits, with one decimal point (or, with `comma`, a
/// decimal comma followed by a digit) and an optional exponent. A digit inside a word
/// (`vec3`, `f32`, `2D`) is part of an identifier, not a number, and is skipped.
#[must_use]
pub fn numbers(text: &str, comma: bool) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let starts = chars[i].is_ascii_digit() && (i == 0 || !chars[i - 1].is_alphanumeric() && chars[i - 1] != '_');
        if !starts {
            i += 1;
            continue;
        }
        let mut n = String::new();
        while i < chars.len() && chars[i].is_ascii_digit() {
            n.push(chars[i]);
            i += 1;
        }
        let decimal = |c: char| c == '.' || comma && c == ',';
        if i + 1 < chars.len() && decimal(chars[i]) && chars[i + 1].is_ascii_digit() {
            n.push('.');
            i += 1;
            while i < chars.len() && chars[i].is_ascii_digit() {
                n.push(chars[i]);
                i += 1;
            }
        }
        // an identifier such as 2D or 3x3 is not a number
        if i < chars.len() && (chars[i].is_alphabetic() || chars[i] == '_') && !matches!(chars[i], 'e' | 'x' | '×') {
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            continue;
        }
        out.push(n);
    }
    out
}

/// Every problem of `po` (the translation into `lang`) against `pot`, in template order.
#[must_use]
pub fn check(pot: &Catalog, po: &Catalog, lang: Lang) -> Vec<Problem> {
    let mut problems = Vec::new();
    for m in pot.messages() {
        let msgid = m.msgid();
        if msgid.is_empty() {
            continue;
        }
        let problem = |what: String| Problem { source: first_source(m.source()), msgid: short(msgid), what };
        let Some(t) = po.find_message(None, msgid, None) else {
            problems.push(problem("missing from the PO file".into()));
            continue;
        };
        let msgstr = t.msgstr().unwrap_or_default();
        if !t.is_translated() || msgstr.is_empty() {
            problems.push(problem("not translated".into()));
            continue;
        }
        if t.flags().is_fuzzy() {
            problems.push(problem("fuzzy (the English changed: check the translation, then remove the flag)".into()));
            continue;
        }
        problems.extend(compare(msgid, msgstr, lang).into_iter().map(problem));
    }
    problems
}

/// The problems of `part`, a part of a translation into `lang`: each of its messages must
/// be in the template, translated, not fuzzy, and match its English ([`compare`]).
#[must_use]
pub fn check_part(pot: &Catalog, part: &Catalog, lang: Lang) -> Vec<Problem> {
    let mut problems = Vec::new();
    for t in part.messages() {
        let msgid = t.msgid();
        if msgid.is_empty() {
            continue;
        }
        let problem = |what: String| Problem { source: first_source(t.source()), msgid: short(msgid), what };
        if pot.find_message(None, msgid, None).is_none() {
            problems.push(problem("not in po/messages.pot (was the msgid changed?)".into()));
            continue;
        }
        let msgstr = t.msgstr().unwrap_or_default();
        if !t.is_translated() || msgstr.is_empty() {
            problems.push(problem("not translated".into()));
        } else if t.flags().is_fuzzy() {
            problems.push(problem("fuzzy".into()));
        } else {
            problems.extend(compare(msgid, msgstr, lang).into_iter().map(problem));
        }
    }
    problems
}

/// What differs between an English message and its translation (empty when they match).
#[must_use]
pub fn compare(msgid: &str, msgstr: &str, lang: Lang) -> Vec<String> {
    let mut out = Vec::new();
    if msgid == msgstr {
        return out; // kept as it is (a quotation, a name): nothing can differ
    }
    let (en, tr) = (parts(msgid, false), parts(msgstr, lang.decimal_comma()));
    if en.numbers != tr.numbers {
        out.push(format!("numbers differ: English {:?}, translation {:?}", en.numbers, tr.numbers));
    }
    if en.spans != tr.spans {
        let missing: Vec<&String> = en.spans.iter().filter(|s| !tr.spans.contains(s)).collect();
        let extra: Vec<&String> = tr.spans.iter().filter(|s| !en.spans.contains(s)).collect();
        out.push(format!(
            "code, link, TeX or HTML spans differ: missing {missing:?}, not in the English {extra:?} ({} against {})",
            tr.spans.len(),
            en.spans.len()
        ));
    }
    if msgid.matches("{}").count() != msgstr.matches("{}").count() {
        out.push("the {} placeholders differ in number".into());
    }
    if lang == Lang::Fr {
        out.extend(french_spacing(msgid, msgstr));
    }
    out
}

/// The punctuation French writes after a no-break space.
const FRENCH_SPACED: [char; 4] = [':', ';', '?', '!'];

/// The prose of a message (its Markdown text, without code blocks, code spans, TeX, links'
/// targets or HTML).
fn prose(markdown: &str) -> String {
    let options = Options::ENABLE_MATH | Options::ENABLE_TABLES | Options::ENABLE_STRIKETHROUGH;
    let mut out = String::new();
    let mut in_code_block = false;
    for event in Parser::new_ext(markdown, options) {
        match event {
            Event::Start(Tag::CodeBlock(_)) => in_code_block = true,
            Event::End(pulldown_cmark::TagEnd::CodeBlock) => in_code_block = false,
            Event::Text(t) if !in_code_block => out.push_str(&t),
            // a span or a break separates the texts around it
            Event::Code(_) | Event::InlineMath(_) | Event::DisplayMath(_) | Event::SoftBreak | Event::HardBreak => {
                out.push('\u{1}');
            }
            _ => {}
        }
    }
    out
}

/// How many times `text` puts an ordinary space before `:`, `;`, `?` or `!`.
fn plain_spaces_before_punctuation(text: &str) -> usize {
    text.as_bytes().windows(2).filter(|w| w[0] == b' ' && FRENCH_SPACED.iter().any(|&c| w[1] == c as u8)).count()
}

/// French typography: `:`, `;`, `?` and `!` take a no-break space (U+00A0) before them, as
/// every message of the French PO file does. An ordinary space there may break the line
/// before the sign. The English's own ` :` (code-like text, a quotation of the French seed)
/// is allowed as many times as it has it.
fn french_spacing(msgid: &str, msgstr: &str) -> Option<String> {
    let (en, fr) = (plain_spaces_before_punctuation(&prose(msgid)), plain_spaces_before_punctuation(&prose(msgstr)));
    (fr > en).then(|| {
        format!(
            "an ordinary space before `:`, `;`, `?` or `!` ({fr} times): French puts a no-break space (U+00A0) there"
        )
    })
}

/// The first source reference of a message (`book/src/x.md:12`), or `(no source)`.
fn first_source(source: &str) -> String {
    source.split_whitespace().next().unwrap_or("(no source)").to_owned()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_skip_identifiers_and_read_decimal_commas() {
        assert_eq!(numbers("vec3 at 45.28 and 2D, 1e-3, 16 lights", false), ["45.28", "1", "3", "16"]);
        assert_eq!(numbers("45,28 et 12", true), ["45.28", "12"]);
        // without the comma rule, 45,28 is two numbers
        assert_eq!(numbers("45,28", false), ["45", "28"]);
        assert_eq!(numbers("1, 2", true), ["1", "2"]);
    }

    #[test]
    fn french_wants_a_no_break_space_before_its_high_punctuation() {
        let nbsp = "Le seuil vaut 12,5 degrés\u{a0}: `a ? b : c`.";
        assert!(compare("The cut-off is 12.5 degrees: `a ? b : c`.", nbsp, Lang::Fr).is_empty());
        let plain = "Le seuil vaut 12,5 degrés : `a ? b : c`.";
        let problems = compare("The cut-off is 12.5 degrees: `a ? b : c`.", plain, Lang::Fr);
        assert!(problems.len() == 1 && problems[0].contains("U+00A0"), "{problems:?}");
        // Ukrainian puts no space there; a quotation the English keeps is allowed
        assert!(compare("It is 12.5 degrees: yes.", "Це 12,5 градуса: так.", Lang::Uk).is_empty());
        let quoted = compare(
            "The seed says « angle d'ouverture : cône ».",
            "Le seed dit « angle d'ouverture : cône ».",
            Lang::Fr,
        );
        assert!(quoted.is_empty(), "{quoted:?}");
    }

    #[test]
    fn a_changed_number_or_span_is_named() {
        let en = "The cut-off is 12.5 degrees: `cutOff` in [the chapter](05-light-casters.md#spot), $\\cos\\theta$.";
        let good =
            "Le seuil vaut 12,5 degrés\u{a0}: `cutOff` dans [le chapitre](05-light-casters.md#spot), $\\cos\\theta$.";
        assert!(compare(en, good, Lang::Fr).is_empty(), "{:?}", compare(en, good, Lang::Fr));
        let number = good.replace("12,5", "12,6");
        assert!(compare(en, &number, Lang::Fr)[0].contains("numbers differ"));
        let code = good.replace("`cutOff`", "`cutoff`");
        assert!(compare(en, &code, Lang::Fr)[0].contains("spans differ"));
        let link = good.replace("#spot", "#spotlight");
        assert!(compare(en, &link, Lang::Fr)[0].contains("spans differ"));
        let tex = good.replace("\\theta", "\\phi");
        assert!(compare(en, &tex, Lang::Fr)[0].contains("spans differ"));
        // the words of \text{} may be translated, the rest of the TeX may not
        let en = "`$$ c_{\\text{light}} + c_{\\text{point},1} $$` shown";
        let fr = "`$$ c_{\\text{lumière}} + c_{\\text{ponctuelle},1} $$` montré";
        assert!(compare(en, fr, Lang::Fr).is_empty(), "{:?}", compare(en, fr, Lang::Fr));
        assert!(compare(en, &fr.replace(",1}", ",2}"), Lang::Fr)[0].contains("spans differ"));
        assert!(compare("$\\text{in 2 cases}$", "$\\text{en 3 cas}$", Lang::Fr)[0].contains("numbers differ"));
        // English keeps its decimal point
        assert!(!compare("12.5", "12,5", Lang::En).is_empty());
    }
}
