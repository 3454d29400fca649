//! The book builds, and what it builds holds together: every image exists, every
//! internal link and anchor resolves, every `{{#include}}` names an existing file and
//! anchor, every generated file is used by a chapter, nothing is loaded from the
//! network, the math is rendered, and generation is deterministic.
//!
//! The book is copied into `CARGO_TARGET_TMPDIR` and built there, so the worktree's
//! `book/build/` and `book/src/generated/` are never touched.
#![cfg(feature = "book")]

mod book_checks;

use book_checks::*;

use lightlab::book::{self, BuildOptions};
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// A built copy of the book.
struct Built {
    /// The copy's book root (holding book.toml).
    root: PathBuf,
    /// Directory holding the built index.html.
    html: PathBuf,
}

fn repo_book() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("book")
}

/// A fresh scratch directory for this test process, named `tag`.
fn scratch(tag: &str) -> PathBuf {
    let base = Path::new(env!("CARGO_TARGET_TMPDIR"));
    let dir = base.join(format!("book-{}-{tag}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).unwrap();
    dir
}

/// Copy the hand-written book (not its build output, generated files or cache).
fn copy_book(from: &Path, to: &Path) {
    for entry in fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name().to_string_lossy().into_owned();
        let skip = name == "build" || name == "generated" || name.starts_with('.');
        let src = entry.path();
        let dst = to.join(&name);
        if skip {
            continue;
        }
        if src.is_dir() {
            fs::create_dir_all(&dst).unwrap();
            copy_book(&src, &dst);
        } else {
            fs::copy(&src, &dst).unwrap();
        }
    }
}

/// Copy the book into `dir/book`, with the crate's `src/` and `examples/` beside it,
/// because chapters include compiled code through `{{#include ../../src/...}}`.
/// Returns the copy's book root.
fn copy_book_with_sources(dir: &Path) -> PathBuf {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    // chapters include compiled code from src/ and examples/; the translations are po/
    for code in ["src", "examples", "po"] {
        fs::create_dir_all(dir.join(code)).unwrap();
        copy_book(&crate_dir.join(code), &dir.join(code));
    }
    let root = dir.join("book");
    fs::create_dir_all(&root).unwrap();
    copy_book(&repo_book(), &root);
    root
}

/// Build the book once per test process and share it between the tests.
fn built() -> &'static Built {
    static BUILT: OnceLock<Built> = OnceLock::new();
    BUILT.get_or_init(|| {
        // Remove copies left by earlier runs of this test binary.
        let base = Path::new(env!("CARGO_TARGET_TMPDIR"));
        if let Ok(entries) = fs::read_dir(base) {
            for e in entries.flatten() {
                let name = e.file_name().to_string_lossy().into_owned();
                let mine = name.starts_with(&format!("book-{}-", std::process::id()));
                if name.starts_with("book-") && !mine {
                    let _ = fs::remove_dir_all(e.path());
                }
            }
        }
        let root = copy_book_with_sources(&scratch("built"));
        let opts = BuildOptions { root: root.clone(), force: true, quiet: true, no_solutions: false };
        let report = book::build(&opts).unwrap_or_else(|e| panic!("book build failed: {e}"));
        let html = report.index_html.parent().unwrap().to_path_buf();
        assert!(report.chapters >= 12, "only {} chapters", report.chapters);
        Built { root, html }
    })
}

/// HTML pages to check; `404.html` is skipped because it sets `<base href="/">` and so
/// only resolves when served from a site root.
fn pages(b: &Built) -> Vec<(PathBuf, String)> {
    files_with_ext(&b.html, "html")
        .into_iter()
        .map(|p| {
            let text = fs::read_to_string(&p).unwrap();
            (p, text)
        })
        .filter(|(_, text)| !text.contains("<base href"))
        // `generated/` holds fragments that chapters include (the live figures'
        // HTML); their relative links resolve from the chapter, not from the copy.
        // (in every language: the translations are under fr/ and uk/)
        .filter(|(p, _)| {
            !p.strip_prefix(&b.html).is_ok_and(|rel| rel.components().any(|c| c.as_os_str() == "generated"))
        })
        .collect()
}

#[test]
fn every_image_exists() {
    let b = built();
    let mut missing = Vec::new();
    let mut count = 0;
    for (page, text) in pages(b) {
        for src in attr_values(&text, "src") {
            if is_external(&src) || src.starts_with("data:") {
                continue;
            }
            count += 1;
            let target = page.parent().unwrap().join(src.split(['?', '#']).next().unwrap());
            if !target.is_file() {
                missing.push(format!("{} -> {src}", page.display()));
            }
        }
    }
    assert!(missing.is_empty(), "missing images/scripts:\n{}", missing.join("\n"));
    // The proof figure and chart are images of the basic lighting chapter.
    let ch2 = fs::read_to_string(b.html.join("02-basic-lighting.html")).unwrap();
    for png in ["generated/diagrams/phong-vectors.png", "generated/charts/specular-falloff.png"] {
        assert!(ch2.contains(png), "02-basic-lighting.html does not show {png}");
    }
    assert!(count > 0, "no src attribute found: the scanner is broken");
}

#[test]
fn every_internal_link_resolves() {
    let b = built();
    let pages = pages(b);
    assert!(pages.len() >= 12, "only {} pages", pages.len());
    let broken = broken_links(&pages);
    assert!(broken.is_empty(), "broken links:\n{}", broken.join("\n"));
    let internal = pages.iter().flat_map(|(_, t)| attr_values(t, "href")).filter(|h| !is_external(h)).count();
    // 12 pages, each linking at least the table of contents: the scanner found them.
    assert!(internal >= 12 * 12, "only {internal} internal links found");
}

#[test]
fn link_checker_catches_a_broken_link_and_anchor() {
    let dir = scratch("links");
    let a = dir.join("a.html");
    fs::write(dir.join("b.html"), "<h1 id=\"top\">B</h1>").unwrap();
    let good = "<a href=\"b.html#top\">ok</a> <a href=\"#here\" id=\"here\">self</a>";
    fs::write(&a, good).unwrap();
    let pages = vec![(a.clone(), good.to_owned()), (dir.join("b.html"), "<h1 id=\"top\">B</h1>".to_owned())];
    assert!(broken_links(&pages).is_empty(), "{:?}", broken_links(&pages));
    let bad = "<a href=\"c.html\">x</a> <a href=\"b.html#nope\">y</a>";
    let pages = vec![(a, bad.to_owned()), (dir.join("b.html"), "<h1 id=\"top\">B</h1>".to_owned())];
    assert_eq!(broken_links(&pages).len(), 2, "{:?}", broken_links(&pages));
}

#[test]
fn nothing_is_loaded_from_the_network() {
    let b = built();
    let mut remote = Vec::new();
    for (page, text) in pages(b) {
        if text.to_lowercase().contains("mathjax") {
            remote.push(format!("{}: mentions MathJax", page.display()));
        }
        for src in attr_values(&text, "src") {
            if is_external(&src) {
                remote.push(format!("{}: src={src}", page.display()));
            }
        }
        // Style sheets, fonts and icons come through <link href>; plain <a href> to the
        // web is fine.
        for tag in text.split("<link ").skip(1) {
            let tag = &tag[..tag.find('>').unwrap_or(tag.len())];
            for href in attr_values(&format!(" {tag}"), "href") {
                if is_external(&href) {
                    remote.push(format!("{}: <link href={href}>", page.display()));
                }
            }
        }
    }
    for css in files_with_ext(&b.html, "css") {
        let text = fs::read_to_string(&css).unwrap();
        for piece in text.split("url(").skip(1) {
            let url = piece[..piece.find(')').unwrap_or(0)].trim_matches(['"', '\'']);
            if !url.starts_with("data:") && is_external(url) {
                remote.push(format!("{}: url({url})", css.display()));
            }
        }
    }
    assert!(remote.is_empty(), "network references:\n{}", remote.join("\n"));
}

#[test]
fn katex_css_and_fonts_are_shipped() {
    let b = built();
    let css: Vec<PathBuf> = files_with_ext(&b.html.join("theme/katex"), "css");
    assert_eq!(css.len(), 1, "expected one KaTeX style sheet, found {css:?}");
    let text = fs::read_to_string(&css[0]).unwrap();
    let urls = book::css_relative_urls(&text);
    assert!(urls.len() >= 20, "KaTeX CSS names only {} fonts", urls.len());
    for url in urls {
        let font = css[0].parent().unwrap().join(&url);
        assert!(font.is_file(), "{} names missing {url}", css[0].display());
    }
    let index = fs::read_to_string(b.html.join("index.html")).unwrap();
    // mdBook fingerprints the name: theme/katex/katex-<hash>.min.css.
    let link =
        attr_values(&index, "href").into_iter().any(|h| h.starts_with("theme/katex/katex") && h.ends_with(".css"));
    assert!(link, "index.html does not link the KaTeX CSS");
}

#[test]
fn math_is_rendered_at_build_time() {
    let b = built();
    let ch2 = fs::read_to_string(b.html.join("02-basic-lighting.html")).unwrap();
    assert!(ch2.contains("katex-display"), "no display math in chapter 2");
    assert!(ch2.contains("<math"), "no MathML in chapter 2");
    assert!(!ch2.contains("$$"), "raw $$ left in chapter 2");
    assert!(!ch2.contains("katex-error"), "KaTeX reported an error in chapter 2");
}

#[test]
fn no_page_has_unrendered_display_math() {
    // mdbook-katex only warns on a LaTeX error and keeps the source; catch it here.
    let b = built();
    let bad: Vec<String> = pages(b)
        .into_iter()
        .filter(|(_, t)| without_code(t).contains("$$") || t.contains("katex-error"))
        .map(|(p, _)| p.display().to_string())
        .collect();
    assert!(bad.is_empty(), "unrendered math in:\n{}", bad.join("\n"));
    assert!(without_code("a<code>$$x$$</code>b<pre>$$</pre>c") == "abc");
}

#[test]
fn search_index_is_built() {
    let b = built();
    let has_index = book::list_files(&b.html)
        .unwrap()
        .iter()
        .any(|p| p.file_name().unwrap().to_string_lossy().starts_with("searchindex"));
    assert!(has_index, "no searchindex file: is mdbook-driver's `search` feature on?");
}

#[test]
fn every_include_resolves() {
    let b = built();
    let mut problems = Vec::new();
    for md in files_with_ext(&b.root.join("src"), "md") {
        problems.extend(include_problems(&md, &fs::read_to_string(&md).unwrap()));
    }
    assert!(problems.is_empty(), "bad includes:\n{}", problems.join("\n"));
}

#[test]
fn include_checker_catches_missing_files_and_anchors() {
    let dir = scratch("includes");
    let md = dir.join("ch.md");
    fs::write(dir.join("code.rs"), "// ANCHOR: here\nfn f() {}\n// ANCHOR_END: here\n").unwrap();
    let good = "{{#include code.rs}} {{#include code.rs:here}} {{#include code.rs:2}} \\{{#include nope.rs}}";
    assert!(include_problems(&md, good).is_empty(), "{:?}", include_problems(&md, good));
    let bad = "{{#include nope.rs}} {{#include code.rs:there}} {{#rustdoc_include code.rs:9:12}}";
    assert_eq!(include_problems(&md, bad).len(), 3, "{:?}", include_problems(&md, bad));
}

#[test]
fn every_generated_file_is_used_by_a_chapter() {
    let b = built();
    let src = b.root.join("src");
    let generated = src.join("generated");
    // A chapter uses a file directly, or through an HTML fragment it includes (the
    // live figures' scripts are named by their fragments).
    let mut chapters: Vec<String> = files_with_ext(&src, "md").iter().map(|p| fs::read_to_string(p).unwrap()).collect();
    chapters.extend(files_with_ext(&generated, "html").iter().map(|p| fs::read_to_string(p).unwrap()));
    let files = book::list_files(&generated).unwrap();
    let registered: usize = book::artifacts(&b.root).iter().map(|a| a.paths().len()).sum();
    assert_eq!(files.len(), registered, "generated/ holds {files:?}");
    let unused: Vec<String> = files
        .iter()
        .map(|f| {
            let rel = f.strip_prefix(&generated).unwrap().to_string_lossy().replace('\\', "/");
            // a language's copy (`fr/charts/x.png`) is used where the English one is: a
            // translated chapter points at it (lightlab::i18n::localize)
            let english = lightlab::i18n::Lang::ALL
                .iter()
                .filter(|l| l.is_translation())
                .find_map(|l| rel.strip_prefix(&format!("{}/", l.code())))
                .unwrap_or(&rel)
                .to_owned();
            format!("generated/{english}")
        })
        .filter(|rel| !chapters.iter().any(|c| c.contains(rel.as_str())))
        .collect();
    assert!(unused.is_empty(), "generated files no chapter uses:\n{}", unused.join("\n"));
}

/// Two forced runs of the generators (each with its generators in parallel) write the same
/// bytes: the shared build's ([`built`], forced) and one more into a directory of its own.
#[test]
fn generation_is_deterministic() {
    let b = built();
    let dir = scratch("determinism");
    let all = book::artifacts(&b.root);
    book::generate(&dir.join("a"), &dir.join("cache-a"), &all, true).unwrap();
    let shared = b.root.join("src").join("generated");
    for path in all.iter().flat_map(|art| art.paths()) {
        let (x, y) = (fs::read(dir.join("a").join(path)).unwrap(), fs::read(shared.join(path)).unwrap());
        assert!(x == y, "{path} differs between two builds");
    }
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn a_second_build_rewrites_nothing() {
    let dir = scratch("rebuild");
    let root = copy_book_with_sources(&dir);
    let opts = BuildOptions { root: root.clone(), force: false, quiet: true, no_solutions: false };
    let first = book::build(&opts).unwrap();
    let generated = root.join("src/generated");
    let before: Vec<Vec<u8>> = book::list_files(&generated).unwrap().iter().map(|p| fs::read(p).unwrap()).collect();
    let second = book::build(&opts).unwrap();
    let after: Vec<Vec<u8>> = book::list_files(&generated).unwrap().iter().map(|p| fs::read(p).unwrap()).collect();
    assert_eq!(first.generated.written, first.generated.total);
    assert_eq!(second.generated.written, 0, "{:?}", second.generated);
    assert_eq!(second.generated.cached, second.generated.total, "{:?}", second.generated);
    assert!(before == after, "generated files changed between two builds");
    assert!(second.index_html.is_file());
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn missing_book_toml_is_a_clear_error() {
    let dir = scratch("empty");
    let e = book::build(&BuildOptions::new(&dir)).unwrap_err().to_string();
    assert!(e.contains("book.toml"), "{e}");
}

#[test]
fn every_anchor_is_included_and_every_included_anchor_exists() {
    let crate_root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let defined = anchors_in_code(crate_root);
    let included = anchors_included(&crate_root.join("book/src"));
    assert!(defined.len() > 20, "the scan found only {defined:?}: is the pattern right?");
    let unused: Vec<_> = defined.difference(&included).collect();
    let missing: Vec<_> = included.difference(&defined).collect();
    assert!(unused.is_empty(), "anchors no chapter includes (include them or remove them): {unused:?}");
    assert!(missing.is_empty(), "chapters include anchors the code does not have: {missing:?}");
}

#[test]
fn anchor_scan_sees_both_directions() {
    let dir = scratch("anchors");
    let root = dir.join("crate");
    fs::create_dir_all(root.join("src")).unwrap();
    fs::create_dir_all(root.join("book/src")).unwrap();
    fs::write(
        root.join("src/a.rs"),
        "// ANCHOR: used\n// ANCHOR_END: used\n    // ANCHOR: spare\nlet s = \"// ANCHOR: quoted\";\n",
    )
    .unwrap();
    fs::write(
        root.join("book/src/ch.md"),
        "{{#include ../../src/a.rs:used}} {{#include ../../src/a.rs:gone}} {{#include ../../src/a.rs:3}}",
    )
    .unwrap();
    let defined = anchors_in_code(&root);
    let included = anchors_included(&root.join("book/src"));
    let pair = |a: &str| ("src/a.rs".to_owned(), a.to_owned());
    assert_eq!(defined, [pair("used"), pair("spare")].into_iter().collect());
    assert_eq!(included, [pair("used"), pair("gone")].into_iter().collect());
}

#[test]
fn no_stale_statements_in_the_book_readme_or_docs() {
    let crate_root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = files_with_ext(&crate_root.join("book/src"), "md");
    files.retain(|f| !f.starts_with(crate_root.join("book/src/generated")));
    files.push(crate_root.join("README.md"));
    files.extend(files_with_ext(&crate_root.join("src"), "rs"));
    let mut problems = Vec::new();
    for f in &files {
        let name = f.strip_prefix(crate_root).unwrap().to_string_lossy().into_owned();
        problems.extend(stale_lines(&name, &fs::read_to_string(f).unwrap()));
    }
    assert!(files.len() > 30, "only {} files scanned", files.len());
    assert!(problems.is_empty(), "stale statements:\n{}", problems.join("\n"));
}

#[test]
fn stale_checker_catches_what_it_should() {
    let md = "Renders will join these chapters when the rasterizer and OpenGL check land.\nFine.";
    assert_eq!(stale_lines("x.md", md).len(), 3, "{:?}", stale_lines("x.md", md));
    let rs = "//! Source: lightlab issue 6.\n// issue 6 in a plain comment is fine\n/// Before phase 2.\n";
    assert_eq!(stale_lines("x.rs", rs).len(), 3, "{:?}", stale_lines("x.rs", rs));
}

/// Run the `lightlab` binary with `args`, in `cwd`, with `env` added; returns
/// `(success, stderr)`.
fn run_lightlab(args: &[&std::ffi::OsStr], cwd: &Path, env: &[(&std::ffi::OsStr, &std::ffi::OsStr)]) -> (bool, String) {
    let mut cmd = std::process::Command::new(env!("CARGO_BIN_EXE_lightlab"));
    cmd.args(args).current_dir(cwd);
    for (k, v) in env {
        cmd.env(k, v);
    }
    let out = cmd.output().unwrap();
    (out.status.success(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[cfg(unix)]
#[test]
fn the_build_survives_non_utf8_environment_and_directories() {
    use std::ffi::{OsStr, OsString};
    use std::os::unix::ffi::{OsStrExt, OsStringExt};
    let dir = scratch("non-utf8");
    // A working directory whose name is not UTF-8 (0xFF never occurs in UTF-8), with
    // the book copied under it, so the book's own paths are not UTF-8 either.
    let odd = dir.join(OsStr::from_bytes(b"dir-\xff-here"));
    fs::create_dir_all(&odd).unwrap();
    let root = copy_book_with_sources(&odd);
    let bad_value = OsString::from_vec(b"value-\xfe".to_vec());
    let bad_name = OsString::from_vec(b"LIGHTLAB_TEST_\xff".to_vec());
    let mdbook_bad = OsString::from_vec(b"\xff".to_vec());
    let env: [(&OsStr, &OsStr); 3] = [
        (OsStr::new("LIGHTLAB_TEST_VALUE"), &bad_value),
        (&bad_name, OsStr::new("x")),
        (OsStr::new("MDBOOK_BOOK__TITLE"), &mdbook_bad),
    ];
    let (ok, stderr) = run_lightlab(&[OsStr::new("book"), OsStr::new("--root"), root.as_os_str()], &odd, &env);
    assert!(ok, "the build failed:\n{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(root.join("build").join("index.html").is_file());
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn a_second_build_waits_for_the_lock_and_names_its_holder() {
    use std::io::{BufRead, BufReader};
    let dir = scratch("lock");
    let root = copy_book_with_sources(&dir);
    let held = lightlab::outfile::lock_dir(&root, |who| panic!("nobody holds it yet, but {who}")).unwrap();
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .args(["book", "--root"])
        .arg(&root)
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut lines = BufReader::new(child.stderr.take().unwrap()).lines();
    let first = lines.next().expect("the build said nothing").unwrap();
    assert!(first.contains("waiting") && first.contains(&format!("process {}", std::process::id())), "{first}");
    // It waited: nothing was generated while the lock was held.
    assert!(!root.join("src/generated").exists(), "the build wrote while another process held the lock");
    drop(held);
    let rest: Vec<String> = lines.map_while(Result::ok).collect();
    assert!(child.wait().unwrap().success(), "{rest:?}");
    assert!(root.join("build/index.html").is_file());
    let _ = fs::remove_dir_all(&dir);
}

#[test]
fn two_builds_at_once_both_succeed_with_the_same_bytes() {
    let dir = scratch("concurrent");
    let root = copy_book_with_sources(&dir);
    let spawn = || {
        std::process::Command::new(env!("CARGO_BIN_EXE_lightlab"))
            .args(["book", "--force", "-q", "--root"])
            .arg(&root)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap()
    };
    let (a, b) = (spawn(), spawn());
    for child in [a, b] {
        let out = child.wait_with_output().unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    }
    let files = book::list_files(&root.join("src/generated")).unwrap();
    let registered: usize = book::artifacts(&root).iter().map(|a| a.paths().len()).sum();
    assert_eq!(files.len(), registered);
    let leftovers: Vec<_> = fs::read_dir(&root)
        .unwrap()
        .flatten()
        .map(|e| e.file_name())
        .filter(|n| n.to_string_lossy().starts_with(".build-"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    let _ = fs::remove_dir_all(&dir);
}

/// The French and Ukrainian books sit beside the English one with every chapter, each page
/// with `<html lang>` set and a picker that links the same page in the other languages.
#[test]
fn every_language_has_every_chapter_and_a_picker() {
    use lightlab::i18n::Lang;
    let b = built();
    let english: Vec<PathBuf> = fs::read_dir(&b.html)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "html"))
        .collect();
    assert!(english.len() >= 14, "{} English pages", english.len());
    for lang in Lang::ALL {
        let dir = if lang.is_translation() { b.html.join(lang.code()) } else { b.html.clone() };
        for page in &english {
            let name = page.file_name().unwrap();
            let path = dir.join(name);
            let html = fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(html.contains(&format!("<html lang=\"{}\"", lang.code())), "{}: no lang={}", path.display(), lang);
            if html.contains("<base href") || name == "toc.html" {
                continue; // 404.html, and the sidebar's frame page (no menu bar)
            }
            for other in Lang::ALL.into_iter().filter(|o| *o != lang) {
                let prefix = match (lang.is_translation(), other.is_translation()) {
                    (false, true) => format!("{}/", other.code()),
                    (true, true) => format!("../{}/", other.code()),
                    (true, false) => "../".to_owned(),
                    (false, false) => String::new(),
                };
                let link = format!("href=\"{prefix}{}\" hreflang=\"{}\"", name.to_string_lossy(), other.code());
                assert!(html.contains(&link), "{}: no picker link {link}", path.display());
                let target = dir.join(format!("{prefix}{}", name.to_string_lossy()));
                assert!(target.is_file(), "{}: picker target {} missing", path.display(), target.display());
            }
        }
    }
}

/// A translated page shows its language's copy of every generated file that has one (a chart,
/// a diagram, a live figure's markup and words), and an English page never does.
#[test]
fn translated_pages_show_their_languages_figures() {
    use lightlab::i18n::Lang;
    let b = built();
    let generated = b.root.join("src/generated");
    for lang in Lang::ALL {
        let dir = if lang.is_translation() { b.html.join(lang.code()) } else { b.html.clone() };
        let mut localized = 0;
        for page in files_with_ext(&dir, "html").iter().filter(|p| p.parent() == Some(dir.as_path())) {
            let html = fs::read_to_string(page).unwrap();
            for (at, _) in html.match_indices("generated/") {
                let path: String = html[at + "generated/".len()..]
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric() || "/.-_@".contains(*c))
                    .collect();
                let in_lang =
                    Lang::ALL.iter().any(|l| l.is_translation() && path.starts_with(&format!("{}/", l.code())));
                if in_lang {
                    assert!(path.starts_with(&format!("{}/", lang.code())), "{}: shows {path}", page.display());
                    localized += 1;
                } else if lang.is_translation() {
                    let copy = generated.join(lang.code()).join(&path);
                    assert!(
                        !copy.is_file(),
                        "{}: shows the English generated/{path}, not its {lang} copy",
                        page.display()
                    );
                }
            }
        }
        assert_eq!(localized > 0, lang.is_translation(), "{lang}: {localized} localized references");
    }
}

/// `po/messages.pot` holds exactly the messages of the current English text (the book after
/// its generated files, and the Rust strings): a changed sentence without `lightlab i18n
/// extract` fails here, naming it.
#[test]
fn the_translation_template_is_current() {
    use std::collections::BTreeSet;
    let b = built();
    let fresh = lightlab::cli::messages::translation_template(&b.root).unwrap();
    let committed =
        lightlab::i18n::catalog::parse_po_file(&repo_book().parent().unwrap().join("po/messages.pot")).unwrap();
    let ids =
        |c: &polib::catalog::Catalog| -> BTreeSet<String> { c.messages().map(|m| m.msgid().to_owned()).collect() };
    let (now, then) = (ids(&fresh), ids(&committed));
    let new: Vec<&String> = now.difference(&then).take(5).collect();
    let gone: Vec<&String> = then.difference(&now).take(5).collect();
    assert!(
        new.is_empty() && gone.is_empty(),
        "po/messages.pot is stale: run `cargo run --release -- i18n extract`; new: {new:?}; gone: {gone:?}"
    );
}

#[test]
fn no_solutions_leaves_the_reference_solutions_out_of_every_language() {
    use lightlab::book::solutions::SOLUTION_START;
    use lightlab::i18n::Lang;
    let with = built();
    let root = copy_book_with_sources(&scratch("no-solutions"));
    let opts = BuildOptions { root, force: false, quiet: true, no_solutions: true };
    let report = book::build(&opts).unwrap_or_else(|e| panic!("book build failed: {e}"));
    let without = report.index_html.parent().unwrap().to_path_buf();
    for (lang, dir) in [(Lang::En, ""), (Lang::Fr, "fr"), (Lang::Uk, "uk")] {
        let page = |html: &Path| fs::read_to_string(html.join(dir).join("12-exercises.html")).unwrap();
        let (a, b) = (page(&with.html), page(&without));
        // the summary in the page's language (the words of an HTML block are translated)
        let summary = lightlab::i18n::tr(lang, "Reference solution");
        assert_eq!(lang == Lang::En, summary == "Reference solution", "{dir}: the summary is not translated");
        let start_tag = SOLUTION_START.replace("Reference solution", &summary);
        assert!(a.matches(&start_tag).count() >= 15, "{dir}: the default build folds the solutions");
        assert_eq!(b.matches(&start_tag).count(), 0, "{dir}: --no-solutions keeps a folded solution");
        // the first solution's code itself is gone, not only its summary
        let start = a.find(&start_tag).unwrap();
        let block = &a[start..start + a[start..].find("</details>").unwrap()];
        let code = &block[block.find("<code").unwrap()..];
        assert!(code.len() > 100 && !b.contains(code), "{dir}: the solution's code is still in the page");
        assert!(b.contains("lightlab exercise show"), "{dir}: the statements stay");
    }
    let data = |html: &Path| -> Vec<String> {
        let dir = html.join("generated/live");
        let mut files: Vec<PathBuf> = fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()).collect();
        files.retain(|p| {
            p.file_name().unwrap().to_string_lossy().starts_with("exercise-")
                && p.extension().is_some_and(|e| e == "js")
        });
        files.sort();
        files.iter().map(|p| fs::read_to_string(p).unwrap()).collect()
    };
    let (a, b) = (data(&with.html), data(&without));
    assert_eq!(a.len(), b.len());
    assert!(a.iter().any(|js| js.contains("\"solution\":")), "the default page data carries solutions");
    for js in &b {
        assert!(!js.contains("\"solution\":"), "page data keeps a solution: {:.200}", js);
    }
    assert_eq!(
        a.iter().filter(|js| js.contains("\"reference\":")).count(),
        b.iter().filter(|js| js.contains("\"reference\":")).count(),
        "the in-page checker keeps its reference shaders"
    );
}

/// mdBook's own words (menu bar, theme menu, search, keyboard help, code buttons, 404) are
/// in the page's language: every listed context is found in the English book (so the list
/// follows mdBook), and no translated page or script still holds it in English.
#[test]
fn mdbooks_own_words_are_in_the_pages_language() {
    use lightlab::i18n::chrome::{PAGE, SCRIPT};
    use lightlab::i18n::Lang;
    let b = built();
    let top_files = |dir: &Path, ext: &str| -> String {
        files_with_ext(dir, ext)
            .iter()
            .filter(|p| p.parent() == Some(dir))
            .filter(|p| ext == "html" || p.file_name().unwrap().to_string_lossy().starts_with(['b', 's']))
            .map(|p| fs::read_to_string(p).unwrap())
            .collect()
    };
    for (list, ext) in [(PAGE, "html"), (SCRIPT, "js")] {
        let english = top_files(&b.html, ext);
        for c in list {
            assert!(english.contains(&c.fill(c.words)), "mdBook no longer writes {:?}", c.fill(c.words));
        }
        for lang in Lang::ALL.into_iter().filter(|l| l.is_translation()) {
            let text = top_files(&b.html.join(lang.code()), ext);
            for c in list.iter().filter(|c| lightlab::i18n::tr(lang, c.words) != c.words) {
                assert!(!text.contains(&c.fill(c.words)), "{lang}: {:?} is left in English", c.fill(c.words));
                let translated = c.fill(&lightlab::i18n::tr(lang, c.words));
                assert!(text.contains(&translated), "{lang}: {translated:?} is not shown");
            }
        }
    }
}

/// The command-line options in `html` that mdBook's smart punctuation turned into an en
/// dash (`--scaling` written outside a code span reaches the reader as `–scaling`, which no
/// shell accepts): an en dash after a space, `(` or a tag, before a lowercase letter.
fn options_turned_into_dashes(html: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in html.match_indices('–') {
        let before = html[..i].chars().next_back();
        let rest = &html[i + '–'.len_utf8()..];
        if matches!(before, Some(' ' | '(' | '>')) && rest.chars().next().is_some_and(|c| c.is_ascii_lowercase()) {
            out.push(rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '-').collect());
        }
    }
    out
}

#[test]
fn no_command_line_option_became_an_en_dash() {
    assert_eq!(options_turned_into_dashes("the limit (–memory) and bench –scaling"), ["memory", "scaling"]);
    assert!(options_turned_into_dashes("pages 3–5, a pause – then <code>--memory</code>").is_empty());
    let mut bad = Vec::new();
    for (page, text) in pages(built()) {
        for option in options_turned_into_dashes(&text) {
            bad.push(format!("{}: –{option}", page.display()));
        }
    }
    assert!(bad.is_empty(), "options outside code spans, shown with an en dash:\n{}", bad.join("\n"));
}
