//! Checking the submissions: each in its own child process (`exercise check
//! --in-process`, contained by [`crate::cli::child`]), one child per core, results in
//! the submissions' order whatever the order they finish in.

use std::path::PathBuf;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

use super::texts::{self, tr, tr_fill};
use super::Row;
use crate::checker::check::{Mapping, MAX_SOURCE_BYTES};
use crate::checker::diagnose::Submission;
use crate::cli::child::{run_child, this_binary, ChildEnd, Limits};
use crate::exercises::{self, Exercise, ExerciseError, ExerciseResult};

/// One check to run: a submission's files for one exercise, or the error that stands
/// for it.
#[derive(Debug, Clone)]
pub struct Job {
    /// The row's name (`alice.frag`, `alice/`).
    pub file: String,
    /// The student.
    pub student: String,
    /// The stem of the student's feedback page and pictures, unique in the class even on
    /// a case-insensitive disk ([`super::feedback::assign_pages`]); set before the run.
    pub page: String,
    /// The exercise.
    pub exercise: &'static Exercise,
    /// The fragment shader (or answer file) and its vertex shader; `Err` is the row's error.
    pub files: Result<(PathBuf, Option<PathBuf>), String>,
}

/// What the checks share.
pub struct Settings<'a> {
    /// Random cases per shader.
    pub cases: usize,
    /// The teacher's mapping file, forwarded to each child.
    pub uniforms: Option<&'a std::path::Path>,
    /// The teacher's mapping, for checks run in this process.
    pub mapping: &'a Mapping,
    /// The seed of the cases.
    pub seed: u64,
    /// Each child's limits.
    pub limits: Limits,
    /// Where the children draw the feedback pictures, if anywhere.
    pub pictures: Option<&'a std::path::Path>,
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// A counterexample on one short line: what was expected and what the shader gave
/// first, then the inputs in the chapter's names (`lightPos`, `Normal`, ...), without the
/// quantities the shader does not declare; its labels in the output language. The block
/// comes from the checking child in its English form (its JSON), which this reads.
fn short(s: &str) -> String {
    let lines: Vec<&str> =
        s.lines().map(str::trim).filter(|l| !l.is_empty() && !l.starts_with("(not declared)")).collect();
    let is_result = |l: &str| l.starts_with("expected") || l.starts_with("got");
    let mut parts: Vec<&str> = lines.iter().copied().filter(|l| is_result(l)).collect();
    parts.extend(lines.iter().copied().filter(|l| !is_result(l)));
    let parts: Vec<String> = parts.into_iter().map(crate::checker::texts::localize_counterexample).collect();
    let line = one_line(&parts.join("; "));
    cut_at_a_part(line, SHORT_CHARS)
}

/// The longest counterexample line a row holds, in characters: the two colours and the
/// basic-lighting inputs (about 420) fit; the full case is in `exercise check`'s output.
const SHORT_CHARS: usize = 480;

/// `line` if it has at most `max` characters; otherwise its first `; `-separated parts
/// that fit, then `; …`, so that no value is cut in the middle (a learner would copy a
/// wrong number). A first part longer than `max` is cut at `max` characters, then `…`.
fn cut_at_a_part(line: String, max: usize) -> String {
    let Some((limit, _)) = line.char_indices().nth(max) else { return line };
    match line[..limit].rfind("; ") {
        Some(end) => format!("{}; …", &line[..end]),
        None => format!("{}…", &line[..limit]),
    }
}

/// The verdict of a row whose check ran out of memory: its own word in the table, as in
/// `check-shader`'s output, so a teacher can tell it from an error and raise `--memory`.
pub const OUT_OF_MEMORY_VERDICT: &str = "ran out of memory";
/// The verdict of a row whose loop reached the loop guard's cap
/// ([`crate::checker::check::loops`]): its own word, as in `exercise check`'s JSON; the output
/// of such a shader is never graded (score 0).
pub const DOES_NOT_TERMINATE_VERDICT: &str = "does not terminate";
/// The verdict of a row whose shader breaks the exercise's own rules (`[rules]` of its
/// mapping: a quantity it must not declare, or must): not graded (score 0).
pub const BREAKS_RULE_VERDICT: &str = "does not follow the exercise";
/// The verdicts of `exercise check`'s JSON whose output was not graded.
const UNGRADED_VERDICTS: [&str; 2] = [DOES_NOT_TERMINATE_VERDICT, BREAKS_RULE_VERDICT];

fn error_row(job: &Job, error: String, ungradable: bool) -> Row {
    Row {
        file: job.file.clone(),
        student: job.student.clone(),
        page: job.page.clone(),
        exercise: job.exercise.id,
        verdict: "error",
        error,
        ungradable,
        ..Row::default()
    }
}

/// The row of a finished check (in this process or parsed from a child).
fn result_row(job: &Job, r: &ExerciseResult) -> Row {
    let stat = |k: &str| r.stats.get(k).and_then(serde_json::Value::as_u64);
    Row {
        file: job.file.clone(),
        student: job.student.clone(),
        page: job.page.clone(),
        exercise: job.exercise.id,
        verdict: if r.agrees { "agrees" } else { "disagrees" },
        agrees: r.agrees,
        defined: stat("defined"),
        failing: stat("failing"),
        diagnosis: r.diagnosis.iter().map(super::Diagnosis::of).collect(),
        // The checks list their counterexamples worst first.
        counterexample: r.counterexamples.first().map_or(String::new(), |c| short(c)),
        ..Row::default()
    }
}

/// Checks one job in this process (numeric and choice exercises, which need no OpenGL).
fn in_process(job: &Job, s: &Settings<'_>) -> Row {
    let (path, vertex) = match &job.files {
        Ok(f) => f,
        Err(e) => return error_row(job, e.clone(), false),
    };
    if vertex.is_some() {
        return error_row(job, tr_fill(texts::ROW_ONE_ANSWER_FILE, &[job.exercise.id]), true);
    }
    let text = match crate::cli::input::read_limited(path, MAX_SOURCE_BYTES)
        .and_then(|b| exercises::text_of(&b).map_err(|e| e.to_string()))
    {
        Ok(t) => t,
        Err(e) => return error_row(job, e, true),
    };
    match exercises::check_submission(
        None,
        job.exercise,
        Submission { fragment: &text, vertex: None },
        s.mapping,
        s.cases,
        s.seed,
    ) {
        Ok(r) => result_row(job, &r),
        Err(ExerciseError::Input(e)) => error_row(job, one_line(&e), true),
        Err(e) => error_row(job, one_line(&e.to_string()), false),
    }
}

/// Checks one job in a child process.
fn in_child(job: &Job, s: &Settings<'_>) -> Row {
    let (path, vertex) = match &job.files {
        Ok(f) => f,
        Err(e) => return error_row(job, e.clone(), false),
    };
    let mut cmd = match this_binary() {
        Ok(cmd) => cmd,
        Err(e) => return error_row(job, e.to_string(), false),
    };
    cmd.args(["exercise", "check", job.exercise.id, "--in-process"]).arg(path);
    if let Some(v) = vertex {
        cmd.arg("--vertex").arg(v);
    }
    cmd.args(["--format", "json", "--cases", &s.cases.to_string(), "--seed", &s.seed.to_string()]);
    // The child writes its titles and sentences in the grading's language (`--lang`, or
    // the assignment's `lang`).
    cmd.env("LIGHTLAB_LANG", crate::i18n::output_lang().code());
    if let Some(u) = s.uniforms {
        cmd.arg("--uniforms").arg(u).arg("--class-mapping");
    }
    let picture = match (s.pictures, vertex) {
        (Some(dir), None) => {
            // The page's own stem: two students never share a picture.
            let path = dir.join(super::feedback::picture_file(&job.page, job.exercise.id));
            let _ = std::fs::remove_file(&path);
            cmd.arg("--picture").arg(&path);
            Some(path)
        }
        _ => None,
    };
    let (mut row, stderr) = in_child_run(job, s, cmd);
    if let Some(path) = picture {
        if path.is_file() {
            row.picture = Some(path);
        } else if row.verdict == "agrees" || row.verdict == "disagrees" {
            // The child says why on standard error (`exercise check --picture`).
            let why = stderr
                .lines()
                .find_map(|l| l.trim().strip_prefix(PICTURE_NOTE))
                .map_or_else(|| "the check drew none".to_string(), one_line);
            row.picture_note = why;
        }
    }
    row
}

/// The line `exercise check --picture` prints on standard error when it draws no picture,
/// before the reason.
pub const PICTURE_NOTE: &str = "note: no feedback picture: ";

/// The row of a child's check, and the child's standard error.
fn in_child_run(job: &Job, s: &Settings<'_>, cmd: std::process::Command) -> (Row, String) {
    let end = match run_child(cmd, s.limits) {
        Ok(end) => end,
        Err(e) => return (error_row(job, e, false), String::new()),
    };
    if let Some(why) = end.limit_message(s.limits) {
        let mut row = error_row(job, why, false);
        if matches!(end, ChildEnd::OutOfMemory) {
            row.verdict = OUT_OF_MEMORY_VERDICT;
        }
        return (row, String::new());
    }
    let ChildEnd::Exited { code, stdout, stderr } = end else {
        return (error_row(job, tr(texts::ROW_NO_RESULT), false), String::new());
    };
    let row = child_row(job, code, &stdout, &stderr);
    (row, stderr)
}

/// The reason in a child's error line, `lightlab exercise: error: FILE: why` in the class's
/// language ([`crate::cli::ERROR_LINE`]): the why alone, without the line's prefix or the
/// teacher's path to the file.
fn child_error_reason<'s>(job: &Job, stderr: &'s str) -> &'s str {
    let msg = stderr.trim();
    let prefix = tr_fill(crate::cli::ERROR_LINE, &["lightlab exercise", ""]);
    let msg =
        msg.strip_prefix(prefix.as_str()).or_else(|| msg.split_once("error: ").map(|(_, rest)| rest)).unwrap_or(msg);
    let files = job.files.as_ref().map(|(f, v)| [Some(f), v.as_ref()]).unwrap_or_default();
    let named = files.into_iter().flatten().find_map(|p| msg.strip_prefix(&format!("{}: ", p.display())));
    named.or_else(|| msg.split_once(": ").filter(|(p, _)| p.contains('/')).map(|(_, rest)| rest)).unwrap_or(msg)
}

/// The row of a child that exited with `code`.
fn child_row(job: &Job, code: i32, stdout: &str, stderr: &str) -> Row {
    if code != 0 && code != 1 {
        // An input error (empty, not text, too large): the student can resubmit.
        return error_row(job, one_line(child_error_reason(job, stderr)), code == 2);
    }
    let v: serde_json::Value = match serde_json::from_str(stdout.trim()) {
        Ok(v) => v,
        Err(e) => return error_row(job, one_line(&tr_fill(texts::ROW_UNREADABLE, &[&e.to_string(), stderr])), false),
    };
    if let Some(c) = v.get("compile_error") {
        let log = crate::checker::texts::compile_log(c["log"].as_str().unwrap_or(""));
        let lines = c["lines"].as_str().unwrap_or("");
        return error_row(job, one_line(&tr_fill(texts::ROW_DOES_NOT_COMPILE, &[&format!("{log} {lines}")])), true);
    }
    if let Some(verdict) = UNGRADED_VERDICTS.iter().find(|w| v["verdict"] == **w) {
        let mut row = error_row(job, one_line(v["error"].as_str().unwrap_or("")), true);
        row.verdict = verdict;
        return row;
    }
    let agrees = v["verdict"] == "agrees";
    let diagnosis = v["diagnosis"]
        .as_array()
        .map(|a| {
            a.iter()
                .map(|f| crate::checker::diagnose::Finding {
                    id: f["id"].as_str().unwrap_or("").into(),
                    title: f["title"].as_str().unwrap_or("").into(),
                    evidence: f["evidence"].as_str().unwrap_or("").into(),
                    link: f["link"].as_str().unwrap_or("").into(),
                    hints: f["hints"]
                        .as_array()
                        .map(|h| h.iter().filter_map(|x| x.as_str().map(String::from)).collect())
                        .unwrap_or_default(),
                    site: f["site"].as_str().and_then(crate::checker::sites::Site::parse),
                    second: None,
                })
                .collect()
        })
        .unwrap_or_default();
    let counterexamples =
        v["counterexamples"].as_array().map(|a| a.iter().filter_map(|c| c.as_str().map(String::from)).collect());
    let r = ExerciseResult {
        exercise: job.exercise.id,
        agrees,
        stats: v["stats"].clone(),
        counterexamples: counterexamples.unwrap_or_default(),
        diagnosis,
        notes: Vec::new(),
        text: String::new(),
    };
    result_row(job, &r)
}

/// Checks every job, `threads` at a time (children when `gl`), printing progress on
/// standard error (`12/30 alice.frag agrees`); rows come back in the jobs' order.
pub fn run_all(jobs: &[Job], s: &Settings<'_>, gl: bool, threads: usize) -> Vec<Row> {
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let rows: Mutex<Vec<Option<Row>>> = Mutex::new(vec![None; jobs.len()]);
    let threads = threads.clamp(1, jobs.len().max(1));
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| loop {
                let k = next.fetch_add(1, Ordering::SeqCst);
                let Some(job) = jobs.get(k) else { break };
                let row = if gl && job.files.is_ok() { in_child(job, s) } else { in_process(job, s) };
                let n = done.fetch_add(1, Ordering::SeqCst) + 1;
                let what = if row.verdict == "error" { "error" } else { row.verdict };
                eprintln!("{n}/{} {} {what}", jobs.len(), job.file);
                if let Ok(mut rows) = rows.lock() {
                    rows[k] = Some(row);
                }
            });
        }
    });
    let rows = rows.into_inner().unwrap_or_default();
    rows.into_iter()
        .zip(jobs)
        .map(|(r, job)| r.unwrap_or_else(|| error_row(job, tr(texts::ROW_NOT_RUN), false)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A long counterexample is cut between two parts, never inside a value.
    #[test]
    fn a_long_counterexample_is_cut_between_parts() {
        let line = "expected (f64) = [0.5, 0.25, 0.0]; lightPos = (1.0, 2.0, 3.0); shininess = 32.0".to_string();
        assert_eq!(cut_at_a_part(line.clone(), 200), line);
        assert_eq!(cut_at_a_part(line.clone(), 70), "expected (f64) = [0.5, 0.25, 0.0]; lightPos = (1.0, 2.0, 3.0); …");
        assert_eq!(cut_at_a_part(line.clone(), 40), "expected (f64) = [0.5, 0.25, 0.0]; …");
        assert_eq!(cut_at_a_part(line, 10), "expected (…");
    }

    /// The basic-lighting counterexample a grading row holds keeps every input the shader
    /// declares, the last one (`shininess`) included (it was cut at 400 characters).
    #[test]
    fn a_basic_lighting_counterexample_keeps_its_inputs() {
        let block = "  FragPos = (1.6374738, -0.13147329, 0.67461973)\n  Normal = (-0.8393494, -1.0685908, 0.2002957)\n  \
                     lightPos = (-6.994622, -7.760737, -2.8767052)\n  viewPos = (1.105973, -9.310708, 8.382127)\n  \
                     lightColor = (0.55797464, 0.30155018, 0.11856018)\n  objectColor = (0.5949384, 0.2434301, 0.5613173)\n  \
                     shininess = 32.0\n  expected (f64) = [0.3282709, 0.0725905, 0.0658102]\n  \
                     got (llvmpipe) = [0.3633630, 0.0803504, 0.0728453]";
        let line = short(block);
        assert!(line.starts_with("expected (f64) = [0.3282709"), "{line}");
        assert!(line.ends_with("shininess = 32.0"), "{line}");
    }
}
