//! The translations checked like numbers: every message of `po/messages.pot` translated in
//! `po/fr.po` and `po/uk.po`, none fuzzy, the same numbers in the same order (a decimal comma
//! allowed), the same code, links and TeX byte for byte; the glossary's stray words absent;
//! and each check able to fail on a real message. (That the template matches the current
//! English is `tests/book.rs`'s `the_translation_template_is_current`, which has the built
//! book.)
#![cfg(all(feature = "book", feature = "gl"))]

use std::path::{Path, PathBuf};

use lightlab::i18n::{self, catalog::parse_po_file, check, glossary, Lang};
use polib::catalog::Catalog;
use polib::message::{MessageMutView, MessageView};

fn po(name: &str) -> Catalog {
    let path: PathBuf = Path::new(env!("CARGO_MANIFEST_DIR")).join("po").join(name);
    parse_po_file(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn translations() -> [(Lang, Catalog); 2] {
    [(Lang::Fr, po("fr.po")), (Lang::Uk, po("uk.po"))]
}

#[test]
fn every_message_is_translated_and_keeps_its_numbers_code_links_and_tex() {
    let pot = po("messages.pot");
    assert!(pot.count() > 1000, "the template has only {} messages", pot.count());
    for (lang, catalog) in translations() {
        let problems = check::check(&pot, &catalog, lang);
        let shown: Vec<String> = problems.iter().take(20).map(ToString::to_string).collect();
        assert!(
            problems.is_empty(),
            "{lang}: {} problems (run lightlab i18n check):\n{}",
            problems.len(),
            shown.join("\n")
        );
    }
}

/// The check fails, naming the message, when one number of one msgstr changes, when a code
/// span changes, and when a message is missing.
#[test]
fn a_changed_number_a_changed_code_span_and_a_missing_message_are_named() {
    let pot = po("messages.pot");
    let (lang, mut catalog) = translations().into_iter().next().unwrap();
    // the first translated message with a number in its text, and one with a code span
    let with_number = catalog
        .messages()
        .find(|m| m.msgid() != m.msgstr().unwrap_or_default() && !check::parts(m.msgid(), false).numbers.is_empty())
        .map(|m| m.msgid().to_owned())
        .expect("a message with a number");
    let mut m = catalog.find_message_mut(None, &with_number, None).unwrap();
    let text = m.msgstr().unwrap().to_owned();
    let digit = text.find(|c: char| c.is_ascii_digit()).unwrap();
    let changed =
        format!("{}{}{}", &text[..digit], if &text[digit..=digit] == "7" { "8" } else { "7" }, &text[digit + 1..]);
    m.set_msgstr(changed).unwrap();
    let problems = check::check(&pot, &catalog, lang);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(problems[0].what.contains("numbers differ"), "{}", problems[0]);
    assert!(with_number.starts_with(problems[0].msgid.trim_end_matches('…')), "{} names another message", problems[0]);

    // the first translated message with an inline code span: its first span renamed
    let (with_code, span) = po("fr.po")
        .messages()
        .filter(|m| m.msgid() != m.msgstr().unwrap_or_default())
        .find_map(|m| {
            let span =
                check::parts(m.msgid(), false).spans.into_iter().find(|s| s.starts_with('`') && !s.contains('$'))?;
            m.msgstr().unwrap_or_default().contains(&span).then(|| (m.msgid().to_owned(), span))
        })
        .expect("a translated message with a code span");
    let mut catalog = po("fr.po");
    let mut m = catalog.find_message_mut(None, &with_code, None).unwrap();
    let renamed = format!("{}_renamed`", span.trim_end_matches('`'));
    let text = m.msgstr().unwrap().replacen(&span, &renamed, 1);
    m.set_msgstr(text).unwrap();
    let problems = check::check(&pot, &catalog, Lang::Fr);
    assert!(problems.len() == 1 && problems[0].what.contains("spans differ"), "{problems:?}");

    let mut catalog = po("uk.po");
    catalog.delete_message(None, &with_code, None);
    let problems = check::check(&pot, &catalog, Lang::Uk);
    assert!(problems.len() == 1 && problems[0].what.contains("missing"), "{problems:?}");
}

/// A translated message does not use a word the glossary lists as a seed's error (the
/// Ukrainian lab's "центр уваги" for spotlight, "ролик" for caster, ...), unless its English
/// quotes that word, or it is in the errata chapter, whose subject is those errors.
#[test]
fn translations_use_the_glossarys_terms_not_the_seeds_errors() {
    for (lang, catalog) in translations() {
        let avoided = glossary::avoided(lang);
        let mut bad = Vec::new();
        let errata_only = |source: &str| source.split_whitespace().all(|s| s.starts_with("src/10-errata.md"));
        for m in catalog.messages().filter(|m| !errata_only(m.source())) {
            let (en, tr) = (m.msgid().to_lowercase(), m.msgstr().unwrap_or_default().to_lowercase());
            for (word, term) in &avoided {
                if tr.contains(word) && !en.contains(word) {
                    bad.push(format!("{lang}: \"{}\" for {} in {}", word, term.en, m.source()));
                }
            }
        }
        assert!(bad.is_empty(), "{}", bad.join("\n"));
    }
    // the check can fail: a stray word in a message that does not quote it is found
    let (word, _) = glossary::avoided(Lang::Uk)[0];
    assert!(!"a spotlight".contains(word) && format!("це {word}").contains(word));
}

/// The glossary's main terms are the ones the translations use: each Ukrainian and French
/// term occurs in the translated book (so the glossary is not a list nobody follows).
#[test]
fn the_glossarys_terms_occur_in_the_translations() {
    for (lang, catalog) in translations() {
        let all: String = catalog.messages().map(|m| m.msgstr().unwrap_or_default().to_lowercase()).collect();
        let missing: Vec<&str> = glossary::TERMS
            .iter()
            .map(|t| if lang == Lang::Fr { t.fr.0 } else { t.uk.0 })
            .filter(|term| {
                // the stem of the term's first word (inflection changes endings)
                let first = term.split_whitespace().next().unwrap_or("").to_lowercase();
                let stem: String = first.chars().take(first.chars().count().saturating_sub(2).max(4)).collect();
                !all.contains(&stem)
            })
            .collect();
        assert!(missing.is_empty(), "{lang}: glossary terms never used: {missing:?}");
    }
}

/// The command line's sentences come from the same files: the built-in catalogs translate a
/// checker sentence, and a placeholder survives.
#[test]
fn the_command_line_reads_the_same_po_files() {
    use lightlab::checker::diagnose::AGREES;
    for lang in [Lang::Fr, Lang::Uk] {
        let t = i18n::catalog::tr_fill(lang, AGREES, &["spot"]);
        assert!(t.contains("spot") && t != AGREES.replace("{}", "spot"), "{lang}: {t}");
    }
    assert_eq!(i18n::catalog::tr_fill(Lang::En, AGREES, &["spot"]), "Your shader agrees with the model spot.");
}
