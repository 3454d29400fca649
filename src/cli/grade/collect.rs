//! Finding the submissions in a class folder, as classes hand them in, without reading
//! anything outside the folder.
//!
//! | in the folder | is |
//! | --- | --- |
//! | `alice.frag` (also `.glsl`, `.fs`) | one submission, a fragment shader |
//! | `alice.vert` (or `.vs`, or `alice.vert.glsl`) beside `alice.frag` (or `alice.frag.glsl`) | the same submission: the pair is checked together |
//! | `alice/` | one submission: the fragment shader inside (and its vertex shader, if any), found at any depth up to [`MAX_DEPTH`]; several candidates are an error row |
//! | `alice.txt` (numeric and choice exercises only) | one answer file |
//! | a symbolic link | followed only when its target, resolved, is inside the folder (inside the student's own folder, for a link in a student's folder); otherwise an error row, and the target is never opened |
//! | a FIFO, device or socket with a graded name | an error row; it is never opened |
//! | `.hidden` files, `__MACOSX/` (a Mac zip's resource forks) | skipped silently |
//! | anything else (`README.txt`, `notes.pdf`) | listed in the "not graded" note, never a row |
//!
//! A vertex shader is recognised by its extension (`.vert`, `.vs`), else by a part of its
//! name (`vertex.glsl`, `x.vert.glsl`, `x_vs.glsl`: the parts `vert`, `vs`, `vertex`),
//! else, when a student's folder holds two shaders that the names do not tell apart, by
//! its content: it writes `gl_Position`.

use super::texts;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Files with their names as shown in rows.
type Named = Vec<(String, PathBuf)>;

/// How deep a student's folder is searched (Moodle's "download as folders" adds one level).
pub const MAX_DEPTH: usize = 4;

/// Extensions of fragment shaders.
pub const FRAGMENT_EXTS: &[&str] = &["frag", "glsl", "fs"];
/// Extensions of vertex shaders.
pub const VERTEX_EXTS: &[&str] = &["vert", "vs"];
/// Extensions of answer files of numeric and choice exercises.
pub const ANSWER_EXTS: &[&str] = &["txt"];

/// One submission to check.
#[derive(Debug, Clone, PartialEq)]
pub struct Found {
    /// Its row name: `alice.frag`, `alice.frag + alice.vert`, `alice/`.
    pub name: String,
    /// The student: the file's stem or the folder's name.
    pub student: String,
    /// The fragment shader (or answer file), resolved inside the class folder; `Err` is
    /// the row's error when it cannot be graded.
    pub files: Result<(PathBuf, Option<PathBuf>), String>,
}

/// The submissions of a folder and the names left out.
#[derive(Debug, Default)]
pub struct Class {
    /// One per student, in name order.
    pub found: Vec<Found>,
    /// Files and folders that are not submissions (relative names).
    pub not_graded: Vec<String>,
}

/// What a directory entry is once links are resolved inside the root.
enum Kind {
    File(PathBuf),
    Dir(PathBuf),
    /// A FIFO, device or socket.
    Special,
    Outside,
    Broken(String),
}

/// Resolves `path` (an entry of a folder inside `root`, itself canonical).
fn kind(root: &Path, path: &Path) -> Kind {
    let target = match std::fs::canonicalize(path) {
        Ok(t) => t,
        Err(e) => return Kind::Broken(e.to_string()),
    };
    if !target.starts_with(root) {
        return Kind::Outside;
    }
    match std::fs::metadata(&target) {
        Ok(m) if m.is_file() => Kind::File(target),
        Ok(m) if m.is_dir() => Kind::Dir(target),
        Ok(_) => Kind::Special,
        Err(e) => Kind::Broken(e.to_string()),
    }
}

fn ext_of(name: &str) -> String {
    Path::new(name).extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default()
}

fn stem_of(name: &str) -> String {
    Path::new(name).file_stem().map_or_else(|| name.to_string(), |s| s.to_string_lossy().into_owned())
}

/// Whether `name` is graded for an exercise whose answers are shaders (`shader`) or text.
fn graded(name: &str, shader: bool) -> bool {
    let ext = ext_of(name);
    if shader {
        FRAGMENT_EXTS.contains(&ext.as_str()) || VERTEX_EXTS.contains(&ext.as_str())
    } else {
        ANSWER_EXTS.contains(&ext.as_str()) && !name.to_ascii_lowercase().starts_with("readme")
    }
}

/// Names skipped without a word: hidden files (`.DS_Store`, `._x`) and the `__MACOSX`
/// folder a Mac's zip adds beside the files.
pub fn skipped(name: &str) -> bool {
    name.starts_with('.') || name == "__MACOSX"
}

/// [`texts::FOLDER_UNREADABLE`] for `dir`.
pub(super) fn unreadable_folder(dir: &Path, e: &std::io::Error) -> String {
    texts::tr_fill(texts::FOLDER_UNREADABLE, &[&dir.display().to_string(), &e.to_string()])
}

fn entries(dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let mut v: Vec<(String, PathBuf)> = std::fs::read_dir(dir)
        .map_err(|e| unreadable_folder(dir, &e))?
        .filter_map(Result::ok)
        .map(|e| (e.file_name().to_string_lossy().into_owned(), e.path()))
        .filter(|(n, _)| !skipped(n))
        .collect();
    v.sort();
    Ok(v)
}

/// The words that name a vertex shader inside a file name (`vertex.glsl`, `x.vert.glsl`,
/// `x_vs.glsl`), and a fragment shader's.
const VERTEX_WORDS: &[&str] = &["vert", "vs", "vertex"];
const FRAGMENT_WORDS: &[&str] = &["frag", "fs", "fragment"];

/// The lower-case words of a file name before its extension, split at `.`, `_`, `-` and spaces.
fn name_words(name: &str) -> Vec<String> {
    let stem = stem_of(name).to_lowercase();
    stem.split(['.', '_', '-', ' ']).filter(|w| !w.is_empty()).map(String::from).collect()
}

/// Whether a graded shader file is a vertex shader by its name: a vertex extension, or a
/// shader extension with a vertex word in the name (and no fragment word).
pub fn is_vertex_name(name: &str) -> bool {
    if VERTEX_EXTS.contains(&ext_of(name).as_str()) {
        return true;
    }
    let words = name_words(name);
    words.iter().any(|w| VERTEX_WORDS.contains(&w.as_str()))
        && !words.iter().any(|w| FRAGMENT_WORDS.contains(&w.as_str()))
}

/// Whether a shader file is a fragment shader by its name: `.frag` or `.fs`, or a fragment
/// word in the name (and no vertex word). A `.glsl` file without such a word is neither.
pub fn is_fragment_name(name: &str) -> bool {
    if matches!(ext_of(name).as_str(), "frag" | "fs") {
        return true;
    }
    let words = name_words(name);
    words.iter().any(|w| FRAGMENT_WORDS.contains(&w.as_str()))
        && !words.iter().any(|w| VERTEX_WORDS.contains(&w.as_str()))
}

/// The student of a loose file: its stem, without a trailing `.vert`, `.frag`, `.vs`,
/// `.fs`, `.vertex` or `.fragment` (`frank.vert.glsl` and `frank.frag.glsl` are frank's pair).
fn loose_student(name: &str) -> String {
    let stem = stem_of(name);
    if let Some((head, last)) = stem.rsplit_once('.') {
        let last = last.to_lowercase();
        if !head.is_empty() && (VERTEX_WORDS.contains(&last.as_str()) || FRAGMENT_WORDS.contains(&last.as_str())) {
            return head.to_string();
        }
    }
    stem
}

/// Whether a shader's text writes `gl_Position` (a vertex shader does; a fragment shader
/// cannot). Reads at most 4 MiB, the limit of a submission.
fn writes_gl_position(path: &Path) -> bool {
    let Ok(bytes) = crate::cli::input::read_limited(path, crate::checker::check::MAX_SOURCE_BYTES) else {
        return false;
    };
    let text = String::from_utf8_lossy(&bytes);
    let mut rest: &str = &text;
    while let Some(k) = rest.find("gl_Position") {
        let after = rest[k + "gl_Position".len()..].trim_start();
        // `gl_Position = ...`, `gl_Position.xy = ...`: an assignment, not a comparison.
        let after = after.trim_start_matches(|c: char| c == '.' || c.is_ascii_alphabetic()).trim_start();
        if after.starts_with('=') && !after.starts_with("==") {
            return true;
        }
        rest = &rest[k + 1..];
    }
    false
}

/// The submissions in `dir` for an exercise whose answers are shaders (`shader`) or text
/// files. Errors: the folder itself cannot be read.
pub fn collect(dir: &Path, shader: bool) -> Result<Class, String> {
    let root = std::fs::canonicalize(dir).map_err(|e| unreadable_folder(dir, &e))?;
    let mut class = Class::default();
    // student -> (fragment candidates, vertex candidates, errors)
    let mut loose: BTreeMap<String, (Named, Named)> = BTreeMap::new();
    for (name, path) in entries(&root)? {
        match kind(&root, &path) {
            Kind::Outside => class.found.push(Found {
                name: name.clone(),
                student: stem_of(&name),
                files: Err(texts::tr(texts::ENTRY_OUTSIDE_CLASS)),
            }),
            // A link to the class folder itself would make one student of the whole class.
            Kind::Dir(d) if d == root => class.found.push(Found {
                name: format!("{name}/"),
                student: name.clone(),
                files: Err(texts::tr(texts::ENTRY_SELF_LINK)),
            }),
            Kind::Dir(d) => class.found.push(in_folder(&root, &d, &name, shader)),
            Kind::File(f) if graded(&name, shader) => {
                let slot = loose.entry(loose_student(&name)).or_default();
                if is_vertex_name(&name) {
                    slot.1.push((name, f));
                } else {
                    slot.0.push((name, f));
                }
            }
            Kind::Special if graded(&name, shader) => {
                let why = texts::tr_fill(texts::ENTRY_SPECIAL, &[&name]);
                class.found.push(Found { name: name.clone(), student: stem_of(&name), files: Err(why) })
            }
            Kind::Broken(why) if graded(&name, shader) => {
                let why = texts::tr_fill(texts::ENTRY_BROKEN, &[&name, &why]);
                class.found.push(Found { name: name.clone(), student: stem_of(&name), files: Err(why) })
            }
            Kind::Broken(_) | Kind::Special | Kind::File(_) => class.not_graded.push(name),
        }
    }
    for (student, (frags, verts)) in loose {
        class.found.push(assemble(student, &frags, &verts, None));
    }
    class.found.sort_by(|a, b| a.name.cmp(&b.name));
    Ok(class)
}

/// One submission from its candidates: one fragment shader and at most one vertex shader.
fn assemble(student: String, frags: &[(String, PathBuf)], verts: &[(String, PathBuf)], folder: Option<&str>) -> Found {
    let names = |v: &[(String, PathBuf)]| v.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>().join(", ");
    let name = match folder {
        Some(f) => format!("{f}/"),
        None => {
            let mut all: Vec<&str> = frags.iter().chain(verts).map(|(n, _)| n.as_str()).collect();
            all.sort();
            all.join(" + ")
        }
    };
    // Two shaders the names do not tell apart: the one that writes `gl_Position` is the
    // vertex shader.
    let (frags, verts): (Named, Named) = if frags.len() == 2 && verts.is_empty() {
        let (v, f): (Vec<_>, Vec<_>) = frags.iter().cloned().partition(|(_, p)| writes_gl_position(p));
        if v.len() == 1 {
            (f, v)
        } else {
            (frags.to_vec(), Vec::new())
        }
    } else {
        (frags.to_vec(), verts.to_vec())
    };
    let files = match (frags.as_slice(), verts.as_slice()) {
        ([], []) => Err(texts::tr(texts::FOLDER_NO_SHADER)),
        ([], _) => Err(texts::tr_fill(texts::FOLDER_VERTEX_ALONE, &[&names(&verts)])),
        ([(_, f)], []) => Ok((f.clone(), None)),
        ([(_, f)], [(_, v)]) => Ok((f.clone(), Some(v.clone()))),
        ([_], _) => Err(texts::tr_fill(texts::FOLDER_SEVERAL_VERTEX, &[&names(&verts)])),
        _ => Err(texts::tr_fill(texts::FOLDER_SEVERAL_FRAGMENT, &[&names(&frags)])),
    };
    Found { name, student, files }
}

/// How deep a folder skipped for being too deep is searched, to name the shader it hides
/// in the row's reason (a bound, so a link loop inside the folder ends).
const DEEPER_SEARCH: usize = 16;

/// A graded file somewhere under `dir` (links kept inside `student`), for the reason of
/// a folder that holds its shader too deep.
fn deeper(student: &Path, dir: &Path, prefix: &str, shader: bool, depth: usize) -> Option<String> {
    if depth > DEEPER_SEARCH {
        return None;
    }
    for (n, p) in entries(dir).ok()? {
        let shown = format!("{prefix}{n}");
        match kind(student, &p) {
            Kind::File(_) if graded(&n, shader) => return Some(shown),
            Kind::Dir(sub) => {
                if let Some(found) = deeper(student, &sub, &format!("{shown}/"), shader, depth + 1) {
                    return Some(found);
                }
            }
            _ => {}
        }
    }
    None
}

/// A student's folder: its graded files at any depth up to [`MAX_DEPTH`]. A link that
/// leads outside the student's own folder (`up -> ..` into the class) is refused.
fn in_folder(_root: &Path, dir: &Path, name: &str, shader: bool) -> Found {
    let (mut frags, mut verts) = (Vec::new(), Vec::new());
    let (mut too_deep, mut unreadable) = (Vec::new(), Vec::new());
    let mut stack = vec![(dir.to_path_buf(), String::new(), 0usize)];
    let refuse = |files: String| Found { name: format!("{name}/"), student: name.to_string(), files: Err(files) };
    while let Some((d, prefix, depth)) = stack.pop() {
        let list = match std::fs::read_dir(&d) {
            Ok(_) => entries(&d).unwrap_or_default(),
            Err(e) => {
                unreadable.push((format!("{name}/{prefix}"), e.to_string()));
                continue;
            }
        };
        for (n, p) in list {
            let shown = format!("{prefix}{n}");
            match kind(dir, &p) {
                Kind::Outside => return refuse(texts::tr_fill(texts::ENTRY_OUTSIDE, &[&shown])),
                Kind::Dir(sub) if depth + 1 < MAX_DEPTH => stack.push((sub, format!("{shown}/"), depth + 1)),
                Kind::Dir(sub) => too_deep.push((sub, format!("{shown}/"))),
                Kind::File(f) if graded(&n, shader) => {
                    if is_vertex_name(&n) {
                        verts.push((shown, f));
                    } else {
                        frags.push((shown, f));
                    }
                }
                Kind::Special if graded(&n, shader) => return refuse(texts::tr_fill(texts::ENTRY_SPECIAL, &[&shown])),
                Kind::Broken(why) if graded(&n, shader) => {
                    return refuse(texts::tr_fill(texts::ENTRY_BROKEN, &[&shown, &why]))
                }
                _ => {}
            }
        }
    }
    if frags.is_empty() && verts.is_empty() {
        if let Some((folder, why)) = unreadable.first() {
            return refuse(texts::tr_fill(texts::FOLDER_UNREADABLE, &[folder, why]));
        }
        for (sub, shown) in &too_deep {
            if let Some(found) = deeper(dir, sub, shown, shader, 0) {
                return refuse(texts::tr_fill(texts::FOUND_TOO_DEEP, &[&found, &MAX_DEPTH.to_string()]));
            }
        }
    }
    frags.sort();
    verts.sort();
    assemble(name.to_string(), &frags, &verts, Some(name))
}

/// Whether `name` matches the glob `pattern` (`*` any run of characters, `?` one
/// character; case-sensitive: [`super::assignment`] retries a pattern that names nothing
/// with case ignored).
pub fn glob_match(pattern: &str, name: &str) -> bool {
    let (p, n): (Vec<char>, Vec<char>) = (pattern.chars().collect(), name.chars().collect());
    let (mut i, mut j, mut star, mut mark) = (0usize, 0usize, None::<usize>, 0usize);
    while j < n.len() {
        if i < p.len() && (p[i] == '?' || p[i] == n[j]) {
            i += 1;
            j += 1;
        } else if i < p.len() && p[i] == '*' {
            star = Some(i);
            mark = j;
            i += 1;
        } else if let Some(s) = star {
            i = s + 1;
            mark += 1;
            j = mark;
        } else {
            return false;
        }
    }
    p[i..].iter().all(|&c| c == '*')
}

/// Every regular file inside the student folder `dir` (links resolved inside `dir`),
/// as (relative name, path); links that lead outside are returned in the error.
pub fn files_in(_root: &Path, dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let mut out = Vec::new();
    let mut stack = vec![(dir.to_path_buf(), String::new(), 0usize)];
    while let Some((d, prefix, depth)) = stack.pop() {
        for (n, p) in entries(&d)? {
            let shown = format!("{prefix}{n}");
            // Links stay inside the student's own folder (not only the class's).
            match kind(dir, &p) {
                Kind::Outside => return Err(texts::tr_fill(texts::ENTRY_OUTSIDE, &[&shown])),
                Kind::Dir(sub) if depth + 1 < MAX_DEPTH => stack.push((sub, format!("{shown}/"), depth + 1)),
                Kind::File(f) => out.push((shown, f)),
                _ => {}
            }
        }
    }
    out.sort();
    Ok(out)
}

/// Checks an assignment's `files` or `vertex` pattern: `*` and `?` within a name, `**`
/// for any number of folders, `/` between folders, `{a,b}` for alternatives (not nested).
/// Anything else a shell would read as syntax (`[`, `]`, `\\`, nested or unbalanced
/// braces), an empty pattern, a leading `/` and `..` are refused.
// String error: the caller adds the field and the line.
pub fn check_pattern(pattern: &str) -> Result<(), String> {
    if pattern.trim().is_empty() {
        return Err(texts::tr(texts::PATTERN_EMPTY));
    }
    if let Some(c) = pattern.chars().find(|c| matches!(c, '[' | ']' | '\\')) {
        return Err(texts::tr_fill(texts::PATTERN_UNSUPPORTED, &[&c.to_string()]));
    }
    if pattern.starts_with('/') || pattern.split('/').any(|s| s == ".." || s.is_empty()) {
        return Err(texts::tr(texts::PATTERN_OUTSIDE));
    }
    let mut depth = 0;
    for c in pattern.chars() {
        match c {
            '{' if depth > 0 => return Err(texts::tr(texts::PATTERN_NESTED)),
            '{' => depth += 1,
            '}' if depth == 0 => return Err(texts::tr(texts::PATTERN_UNOPENED)),
            '}' => depth -= 1,
            _ => {}
        }
    }
    if depth != 0 {
        return Err(texts::tr(texts::PATTERN_UNCLOSED));
    }
    Ok(())
}

/// The alternatives of a pattern's braces: `*.{fs,frag}` is `*.fs` and `*.frag`.
fn expand_braces(pattern: &str) -> Vec<String> {
    let (Some(open), Some(close)) = (pattern.find('{'), pattern.find('}')) else { return vec![pattern.to_string()] };
    if close < open {
        return vec![pattern.to_string()];
    }
    let (head, tail) = (&pattern[..open], &pattern[close + 1..]);
    pattern[open + 1..close].split(',').flat_map(|alt| expand_braces(&format!("{head}{alt}{tail}"))).collect()
}

fn segments_match(pattern: &[&str], path: &[&str]) -> bool {
    match pattern.split_first() {
        None => path.is_empty(),
        Some((&"**", rest)) => (0..=path.len()).any(|k| segments_match(rest, &path[k..])),
        Some((p, rest)) => {
            path.first().is_some_and(|name| glob_match(&p.replace("**", "*"), name)) && segments_match(rest, &path[1..])
        }
    }
}

/// Whether the path `rel` (relative to the student's folder, `/`-separated) matches an
/// assignment pattern ([`check_pattern`]): a pattern without `/` matches the file's name
/// at any depth (`*lighting*.frag`); one with `/` or `**` matches the whole relative path
/// (`src/*.frag`, `**/*.frag`, `**` matching zero or more folders).
pub fn pattern_match(pattern: &str, rel: &str) -> bool {
    let path: Vec<&str> = rel.split('/').collect();
    expand_braces(pattern).iter().any(|p| {
        if p.contains('/') || p.contains("**") {
            segments_match(&p.split('/').collect::<Vec<_>>(), &path)
        } else {
            glob_match(p, path.last().copied().unwrap_or(rel))
        }
    })
}

#[cfg(test)]
mod tests {
    use super::glob_match;

    #[test]
    fn globs_match_as_shells_do() {
        assert!(glob_match("*.frag", "alice.frag"));
        assert!(glob_match("spot*.frag", "spot_light.frag"));
        assert!(!glob_match("spot*.frag", "point.frag"));
        assert!(glob_match("a?c", "abc"));
        assert!(!glob_match("*.frag", "alice.vert"));
        assert!(glob_match("*", ""));
    }
}
