//! The assignment file (`grade --assignment FILE.toml`): several exercises, their
//! weights, which files answer each, and the partial credit.
//!
//! ```toml
//! title = "Lab 2: lighting"          # optional, shown in reports
//! lang = "uk"                        # optional: the feedback's language, en, fr or uk
//!                                    # (`--lang` on the command line wins)
//!
//! [[exercise]]
//! id = "basic-move-light"            # an id of `lightlab exercise list`
//! weight = 40                        # points (default 100)
//! files = "basic*.frag"              # pattern of its file in a student's folder (default: any fragment shader)
//! vertex = "basic*.vert"             # optional: its vertex shader, checked as a pair
//! partial = "cases"                  # "cases" (default), "none", or a number 0..=100
//!
//! [exercise.mistakes]                # credit for a named mistake, 0..=100, over `partial`
//! blinn-for-phong = 50
//! ```
//!
//! With one exercise the class folder may hold a file per student; with several, each
//! student is a folder and `files` picks the answer to each exercise in it. A malformed
//! file is an error that names the field and the line.
//!
//! Patterns ([`collect::check_pattern`]): `*` any run of characters and `?` one, within a
//! name; without `/` the pattern matches a file's name at any depth (`*lighting*.frag`);
//! with `/` or `**` it matches the path from the student's folder (`src/*.frag`,
//! `**/*.frag`, `**` being zero or more folders); `{fs,frag}` gives alternatives.
//! A pattern that names no file is tried again with case ignored (`Lighting.FRAG`). Other
//! syntax (`[abc]`) is refused.

use std::path::Path;

use serde::Deserialize;

use super::collect::{self, check_pattern, pattern_match};
use super::run::Job;
use super::texts::{self as t, tr, tr_fill};
use super::{Row, Total};
use crate::exercises::Exercise;

/// Partial credit of a shader that disagrees.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Policy {
    /// Credit by catalogue mistake id (the diagnosis's first, best finding), 0 to 100.
    pub mistakes: Vec<(String, u32)>,
    /// Credit otherwise.
    pub partial: Partial,
}

/// Credit of a disagreeing shader whose mistake has no credit of its own.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Partial {
    /// `floor(90 × passing / defined)` (the default; reason in [`super`]'s docs).
    #[default]
    Cases,
    /// 0.
    Nothing,
    /// A fixed credit.
    Fixed(u32),
}

impl Policy {
    /// The score of a row, 0 to 100 (see [`super`]'s docs).
    pub fn score(&self, row: &Row) -> u32 {
        if row.agrees {
            return 100;
        }
        if row.verdict != "disagrees" {
            return 0;
        }
        if let Some(first) = row.diagnosis.first() {
            if let Some((_, credit)) = self.mistakes.iter().find(|(id, _)| *id == first.id) {
                return *credit;
            }
        }
        match self.partial {
            Partial::Nothing => 0,
            Partial::Fixed(p) => p,
            Partial::Cases => match (row.defined, row.failing) {
                (Some(defined), Some(failing)) if defined > 0 => {
                    (90 * (defined - failing.min(defined)) / defined) as u32
                }
                _ => 0,
            },
        }
    }
}

/// One exercise of an assignment.
#[derive(Debug, Clone)]
pub struct Item {
    /// The exercise.
    pub exercise: &'static Exercise,
    /// Its points.
    pub weight: f64,
    /// Glob of its answer file in a student's folder (`None`: the one fragment shader).
    pub files: Option<String>,
    /// Glob of its vertex shader.
    pub vertex: Option<String>,
    /// Its partial credit.
    pub policy: Policy,
}

/// An assignment: its exercises.
#[derive(Debug, Clone)]
pub struct Assignment {
    /// The exercises, in the file's order.
    pub exercises: Vec<Item>,
    /// The class's language (`lang = "uk"`), when the file sets one.
    pub lang: Option<crate::i18n::Lang>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileToml {
    #[allow(dead_code)]
    title: Option<String>,
    lang: Option<toml::Spanned<String>>,
    exercise: Vec<toml::Spanned<ItemToml>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ItemToml {
    id: toml::Spanned<String>,
    weight: Option<toml::Spanned<f64>>,
    files: Option<toml::Spanned<String>>,
    vertex: Option<toml::Spanned<String>>,
    partial: Option<toml::Spanned<toml::Value>>,
    #[serde(default)]
    mistakes: std::collections::BTreeMap<String, toml::Spanned<toml::Value>>,
}

/// [`t::AT_LINE`]: `why` at `line` of the file.
fn at_line(line: usize, why: &str) -> String {
    tr_fill(t::AT_LINE, &[&line.to_string(), why])
}

/// [`at_line`] for one field of the file (`exercise.weight`, written as in the file).
fn at_field(line: usize, field: &str, why: &str) -> String {
    at_line(line, &tr_fill(t::AT_FIELD, &[field, why]))
}

fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].matches('\n').count() + 1
}

/// A file of a student's folder: its path from the folder (`src/lighting.frag`) and on disk.
type Hit = (String, std::path::PathBuf);

/// The one file of `hits` that a pattern (`glob`) picks, `None` for none, or an error
/// naming them all.
fn one_of(hits: Vec<Hit>, glob: &str) -> Result<Option<Hit>, String> {
    match hits.as_slice() {
        [] => Ok(None),
        [_] => Ok(hits.into_iter().next()),
        many => {
            let names = many.iter().map(|(n, _)| n.as_str()).collect::<Vec<_>>().join(", ");
            Err(super::texts::tr_fill(super::texts::PATTERN_SEVERAL, &[glob, &names]))
        }
    }
}

/// When several files match, keeps those whose name satisfies `wanted`, unless none does.
/// A fragment pattern such as `*lighting*` names the pair `lighting.vert` + `lighting.frag`,
/// and the fragment shader is its answer; a vertex pattern the other way round.
fn prefer(hits: Vec<Hit>, wanted: impl Fn(&str) -> bool) -> Vec<Hit> {
    if hits.len() < 2 {
        return hits;
    }
    let kept: Vec<Hit> = hits.iter().filter(|(n, _)| wanted(n)).cloned().collect();
    if kept.is_empty() {
        hits
    } else {
        kept
    }
}

/// The files `glob` names; when it names none, those it names with case ignored
/// (`Lighting.FRAG` for `*lighting*.frag`: students on Windows and macOS capitalise as
/// they like, and their file systems do not mind).
fn matching(files: &[Hit], glob: &str) -> Vec<Hit> {
    let exact: Vec<Hit> = files.iter().filter(|(n, _)| pattern_match(glob, n)).cloned().collect();
    if !exact.is_empty() {
        return exact;
    }
    let glob = glob.to_lowercase();
    files.iter().filter(|(n, _)| pattern_match(&glob, &n.to_lowercase())).cloned().collect()
}

/// What an exercise's patterns pick in one student's `files`: the row's name (`src/x.frag`,
/// or `src/x.frag + src/x.vert`), the fragment shader and the vertex shader; or the row's
/// error in the class language (nothing matches, several match, both patterns pick one file).
fn pick(files: &[Hit], item: &Item) -> Result<(String, std::path::PathBuf, Option<std::path::PathBuf>), String> {
    use super::texts::{tr_fill, PATTERN_NO_MATCH, PATTERN_NO_MATCH_VERTEX, PATTERN_SAME_FILE};
    // A vertex pattern never picks a fragment shader by name (`*lighting*` in a folder
    // with `lighting.frag` alone: the vertex shader is not handed in).
    let vertex = match item.vertex.as_deref() {
        Some(glob) => {
            let hits = matching(files, glob).into_iter().filter(|(n, _)| !collect::is_fragment_name(n)).collect();
            one_of(prefer(hits, collect::is_vertex_name), glob)?
        }
        None => None,
    };
    let glob = item.files.as_deref().unwrap_or("*.frag");
    let hits = matching(files, glob);
    let picked_vertex = vertex.as_ref().map(|(n, _)| n.as_str());
    let rest: Vec<Hit> = hits.iter().filter(|(n, _)| Some(n.as_str()) != picked_vertex).cloned().collect();
    if let (true, false, Some(both)) = (rest.is_empty(), hits.is_empty(), picked_vertex) {
        return Err(tr_fill(PATTERN_SAME_FILE, &[both]));
    }
    let Some((name, fragment)) = one_of(prefer(rest, |n| !collect::is_vertex_name(n)), glob)? else {
        return Err(tr_fill(PATTERN_NO_MATCH, &[glob]));
    };
    match (vertex, item.vertex.as_deref()) {
        (Some((vname, v)), _) => Ok((format!("{name} + {vname}"), fragment, Some(v))),
        (None, Some(vglob)) => Err(tr_fill(PATTERN_NO_MATCH_VERTEX, &[vglob])),
        (None, None) => Ok((name, fragment, None)),
    }
}

/// Why `vertex` (a pattern, or `None`) does not suit `exercise`: a pair exercise needs its
/// vertex shader picked, and only a shader exercise takes one.
/// `option` names the field as the teacher wrote it (`--vertex`, `exercise.vertex`).
fn vertex_misfit(exercise: &Exercise, vertex: Option<&str>, option: &str) -> Option<String> {
    use crate::exercises::Check;
    match (exercise.check, vertex) {
        (Check::Pair { .. }, None) => Some(tr_fill(t::PAIR_NEEDS_VERTEX, &[exercise.id, option])),
        (Check::Shader { .. } | Check::Pair { .. }, _) | (_, None) => None,
        (_, Some(_)) => Some(tr_fill(t::TAKES_NO_VERTEX, &[option, exercise.id])),
    }
}

impl Assignment {
    /// One exercise, weight 100, every submission answers it.
    pub fn single(exercise: &'static Exercise) -> Assignment {
        Assignment {
            exercises: vec![Item { exercise, weight: 100.0, files: None, vertex: None, policy: Policy::default() }],
            lang: None,
        }
    }

    /// One exercise, weight 100, its answer picked in each student's folder by `files` and
    /// `vertex` (`grade --exercise ID --files PATTERN`); without either, [`Self::single`].
    // String error: printed as a usage error, naming the option.
    pub fn single_with(
        exercise: &'static Exercise,
        files: Option<String>,
        vertex: Option<String>,
    ) -> Result<Assignment, String> {
        for (option, pattern) in [("--files", &files), ("--vertex", &vertex)] {
            if let Some(p) = pattern {
                check_pattern(p).map_err(|e| format!("{option} `{p}`: {e}"))?;
            }
        }
        if vertex.is_some() && files.is_none() {
            return Err(tr(t::VERTEX_NEEDS_FILES));
        }
        if files.is_some() {
            if let Some(e) = vertex_misfit(exercise, vertex.as_deref(), "--vertex") {
                return Err(e);
            }
        }
        let mut a = Assignment::single(exercise);
        a.exercises[0].files = files;
        a.exercises[0].vertex = vertex;
        Ok(a)
    }

    // String error: printed as a usage error, naming the file, the field and the line.
    /// Reads an assignment file.
    pub fn read(path: &Path) -> Result<Assignment, String> {
        let at_file = |e: &str| tr_fill(t::ASSIGNMENT_FILE, &[&path.display().to_string(), e]);
        let bytes = crate::cli::input::read_limited(path, 1 << 20).map_err(|e| at_file(&e))?;
        let text = String::from_utf8(bytes).map_err(|_| at_file(&tr(t::NOT_UTF8)))?;
        Assignment::parse(&text).map_err(|e| at_file(&e))
    }

    // String error: the caller adds the file's name.
    /// Parses an assignment's TOML text.
    pub fn parse(text: &str) -> Result<Assignment, String> {
        let file: FileToml = toml::from_str(text).map_err(|e| {
            // toml's message names the type, not always the key: show the line itself.
            let at = e.span().map(|s| {
                let line = line_of(text, s.start);
                let shown = text.lines().nth(line - 1).unwrap_or("").trim();
                (line, shown)
            });
            match at {
                Some((line, shown)) => tr_fill(t::AT_LINE_SHOWN, &[&line.to_string(), shown, e.message().trim_end()]),
                None => e.message().trim_end().to_string(),
            }
        })?;
        if file.exercise.is_empty() {
            return Err(tr(t::NO_EXERCISE));
        }
        let lang = match &file.lang {
            None => None,
            Some(l) => Some(
                l.get_ref()
                    .parse::<crate::i18n::Lang>()
                    .map_err(|e| at_field(line_of(text, l.span().start), "lang", &e.to_string()))?,
            ),
        };
        let mut exercises: Vec<Item> = Vec::new();
        let mut seen: Vec<(&str, usize)> = Vec::new();
        for item in &file.exercise {
            let line = line_of(text, item.span().start);
            let item = item.get_ref();
            let id_line = line_of(text, item.id.span().start);
            if let Some((_, first)) = seen.iter().find(|(id, _)| *id == item.id.get_ref().as_str()) {
                let why = tr_fill(t::LISTED_TWICE, &[item.id.get_ref(), &first.to_string()]);
                return Err(at_field(id_line, "exercise.id", &why));
            }
            seen.push((item.id.get_ref().as_str(), id_line));
            let exercise = Exercise::by_id(item.id.get_ref()).ok_or_else(|| {
                let why = super::super::exercise::find(item.id.get_ref()).err().unwrap_or_default();
                at_field(id_line, "exercise.id", &why)
            })?;
            let weight = item.weight.as_ref().map_or(100.0, |w| *w.get_ref());
            if !(weight.is_finite() && weight >= 0.0) {
                let at = item.weight.as_ref().map_or(line, |w| line_of(text, w.span().start));
                return Err(at_field(at, "exercise.weight", &tr_fill(t::NOT_POINTS, &[&weight.to_string()])));
            }
            for (field, pattern) in [("files", &item.files), ("vertex", &item.vertex)] {
                if let Some(p) = pattern {
                    check_pattern(p.get_ref()).map_err(|e| {
                        at_field(
                            line_of(text, p.span().start),
                            &format!("exercise.{field}"),
                            &tr_fill(t::AT_FIELD, &[&format!("`{}`", p.get_ref()), &e]),
                        )
                    })?;
                }
            }
            let vertex_line = item.vertex.as_ref().map_or(line, |v| line_of(text, v.span().start));
            let vertex = item.vertex.as_ref().map(|v| v.get_ref().as_str());
            if let Some(e) = vertex_misfit(exercise, vertex, "exercise.vertex") {
                return Err(at_line(vertex_line, &e));
            }
            let partial = match &item.partial {
                None => Partial::Cases,
                Some(v) => {
                    let l = line_of(text, v.span().start);
                    match v.get_ref() {
                        toml::Value::String(s) if s == "cases" => Partial::Cases,
                        toml::Value::String(s) if s == "none" => Partial::Nothing,
                        toml::Value::Integer(p) if (0..=100).contains(p) => Partial::Fixed(*p as u32),
                        other => {
                            let why = tr_fill(t::BAD_PARTIAL, &[&other.to_string()]);
                            return Err(at_field(l, "exercise.partial", &why));
                        }
                    }
                }
            };
            let mut mistakes = Vec::new();
            for (id, credit) in &item.mistakes {
                let at = line_of(text, credit.span().start);
                let credit = credit.get_ref();
                let credit = credit.as_integer().filter(|c| (0..=100).contains(c)).ok_or_else(|| {
                    at_field(at, &format!("exercise.mistakes.{id}"), &tr_fill(t::BAD_CREDIT, &[&credit.to_string()]))
                })?;
                let Some(mistake) = crate::checker::mistakes::Mistake::by_id(id) else {
                    return Err(at_field(at, &format!("exercise.mistakes.{id}"), &tr(t::NO_SUCH_MISTAKE)));
                };
                // A credit for a mistake the exercise's check can never name would never be given.
                match exercise.model() {
                    Some(model) if mistake.applies_to(model) => {}
                    Some(model) => {
                        let ids = crate::checker::mistakes::for_model(model).iter().map(|m| m.id).collect::<Vec<_>>();
                        let why = tr_fill(t::NOT_MISTAKE_OF, &[exercise.id, &model.to_string(), &ids.join(", ")]);
                        return Err(at_field(at, &format!("exercise.mistakes.{id}"), &why));
                    }
                    None => {
                        let why = tr_fill(t::NO_NAMED_MISTAKES, &[exercise.id]);
                        return Err(at_field(at, &format!("exercise.mistakes.{id}"), &why));
                    }
                }
                mistakes.push((id.clone(), credit as u32));
            }
            exercises.push(Item {
                exercise,
                weight,
                files: item.files.as_ref().map(|f| f.get_ref().clone()),
                vertex: item.vertex.as_ref().map(|f| f.get_ref().clone()),
                policy: Policy { mistakes, partial },
            });
        }
        Ok(Assignment { exercises, lang })
    }

    /// The checks to run on `dir`, and the names not graded. With one exercise and no
    /// `files` glob: [`collect::collect`]'s submissions. Otherwise each sub-folder is a
    /// student (or `dir` itself when `one`, the Gradescope and PrairieLearn case), and
    /// each exercise's glob picks its file.
    // String error: printed as a usage error.
    pub fn jobs(&self, dir: &Path, one: bool) -> Result<(Vec<Job>, Vec<String>), String> {
        if let [item] = self.exercises.as_slice() {
            if item.files.is_none() {
                let shader = crate::cli::exercise::needs_gl(item.exercise);
                let class = collect::collect(dir, shader)?;
                let jobs = class
                    .found
                    .iter()
                    .map(|f| Job {
                        file: f.name.clone(),
                        student: f.student.clone(),
                        page: String::new(),
                        exercise: item.exercise,
                        files: f.files.clone(),
                    })
                    .collect();
                return Ok((jobs, class.not_graded));
            }
        }
        let root = std::fs::canonicalize(dir).map_err(|e| collect::unreadable_folder(dir, &e))?;
        let mut students: Vec<(String, std::path::PathBuf)> = Vec::new();
        let mut not_graded = Vec::new();
        if one {
            let name = root.file_name().map_or_else(|| "submission".into(), |n| n.to_string_lossy().into_owned());
            students.push((name, root.clone()));
        } else {
            let mut list: Vec<_> = std::fs::read_dir(&root)
                .map_err(|e| collect::unreadable_folder(dir, &e))?
                .filter_map(Result::ok)
                .map(|e| (e.file_name().to_string_lossy().into_owned(), e.path()))
                .filter(|(n, _)| !collect::skipped(n))
                .collect();
            list.sort();
            for (n, p) in list {
                match std::fs::canonicalize(&p) {
                    Ok(t) if t.starts_with(&root) && t.is_dir() => students.push((n, t)),
                    _ => not_graded.push(n),
                }
            }
        }
        let mut jobs = Vec::new();
        for (student, folder) in &students {
            let files = collect::files_in(&root, folder);
            for item in &self.exercises {
                let picked = files.as_ref().map_err(Clone::clone).and_then(|files| pick(files, item));
                let (file, files) = match picked {
                    Ok((name, fragment, vertex)) => (format!("{student}/{name}"), Ok((fragment, vertex))),
                    Err(e) => (format!("{student}/"), Err(e)),
                };
                jobs.push(Job { file, student: student.clone(), page: String::new(), exercise: item.exercise, files });
            }
        }
        Ok((jobs, not_graded))
    }

    /// Each student's points: Σ weight × score / 100 over the assignment's exercises.
    pub fn totals(&self, rows: &[Row]) -> Vec<Total> {
        let mut totals: Vec<Total> = Vec::new();
        let max_points: f64 = self.exercises.iter().map(|e| e.weight).sum();
        for row in rows {
            let weight = self.exercises.iter().find(|e| e.exercise.id == row.exercise).map_or(0.0, |e| e.weight);
            let points = weight * f64::from(row.score) / 100.0;
            match totals.iter_mut().find(|t| t.student == row.student) {
                Some(t) => t.points += points,
                None => totals.push(Total { student: row.student.clone(), points, max_points }),
            }
        }
        totals
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_malformed_assignment_names_the_field_and_the_line() {
        let e = Assignment::parse("[[exercise]]\nid = \"basic-move-light\"\nweight = \"lots\"\n").unwrap_err();
        assert!(e.contains("line 3") && e.contains("weight"), "{e}");
        let e = Assignment::parse("[[exercise]]\nid = \"no-such\"\n").unwrap_err();
        assert!(e.contains("line 2") && e.contains("no-such"), "{e}");
        let e = Assignment::parse("[[exercise]]\nid = \"basic-move-light\"\npartial = \"half\"\n").unwrap_err();
        assert!(e.contains("line 3") && e.contains("partial"), "{e}");
        let e = Assignment::parse("[[exercise]]\nid = \"basic-move-light\"\n[exercise.mistakes]\nnot-a-mistake = 5\n")
            .unwrap_err();
        assert!(e.contains("not-a-mistake") && e.contains("line 4"), "{e}");
    }

    #[test]
    fn a_named_mistake_takes_its_credit_over_the_cases_share() {
        let a =
            Assignment::parse("[[exercise]]\nid = \"basic-move-light\"\n[exercise.mistakes]\nblinn-for-phong = 50\n")
                .unwrap();
        let policy = &a.exercises[0].policy;
        let mut row = Row { verdict: "disagrees", defined: Some(1000), failing: Some(30), ..Row::default() };
        // 90 × 970 / 1000 = 87.3, floored.
        assert_eq!(policy.score(&row), 87);
        row.diagnosis.push(super::super::Diagnosis { id: "blinn-for-phong".into(), ..Default::default() });
        assert_eq!(policy.score(&row), 50);
        row.agrees = true;
        assert_eq!(policy.score(&row), 100);
    }
}
