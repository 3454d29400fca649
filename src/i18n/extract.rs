//! `lightlab i18n extract`: writes `po/messages.pot` and merges it into every PO file.
//!
//! The template holds the book's messages, cut by mdbook-i18n-helpers' `xgettext` renderer
//! run in process on the book after mdBook's `links` preprocessor (so the generated tables
//! that chapters include are in it), then the Rust strings a reader sees
//! (`crate::cli::messages::rust_messages`). Its creation date is fixed, so the file is byte-identical until the
//! English changes.

use std::path::{Path, PathBuf};

use polib::catalog::Catalog;
use polib::message::{Message, MessageMutView};
use polib::metadata::CatalogMetadata;

use super::Lang;

/// The creation date written into the template (a fixed value: generated files are
/// byte-identical on every run).
const POT_DATE: &str = "2026-01-01T00:00:00+00:00";

/// What `extract` wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ExtractReport {
    /// Messages in the template.
    pub messages: usize,
    /// Per translation: (language, messages kept translated, messages now empty).
    pub merged: Vec<(Lang, usize, usize)>,
}

/// Where the PO files of the book at `book_root` live: `po/` beside the book directory.
#[must_use]
pub fn po_dir(book_root: &Path) -> PathBuf {
    book_root.parent().unwrap_or(book_root).join("po")
}

/// The template: the book's messages, then `rust`, the Rust strings a reader sees (with the
/// file that defines each), not already among them, then `drawn`: the words the book's
/// generated files draw, with the file that draws each. The caller gathers both
/// (`crate::cli::messages`); this module knows neither the generators nor the strings.
pub fn template(book_root: &Path, rust: &[(String, &str)], drawn: &[(String, String)]) -> Result<Catalog, String> {
    let mut catalog = book_messages(book_root)?;
    let html = html_messages(&book_root.join("src"))?;
    let drawn = drawn.iter().filter(|(msgid, _)| !is_neutral(msgid)).map(|(m, s)| (m.clone(), s.as_str()));
    let html = html.iter().map(|(m, s)| (m.clone(), s.as_str()));
    for (msgid, source) in rust.iter().map(|(m, s)| (m.clone(), *s)).chain(html).chain(drawn) {
        if catalog.find_message(None, &msgid, None).is_none() {
            catalog.append_or_update(Message::build_singular().with_msgid(msgid).with_source(source.to_owned()).done());
        }
    }
    catalog.metadata.pot_creation_date = POT_DATE.to_owned();
    Ok(catalog)
}

/// The words inside the HTML blocks of the chapters in `src` (its `*.md` files, in name
/// order), each with its `src/<file>:<line>`: a `<summary>`'s title, a link's text
/// ([`super::translate::html_texts`]). The xgettext renderer leaves HTML blocks out, and
/// the translating preprocessor puts these back one by one. Figure markup under
/// `src/generated/` is not among them: it has a copy per language.
fn html_messages(src: &Path) -> Result<Vec<(String, String)>, String> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(src)
        .map_err(|e| format!("{}: {e}", src.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .collect();
    files.sort();
    let mut out = Vec::new();
    for path in files {
        let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        for (line, event) in mdbook_i18n_helpers::extract_events(&text, None) {
            if let pulldown_cmark::Event::Html(html) = event {
                for range in super::translate::html_texts(&html) {
                    out.push((html[range].to_owned(), format!("src/{name}:{line}")));
                }
            }
        }
    }
    Ok(out)
}

/// The book's messages, by mdbook-i18n-helpers' xgettext renderer, run in process.
fn book_messages(book_root: &Path) -> Result<Catalog, String> {
    let root = book_root.canonicalize().map_err(|e| format!("{}: {e}", book_root.display()))?;
    let mut config = mdbook_driver::config::Config::from_disk(root.join("book.toml"))
        .map_err(|e| format!("{}: {e:#}", root.join("book.toml").display()))?;
    config.book.language = Some("en".to_owned());
    let tmp = root.join(format!(".xgettext-{}", std::process::id()));
    config.build.build_dir = tmp.clone();
    let title = config.book.title.clone();
    let mut md = mdbook_driver::MDBook::load_with_config(&root, config).map_err(|e| format!("{e:#}"))?;
    md.with_preprocessor(super::localize::Localize::new(Lang::En));
    md.with_preprocessor(super::translate::Translate::new(Lang::En, &po_dir(&root)).map_err(|e| e.to_string())?);
    md.with_preprocessor(mdbook_katex::preprocess::KatexProcessor);
    let result = md
        .execute_build_process(&mdbook_i18n_helpers::renderers::Xgettext)
        .map_err(|e| format!("xgettext: {e:#}"))
        .and_then(|()| {
            let pot = find_pot(&tmp).ok_or("xgettext wrote no .pot file")?;
            let mut catalog = super::catalog::parse_po_file(&pot)?;
            if let Some(title) = title.filter(|t| catalog.find_message(None, t, None).is_none()) {
                catalog.append_or_update(
                    Message::build_singular().with_msgid(title).with_source("book/book.toml".to_owned()).done(),
                );
            }
            Ok(catalog)
        });
    let _ = std::fs::remove_dir_all(&tmp);
    result
}

/// The first `.pot` file under `dir` (the xgettext renderer writes one, in its own folder).
fn find_pot(dir: &Path) -> Option<PathBuf> {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir).ok()?.flatten().map(|e| e.path()).collect();
    entries.sort();
    entries
        .iter()
        .find(|p| p.is_file() && p.extension().is_some_and(|x| x == "pot"))
        .cloned()
        .or_else(|| entries.iter().filter(|p| p.is_dir()).find_map(|d| find_pot(d)))
}

/// `po` brought up to `pot`: every message of the template in its order, with the
/// translation kept when the msgid is unchanged, and a message with nothing to translate
/// ([`is_neutral`]) filled with its msgid. A message whose English changed comes
/// back empty; when a message of the same source line had a translation and has left the
/// template (its English was rewritten, not kept beside the new message), that old
/// translation is kept as a translator comment (`# previous: …`) to start from. A message
/// that is simply new gets no such comment, even when its source file has translated
/// messages. Messages that left the template are dropped. Returns the merged catalog, kept and empty counts.
#[must_use]
pub fn merge(pot: &Catalog, po: &Catalog) -> (Catalog, usize, usize) {
    let mut out = Catalog::new(copy_metadata(&po.metadata));
    out.metadata.pot_creation_date = pot.metadata.pot_creation_date.clone();
    let (mut kept, mut empty) = (0, 0);
    for m in pot.messages() {
        let old = po.find_message(None, m.msgid(), None);
        let mut new = Message::build_singular()
            .with_msgid(m.msgid().to_owned())
            .with_source(m.source().to_owned())
            .with_comments(m.comments().to_owned())
            .done();
        match old.filter(|o| o.is_translated()) {
            Some(o) => {
                let _ = new.set_msgstr(o.msgstr().unwrap_or_default().to_owned());
                if o.flags().is_fuzzy() {
                    new.flags_mut().add_flag("fuzzy");
                }
                kept += 1;
            }
            None if is_neutral(m.msgid()) => {
                let _ = new.set_msgstr(m.msgid().to_owned());
                kept += 1;
            }
            None => {
                let previous = po
                    .messages()
                    .find(|o| {
                        o.is_translated()
                            && !m.source().is_empty()
                            && o.source() == m.source()
                            && pot.find_message(None, o.msgid(), None).is_none()
                    })
                    .and_then(|o| o.msgstr().ok());
                if let Some(p) = previous {
                    *new.comments_mut() = format!("previous: {}", p.replace('\n', " "));
                }
                let _ = new.set_msgstr(String::new());
                empty += 1;
            }
        }
        out.append_or_update(new);
    }
    (out, kept, empty)
}

/// Whether a message has nothing to translate: no blank `{}` (a template, whose punctuation
/// each language writes) and no letter in its text outside inline code,
/// TeX, HTML and link targets (a table cell of numbers, a code span). Such a message is
/// its own translation, filled in by [`merge`]; its numbers then match by construction.
#[must_use]
pub fn is_neutral(msgid: &str) -> bool {
    use pulldown_cmark::{Event, Options, Parser};
    // a template's blanks are filled with words, and its punctuation is the language's
    // (`({}) : {}` in French)
    !msgid.contains("{}")
        && Parser::new_ext(msgid, Options::ENABLE_MATH | Options::ENABLE_TABLES)
            .all(|e| !matches!(e, Event::Text(t) if has_word_letter(&t)))
}

/// Whether `text` holds a letter that is not a number's exponent: the `e` of `2.5e-4`
/// (a digit before it, a digit or a sign and a digit after) is part of a number.
fn has_word_letter(text: &str) -> bool {
    let chars: Vec<char> = text.chars().collect();
    let digit = |i: usize| chars.get(i).is_some_and(char::is_ascii_digit);
    let exponent = |i: usize| {
        matches!(chars[i], 'e' | 'E')
            && i > 0
            && digit(i - 1)
            && (digit(i + 1) || matches!(chars.get(i + 1), Some('-' | '+')) && digit(i + 2))
    };
    (0..chars.len()).any(|i| chars[i].is_alphabetic() && !exponent(i))
}

/// Write the template and merge it into `po/<lang>.po` for every translation (a missing PO
/// file starts empty). `rust` and `drawn` as for [`template`].
pub fn extract(book_root: &Path, rust: &[(String, &str)], drawn: &[(String, String)]) -> Result<ExtractReport, String> {
    let dir = po_dir(book_root);
    let pot = template(book_root, rust, drawn)?;
    write_catalog(&pot, &dir.join("messages.pot"))?;
    let mut merged = Vec::new();
    for lang in Lang::ALL.into_iter().filter(|l| l.is_translation()) {
        let path = dir.join(format!("{}.po", lang.code()));
        let po = if path.is_file() {
            super::catalog::parse_po_file(&path).map_err(|e| format!("{}: {e}", path.display()))?
        } else {
            let mut c = Catalog::new(copy_metadata(&pot.metadata));
            c.metadata.language = lang.code().to_owned();
            c
        };
        let (catalog, kept, empty) = merge(&pot, &po);
        write_catalog(&catalog, &path)?;
        merged.push((lang, kept, empty));
    }
    Ok(ExtractReport { messages: pot.count(), merged })
}

/// Copy into the PO file at `path` every translation of `parts` whose msgid it holds (a
/// translator's partial file, as `msgcat --use-first` would): non-empty, not fuzzy ones
/// only. Returns how many were taken.
pub fn merge_translations(path: &Path, parts: &[Catalog]) -> Result<usize, String> {
    let mut po = super::catalog::parse_po_file(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut taken = 0;
    for part in parts {
        for m in part.messages() {
            let Ok(text) = m.msgstr() else { continue };
            if m.msgid().is_empty() || text.is_empty() || m.flags().is_fuzzy() {
                continue;
            }
            if let Some(mut target) = po.find_message_mut(None, m.msgid(), None) {
                let _ = target.set_msgstr(text.to_owned());
                target.flags_mut().remove_flag("fuzzy");
                taken += 1;
            }
        }
    }
    write_catalog(&po, path)?;
    Ok(taken)
}

/// Write a catalog through a temporary file and a rename.
fn write_catalog(catalog: &Catalog, path: &Path) -> Result<(), String> {
    let tmp = path.with_extension(format!("tmp{}", std::process::id()));
    polib::po_file::write(catalog, &tmp).map_err(|e| format!("writing {}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("writing {}: {e}", path.display()))
}

/// A copy of a catalog's header (polib's metadata has no `Clone`).
fn copy_metadata(m: &CatalogMetadata) -> CatalogMetadata {
    CatalogMetadata::parse(&m.export_for_po()).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn catalog(messages: &[(&str, &str, &str)]) -> Catalog {
        let mut c = Catalog::new(CatalogMetadata::default());
        for (id, source, str_) in messages {
            let mut m = Message::build_singular().with_msgid((*id).to_owned()).with_source((*source).to_owned()).done();
            let _ = m.set_msgstr((*str_).to_owned());
            c.append_or_update(m);
        }
        c
    }

    fn comment(c: &Catalog, id: &str) -> String {
        c.find_message(None, id, None).map(|m| m.comments().to_owned()).unwrap_or_default()
    }

    #[test]
    fn a_rewritten_message_keeps_its_old_translation_as_a_comment() {
        let po = catalog(&[("Old words", "src/a.rs", "Anciens mots")]);
        let pot = catalog(&[("New words", "src/a.rs", "")]);
        let (merged, kept, empty) = merge(&pot, &po);
        assert_eq!((kept, empty), (0, 1));
        assert_eq!(comment(&merged, "New words"), "previous: Anciens mots");
    }

    #[test]
    fn a_new_message_beside_kept_ones_of_the_same_file_gets_no_previous_comment() {
        // the Rust strings of one file share their source: a kept translation is not an
        // earlier version of the new message
        let po = catalog(&[("Kept words", "src/a.rs", "Mots gardés")]);
        let pot = catalog(&[("Kept words", "src/a.rs", ""), ("Brand new", "src/a.rs", "")]);
        let (merged, kept, empty) = merge(&pot, &po);
        assert_eq!((kept, empty), (1, 1));
        assert_eq!(comment(&merged, "Brand new"), "");
        assert_eq!(merged.find_message(None, "Kept words", None).and_then(|m| m.msgstr().ok()), Some("Mots gardés"));
    }

    #[test]
    fn a_numbers_exponent_is_no_word_but_a_word_is() {
        assert!(is_neutral("2.5e-4"));
        assert!(is_neutral("(1.0E+3, 6.62e-4) | `vec3(1.0)`"));
        assert!(!is_neutral("e-4"), "an e with no digit before it is a letter");
        assert!(!is_neutral("2e"), "nor one with nothing after it");
        assert!(!is_neutral("1e-4 ms"));
        assert!(!is_neutral("sphere4096"));
        assert!(!is_neutral("({}): {}"), "a template is translated, for its punctuation");
    }
}
