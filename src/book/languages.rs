//! The book in each language: the language picker on every page, and the words the
//! generated files draw, for the translation template.

use std::collections::BTreeMap;
use std::fs;
use std::path::Path;

use super::{artifacts, list_files, write_atomic, BookError, LANGUAGE_LABEL};
use crate::i18n::Lang;

/// The words the book's generated files draw (axes, legends, labels, captions of the
/// [`crate::figures::artifact::Artifact::localized`] generators), each with the file that draws it: every English
/// generator runs once under [`crate::i18n::catalog::record`]. These join the translation
/// template (`lightlab i18n extract`). `root` is the book's (its data draws the charts).
pub fn drawn_words(root: &Path) -> Result<Vec<(String, String)>, BookError> {
    let mut out = BTreeMap::new();
    for a in artifacts(root).iter().filter(|a| a.lang() == Some(Lang::En)) {
        let (made, heard) = crate::i18n::catalog::record(|| a.make());
        if let Err(e) = made {
            return Err(BookError::Generators {
                failed: 1,
                total: 1,
                lines: vec![format!("  {}: {e}", a.paths().join(", "))],
            });
        }
        let source = format!("book/src/generated/{}", a.paths().first().map_or("", String::as_str));
        for word in heard {
            out.entry(word).or_insert_with(|| source.clone());
        }
    }
    Ok(out.into_iter().collect())
}

/// The top of every page of every language: a picker linking the same page in the other
/// languages, inserted before the menu bar's right-hand buttons; in a translation, mdBook's
/// own words too ([`crate::i18n::chrome`]). Pages are found by walking `tmp` (English at the
/// top, translations in `<code>/`).
pub(super) fn add_language_pickers(tmp: &Path) -> Result<(), BookError> {
    for lang in Lang::ALL {
        let dir = if lang.is_translation() { tmp.join(lang.code()) } else { tmp.to_path_buf() };
        for page in list_files(&dir)? {
            let Ok(rel) = page.strip_prefix(&dir) else { continue };
            let top_level_other = rel.components().next().is_some_and(|c| {
                Lang::ALL.iter().any(|l| l.is_translation() && !lang.is_translation() && c.as_os_str() == l.code())
            });
            if page.extension().is_none_or(|e| e != "html") || top_level_other {
                continue;
            }
            let html = fs::read_to_string(&page).map_err(BookError::io("reading", &page))?;
            let depth = rel.components().count() - 1;
            let html = crate::i18n::chrome::translate_page(&html, lang);
            let picker = language_picker(lang, rel, depth);
            let anchor = "<div class=\"right-buttons\">";
            if let Some(at) = html.find(anchor) {
                let mut out = String::with_capacity(html.len() + picker.len());
                out.push_str(&html[..at]);
                out.push_str(&picker);
                out.push_str(&html[at..]);
                write_atomic(&page, out.as_bytes())?;
            }
        }
        if lang.is_translation() {
            translate_scripts(&dir, lang)?;
        }
    }
    Ok(())
}

/// mdBook's scripts at the top of a translated book (`book-*.js`, `searcher-*.js`) with
/// their words in `lang` ([`crate::i18n::chrome`]).
fn translate_scripts(dir: &Path, lang: Lang) -> Result<(), BookError> {
    for entry in fs::read_dir(dir).map_err(BookError::io("listing", dir))? {
        let path = entry.map_err(BookError::io("listing", dir))?.path();
        let name = path.file_name().and_then(|n| n.to_str()).unwrap_or_default();
        if !(name.ends_with(".js") && (name.starts_with("book-") || name.starts_with("searcher-"))) {
            continue;
        }
        let js = fs::read_to_string(&path).map_err(BookError::io("reading", &path))?;
        let translated = crate::i18n::chrome::translate_script(&js, lang);
        if translated != js {
            write_atomic(&path, translated.as_bytes())?;
        }
    }
    Ok(())
}

/// The picker of a page at `rel` (relative to its language's root, `depth` folders deep) in
/// `lang`: a `<nav>` with one link per language, the current one marked.
fn language_picker(lang: Lang, rel: &Path, depth: usize) -> String {
    let up = "../".repeat(depth + usize::from(lang.is_translation()));
    let rel = rel.to_string_lossy().replace('\\', "/");
    let label = crate::i18n::tr(lang, LANGUAGE_LABEL);
    let mut s =
        format!("<nav class=\"lightlab-languages\" aria-label=\"{}\">", crate::i18n::translate::html_attr(&label));
    for other in Lang::ALL {
        let prefix = if other.is_translation() { format!("{}/", other.code()) } else { String::new() };
        if other == lang {
            s += &format!("<span aria-current=\"page\" lang=\"{}\">{}</span>", other.code(), other.native_name());
        } else {
            s += &format!(
                "<a href=\"{up}{prefix}{rel}\" hreflang=\"{code}\" lang=\"{code}\">{name}</a>",
                code = other.code(),
                name = other.native_name()
            );
        }
    }
    s += "</nav>";
    s
}
