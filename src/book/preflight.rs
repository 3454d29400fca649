//! Checks a book build makes before its work, so that a bad tree is a user error naming
//! the path instead of a half-installed book:
//!
//! - the build directory (`book/build`) must be a directory or absent: a regular file
//!   there used to let the new book render, then fail to install with exit 3 and leave a
//!   `.build-old-PID` behind;
//! - every `{{#include PATH}}` in a chapter must name an existing file: mdBook only logs
//!   an ERROR for a missing one and goes on, so the build exited 0 with a hole in a page.

use std::fs;
use std::path::{Path, PathBuf};

use super::BookError;

/// Why a build was refused before it started: the path and what is wrong with it.
#[derive(Debug, thiserror::Error)]
#[error("{}: {reason}", .path.display())]
pub struct PreflightError {
    /// The file concerned (the build directory, or the chapter holding the include).
    pub path: PathBuf,
    /// What is wrong, and what to do.
    pub reason: String,
}

impl BookError {
    /// Whether the error is the user's to fix (a path in the way, a missing include, a
    /// missing `book.toml`, a missing or malformed data file), as opposed to a failure of
    /// lightlab or of the machine.
    pub fn is_user_error(&self) -> bool {
        match self {
            BookError::Preflight(_) | BookError::NoBookToml(_) => true,
            BookError::Lock(e) => e.is_user_error(),
            _ => false,
        }
    }
}

/// Refuses a build directory `final_dir` that exists and is not a directory.
///
/// Errors: [`PreflightError`] naming `final_dir`.
pub fn check_build_dir(final_dir: &Path) -> Result<(), PreflightError> {
    match fs::symlink_metadata(final_dir) {
        Ok(m) if !m.is_dir() => Err(PreflightError {
            path: final_dir.to_path_buf(),
            reason: "exists and is not a directory; the book is built there: move or delete it, or set \
                     build.build-dir in book.toml"
                .into(),
        }),
        _ => Ok(()),
    }
}

/// Refuses a book whose measured data ([`crate::figures::book_data::FILES`] under
/// `data`) is missing or does not parse: the charts are drawn from it.
///
/// Errors: [`PreflightError`] naming the first missing file, or the parse error (which
/// names the file and its line).
pub fn check_data(data: &crate::figures::book_data::BookData) -> Result<(), PreflightError> {
    present(data)?;
    // the readers' messages are "PATH: what is wrong"
    let malformed = |e: crate::figures::FigureError| {
        let message = e.to_string();
        match message.split_once(": ") {
            Some((path, reason)) => PreflightError { path: path.into(), reason: reason.to_owned() },
            None => PreflightError { path: data.path(""), reason: message },
        }
    };
    for scene in crate::study::speed::SCENES {
        crate::figures::study_charts::scene_data(data, scene).map_err(malformed)?;
    }
    crate::figures::bench_charts::roofline_rows(data).map_err(malformed)?;
    crate::figures::bench_charts::scaling_rows(data).map_err(malformed)?;
    crate::figures::bench_charts::sweep_rows(data).map_err(malformed)?;
    Ok(())
}

/// Every data file exists. Errors: [`PreflightError`] naming the first missing one.
fn present(data: &crate::figures::book_data::BookData) -> Result<(), PreflightError> {
    for rel in crate::figures::book_data::FILES {
        let path = data.path(rel);
        if !path.is_file() {
            return Err(PreflightError {
                path,
                reason: "missing: the book draws its charts from it (`lightlab study` writes the study CSVs, \
                         `lightlab bench --roofline --csv`, `--scaling --csv`, `--specialisations --csv` and \
                         `--sweep --llvmpipe --csv` the bench ones)"
                    .into(),
            });
        }
    }
    Ok(())
}

/// Every `{{#include PATH…}}` of every chapter under `src` whose file does not exist, as
/// one error naming the chapter, its line and the path (relative to the chapter, as mdBook
/// resolves it). An escaped `\{{#include …}}` is text, not an include.
///
/// Errors: [`PreflightError`] naming the first chapter with a missing include and listing
/// every missing one.
pub fn check_includes(src: &Path) -> Result<(), PreflightError> {
    let mut missing = Vec::new();
    let mut first = None;
    for chapter in markdown_files(src) {
        let Ok(text) = fs::read_to_string(&chapter) else { continue };
        let dir = chapter.parent().unwrap_or(src);
        for (line, target) in includes(&text) {
            if !dir.join(&target).is_file() {
                first.get_or_insert_with(|| chapter.clone());
                missing.push(format!("{}: line {line}: {{{{#include {target}}}}}: no such file", chapter.display()));
            }
        }
    }
    match first {
        None => Ok(()),
        Some(path) => {
            Err(PreflightError { path, reason: format!("an included file is missing:\n  {}", missing.join("\n  ")) })
        }
    }
}

/// The `.md` files under `dir`, sorted (a missing or unreadable folder has none).
fn markdown_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let Ok(entries) = fs::read_dir(dir) else { return out };
    for entry in entries.flatten() {
        let path = entry.path();
        let Ok(kind) = entry.file_type() else { continue };
        if kind.is_dir() {
            out.extend(markdown_files(&path));
        } else if path.extension().is_some_and(|e| e == "md") {
            out.push(path);
        }
    }
    out.sort();
    out
}

/// `(line, file)` of each `{{#include file[:anchor|:range]}}` in `text` (1-based lines).
fn includes(text: &str) -> Vec<(usize, String)> {
    const OPEN: &str = "{{#include ";
    let mut out = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let mut rest = line;
        let escaped_before = |at: usize, rest: &str| at > 0 && rest.as_bytes()[at - 1] == b'\\';
        while let Some(at) = rest.find(OPEN) {
            let after = &rest[at + OPEN.len()..];
            let Some(end) = after.find("}}") else { break };
            if !escaped_before(at, rest) {
                let arg = after[..end].trim();
                // `file.rs:anchor` or `file.rs:2:10`: the path is before the first colon
                let file = arg.split(':').next().unwrap_or(arg).trim();
                if !file.is_empty() {
                    out.push((i + 1, file.to_owned()));
                }
            }
            rest = &after[end + 2..];
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn includes_are_found_with_their_lines_and_escapes_skipped() {
        let text = "intro\n{{#include ../../src/phong.rs:diffuse}}\n\\{{#include not/this.rs}}\n\
                    a {{#include generated/t.md}} b {{#include x.rs:2:10}}\n";
        assert_eq!(
            includes(text),
            vec![(2, "../../src/phong.rs".to_owned()), (4, "generated/t.md".to_owned()), (4, "x.rs".to_owned())]
        );
    }

    #[test]
    fn a_missing_include_names_the_chapter_line_and_path() {
        let dir = crate::scratch::Scratch::new("preflight");
        fs::write(dir.join("there.rs"), "fn main() {}\n").unwrap();
        fs::write(dir.join("ok.md"), "{{#include there.rs}}\n").unwrap();
        assert!(check_includes(&dir).is_ok());
        fs::write(dir.join("ch.md"), "# Chapter\n\n{{#include gone.rs:anchor}}\n").unwrap();
        let e = check_includes(&dir).unwrap_err().to_string();
        assert!(e.contains("ch.md: line 3") && e.contains("gone.rs"), "{e}");
        let file = dir.join("build");
        fs::write(&file, "not a folder").unwrap();
        let e = check_build_dir(&file).unwrap_err().to_string();
        assert!(e.contains("build") && e.contains("not a directory"), "{e}");
        assert!(check_build_dir(&dir).is_ok() && check_build_dir(&dir.join("absent")).is_ok());
    }

    #[test]
    fn changed_inputs_run_every_generator_again() {
        use crate::book::{generate_keyed, Artifact};
        use std::sync::atomic::{AtomicUsize, Ordering};
        static RUNS: AtomicUsize = AtomicUsize::new(0);
        let dir = crate::scratch::Scratch::new("gen-inputs");
        let (gen, cache) = (dir.join("generated"), dir.join("cache"));
        let all = [Artifact::file("t/chart.txt", || {
            RUNS.fetch_add(1, Ordering::SeqCst);
            Ok::<_, String>(b"chart".to_vec())
        })];
        generate_keyed(&gen, &cache, &all, false, 1).unwrap();
        let same = generate_keyed(&gen, &cache, &all, false, 1).unwrap();
        assert_eq!((same.cached, RUNS.load(Ordering::SeqCst)), (1, 1), "same inputs: served from the cache");
        let changed = generate_keyed(&gen, &cache, &all, false, 2).unwrap();
        assert_eq!((changed.cached, RUNS.load(Ordering::SeqCst)), (0, 2), "a CSV changed: the generator runs");
    }
}
