//! Finding the submissions in a class folder, as classes hand them in, without reading
//! anything outside the folder.
//!
//! | in the folder | is |
//! | --- | --- |
//! | `alice.frag` (also `.glsl`, `.fs`) | one submission, a fragment shader |
//! | `alice.vert` (or `.vs`) beside `alice.frag` | the same submission: the pair is checked together |
//! | `alice/` | one submission: the fragment shader inside (and its vertex shader, if any), found at any depth up to [`MAX_DEPTH`]; several candidates are an error row |
//! | `alice.txt` (numeric and choice exercises only) | one answer file |
//! | a symbolic link | followed only when its target, resolved, is inside the folder; otherwise an error row, and the target is never opened |
//! | a FIFO, device or socket with a graded name | an error row; it is never opened |
//! | `.hidden` files, anything else (`README.txt`, `notes.pdf`) | listed in the "not graded" note, never a row |

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
    Special(&'static str),
    Outside,
    Broken(String),
}

/// Resolves `path` (an entry of a folder inside `root`, itself canonical).
fn kind(root: &Path, path: &Path) -> Kind {
    let target = match std::fs::canonicalize(path) {
        Ok(t) => t,
        Err(e) => return Kind::Broken(format!("cannot be opened: {e}")),
    };
    if !target.starts_with(root) {
        return Kind::Outside;
    }
    match std::fs::metadata(&target) {
        Ok(m) if m.is_file() => Kind::File(target),
        Ok(m) if m.is_dir() => Kind::Dir(target),
        Ok(_) => Kind::Special("not a regular file (a FIFO, device or socket)"),
        Err(e) => Kind::Broken(format!("cannot be opened: {e}")),
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

const OUTSIDE: &str = "a symbolic link that leads outside the class folder: refused, not read";

fn entries(dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let mut v: Vec<(String, PathBuf)> = std::fs::read_dir(dir)
        .map_err(|e| format!("cannot read directory {}: {e}", dir.display()))?
        .filter_map(Result::ok)
        .map(|e| (e.file_name().to_string_lossy().into_owned(), e.path()))
        .filter(|(n, _)| !n.starts_with('.'))
        .collect();
    v.sort();
    Ok(v)
}

/// The submissions in `dir` for an exercise whose answers are shaders (`shader`) or text
/// files. Errors: the folder itself cannot be read.
pub fn collect(dir: &Path, shader: bool) -> Result<Class, String> {
    let root = std::fs::canonicalize(dir).map_err(|e| format!("cannot read directory {}: {e}", dir.display()))?;
    let mut class = Class::default();
    // student -> (fragment candidates, vertex candidates, errors)
    let mut loose: BTreeMap<String, (Named, Named)> = BTreeMap::new();
    for (name, path) in entries(&root)? {
        match kind(&root, &path) {
            Kind::Outside => {
                class.found.push(Found { name: name.clone(), student: stem_of(&name), files: Err(OUTSIDE.into()) })
            }
            Kind::Dir(d) => class.found.push(in_folder(&root, &d, &name, shader)),
            Kind::File(f) if graded(&name, shader) => {
                let slot = loose.entry(stem_of(&name)).or_default();
                if VERTEX_EXTS.contains(&ext_of(&name).as_str()) {
                    slot.1.push((name, f));
                } else {
                    slot.0.push((name, f));
                }
            }
            Kind::Special(why) if graded(&name, shader) => {
                class.found.push(Found { name: name.clone(), student: stem_of(&name), files: Err(why.to_string()) })
            }
            Kind::Broken(why) if graded(&name, shader) => {
                class.found.push(Found { name: name.clone(), student: stem_of(&name), files: Err(why) })
            }
            Kind::Broken(_) | Kind::Special(_) | Kind::File(_) => class.not_graded.push(name),
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
    let files = match (frags, verts) {
        ([], []) => Err("no fragment shader (.frag, .glsl, .fs) or answer file (.txt) in it".to_string()),
        ([], _) => Err(format!("a vertex shader alone ({}): hand in its fragment shader beside it", names(verts))),
        ([(_, f)], []) => Ok((f.clone(), None)),
        ([(_, f)], [(_, v)]) => Ok((f.clone(), Some(v.clone()))),
        ([_], _) => Err(format!("several vertex shaders ({}): keep one", names(verts))),
        _ => Err(format!("several candidate files ({}): keep one", names(frags))),
    };
    Found { name, student, files }
}

/// A student's folder: its graded files at any depth up to [`MAX_DEPTH`].
fn in_folder(root: &Path, dir: &Path, name: &str, shader: bool) -> Found {
    let (mut frags, mut verts) = (Vec::new(), Vec::new());
    let mut stack = vec![(dir.to_path_buf(), String::new(), 0usize)];
    while let Some((d, prefix, depth)) = stack.pop() {
        let Ok(list) = entries(&d) else { continue };
        for (n, p) in list {
            let shown = format!("{prefix}{n}");
            match kind(root, &p) {
                Kind::Outside => {
                    return Found {
                        name: format!("{name}/"),
                        student: name.to_string(),
                        files: Err(format!("{shown} is {OUTSIDE}")),
                    }
                }
                Kind::Dir(sub) if depth + 1 < MAX_DEPTH => stack.push((sub, format!("{shown}/"), depth + 1)),
                Kind::File(f) if graded(&n, shader) => {
                    if VERTEX_EXTS.contains(&ext_of(&n).as_str()) {
                        verts.push((shown, f));
                    } else {
                        frags.push((shown, f));
                    }
                }
                Kind::Special(why) if graded(&n, shader) => {
                    return Found {
                        name: format!("{name}/"),
                        student: name.to_string(),
                        files: Err(format!("{shown}: {why}")),
                    }
                }
                _ => {}
            }
        }
    }
    frags.sort();
    verts.sort();
    assemble(name.to_string(), &frags, &verts, Some(name))
}

/// Whether `name` matches the glob `pattern` (`*` any run of characters, `?` one
/// character; case-sensitive, as file systems are).
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

/// Every regular file inside the student folder `dir` (links resolved inside `root`),
/// as (relative name, path); links that lead outside are returned in the error.
pub fn files_in(root: &Path, dir: &Path) -> Result<Vec<(String, PathBuf)>, String> {
    let mut out = Vec::new();
    let mut stack = vec![(dir.to_path_buf(), String::new(), 0usize)];
    while let Some((d, prefix, depth)) = stack.pop() {
        for (n, p) in entries(&d)? {
            let shown = format!("{prefix}{n}");
            match kind(root, &p) {
                Kind::Outside => return Err(format!("{shown} is {OUTSIDE}")),
                Kind::Dir(sub) if depth + 1 < MAX_DEPTH => stack.push((sub, format!("{shown}/"), depth + 1)),
                Kind::File(f) => out.push((shown, f)),
                _ => {}
            }
        }
    }
    out.sort();
    Ok(out)
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
