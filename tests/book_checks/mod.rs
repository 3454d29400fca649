//! The book test's checkers, each a pure function of text or paths so that its own test can
//! feed it a broken case: links and anchors, `{{#include}}`s, code anchors, stale statements.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

use lightlab::book;

/// The files under `dir` whose extension is `ext`.
pub fn files_with_ext(dir: &Path, ext: &str) -> Vec<PathBuf> {
    book::list_files(dir).unwrap().into_iter().filter(|p| p.extension().is_some_and(|e| e == ext)).collect()
}

/// Values of `attr="..."` in `html` (mdBook writes double-quoted attributes), with
/// `&amp;` decoded.
pub fn attr_values(html: &str, attr: &str) -> Vec<String> {
    let needle = format!("{attr}=\"");
    let mut out = Vec::new();
    let mut rest = html;
    while let Some(i) = rest.find(&needle) {
        let before = rest[..i].chars().last();
        let after = &rest[i + needle.len()..];
        let end = after.find('"').unwrap_or(after.len());
        if before.is_some_and(char::is_whitespace) {
            out.push(after[..end].replace("&amp;", "&"));
        }
        rest = &after[end..];
    }
    out
}

pub fn is_external(url: &str) -> bool {
    url.contains("://") || url.starts_with("mailto:") || url.starts_with("javascript:")
}

/// The ids defined in each page.
pub fn ids_by_page(pages: &[(PathBuf, String)]) -> BTreeMap<PathBuf, BTreeSet<String>> {
    pages.iter().map(|(p, t)| (p.clone(), attr_values(t, "id").into_iter().collect())).collect()
}

/// Broken internal links of `pages`: (page, href) pairs whose file or anchor is missing.
pub fn broken_links(pages: &[(PathBuf, String)]) -> Vec<String> {
    let ids = ids_by_page(pages);
    let mut broken = Vec::new();
    for (page, text) in pages {
        for href in attr_values(text, "href") {
            if is_external(&href) {
                continue;
            }
            let (path, anchor) = href.split_once('#').unwrap_or((&href, ""));
            let path = path.split('?').next().unwrap();
            let target = if path.is_empty() { page.clone() } else { page.parent().unwrap().join(path) };
            let target = if target.is_dir() { target.join("index.html") } else { target };
            if !target.is_file() {
                broken.push(format!("{}: {href} (no file)", page.display()));
                continue;
            }
            if anchor.is_empty() || target.extension().is_none_or(|e| e != "html") {
                continue;
            }
            let key = target.canonicalize().unwrap();
            let found = ids
                .iter()
                .find(|(p, _)| p.canonicalize().ok().as_ref() == Some(&key))
                .is_some_and(|(_, set)| set.contains(anchor));
            if !found {
                broken.push(format!("{}: {href} (no id '{anchor}')", page.display()));
            }
        }
    }
    broken
}

/// `html` with `<pre>` and `<code>` elements removed (math delimiters shown as code
/// are fine).
pub fn without_code(html: &str) -> String {
    let mut out = String::new();
    let mut rest = html;
    loop {
        let next = ["<pre", "<code"].iter().filter_map(|t| rest.find(t).map(|i| (i, *t))).min();
        let Some((i, tag)) = next else { break };
        out.push_str(&rest[..i]);
        let close = if tag == "<pre" { "</pre>" } else { "</code>" };
        rest = rest[i..].find(close).map_or("", |j| &rest[i + j + close.len()..]);
    }
    out.push_str(rest);
    out
}

/// Problems with the `{{#include}}`-style links of one markdown text at `md_path`:
/// missing files, and anchors or line ranges that the file does not have.
pub fn include_problems(md_path: &Path, text: &str) -> Vec<String> {
    let mut problems = Vec::new();
    for kind in ["include", "rustdoc_include", "playground"] {
        let open = format!("{{{{#{kind} ");
        let mut rest = text;
        while let Some(i) = rest.find(&open) {
            let escaped = rest[..i].ends_with('\\');
            let after = &rest[i + open.len()..];
            let end = after.find("}}").unwrap_or(after.len());
            let spec = after[..end].trim();
            rest = &after[end..];
            if escaped {
                continue;
            }
            // `path`, `path:anchor`, `path:N`, `path:N:M`, `path:N:`, `path::M`, then
            // optional attributes after whitespace (playground).
            let spec = spec.split_whitespace().next().unwrap_or("");
            let (file, selector) = spec.split_once(':').unwrap_or((spec, ""));
            let target = md_path.parent().unwrap().join(file);
            let Ok(content) = fs::read_to_string(&target) else {
                problems.push(format!("{}: {{{{#{kind} {spec}}}}}: no file {}", md_path.display(), target.display()));
                continue;
            };
            if selector.is_empty() {
                continue;
            }
            let numeric = selector.chars().all(|c| c.is_ascii_digit() || c == ':');
            if numeric {
                let lines = content.lines().count();
                let first = selector.split(':').find_map(|n| n.parse::<usize>().ok()).unwrap_or(1);
                if first > lines {
                    problems.push(format!("{}: {spec}: file has only {lines} lines", md_path.display()));
                }
            } else {
                let start = format!("ANCHOR: {selector}");
                let stop = format!("ANCHOR_END: {selector}");
                let has = |m: &str| content.lines().any(|l| l.trim_end().ends_with(m));
                if !has(&start) || !has(&stop) {
                    problems.push(format!("{}: {spec}: no anchor '{selector}'", md_path.display()));
                }
            }
        }
    }
    problems
}

/// `(file relative to the crate root, anchor)` for every `// ANCHOR: name` line in
/// `src/`, `examples/` and `tests/` (a comment line of its own, so anchors quoted
/// inside strings do not count).
pub fn anchors_in_code(crate_root: &Path) -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    for dir in ["src", "examples", "tests"] {
        for file in files_with_ext(&crate_root.join(dir), "rs") {
            let rel = file.strip_prefix(crate_root).unwrap().to_string_lossy().replace('\\', "/");
            for line in fs::read_to_string(&file).unwrap().lines() {
                if let Some(name) = line.trim().strip_prefix("// ANCHOR: ") {
                    out.insert((rel.clone(), name.trim().to_owned()));
                }
            }
        }
    }
    out
}

/// `(file relative to the crate root, anchor)` for every `{{#include path:anchor}}`
/// (and `rustdoc_include`) in the chapters under `book_src`, which sits two levels
/// below the crate root.
pub fn anchors_included(book_src: &Path) -> BTreeSet<(String, String)> {
    let mut out = BTreeSet::new();
    for md in files_with_ext(book_src, "md") {
        let text = fs::read_to_string(&md).unwrap();
        for piece in text.split("{{#").skip(1) {
            let Some(spec) = piece.strip_prefix("include ").or_else(|| piece.strip_prefix("rustdoc_include ")) else {
                continue;
            };
            let spec = spec.split("}}").next().unwrap_or("").trim();
            let Some((file, anchor)) = spec.split_once(':') else { continue };
            let numeric = anchor.chars().all(|c| c.is_ascii_digit() || c == ':');
            if let (Some(rel), false) = (file.strip_prefix("../../"), numeric) {
                out.insert((rel.to_owned(), anchor.to_owned()));
            }
        }
    }
    out
}

/// Statements that were true once and are not any more: each is a pattern that must
/// not appear in the book's chapters, the README or a doc comment under `src/`, and
/// why it is wrong.
pub const STALE: [(&str, &str); 6] = [
    ("will join these chapters", "renders are in the chapters now"),
    ("when the rasterizer", "the rasterizer exists"),
    ("OpenGL check land", "the OpenGL check exists"),
    ("until then every figure", "the book has renders, not only diagrams and charts"),
    ("lightlab issue", "readers have no issue tracker; say what the code does"),
    ("the issue's", "readers have no issue tracker; say what the code does"),
];

/// Lines of `text` (from `name`) that match a [`STALE`] pattern or mention a
/// development phase. For `.rs` files only doc comments (`///`, `//!`) count.
pub fn stale_lines(name: &str, text: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim_start();
        if name.ends_with(".rs") && !(t.starts_with("///") || t.starts_with("//!")) {
            continue;
        }
        let lower = line.to_lowercase();
        for (pattern, why) in STALE {
            if lower.contains(&pattern.to_lowercase()) {
                out.push(format!("{name}:{}: {pattern:?} ({why})", i + 1));
            }
        }
        let words: Vec<&str> = lower.split(|c: char| !c.is_alphanumeric()).collect();
        if words.windows(2).any(|w| (w[0] == "phase" || w[0] == "issue") && w[1].parse::<u32>().is_ok()) {
            out.push(format!("{name}:{}: names a development phase or issue number", i + 1));
        }
    }
    out
}
