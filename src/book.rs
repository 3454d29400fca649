//! Build the book: generate every figure and table into `book/src/generated/`, then
//! render the HTML in-process with mdBook and KaTeX. `lightlab` with no subcommand
//! (or `lightlab book`) calls [`build`].
//!
//! # Adding a generated file
//!
//! A generated file is an [`Artifact`]: a path under `book/src/generated/` and a
//! function that returns its bytes. Topics keep their own list (for example
//! [`crate::figures::diagrams::artifacts`]); [`artifacts`] concatenates the lists, so a
//! new topic adds one line there and a new figure adds one line to its topic's list.
//! A chapter then shows it with `![alt](generated/<path>)` or includes it with
//! `{{#include generated/<path>}}`. `tests/book.rs` fails when a generated file is not
//! used by any chapter.
//!
//! Generators must be pure: their bytes may depend only on code compiled into the
//! binary (no clock, no unseeded randomness, no reading files that can change).
//!
//! # What [`build`] does
//!
//! 1. **generate**: runs the generators in parallel (rayon). Each file is written only
//!    when its bytes differ from the file on disk, through a temporary file renamed
//!    into place. A generator is skipped entirely when the cache file
//!    `book/.lightlab-cache` says the same executable already produced the file that is
//!    on disk now (the key is a 64-bit hash of the running executable's bytes, and the
//!    entry stores a hash of the file's bytes, so editing or deleting a generated file
//!    regenerates it). Files under `generated/` that no artifact names are deleted.
//! 2. **html**: `MDBook::load(root)` with the `KatexProcessor` of mdbook-katex run
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

/// One generated file of the book.
#[derive(Clone, Copy, Debug)]
pub struct Artifact {
    /// Relative path under `book/src/generated/`, with `/` separators, for example
    /// `"charts/specular-falloff.png"`. No `..`, no leading `/`.
    pub path: &'static str,
    /// Produces the file's bytes; an `Err` names what went wrong and fails the build.
    pub make: fn() -> Result<Vec<u8>, String>,
}

/// Every generated file of the book: the concatenation of each topic's list.
/// To add a topic, add one `all.extend(...)` line.
pub fn artifacts() -> Vec<Artifact> {
    let mut all = Vec::new();
    all.extend(crate::figures::diagrams::artifacts());
    all.extend(crate::figures::charts::artifacts());
    all.extend(crate::figures::tables_md::artifacts());
    all.extend(crate::figures::renders::artifacts());
    all.extend(crate::figures::study_charts::artifacts());
    all.extend(crate::live::artifacts());
    all
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
}

impl BuildOptions {
    /// Options for the book at `root`, cache on, progress printed.
    pub fn new(root: impl Into<PathBuf>) -> BuildOptions {
        BuildOptions { root: root.into(), force: false, quiet: false }
    }
}

/// What the generate stage did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct GenerateReport {
    /// Number of artifacts in the registry.
    pub total: usize,
    /// Files written because their bytes changed (or were missing).
    pub written: usize,
    /// Generators that ran and produced the bytes already on disk.
    pub unchanged: usize,
    /// Generators skipped because the cache showed the file up to date.
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

/// Generate the artifacts, render the HTML, and install it in the configured build
/// directory (`book/build/` by default). See the module docs for the stages.
///
/// Returns an error (never panics) when the root has no `book.toml`, an artifact path
/// is invalid or repeated, a generator fails (all failures are listed), mdBook fails,
/// or a file cannot be written.
pub fn build(opts: &BuildOptions) -> Result<BuildReport, String> {
    if !opts.root.join("book.toml").is_file() {
        return Err(format!("{} has no book.toml: pass the book directory with --root", opts.root.display()));
    }
    // Absolute, so that mdBook's `root.join(build_dir)` keeps our temporary path as is.
    let root = &opts.root.canonicalize().map_err(|e| format!("{}: {e}", opts.root.display()))?;
    let say = |line: String| {
        if !opts.quiet {
            eprintln!("{line}");
        }
    };

    let t = Instant::now();
    let all = artifacts();
    let generated = generate(&root.join("src").join("generated"), &root.join(CACHE_FILE), &all, opts.force)?;
    say(format!(
        "[1/3] generate: {} artifacts ({} written, {} unchanged, {} cached, {} stale removed) in {:.2} s",
        generated.total,
        generated.written,
        generated.unchanged,
        generated.cached,
        generated.removed,
        t.elapsed().as_secs_f64()
    ));

    let t = Instant::now();
    let (tmp, final_dir, chapters) = render_html(root)?;
    say(format!(
        "[2/3] html: {} chapters rendered with mdBook + KaTeX in {:.2} s",
        chapters,
        t.elapsed().as_secs_f64()
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

/// Run the generators of `all` into `dir` (see the module docs for the cache).
pub fn generate(dir: &Path, cache_path: &Path, all: &[Artifact], force: bool) -> Result<GenerateReport, String> {
    check_paths(all)?;
    let exe = exe_hash();
    let cache = match (&exe, force) {
        (Some(exe), false) => Cache::read(cache_path, *exe),
        _ => BTreeMap::new(),
    };
    let results: Vec<(usize, OneResult)> =
        all.par_iter().enumerate().map(|(i, a)| (i, run_one(dir, a, cache.get(a.path).copied()))).collect();

    let mut report = GenerateReport { total: all.len(), ..GenerateReport::default() };
    let mut errors = Vec::new();
    let mut fresh = BTreeMap::new();
    for (i, result) in results {
        match result {
            Ok((outcome, hash)) => {
                fresh.insert(all[i].path.to_owned(), hash);
                match outcome {
                    Outcome::Written => report.written += 1,
                    Outcome::Unchanged => report.unchanged += 1,
                    Outcome::Cached => report.cached += 1,
                }
            }
            Err(e) => errors.push(format!("  {}: {e}", all[i].path)),
        }
    }
    report.removed = remove_stale(dir, all)?;
    if let Some(exe) = exe {
        Cache::write(cache_path, exe, &fresh)?;
    }
    if errors.is_empty() {
        Ok(report)
    } else {
        Err(format!("{} of {} generators failed:\n{}", errors.len(), all.len(), errors.join("\n")))
    }
}

/// The outcome of one artifact and the hash of its final bytes, or its error.
type OneResult = Result<(Outcome, u64), String>;

/// What happened to one artifact.
enum Outcome {
    Written,
    Unchanged,
    Cached,
}

/// Generate one artifact unless the cache entry `cached_hash` matches the file on
/// disk. Returns the outcome and the hash of the file's final bytes.
fn run_one(dir: &Path, a: &Artifact, cached_hash: Option<u64>) -> OneResult {
    let path = dir.join(a.path);
    let old = fs::read(&path).ok();
    let old_hash = old.as_deref().map(hash64);
    if cached_hash.is_some() && cached_hash == old_hash {
        return Ok((Outcome::Cached, old_hash.unwrap_or_default()));
    }
    let bytes = std::panic::catch_unwind(a.make).map_err(|p| format!("generator panicked: {}", panic_text(&*p)))??;
    let hash = hash64(&bytes);
    if old.as_deref() == Some(bytes.as_slice()) {
        return Ok((Outcome::Unchanged, hash));
    }
    write_atomic(&path, &bytes)?;
    Ok((Outcome::Written, hash))
}

/// The message of a caught panic payload.
fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_owned()
    }
}

/// Reject empty, absolute, `..`-containing or repeated artifact paths.
fn check_paths(all: &[Artifact]) -> Result<(), String> {
    let mut seen = BTreeSet::new();
    for a in all {
        let p = Path::new(a.path);
        let plain = p.components().all(|c| matches!(c, Component::Normal(_)));
        if a.path.is_empty() || !plain || a.path.contains('\\') {
            return Err(format!("artifact path '{}' must be a relative path without '..'", a.path));
        }
        if !seen.insert(a.path) {
            return Err(format!("artifact path '{}' is registered twice", a.path));
        }
    }
    Ok(())
}

/// Delete files under `dir` that no artifact names (and directories left empty).
/// Returns how many files were deleted.
fn remove_stale(dir: &Path, all: &[Artifact]) -> Result<usize, String> {
    let keep: BTreeSet<PathBuf> = all.iter().map(|a| dir.join(a.path)).collect();
    let mut removed = 0;
    for file in list_files(dir)? {
        if !keep.contains(&file) {
            fs::remove_file(&file).map_err(|e| format!("removing stale {}: {e}", file.display()))?;
            removed += 1;
        }
    }
    remove_empty_dirs(dir);
    Ok(removed)
}

/// All regular files under `dir`, recursively, sorted; empty when `dir` is missing.
pub fn list_files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = match fs::read_dir(&d) {
            Ok(e) => e,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => continue,
            Err(e) => return Err(format!("reading {}: {e}", d.display())),
        };
        for entry in entries {
            let entry = entry.map_err(|e| format!("reading {}: {e}", d.display()))?;
            let path = entry.path();
            let kind = entry.file_type().map_err(|e| format!("{}: {e}", path.display()))?;
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
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let parent = path.parent().ok_or_else(|| format!("{} has no parent directory", path.display()))?;
    fs::create_dir_all(parent).map_err(|e| format!("creating {}: {e}", parent.display()))?;
    let name = path.file_name().ok_or_else(|| format!("{} has no file name", path.display()))?.to_string_lossy();
    let tmp = parent.join(format!(".{name}.tmp{}", std::process::id()));
    let result = fs::File::create(&tmp)
        .and_then(|mut f| f.write_all(bytes).and_then(|_| f.sync_all()))
        .and_then(|_| fs::rename(&tmp, path));
    result.map_err(|e| {
        let _ = fs::remove_file(&tmp);
        format!("writing {}: {e}", path.display())
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

/// The generate cache: line 1 `exe <hex>`, then one `<hex> <path>` line per artifact.
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

    fn write(path: &Path, exe: u64, entries: &BTreeMap<String, u64>) -> Result<(), String> {
        let mut text = format!("exe {exe:016x}\n");
        for (p, h) in entries {
            text.push_str(&format!("{h:016x} {p}\n"));
        }
        write_atomic(path, text.as_bytes())
    }
}

/// Render the book at `root` into a fresh temporary directory next to the configured
/// build directory. Returns `(temporary dir, configured build dir, chapter count)`.
fn render_html(root: &Path) -> Result<(PathBuf, PathBuf, usize), String> {
    let mut md =
        mdbook_driver::MDBook::load(root).map_err(|e| format!("loading the book at {}: {e:#}", root.display()))?;
    md.with_preprocessor(mdbook_katex::preprocess::KatexProcessor);
    let final_dir = root.join(&md.config.build.build_dir);
    let parent = final_dir.parent().ok_or_else(|| format!("build dir {} has no parent", final_dir.display()))?;
    remove_abandoned(parent);
    let tmp = parent.join(format!(".build-tmp-{}", std::process::id()));
    remove_dir_if_present(&tmp)?;
    md.config.build.build_dir = tmp.clone();
    let chapters = md.iter().filter(|item| matches!(item, mdbook_driver::book::BookItem::Chapter(_))).count();
    let built = md.build().map_err(|e| format!("mdBook build of {} failed: {e:#}", root.display()));
    if let Err(e) = built.and_then(|_| copy_css_assets(root, &md.config, &tmp)) {
        let _ = fs::remove_dir_all(&tmp);
        return Err(e);
    }
    Ok((tmp, final_dir, chapters))
}

/// Copy every file that an `additional-css` style sheet names with a relative
/// `url(...)` from beside the source sheet to beside the output sheet (in `out`, or
/// in `out/html/` when several renderers are configured).
fn copy_css_assets(root: &Path, config: &mdbook_driver::config::Config, out: &Path) -> Result<(), String> {
    let html = config.html_config().unwrap_or_default();
    let out_html = if out.join("html").join("index.html").is_file() { out.join("html") } else { out.to_path_buf() };
    for css in &html.additional_css {
        let src = root.join(css);
        let text = fs::read_to_string(&src).map_err(|e| format!("reading additional-css {}: {e}", src.display()))?;
        let (src_dir, out_dir) = match (src.parent(), css.parent()) {
            (Some(s), Some(rel)) => (s.to_path_buf(), out_html.join(rel)),
            _ => continue,
        };
        for url in css_relative_urls(&text) {
            let from = src_dir.join(&url);
            let bytes = fs::read(&from).map_err(|e| format!("{} names {url}: {e}", src.display()))?;
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
fn index_html_in(dir: &Path) -> Result<PathBuf, String> {
    ["index.html", "html/index.html"]
        .iter()
        .map(PathBuf::from)
        .find(|p| dir.join(p).is_file())
        .ok_or_else(|| format!("mdBook produced no index.html in {}", dir.display()))
}

/// Replace `final_dir` by `tmp`: rename the old one aside, rename the new one in,
/// then delete the old one. On failure the old book is put back.
fn install(tmp: &Path, final_dir: &Path) -> Result<(), String> {
    let parent = final_dir.parent().unwrap_or(Path::new("."));
    let old = parent.join(format!(".build-old-{}", std::process::id()));
    remove_dir_if_present(&old)?;
    let had_old = final_dir.exists();
    if had_old {
        fs::rename(final_dir, &old).map_err(|e| format!("moving {} aside: {e}", final_dir.display()))?;
    }
    if let Err(e) = fs::rename(tmp, final_dir) {
        if had_old {
            let _ = fs::rename(&old, final_dir);
        }
        return Err(format!("installing {}: {e}", final_dir.display()));
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

fn remove_dir_if_present(dir: &Path) -> Result<(), String> {
    match fs::remove_dir_all(dir) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(format!("removing {}: {e}", dir.display())),
        _ => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn registry_paths_are_valid_and_unique() {
        check_paths(&artifacts()).unwrap();
    }

    #[test]
    fn bad_paths_are_rejected() {
        let make = || Ok(Vec::new());
        for bad in ["", "../x.png", "/abs.png", "a/../b.png", "a\\b.png"] {
            let a = [Artifact { path: bad, make }];
            assert!(check_paths(&a).is_err(), "{bad:?} accepted");
        }
        let twice = [Artifact { path: "a.png", make }, Artifact { path: "a.png", make }];
        assert!(check_paths(&twice).unwrap_err().contains("twice"));
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
        let dir = std::env::temp_dir().join(format!("lightlab-gen-{}", std::process::id()));
        let _ = fs::remove_dir_all(&dir);
        let gen = dir.join("generated");
        let cache = dir.join("cache");
        let all = [Artifact { path: "t/one.txt", make: || Ok(b"one".to_vec()) }];
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
        let failing = [Artifact { path: "bad.txt", make: || Err("no data".to_owned()) }];
        let e = generate(&gen, &cache, &failing, false).unwrap_err();
        assert!(e.contains("bad.txt") && e.contains("no data"), "{e}");
        let _ = fs::remove_dir_all(&dir);
    }
}
