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

/// Parse a PO file with polib; the error names the line polib stopped at when it says one.
/// polib 0.2 panics on a header that lacks one of the standard fields
/// (`Project-Id-Version`, `POT-Creation-Date`, `PO-Revision-Date`, `Language-Team`,
/// `MIME-Version`, `Content-Type`, `Content-Transfer-Encoding`, `Language`,
/// `Plural-Forms`): that panic is caught and reported as such an error.
pub fn parse_po_file(path: &Path) -> Result<Catalog, String> {
    match std::panic::catch_unwind(|| polib::po_file::parse(path)) {
        Ok(parsed) => parsed.map_err(|e| e.to_string()),
        Err(_) => Err("the PO header lacks a standard field (Project-Id-Version, POT-Creation-Date, \
                       PO-Revision-Date, Language-Team, MIME-Version, Content-Type, \
                       Content-Transfer-Encoding, Language or Plural-Forms)"
            .to_owned()),
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
    let text = tr(lang, msgid);
    let mut out = String::with_capacity(text.len());
    let mut rest = text.as_ref();
    let mut args = args.iter();
    while let Some(at) = rest.find("{}") {
        out.push_str(&rest[..at]);
        match args.next() {
            Some(a) => out.push_str(a),
            None => out.push_str("{}"),
        }
        rest = &rest[at + 2..];
    }
    out.push_str(rest);
    out
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
    fn the_built_in_catalogs_parse() {
        for lang in [Lang::Fr, Lang::Uk] {
            assert!(built_in(lang).is_some(), "{lang}: the built-in PO file does not parse");
        }
    }
}
