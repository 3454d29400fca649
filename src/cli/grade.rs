//! `lightlab grade DIR --exercise ID [--format csv|json] [--output FILE]`: checks every file
//! of a directory (a class's submissions) against one exercise.
//!
//! One row per file, in file-name order: `file, verdict, score, diagnosis, counterexample,
//! error`. `verdict` is `agrees`, `disagrees` or `error`; `diagnosis` lists the diagnosis ids
//! separated by `;`; `counterexample` is the first one on one line. A file that does not
//! compile, is empty, is not text or is unreadable is a row with its error (verdict
//! `error`, score 0); it never stops the run. Hidden files (`.name`) and directories are
//! skipped.
//!
//! Each shader is checked in a child process (`lightlab exercise check ... --format json`,
//! run in that process: [`super::child`])
//! under a time limit (`--timeout`), so a shader that never ends or crashes the driver is a
//! row with that error and the run goes on.
//!
//! # The score
//! - 100 when the answer agrees;
//! - for a shader that disagrees: `floor(90 × passing / defined)`, where `passing` counts
//!   the defined cases within the bound, so a shader wrong everywhere scores 0, one wrong on
//!   a few cases scores up to 89, and only an agreeing shader scores 100;
//! - 0 for a wrong number or choice, and for a row with an error.
//!
//! Exit status: 0 when every file agrees, 1 when some file does not (or has an error), 2 on
//! a usage error (unknown exercise, unreadable directory, no OpenGL for a shader exercise).

use std::path::{Path, PathBuf};

use super::child::{run_child, this_binary, ChildEnd};
use super::exercise::{context_if_needed, find, printed, read_mapping};
use crate::exercises::{self, ExerciseError, ExerciseResult};
use crate::gl::check::{CheckError, Mapping};
use crate::gl::GlContext;

/// Output format of `grade`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GradeFormat {
    /// Comma-separated values with a header row.
    Csv,
    /// A JSON array of row objects.
    Json,
}

/// Arguments of `lightlab grade`.
#[derive(Debug, Clone, clap::Args)]
pub struct GradeArgs {
    /// The directory of submissions (one answer file each).
    pub dir: PathBuf,
    /// The exercise id (see `lightlab exercise list`).
    #[arg(long)]
    pub exercise: String,
    /// Output format.
    #[arg(long, value_enum, default_value = "csv")]
    pub format: GradeFormat,
    /// Write the table to this file (through a temporary file and a rename) instead of stdout.
    #[arg(long, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// Number of random cases per shader.
    #[arg(long, default_value_t = 20_000)]
    pub cases: usize,
    /// The mapping, the seed (the same cases for every file) and each file's time limit.
    #[command(flatten)]
    pub options: super::child::CheckOptions,
}

/// One graded file.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The file name (relative to the directory).
    pub file: String,
    /// `agrees`, `disagrees` or `error`.
    pub verdict: &'static str,
    /// 0 to 100 (see the module docs).
    pub score: u32,
    /// Diagnosis ids, best first.
    pub diagnosis: Vec<String>,
    /// The first counterexample, on one line.
    pub counterexample: String,
    /// The error, for `error` rows.
    pub error: String,
}

/// The score of a result (see the module docs).
pub fn score(r: &ExerciseResult) -> u32 {
    if r.agrees {
        return 100;
    }
    let defined = r.stats.get("defined").and_then(serde_json::Value::as_u64).unwrap_or(0);
    let failing = r.stats.get("failing").and_then(serde_json::Value::as_u64).unwrap_or(defined);
    if defined == 0 {
        return 0;
    }
    (90 * (defined - failing.min(defined)) / defined) as u32
}

fn one_line(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

fn error_row(file: String, error: String) -> Row {
    Row { file, verdict: "error", score: 0, diagnosis: Vec::new(), counterexample: String::new(), error }
}

/// Grades one file.
pub fn grade_file(
    ctx: Option<&GlContext>,
    exercise: &'static exercises::Exercise,
    path: &Path,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Row {
    let file = path.file_name().map_or_else(|| path.display().to_string(), |f| f.to_string_lossy().into_owned());
    let text = match std::fs::read(path) {
        Ok(b) => match exercises::text_of(&b) {
            Ok(t) => t,
            Err(e) => return error_row(file, e.to_string()),
        },
        Err(e) => return error_row(file, format!("cannot read: {e}")),
    };
    match exercises::check_exercise(ctx, exercise, &text, mapping, n, seed) {
        Ok(r) => Row {
            file,
            verdict: if r.agrees { "agrees" } else { "disagrees" },
            score: score(&r),
            diagnosis: r.diagnosis.iter().map(|f| f.id.clone()).collect(),
            counterexample: r.counterexamples.first().map_or(String::new(), |c| one_line(c)),
            error: String::new(),
        },
        Err(ExerciseError::Check(CheckError::Compile { log, excerpt })) => {
            error_row(file, one_line(&format!("does not compile: {} {excerpt}", log.trim_end())))
        }
        Err(e) => error_row(file, one_line(&e.to_string())),
    }
}

/// Grades one shader file in a child process (see the module docs).
fn grade_file_in_child(args: &GradeArgs, path: &Path) -> Row {
    let file = path.file_name().map_or_else(|| path.display().to_string(), |f| f.to_string_lossy().into_owned());
    let mut cmd = match this_binary() {
        Ok(cmd) => cmd,
        Err(e) => return error_row(file, e.to_string()),
    };
    cmd.args(["exercise", "check", &args.exercise, "--in-process"]).arg(path);
    cmd.args(["--format", "json", "--cases", &args.cases.to_string()]);
    args.options.forward(&mut cmd);
    match run_child(cmd, std::time::Duration::from_secs(args.options.timeout)) {
        Err(e) => error_row(file, e),
        Ok(ChildEnd::TimedOut) => error_row(
            file,
            format!("took longer than {} s (--timeout): an endless loop, or a very slow shader", args.options.timeout),
        ),
        Ok(ChildEnd::Crashed(status)) => {
            error_row(file, format!("the OpenGL driver crashed compiling or running it ({status})"))
        }
        Ok(ChildEnd::Exited { code: 0 | 1, stdout, stderr }) => {
            match serde_json::from_str::<serde_json::Value>(stdout.trim()) {
                Ok(v) if v.get("compile_error").is_some() => {
                    let log = v["compile_error"]["log"].as_str().unwrap_or("");
                    let lines = v["compile_error"]["lines"].as_str().unwrap_or("");
                    error_row(file, one_line(&format!("does not compile: {log} {lines}")))
                }
                Ok(v) => {
                    let agrees = v["verdict"] == "agrees";
                    let diagnosis: Vec<String> = v["diagnosis"]
                        .as_array()
                        .map(|a| a.iter().filter_map(|f| f["id"].as_str().map(String::from)).collect())
                        .unwrap_or_default();
                    let r = ExerciseResult {
                        exercise: "",
                        agrees,
                        stats: v["stats"].clone(),
                        counterexamples: Vec::new(),
                        diagnosis: Vec::new(),
                        notes: Vec::new(),
                        text: String::new(),
                    };
                    Row {
                        file,
                        verdict: if agrees { "agrees" } else { "disagrees" },
                        score: score(&r),
                        diagnosis,
                        counterexample: v["counterexamples"][0].as_str().map_or(String::new(), one_line),
                        error: String::new(),
                    }
                }
                Err(e) => error_row(file, one_line(&format!("unreadable result of the check ({e}): {stderr}"))),
            }
        }
        Ok(ChildEnd::Exited { stderr, .. }) => {
            let msg = stderr.trim().trim_start_matches("error: ");
            let msg = msg.strip_prefix(&format!("{}: ", path.display())).unwrap_or(msg);
            error_row(file, one_line(msg))
        }
    }
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The rows as CSV, header first.
pub fn to_csv(rows: &[Row]) -> String {
    let mut s = String::from("file,verdict,score,diagnosis,counterexample,error\n");
    for r in rows {
        let fields = [
            csv_field(&r.file),
            r.verdict.to_string(),
            r.score.to_string(),
            csv_field(&r.diagnosis.join(";")),
            csv_field(&r.counterexample),
            csv_field(&r.error),
        ];
        s += &fields.join(",");
        s.push('\n');
    }
    s
}

/// The rows as a JSON array.
pub fn to_json(rows: &[Row]) -> serde_json::Value {
    serde_json::Value::Array(
        rows.iter()
            .map(|r| {
                serde_json::json!({
                    "file": r.file, "verdict": r.verdict, "score": r.score, "diagnosis": r.diagnosis,
                    "counterexample": r.counterexample, "error": r.error,
                })
            })
            .collect(),
    )
}

/// Runs `lightlab grade` (see the module docs for the exit status).
pub fn run(args: &GradeArgs) -> super::CliResult {
    super::exercise::from_status(run_status(args))
}

/// Runs `lightlab grade`; returns the exit status, errors already printed.
pub fn run_status(args: &GradeArgs) -> i32 {
    let exercise = match find(&args.exercise) {
        Ok(e) => e,
        Err(msg) => {
            eprintln!("error: {msg}");
            return 2;
        }
    };
    let mapping = match read_mapping(&args.options.uniforms) {
        Ok(m) => m,
        Err(msg) => {
            eprintln!("error: {msg}");
            return 2;
        }
    };
    if args.cases == 0 {
        eprintln!("error: --cases must be at least 1");
        return 2;
    }
    let mut files: Vec<PathBuf> = match std::fs::read_dir(&args.dir) {
        Ok(entries) => entries
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| p.is_file() && !p.file_name().is_some_and(|n| n.to_string_lossy().starts_with('.')))
            .collect(),
        Err(e) => {
            eprintln!("error: cannot read directory {}: {e}", args.dir.display());
            return 2;
        }
    };
    files.sort();
    let ctx = match context_if_needed(exercise) {
        Ok(ctx) => ctx,
        Err(status) => return status,
    };
    let rows: Vec<Row> = files
        .iter()
        .map(|p| {
            if ctx.is_some() {
                grade_file_in_child(args, p)
            } else {
                grade_file(None, exercise, p, &mapping, args.cases, args.options.seed)
            }
        })
        .collect();
    let text = match args.format {
        GradeFormat::Csv => to_csv(&rows),
        GradeFormat::Json => format!("{}\n", to_json(&rows)),
    };
    match &args.output {
        Some(path) => {
            if let Err(e) = crate::outfile::write_atomically(path, &text) {
                eprintln!("error: {e}");
                return if e.is_user_error() { 2 } else { 3 };
            }
        }
        None => return printed(super::output::print(text), i32::from(rows.iter().any(|r| r.verdict != "agrees"))),
    }
    i32::from(rows.iter().any(|r| r.verdict != "agrees"))
}
