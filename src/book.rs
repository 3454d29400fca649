//! Build the book: generate every figure and table into `book/src/generated/`, then
//! render the HTML in-process with mdBook and KaTeX. `lightlab` with no subcommand
//! (or `lightlab book`) calls [`build`].
//!
//! # Adding a generated file
//!
//! A generated file comes from an [`Artifact`] (defined in
//! [`crate::figures::artifact`]): one generator and the paths, under
//! `book/src/generated/`, of the files it writes. Topics keep their own list (for
//! example [`crate::figures::diagrams::artifacts`]); [`artifacts`] concatenates the
//! lists, so a new topic adds one `all.extend(...)` line there and a new figure adds
//! one [`Artifact::file`] (or [`Artifact::files`]) line to its topic's list. A chapter
//! then shows it with `![alt](generated/<path>)` or includes it with
//! `{{#include generated/<path>}}`. `tests/book.rs` fails when a generated file is not
//! used by any chapter.
//!
//! Generators must be pure: their bytes may depend only on code compiled into the
//! binary (no clock, no unseeded randomness, no reading files that can change).
//!
//! # What [`build`] does
//!
//! 0. **lock**: an exclusive lock on `book/.lightlab.lock` ([`LOCK_FILE`]), held to
//!    the end, so a second build of the same book waits (and says which process it
//!    waits for) instead of writing the same files at the same time.
//! 1. **generate**: runs the generators in parallel (rayon). Each file is written only
//!    when its bytes differ from the file on disk, through a temporary file renamed
//!    into place. A generator is skipped entirely when the cache file
//!    `book/.lightlab-cache` says the same executable already produced every file of
//!    it that is on disk now (the key is a 64-bit hash of the running executable's bytes, and the
//!    entry stores a hash of the file's bytes, so editing or deleting a generated file
//!    regenerates it). Files under `generated/` that no artifact names are deleted.
//! 2. **html**: mdBook loads `book.toml` (plus the `MDBOOK_*` environment overrides
//!    that are UTF-8) with the `KatexProcessor` of mdbook-katex run
//!    in-process (math becomes HTML + MathML at build time; no JavaScript, no CDN),
//!    rendered into `book/.build-tmp-<pid>/`. The files that `additional-css` style
//!    sheets refer to by relative `url(...)` (the vendored KaTeX fonts) are copied next
//!    to the style sheets, which mdBook itself does not do.
//! 3. **install**: the finished directory replaces `book/build/` by two renames, so a
//!    reader never sees a half-written book.
//!
//! Each stage prints one line to stderr with counts and time.

use rayon::prelude::*;
use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::io::Write as _;
use std::path::{Component, Path, PathBuf};
use std::time::Instant;

pub mod languages;
pub mod preflight;
pub mod solutions;

pub use languages::drawn_words;

pub use crate::figures::artifact::{check_paths, Artifact, BoxError, RegistryError};
use crate::figures::book_data::BookData;
use crate::i18n::translate::{Coverage, Translate};
use crate::i18n::Lang;

/// Every generated file of the book at `root` (the folder holding `book.toml`; the
/// measured charts read its `data/` CSVs): the concatenation of each topic's list.
/// To add a topic, add one `all.extend(...)` line.
pub fn artifacts(root: &Path) -> Vec<Artifact> {
    let data = crate::figures::book_data::BookData::of_book(root);
    let mut all = Vec::new();
    all.extend(crate::figures::diagrams::artifacts());
    all.extend(crate::figures::charts::artifacts());
    all.extend(crate::figures::tables_md::artifacts());
    all.extend(crate::figures::renders::artifacts());
    all.extend(crate::figures::study_charts::artifacts(&data));
    all.extend(crate::figures::bench_charts::artifacts(&data));
    all.extend(crate::live::artifacts());
    all.extend(crate::live::exercises::artifacts());
    all.push(Artifact::file("tables/glossary.md", || Ok::<_, String>(crate::i18n::glossary::markdown().into_bytes())));
    all
}

/// Why a build (or one of its stages) failed. Every variant names the path or the
/// artifact concerned.
#[derive(Debug, thiserror::Error)]
pub enum BookError {
    /// The root has no `book.toml`.
    #[error("{0} has no book.toml: pass the book directory with --root")]
    NoBookToml(PathBuf),
    /// The artifact registry is invalid.
    #[error(transparent)]
    Registry(#[from] RegistryError),
    /// Some generators failed; each line names the artifact's paths and the error.
    #[error("{failed} of {total} generators failed:\n{}", .lines.join("\n"))]
    Generators {
        /// Number of failed generators.
        failed: usize,
        /// Number of generators.
        total: usize,
        /// One `  path[, path]: message` line per failure.
        lines: Vec<String>,
    },
    /// A file or directory operation failed.
    #[error("{what} {}: {source}", .path.display())]
    Io {
        /// What was being done ("writing", "reading", ...).
        what: &'static str,
        /// The path concerned.
        path: PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
    /// mdBook could not load or build the book.
    #[error("{what} {}: {message}", .root.display())]
    MdBook {
        /// "loading the book at" or "mdBook build of".
        what: &'static str,
        /// The book root.
        root: PathBuf,
        /// mdBook's error chain.
        message: String,
    },
    /// A path has no parent directory or no file name where one is needed
    /// (the path, then "parent directory" or "file name").
    #[error("{} has no {what}", .0.display(), what = .1)]
    BadPath(PathBuf, &'static str),
    /// mdBook wrote no `index.html`.
    #[error("mdBook produced no index.html in {}", .0.display())]
    NoIndex(PathBuf),
    /// The output lock could not be taken.
    #[error(transparent)]
    Lock(#[from] crate::outfile::OutputError),
    /// Refused before the work: a path in the way, a missing include ([`preflight`]).
    #[error(transparent)]
    Preflight(#[from] preflight::PreflightError),
}

impl BookError {
    fn io<'a>(what: &'static str, path: &'a Path) -> impl FnOnce(std::io::Error) -> BookError + 'a {
        move |source| BookError::Io { what, path: path.to_path_buf(), source }
    }
}

/// Where and how to build.
#[derive(Clone, Debug)]
pub struct BuildOptions {
    /// The book root: the directory holding `book.toml`.
    pub root: PathBuf,
    /// Regenerate every artifact even when the cache says it is up to date.
    pub force: bool,
    /// Print nothing to stderr.
    pub quiet: bool,
    /// Leave the exercises' reference solutions out ([`solutions`]).
    pub no_solutions: bool,
}

impl BuildOptions {
    /// Options for the book at `root`, cache on, progress printed, solutions in.
    pub fn new(root: impl Into<PathBuf>) -> BuildOptions {
        BuildOptions { root: root.into(), force: false, quiet: false, no_solutions: false }
    }
}

/// What the generate stage did. Counts are of files, not generators.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GenerateReport {
    /// Number of files the registry names.
    pub total: usize,
    /// Files written because their bytes changed (or were missing).
    pub written: usize,
    /// Files whose generator ran and produced the bytes already on disk.
    pub unchanged: usize,
    /// Files whose generator was skipped because the cache showed them up to date.
    pub cached: usize,
    /// Stale files deleted from `generated/`.
    pub removed: usize,
}

/// What [`build`] did.
#[derive(Clone, Debug)]
pub struct BuildReport {
    /// The generate stage.
    pub generated: GenerateReport,
    /// Number of chapters mdBook rendered.
    pub chapters: usize,
    /// The built book's `index.html`.
    pub index_html: PathBuf,
}

/// Name of the lock file, relative to the book root. [`build`] holds an exclusive
/// lock on it from the first generated file to the installed HTML.
pub const LOCK_FILE: &str = crate::outfile::LOCK_FILE;

/// Generate the artifacts, render the HTML, and install it in the configured build
/// directory (`book/build/` by default). See the module docs for the stages.
///
/// Two builds of the same book run one after the other: the second waits for the
/// lock on `book/.lightlab.lock` and says on stderr which process holds it.
///
/// Returns an error (never panics) when the root has no `book.toml`, an artifact path
/// is invalid or repeated, a generator fails (all failures are listed), mdBook fails,
/// or a file cannot be written. Environment variables and paths that are not UTF-8
/// are fine (an `MDBOOK_*` override that is not UTF-8 is ignored).
pub fn build(opts: &BuildOptions) -> Result<BuildReport, BookError> {
    if !opts.root.join("book.toml").is_file() {
        return Err(BookError::NoBookToml(opts.root.clone()));
    }
    // Absolute, so that mdBook's `root.join(build_dir)` keeps our temporary path as is.
    let root = &opts.root.canonicalize().map_err(BookError::io("resolving", &opts.root))?;
    let say = |line: String| {
        if !opts.quiet {
            eprintln!("{line}");
        }
    };
    let _lock = crate::outfile::lock_dir(root, |message| say(format!("lightlab book: {message}")))?;
    preflight::check_build_dir(&root.join(&load_config(root)?.build.build_dir))?;
    preflight::check_data(&BookData::of_book(root))?;

    let t = Instant::now();
    let all = artifacts(root);
    let generated = generate_keyed(
        &root.join("src").join("generated"),
        &root.join(CACHE_FILE),
        &all,
        opts.force,
        BookData::of_book(root).fingerprint(),
    )?;
    say(format!(
        "[1/3] generate: {} files from {} generators ({} written, {} unchanged, {} cached, {} stale removed) in {:.2} s",
        generated.total,
        all.len(),
        generated.written,
        generated.unchanged,
        generated.cached,
        generated.removed,
        t.elapsed().as_secs_f64()
    ));

    preflight::check_includes(&root.join("src"))?;
    let t = Instant::now();
    let Rendered { tmp, final_dir, chapters, coverage } = render_html(root, opts.no_solutions)?;
    if opts.no_solutions {
        solutions::strip_page_data(&tmp).inspect_err(|_| {
            let _ = fs::remove_dir_all(&tmp);
        })?;
    }
    let covered: Vec<String> = coverage
        .iter()
        .map(|(lang, c)| {
            format!("{lang} {:.1} % ({} of {})", c.percent(), c.translated, c.translated + c.untranslated.len())
        })
        .collect();
    say(format!(
        "[2/3] html: {} chapters in {} languages rendered with mdBook + KaTeX in {:.2} s; translated: {}",
        chapters,
        Lang::ALL.len(),
        t.elapsed().as_secs_f64(),
        covered.join(", ")
    ));

    let t = Instant::now();
    let index_rel = index_html_in(&tmp).inspect_err(|_| {
        let _ = fs::remove_dir_all(&tmp);
    })?;
    install(&tmp, &final_dir)?;
    let index_html = final_dir.join(index_rel);
    say(format!("[3/3] install: {} in {:.2} s", final_dir.display(), t.elapsed().as_secs_f64()));
    Ok(BuildReport { generated, chapters, index_html })
}

/// Name of the generate cache, relative to the book root.
const CACHE_FILE: &str = ".lightlab-cache";

/// Make `book/src/generated/` of the book at `root` current (cached as [`build`] does), for a
/// step that reads the chapters with their includes: `lightlab i18n extract` on a fresh
/// clone would otherwise miss every generated table's messages.
pub fn generate_for(root: &Path) -> Result<GenerateReport, BookError> {
    let _lock = crate::outfile::lock_dir(root, |message| eprintln!("lightlab: {message}"))?;
    let data = BookData::of_book(root).fingerprint();
    generate_keyed(&root.join("src").join("generated"), &root.join(CACHE_FILE), &artifacts(root), false, data)
}

/// Run the generators of `all` into `dir` (see the module docs for the cache).
pub fn generate(dir: &Path, cache_path: &Path, all: &[Artifact], force: bool) -> Result<GenerateReport, BookError> {
    generate_keyed(dir, cache_path, all, force, 0)
}

/// [`generate`] with the cache keyed on the executable and on `inputs`, a hash of the files
/// the generators read ([`BookData::fingerprint`]): after `lightlab study` rewrites a CSV,
/// every generator runs again instead of serving the old chart from the cache.
pub fn generate_keyed(
    dir: &Path,
    cache_path: &Path,
    all: &[Artifact],
    force: bool,
    inputs: u64,
) -> Result<GenerateReport, BookError> {
    check_paths(all)?;
    let exe = exe_hash().map(|h| h ^ inputs.rotate_left(1));
    let cache = match (&exe, force) {
        (Some(exe), false) => Cache::read(cache_path, *exe),
        _ => BTreeMap::new(),
    };
    let results: Vec<OneResult> = all.par_iter().map(|a| run_one(dir, a, &cache)).collect();

    let mut report = GenerateReport { total: all.iter().map(|a| a.paths().len()).sum(), ..GenerateReport::default() };
    let mut errors = Vec::new();
    let mut fresh = BTreeMap::new();
    for (a, result) in all.iter().zip(results) {
        match result {
            Ok(files) => {
                for (path, (outcome, hash)) in a.paths().iter().zip(files) {
                    fresh.insert(path.clone(), hash);
                    match outcome {
                        Outcome::Written => report.written += 1,
                        Outcome::Unchanged => report.unchanged += 1,
                        Outcome::Cached => report.cached += 1,
                    }
                }
            }
            Err(e) => errors.push(format!("  {}: {e}", a.paths().join(", "))),
        }
    }
    report.removed = remove_stale(dir, all)?;
    if let Some(exe) = exe {
        Cache::write(cache_path, exe, &fresh)?;
    }
    if errors.is_empty() {
        Ok(report)
    } else {
        Err(BookError::Generators { failed: errors.len(), total: all.len(), lines: errors })
    }
}

/// The outcome and final hash of each file of one artifact, or its error.
type OneResult = Result<Vec<(Outcome, u64)>, BoxError>;

/// What happened to one file.
enum Outcome {
    Written,
    Unchanged,
    Cached,
}

/// Run one artifact's generator unless the cache entry of every one of its files
/// matches the file on disk. Returns each file's outcome and the hash of its bytes.
fn run_one(dir: &Path, a: &Artifact, cache: &BTreeMap<String, u64>) -> OneResult {
    let old: Vec<Option<Vec<u8>>> = a.paths().iter().map(|p| fs::read(dir.join(p)).ok()).collect();
    let old_hashes: Vec<Option<u64>> = old.iter().map(|o| o.as_deref().map(hash64)).collect();
    let all_cached =
        a.paths().iter().zip(&old_hashes).all(|(p, h)| h.is_some() && cache.get(p.as_str()).copied() == *h);
    if all_cached {
        return Ok(old_hashes.into_iter().map(|h| (Outcome::Cached, h.unwrap_or_default())).collect());
    }
    let files = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| a.make()))
        .map_err(|p| format!("generator panicked: {}", crate::error::panic_text(&*p)))??;
    let mut out = Vec::with_capacity(files.len());
    for ((path, bytes), old) in a.paths().iter().zip(files).zip(old) {
        let hash = hash64(&bytes);
        if old.as_deref() == Some(bytes.as_slice()) {
            out.push((Outcome::Unchanged, hash));
        } else {
            write_atomic(&dir.join(path), &bytes)?;
            out.push((Outcome::Written, hash));
        }
    }
    Ok(out)
}

/// Delete files under `dir` that no artifact names (and directories left empty).
/// Returns how many files were deleted.
fn remove_stale(dir: &Path, all: &[Artifact]) -> Result<usize, BookError> {
    let keep: BTreeSet<PathBuf> = all.iter().flat_map(Artifact::paths).map(|p| dir.join(p)).collect();
    let mut removed = 0;
    for file in list_files(dir)? {
        if !keep.contains(&file) {
            fs::remove_file(&file).map_err(BookError::io("removing stale", &file))?;
            removed += 1;
        }
    }
    remove_empty_dirs(dir);
    Ok(removed)
}

/// All regular files under `dir`, recursively, sorted; empty when `dir` is missing.
pub fn list_files(dir: &Path) -> Result<Vec<PathBuf>, BookError> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = match fs::read_dir(&d) {
            Ok(e) => e,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(e) => return Err(BookError::io("reading", &d)(e)),
        };
        for entry in entries {
            let entry = entry.map_err(BookError::io("reading", &d))?;
            let path = entry.path();
            let kind = entry.file_type().map_err(BookError::io("reading the type of", &path))?;
            if kind.is_dir() {
                stack.push(path);
            } else if kind.is_file() {
                out.push(path);
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Remove the empty subdirectories of `dir` (best effort; `dir` itself stays).
fn remove_empty_dirs(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let path = entry.path();
        if path.is_dir() {
            remove_empty_dirs(&path);
            // Fails (and is meant to) when the directory is not empty.
            let _ = fs::remove_dir(&path);
        }
    }
}

/// Write `bytes` to `path` through a temporary file in the same directory, then
/// rename, so readers see the old file or the new one, never a part.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), BookError> {
    let parent = path.parent().ok_or_else(|| BookError::BadPath(path.to_path_buf(), "parent directory"))?;
    fs::create_dir_all(parent).map_err(BookError::io("creating", parent))?;
    let name = path.file_name().ok_or_else(|| BookError::BadPath(path.to_path_buf(), "file name"))?;
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(name);
    tmp_name.push(format!(".tmp{}", std::process::id()));
    let tmp = parent.join(tmp_name);
    let result = fs::File::create(&tmp)
        .and_then(|mut f| f.write_all(bytes).and_then(|_| f.sync_all()))
        .and_then(|_| fs::rename(&tmp, path));
    result.map_err(|e| {
        let _ = fs::remove_file(&tmp);
        BookError::io("writing", path)(e)
    })
}

/// A 64-bit hash of `bytes` (FxHash over 8-byte words, plus the length): fast enough
/// for a 50 MB executable, and stable across runs and Rust versions. Used only to
/// detect change, never for security.
fn hash64(bytes: &[u8]) -> u64 {
    const K: u64 = 0x517c_c1b7_2722_0a95;
    let mut h: u64 = bytes.len() as u64;
    let mut words = bytes.chunks_exact(8);
    for w in &mut words {
        let mut b = [0u8; 8];
        b.copy_from_slice(w);
        h = (h.rotate_left(5) ^ u64::from_le_bytes(b)).wrapping_mul(K);
    }
    for &b in words.remainder() {
        h = (h.rotate_left(5) ^ u64::from(b)).wrapping_mul(K);
    }
    h
}

/// Hash of the running executable, or `None` when it cannot be read (then nothing is
/// cached and every generator runs).
fn exe_hash() -> Option<u64> {
    let exe = std::env::current_exe().ok()?;
    fs::read(exe).ok().map(|b| hash64(&b))
}

/// The generate cache: line 1 `exe <hex>`, then one `<hex> <path>` line per file.
struct Cache;

impl Cache {
    /// Entries written by the executable with hash `exe`; empty on any mismatch or
    /// unreadable file.
    fn read(path: &Path, exe: u64) -> BTreeMap<String, u64> {
        let Ok(text) = fs::read_to_string(path) else {
            return BTreeMap::new();
        };
        let mut lines = text.lines();
        if lines.next() != Some(format!("exe {exe:016x}").as_str()) {
            return BTreeMap::new();
        }
        lines
            .filter_map(|l| {
                let (hash, path) = l.split_once(' ')?;
                Some((path.to_owned(), u64::from_str_radix(hash, 16).ok()?))
            })
            .collect()
    }

    fn write(path: &Path, exe: u64, entries: &BTreeMap<String, u64>) -> Result<(), BookError> {
        let mut text = format!("exe {exe:016x}\n");
        for (p, h) in entries {
            text.push_str(&format!("{h:016x} {p}\n"));
        }
        write_atomic(path, text.as_bytes())
    }
}

/// The book's configuration: `book.toml`, then the `MDBOOK_*` environment overrides
/// that mdBook itself applies (`MDBOOK_BOOK__TITLE` sets `book.title`; the value is
/// JSON or else a string). Unlike mdBook's own loader, a variable whose name or value
/// is not UTF-8 is skipped instead of aborting the process.
fn load_config(root: &Path) -> Result<mdbook_driver::config::Config, BookError> {
    let mdbook_err =
        |message: String| BookError::MdBook { what: "loading the book at", root: root.to_path_buf(), message };
    let mut config =
        mdbook_driver::config::Config::from_disk(root.join("book.toml")).map_err(|e| mdbook_err(format!("{e:#}")))?;
    for (key, value) in std::env::vars_os() {
        let (Some(key), Some(value)) = (key.to_str(), value.to_str()) else { continue };
        let Some(index) = mdbook_env_key(key) else { continue };
        let parsed = serde_json::from_str(value).unwrap_or_else(|_| serde_json::Value::String(value.to_owned()));
        config.set(index, parsed).map_err(|e| mdbook_err(format!("{e:#}")))?;
    }
    Ok(config)
}

/// The config index an `MDBOOK_*` variable overrides, as mdBook derives it
/// (`MDBOOK_BOOK__TEXT_DIRECTION` is `book.text-direction`), or `None` for other
/// names and for top-level tables mdBook does not let the environment set.
fn mdbook_env_key(name: &str) -> Option<String> {
    let index = name.strip_prefix("MDBOOK_")?.to_lowercase().replace("__", ".").replace('_', "-");
    let top = index.split('.').next().unwrap_or("");
    ["book", "build", "rust", "output", "preprocessor"].contains(&top).then_some(index)
}

/// The label of the language picker (translated through the PO files).
pub const LANGUAGE_LABEL: &str = "Language";

/// What [`render_html`] produced.
struct Rendered {
    /// The temporary directory holding the three books.
    tmp: PathBuf,
    /// The configured build directory, where [`install`] puts them.
    final_dir: PathBuf,
    /// Chapters per language.
    chapters: usize,
    /// What each translation's PO file covered.
    coverage: Vec<(Lang, Coverage)>,
}

/// Render the book at `root` in every language into a fresh temporary directory next to
/// the configured build directory: English at its top, each translation in `<code>/`.
fn render_html(root: &Path, no_solutions: bool) -> Result<Rendered, BookError> {
    let final_dir = root.join(&load_config(root)?.build.build_dir);
    let parent = final_dir.parent().ok_or_else(|| BookError::BadPath(final_dir.clone(), "parent directory"))?;
    remove_abandoned(parent);
    let tmp = parent.join(format!(".build-tmp-{}", std::process::id()));
    remove_dir_if_present(&tmp)?;
    let mut chapters = 0;
    let mut coverage = Vec::new();
    for lang in Lang::ALL {
        let out = if lang.is_translation() { tmp.join(lang.code()) } else { tmp.clone() };
        match render_language(root, lang, &out, no_solutions) {
            Ok((n, c)) => {
                chapters = chapters.max(n);
                if lang.is_translation() {
                    coverage.push((lang, c));
                }
            }
            Err(e) => {
                let _ = fs::remove_dir_all(&tmp);
                return Err(e);
            }
        }
    }
    if let Err(e) = languages::add_language_pickers(&tmp) {
        let _ = fs::remove_dir_all(&tmp);
        return Err(e);
    }
    Ok(Rendered { tmp, final_dir, chapters, coverage })
}

/// Render the book in `lang` into `out`: the config's language set (mdBook writes it into
/// `<html lang>`), the translating preprocessor after `links` (and after the solutions'
/// removal with `no_solutions`) and before KaTeX. Returns the chapter count and what the
/// PO file covered.
fn render_language(root: &Path, lang: Lang, out: &Path, no_solutions: bool) -> Result<(usize, Coverage), BookError> {
    let mdbook_err = |what, e: String| BookError::MdBook { what, root: root.to_path_buf(), message: e };
    let mut config = load_config(root)?;
    config.book.language = Some(lang.code().to_owned());
    if no_solutions {
        solutions::order(&mut config).map_err(|e| mdbook_err("configuring", format!("{e:#}")))?;
    }
    let mut md = mdbook_driver::MDBook::load_with_config(root, config)
        .map_err(|e| mdbook_err("loading the book at", format!("{e:#}")))?;
    let translate = Translate::new(lang, &crate::i18n::extract::po_dir(root))
        .map_err(|e| mdbook_err("loading the translation of", e.to_string()))?;
    let coverage = translate.coverage();
    let title = md.config.book.title.as_deref().and_then(|t| translate.title(t));
    md.with_preprocessor(crate::i18n::localize::Localize::new(lang));
    if no_solutions {
        md.with_preprocessor(solutions::StripSolutions);
    }
    md.with_preprocessor(translate);
    md.with_preprocessor(mdbook_katex::preprocess::KatexProcessor);
    if title.is_some() {
        md.config.book.title = title;
    }
    md.config.build.build_dir = out.to_path_buf();
    let chapters = md.iter().filter(|item| matches!(item, mdbook_driver::book::BookItem::Chapter(_))).count();
    md.build().map_err(|e| mdbook_err("mdBook build of", format!("{e:#}")))?;
    // mdBook copies all of src/: keep only this language's copies of the localized files
    for other in Lang::ALL.into_iter().filter(|o| o.is_translation() && *o != lang) {
        remove_dir_if_present(&out.join(crate::i18n::localize::GENERATED).join(other.code()))?;
    }
    copy_css_assets(root, &md.config, out)?;
    let covered = coverage.lock().unwrap_or_else(|e| e.into_inner()).clone();
    Ok((chapters, covered))
}

/// Copy every file that an `additional-css` style sheet names with a relative
/// `url(...)` from beside the source sheet to beside the output sheet (in `out`, or
/// in `out/html/` when several renderers are configured).
fn copy_css_assets(root: &Path, config: &mdbook_driver::config::Config, out: &Path) -> Result<(), BookError> {
    let html = config.html_config().unwrap_or_default();
    let out_html = if out.join("html").join("index.html").is_file() { out.join("html") } else { out.to_path_buf() };
    for css in &html.additional_css {
        let src = root.join(css);
        let text = fs::read_to_string(&src).map_err(BookError::io("reading additional-css", &src))?;
        let (src_dir, out_dir) = match (src.parent(), css.parent()) {
            (Some(s), Some(rel)) => (s.to_path_buf(), out_html.join(rel)),
            _ => continue,
        };
        for url in css_relative_urls(&text) {
            let from = src_dir.join(&url);
            let bytes = fs::read(&from).map_err(BookError::io("reading (named by a style sheet)", &from))?;
            write_atomic(&out_dir.join(&url), &bytes)?;
        }
    }
    Ok(())
}

/// The relative targets of `url(...)` in a style sheet, without query or fragment,
/// deduplicated and sorted. `data:` and absolute URLs are skipped.
pub fn css_relative_urls(css: &str) -> Vec<String> {
    let mut out = BTreeSet::new();
    for piece in css.split("url(").skip(1) {
        let Some(end) = piece.find(')') else { continue };
        let raw = piece[..end].trim().trim_matches(|c| c == '"' || c == '\'');
        let target = raw.split(['?', '#']).next().unwrap_or("");
        let absolute = target.contains(':') || target.starts_with('/') || target.is_empty();
        let escapes = Path::new(target).components().any(|c| !matches!(c, Component::Normal(_)));
        if !absolute && !escapes {
            out.insert(target.to_owned());
        }
    }
    out.into_iter().collect()
}

/// `index.html` relative to a rendered directory (`index.html` or `html/index.html`).
fn index_html_in(dir: &Path) -> Result<PathBuf, BookError> {
    ["index.html", "html/index.html"]
        .iter()
        .map(PathBuf::from)
        .find(|p| dir.join(p).is_file())
        .ok_or_else(|| BookError::NoIndex(dir.to_path_buf()))
}

/// Replace `final_dir` by `tmp`: rename the old one aside, rename the new one in,
/// then delete the old one. On failure the old book is put back.
fn install(tmp: &Path, final_dir: &Path) -> Result<(), BookError> {
    let parent = final_dir.parent().unwrap_or(Path::new("."));
    let old = parent.join(format!(".build-old-{}", std::process::id()));
    remove_dir_if_present(&old)?;
    let had_old = final_dir.exists();
    if had_old {
        fs::rename(final_dir, &old).map_err(BookError::io("moving aside", final_dir))?;
    }
    if let Err(e) = fs::rename(tmp, final_dir) {
        if had_old {
            let _ = fs::rename(&old, final_dir);
        }
        return Err(BookError::io("installing", final_dir)(e));
    }
    if had_old {
        remove_dir_if_present(&old)?;
    }
    Ok(())
}

/// Delete `.build-tmp-<pid>` and `.build-old-<pid>` directories in `dir` left by
/// builds that died (their process is gone). Only where `/proc` shows processes;
/// elsewhere they stay (they are git-ignored).
fn remove_abandoned(dir: &Path) {
    let proc_dir = Path::new("/proc/self");
    if !proc_dir.exists() {
        return;
    }
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let pid = name
            .strip_prefix(".build-tmp-")
            .or_else(|| name.strip_prefix(".build-old-"))
            .and_then(|p| p.parse::<u32>().ok());
        if let Some(pid) = pid {
            if !Path::new("/proc").join(pid.to_string()).exists() {
                let _ = fs::remove_dir_all(entry.path());
            }
        }
    }
}

fn remove_dir_if_present(dir: &Path) -> Result<(), BookError> {
    match fs::remove_dir_all(dir) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(BookError::io("removing", dir)(e)),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_paths_are_valid_and_unique() {
        check_paths(&artifacts(Path::new("book"))).unwrap();
    }

    #[test]
    fn css_urls() {
        let css = "@font-face{src:url(fonts/A.woff2) format(\"woff2\")}\
                   a{background:url('x.png?v=1')} b{background:url(data:image/png;base64,AA)}\
                   c{background:url(https://cdn.example/x.css)} d{background:url(../up.png)}";
        assert_eq!(css_relative_urls(css), vec!["fonts/A.woff2", "x.png"]);
    }

    #[test]
    fn hash_sees_every_byte() {
        assert_ne!(hash64(b"abcdefgh1"), hash64(b"abcdefgh2"));
        assert_ne!(hash64(b"abcdefgh"), hash64(b"bbcdefgh"));
        assert_ne!(hash64(b""), hash64(b"\0"));
    }

    #[test]
    fn generate_writes_caches_and_removes_stale() {
        let dir = crate::scratch::Scratch::new("gen");
        let gen = dir.join("generated");
        let cache = dir.join("cache");
        let all = [Artifact::file("t/one.txt", || Ok::<_, String>(b"one".to_vec()))];
        let first = generate(&gen, &cache, &all, false).unwrap();
        assert_eq!((first.written, first.cached), (1, 0));
        let second = generate(&gen, &cache, &all, false).unwrap();
        assert_eq!((second.written, second.cached), (0, 1));
        let forced = generate(&gen, &cache, &all, true).unwrap();
        assert_eq!((forced.unchanged, forced.cached), (1, 0));
        fs::write(gen.join("t/one.txt"), b"edited").unwrap();
        fs::write(gen.join("stale.txt"), b"old").unwrap();
        let repaired = generate(&gen, &cache, &all, false).unwrap();
        assert_eq!((repaired.written, repaired.removed), (1, 1));
        assert_eq!(fs::read(gen.join("t/one.txt")).unwrap(), b"one");
        let failing = [Artifact::file("bad.txt", || Err::<Vec<u8>, _>("no data".to_owned()))];
        let e = generate(&gen, &cache, &failing, false).unwrap_err().to_string();
        assert!(e.contains("bad.txt") && e.contains("no data"), "{e}");
    }

    #[test]
    fn one_run_writes_every_file_of_a_generator() {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static RUNS: AtomicUsize = AtomicUsize::new(0);
        let dir = crate::scratch::Scratch::new("gen-pair");
        let gen = dir.join("generated");
        let cache = dir.join("cache");
        let all = [Artifact::files(["p/image.bin", "p/caption.md"], || {
            RUNS.fetch_add(1, Ordering::SeqCst);
            Ok::<_, String>([b"image".to_vec(), b"caption".to_vec()])
        })];
        let first = generate(&gen, &cache, &all, false).unwrap();
        assert_eq!((first.total, first.written, RUNS.load(Ordering::SeqCst)), (2, 2, 1));
        assert_eq!(fs::read(gen.join("p/caption.md")).unwrap(), b"caption");
        // Deleting one of the two files reruns the generator once and rewrites only that file.
        fs::remove_file(gen.join("p/image.bin")).unwrap();
        let again = generate(&gen, &cache, &all, false).unwrap();
        assert_eq!((again.written, again.unchanged, again.cached, RUNS.load(Ordering::SeqCst)), (1, 1, 0, 2));
    }

    #[test]
    fn mdbook_env_keys_follow_mdbook() {
        assert_eq!(mdbook_env_key("MDBOOK_BOOK__TITLE").as_deref(), Some("book.title"));
        assert_eq!(mdbook_env_key("MDBOOK_BOOK__TEXT_DIRECTION").as_deref(), Some("book.text-direction"));
        assert_eq!(mdbook_env_key("MDBOOK_VERSION"), None);
        assert_eq!(mdbook_env_key("HOME"), None);
    }
}
