//! The PO files compiled into the binary, so the command line speaks the reader's language
//! wherever it runs; and [`tr`], the lookup every translated Rust string goes through.
//!
//! The Rust strings a reader sees are English msgids in `po/messages.pot` (listed by
//! `crate::cli::messages::rust_messages`); their translations sit in `po/fr.po` and `po/uk.po`
//! beside the book's, one home for each string.

use std::borrow::Cow;
use std::cell::RefCell;
use std::collections::BTreeSet;
use std::path::Path;
use std::sync::OnceLock;

use polib::catalog::Catalog;

use super::Lang;

/// `po/fr.po` as built into this binary.
pub const FR_PO: &str = include_str!("../../po/fr.po");
/// `po/uk.po` as built into this binary.
pub const UK_PO: &str = include_str!("../../po/uk.po");

/// The header fields polib 0.2 requires (it panics on a header without one of them).
pub const REQUIRED_HEADER_FIELDS: [&str; 9] = [
    "Project-Id-Version",
    "POT-Creation-Date",
    "PO-Revision-Date",
    "Language-Team",
    "MIME-Version",
    "Content-Type",
    "Content-Transfer-Encoding",
    "Language",
    "Plural-Forms",
];

/// The fields of [`REQUIRED_HEADER_FIELDS`] that the header of PO text `text` lacks. The
/// header is the `msgstr` of the first entry whose `msgid` is empty; text without such an
/// entry lacks none here (polib reports that itself, with an error and no panic).
#[must_use]
pub fn missing_header_fields(text: &str) -> Vec<&'static str> {
    let mut lines = text.lines().map(str::trim).skip_while(|l| *l != "msgid \"\"");
    if lines.next().is_none() {
        return Vec::new();
    }
    let mut lines = lines.skip_while(|l| l.starts_with('"'));
    if lines.next().is_none_or(|l| !l.starts_with("msgstr")) {
        return Vec::new();
    }
    let header: String =
        lines.take_while(|l| l.starts_with('"')).map(|l| l.trim_matches('"').replace("\\n", "\n")).collect();
    let keys: BTreeSet<&str> = header.lines().filter_map(|l| l.split_once(':')).map(|(k, _)| k.trim()).collect();
    REQUIRED_HEADER_FIELDS.into_iter().filter(|f| !keys.contains(f)).collect()
}

/// Parse a PO file with polib; the error names the line polib stopped at when it says one,
/// and the header fields it lacks ([`missing_header_fields`]), which polib 0.2 would panic on.
/// A panic inside polib is still caught and reported as an error.
pub fn parse_po_file(path: &Path) -> Result<Catalog, String> {
    if let Ok(text) = std::fs::read_to_string(path) {
        let missing = missing_header_fields(&text);
        if !missing.is_empty() {
            return Err(format!(
                "the PO header lacks {}: a PO file starts with msgid \"\" and a msgstr holding every one of {}",
                missing.join(", "),
                REQUIRED_HEADER_FIELDS.join(", ")
            ));
        }
    }
    match std::panic::catch_unwind(|| polib::po_file::parse(path)) {
        Ok(parsed) => parsed.map_err(|e| e.to_string()),
        Err(_) => Err(format!("polib could not read the PO header (it needs {})", REQUIRED_HEADER_FIELDS.join(", "))),
    }
}

/// Parse PO text (polib reads files only, so the text goes through a private temporary file).
pub fn parse_po_text(text: &str) -> Result<Catalog, String> {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!(".lightlab-po-{}-{n}.po", std::process::id()));
    std::fs::write(&path, text).map_err(|e| format!("writing {}: {e}", path.display()))?;
    let parsed = parse_po_file(&path);
    let _ = std::fs::remove_file(&path);
    parsed
}

/// The built-in catalog of `lang` (`None` for English, or when it cannot be read: then
/// every string stays English).
#[must_use]
pub fn built_in(lang: Lang) -> Option<&'static Catalog> {
    static FR: OnceLock<Option<Catalog>> = OnceLock::new();
    static UK: OnceLock<Option<Catalog>> = OnceLock::new();
    match lang {
        Lang::En => None,
        Lang::Fr => FR.get_or_init(|| parse_po_text(FR_PO).ok()).as_ref(),
        Lang::Uk => UK.get_or_init(|| parse_po_text(UK_PO).ok()).as_ref(),
    }
}

/// `msgid` in `lang`: its translation when the built-in catalog has one (not empty, not
/// fuzzy), else the English.
#[must_use]
pub fn tr(lang: Lang, msgid: &str) -> Cow<'_, str> {
    HEARD.with_borrow_mut(|heard| {
        if let Some(heard) = heard {
            heard.insert(msgid.to_owned());
        }
    });
    match built_in(lang).and_then(|c| lookup(c, msgid)) {
        Some(s) => Cow::Owned(s.to_owned()),
        None => Cow::Borrowed(msgid),
    }
}

thread_local! {
    /// The msgids [`tr`] looked up on this thread while [`record`] runs.
    static HEARD: RefCell<Option<BTreeSet<String>>> = const { RefCell::new(None) };
}

/// Run `f` and return, with its result, every msgid [`tr`] looked up on this thread
/// meanwhile. This is how the template learns the words generated files draw (a chart's
/// axis, a label built with numbers): the book's generators run once in English under it.
pub fn record<T>(f: impl FnOnce() -> T) -> (T, BTreeSet<String>) {
    let outer = HEARD.replace(Some(BTreeSet::new()));
    let out = f();
    let heard = HEARD.replace(outer).unwrap_or_default();
    HEARD.with_borrow_mut(|o| {
        if let Some(o) = o {
            o.extend(heard.iter().cloned());
        }
    });
    (out, heard)
}

/// [`tr`], then each `{}` replaced by the next of `args`, in order (a placeholder with no
/// argument left stays as it is).
#[must_use]
pub fn tr_fill(lang: Lang, msgid: &str, args: &[&str]) -> String {
    crate::blanks::fill(&tr(lang, msgid), args)
}

/// The translation of `msgid`, when the catalog has one that is neither empty nor fuzzy.
#[must_use]
pub fn lookup<'c>(catalog: &'c Catalog, msgid: &str) -> Option<&'c str> {
    catalog
        .find_message(None, msgid, None)
        .filter(|m| !m.flags().is_fuzzy() && m.is_translated())
        .and_then(|m| m.msgstr().ok())
        .filter(|s| !s.is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn english_is_the_msgid_and_placeholders_fill_in_order() {
        assert_eq!(tr(Lang::En, "not yet translated"), "not yet translated");
        assert_eq!(tr_fill(Lang::En, "{} of {} cases", &["3", "10"]), "3 of 10 cases");
        assert_eq!(tr_fill(Lang::En, "{} and {}", &["a"]), "a and {}");
    }

    #[test]
    fn record_hears_every_lookup_of_its_closure_and_nests() {
        let ((), outer) = record(|| {
            let _ = tr(Lang::Fr, "a");
            let ((), inner) = record(|| {
                let _ = tr_fill(Lang::Uk, "b {}", &["1"]);
            });
            assert_eq!(inner.into_iter().collect::<Vec<_>>(), ["b {}"]);
        });
        assert_eq!(outer.into_iter().collect::<Vec<_>>(), ["a", "b {}"]);
        let _ = tr(Lang::Fr, "not heard");
    }

    #[test]
    fn a_header_without_polibs_fields_is_an_error_naming_them_not_a_panic() {
        let text = "msgid \"\"\nmsgstr \"\"\n\"Language: fr\\n\"\n\"Content-Type: text/plain; charset=UTF-8\\n\"\n\nmsgid \"a\"\nmsgstr \"b\"\n";
        let missing = missing_header_fields(text);
        assert_eq!(missing.len(), REQUIRED_HEADER_FIELDS.len() - 2, "{missing:?}");
        assert!(!missing.contains(&"Language") && missing.contains(&"Plural-Forms"), "{missing:?}");
        let Err(err) = parse_po_text(text) else { panic!("a header without its fields parsed") };
        assert!(err.contains("lacks Project-Id-Version, POT-Creation-Date"), "{err}");
        assert!(missing_header_fields(FR_PO).is_empty() && missing_header_fields(UK_PO).is_empty());
    }

    #[test]
    fn the_built_in_catalogs_parse() {
        for lang in [Lang::Fr, Lang::Uk] {
            assert!(built_in(lang).is_some(), "{lang}: the built-in PO file does not parse");
        }
    }
}
