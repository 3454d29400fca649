//! `lightlab grade DIR --exercise ID` (or `--assignment FILE`): grades a class's
//! submissions, into the course's system.
//!
//! # What is graded
//! The folder's submissions as [`collect`] finds them: `alice.frag`, the pair
//! `alice.vert` + `alice.frag`, the folder `alice/`. Files that are not submissions
//! (`README.txt`, pictures) are listed in a "not graded" note on standard error (and in
//! the json, gradescope and prairielearn outputs), never as rows. Links that lead outside
//! the folder, FIFOs and devices are rows with their error; nothing outside the folder is
//! opened.
//!
//! Each shader is checked in a child process (`lightlab exercise check ... --in-process
//! --format json`, [`super::child`]) under a time and a memory limit (`--timeout`,
//! `--memory`), one child per core; progress goes to standard error (`12/30 alice.frag
//! agrees`) and the rows come out in file-name order.
//!
//! # Formats (`--format`, to standard output or `-o FILE`)
//! | format | what | one row per |
//! | --- | --- | --- |
//! | `csv` | `file,verdict,score,diagnosis,counterexample,error,mistake,explanation,similar_to` (with `--assignment` or `--files`: `student,exercise,weight,points,` first, and a `TOTAL` row per student) | submission |
//! | `json` | `{rows: [...], totals: [...], not_graded: [...], similar: [...]}` | submission |
//! | `gradescope` | Gradescope's `results.json` (autograder specification) | one submission |
//! | `prairielearn` | PrairieLearn's external-grading `results.json` | one submission |
//! | `moodle` | the `--worksheet` CSV with its grade and feedback cells filled | worksheet row |
//!
//! `gradescope` and `prairielearn` grade one submission, as their scripts run once per
//! submission: the folder must hold exactly one (one file, one pair, or the files of one
//! student). With none or several, the `results.json` is still written, with a score of
//! 0 and a message that tells the student what to hand in (PrairieLearn: `gradable:
//! false`), and the exit status is 1. With `--assignment` the folder is that student's
//! own.
//!
//! # The score (0 to 100 per exercise; [`assignment::Policy`])
//! - 100 when the answer agrees;
//! - a shader that disagrees: the credit the assignment gives its named mistake (`[exercise.mistakes]
//!   blinn-for-phong = 50`), else the exercise's `partial` policy. The default policy,
//!   `"cases"`, gives `floor(90 × passing / defined)`: the share of the random cases it
//!   gets right, capped at 90 so that only an agreeing shader scores 100. Its reason:
//!   it is the one measure the check has for every shader, named mistake or not; a
//!   teacher who judges mistakes differently says so per mistake;
//! - 0 for a wrong number or choice, and for a row with an error.
//!
//! Exit status: 0 when every submission agrees, 1 when some does not (or has an error),
//! when nothing was graded (an empty folder, or a wrong `--exercise`: a warning on
//! standard error) and when gradescope or prairielearn find no or several submissions,
//! 2 on a usage error (unknown exercise, unreadable directory, bad assignment or
//! worksheet, `--worksheet` without `--format moodle`), 3 no OpenGL for a shader exercise.

pub mod assignment;
pub mod collect;
pub mod feedback;
pub mod formats;
pub mod moodle;
pub mod picture;
pub mod run;
pub mod similar;
pub mod texts;

use std::path::PathBuf;

use self::assignment::{Assignment, Policy};
use self::run::Settings;
use super::exercise::{context_if_needed, find, read_mapping};
use crate::checker::diagnose::Finding;
use crate::checker::mistakes::Mistake;
use crate::exercises;

/// Output format of `grade`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum GradeFormat {
    /// Comma-separated values with a header row.
    Csv,
    /// One exercise (--exercise, or an assignment of one): an array of row objects; several: one object with rows, totals, not graded, similar submissions.
    Json,
    /// Gradescope's autograder `results.json` (one submission).
    Gradescope,
    /// PrairieLearn's external grader `results.json` (one submission).
    Prairielearn,
    /// Moodle's grading worksheet (`--worksheet`), filled.
    Moodle,
}

/// Arguments of `lightlab grade`.
#[derive(Debug, Clone, clap::Args)]
pub struct GradeArgs {
    /// The folder of submissions (a file, a vertex + fragment pair or a folder per student).
    pub dir: PathBuf,
    /// The exercise id (see `lightlab exercise list`); or give `--assignment`.
    #[arg(long, required_unless_present = "assignment", conflicts_with = "assignment")]
    pub exercise: Option<String>,
    /// An assignment file (TOML): several exercises, their weights, which files answer
    /// each, and the partial credit (see the book's appendix "Grading a class"). Its
    /// `files` and `vertex` patterns: `*` and `?` within a name; without `/` a pattern
    /// matches a file's name at any depth (`*lighting*.frag`), with `/` or `**` the path
    /// from the student's folder (`src/*.frag`, `**/*.frag`); `{fs,frag}` gives
    /// alternatives; other syntax (`[abc]`) is refused.
    #[arg(long, value_name = "FILE.toml")]
    pub assignment: Option<PathBuf>,
    /// With --exercise: the pattern of the file that answers it in each student's folder
    /// (the syntax of an assignment's `files`), for folders that hold more than the answer,
    /// such as a LearnOpenGL project with its lamp shader (`--files '*lighting*.frag'`).
    /// Each sub-folder of DIR is then a student.
    #[arg(long, value_name = "PATTERN", conflicts_with = "assignment")]
    pub files: Option<String>,
    /// With --exercise: the pattern of the vertex shader of a vertex + fragment exercise
    /// in each student's folder (as an assignment's `vertex`).
    #[arg(long, value_name = "PATTERN", conflicts_with = "assignment")]
    pub vertex: Option<String>,
    /// Output format.
    #[arg(long, value_enum, default_value = "csv")]
    pub format: GradeFormat,
    /// Write the output to this file (through a temporary file and a rename) instead of stdout.
    #[arg(short = 'o', long, visible_alias = "output", value_name = "FILE")]
    pub out: Option<PathBuf>,
    /// Moodle's grading worksheet (CSV, "Download grading worksheet") to fill (`--format moodle`).
    #[arg(long, value_name = "FILE.csv")]
    pub worksheet: Option<PathBuf>,
    /// A CSV `file,identifier` matching submissions (file name without extension) to the
    /// worksheet's identifiers.
    #[arg(long, value_name = "FILE.csv")]
    pub map: Option<PathBuf>,
    /// The worksheet's grade column, when its header is not Moodle's English, French or Ukrainian one.
    #[arg(long, value_name = "NAME")]
    pub grade_column: Option<String>,
    /// The worksheet's feedback column, when its header is not Moodle's English, French or Ukrainian one.
    #[arg(long, value_name = "NAME")]
    pub feedback_column: Option<String>,
    /// Write one feedback page (Markdown and HTML) per submission into this folder (created if missing).
    #[arg(long, value_name = "DIR")]
    pub feedback: Option<PathBuf>,
    /// Number of random cases per shader (1 to 10^6).
    #[arg(long, default_value_t = 20_000, value_parser = clap::value_parser!(u64).range(1..=crate::oracle::cases::MAX_CASES_U64))]
    pub cases: u64,
    /// Submissions checked at once (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=256))]
    pub jobs: Option<u64>,
    /// The mapping, the seed (the same cases for every file), each check's time and memory limits.
    #[command(flatten)]
    pub options: super::child::CheckOptions,
}

/// A named mistake (or the isolation sentence) as a row shows it.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Diagnosis {
    /// The catalogue id (`isolated` for an isolation, `wrong-choice`, `answer-too-high` or
    /// `answer-too-low` for an answer).
    pub id: String,
    /// Its title, or the isolation's sentence.
    pub title: String,
    /// Why the picture looks as it does (the catalogue's explanation), or what was measured.
    pub explanation: String,
    /// The book page that explains it (relative to the book's root).
    pub link: String,
    /// The check's first hint (where to look), in the output language; empty when the
    /// check gave none.
    pub hint: String,
}

impl Diagnosis {
    /// From a check's finding: the catalogue's `why` when the id is a catalogued mistake,
    /// in the output language (`--lang`; the children that check write their titles in it too).
    pub fn of(f: &Finding) -> Diagnosis {
        let lang = crate::i18n::output_lang();
        let (title, explanation) = match Mistake::by_id(&f.id) {
            Some(m) => {
                (f.shown_title(|s| crate::i18n::tr(lang, s).into_owned()), crate::i18n::tr(lang, m.why).into_owned())
            }
            None => (f.title.clone(), f.evidence.clone()),
        };
        // A catalogue mistake's hints are English msgids; an isolation's are already in
        // the language the child wrote them in, which `tr` passes through.
        let hint = f.hints.first().map_or(String::new(), |h| crate::i18n::tr(lang, h).into_owned());
        Diagnosis { id: f.id.clone(), title, explanation, link: f.link.clone(), hint }
    }
}

/// One graded submission for one exercise.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Row {
    /// The submission's name (relative to the folder): `alice.frag`, `alice.frag + alice.vert`, `alice/`.
    pub file: String,
    /// The student (the file's stem or the folder's name).
    pub student: String,
    /// The stem of the student's feedback page and pictures ([`feedback::assign_pages`]).
    pub page: String,
    /// The exercise id.
    pub exercise: &'static str,
    /// `agrees`, `disagrees`, `error`, `does not terminate` (a loop reached the loop
    /// guard's cap), `does not follow the exercise` (a `[rules]` entry broken), or `ran out of memory` (the check's child reached
    /// `--memory`: the submission's own fault or too small a limit, never a grading error).
    pub verdict: &'static str,
    /// Whether the answer agrees.
    pub agrees: bool,
    /// Defined cases checked (shader checks).
    pub defined: Option<u64>,
    /// Cases beyond the bound (shader checks).
    pub failing: Option<u64>,
    /// 0 to 100 (see the module docs), set by [`Policy::score`].
    pub score: u32,
    /// The diagnosis, best first.
    pub diagnosis: Vec<Diagnosis>,
    /// The worst counterexample (the largest error; the checks list theirs worst first),
    /// on one short line in the shader's own names.
    pub counterexample: String,
    /// The error, for `error` rows.
    pub error: String,
    /// The submission cannot be graded: it does not compile, or is empty or not text
    /// (PrairieLearn's `gradable: false`).
    pub ungradable: bool,
    /// No submission was found to check (none, or several, in a Gradescope or PrairieLearn
    /// folder): ungradable too, but the page has no error of the student's to fix.
    pub not_found: bool,
    /// Other submissions with the same token stream ([`similar`]).
    pub similar_to: Vec<String>,
    /// The feedback picture ([`picture`]), when one was drawn.
    pub picture: Option<PathBuf>,
    /// Why the feedback picture was asked for and not drawn (the shader hangs or fails on
    /// the picture's scene); empty otherwise. The `notes` of the csv and json rows.
    pub picture_note: String,
}

/// One student's total over an assignment's exercises.
#[derive(Debug, Clone, PartialEq)]
pub struct Total {
    /// The student.
    pub student: String,
    /// Sum of weight × score / 100.
    pub points: f64,
    /// Sum of the weights.
    pub max_points: f64,
}

/// Everything one run of `grade` found.
#[derive(Debug, Clone, Default)]
pub struct Graded {
    /// The rows, by student then exercise.
    pub rows: Vec<Row>,
    /// Per student.
    pub totals: Vec<Total>,
    /// Files that are not submissions.
    pub not_graded: Vec<String>,
    /// Groups of near-identical submissions.
    pub similar: Vec<Vec<String>>,
    /// The weight of each exercise.
    pub weights: Vec<(&'static str, f64)>,
    /// Seconds the grading took.
    pub seconds: f64,
}

/// Runs `lightlab grade` (see the module docs for the exit status).
///
/// Errors: [`super::CliError::Input`] for a bad option, an unreadable assignment,
/// mapping, worksheet or map, an output that cannot be written;
/// [`super::CliError::Internal`] without OpenGL or on a failed write.
pub fn run(args: &GradeArgs) -> super::CliResult {
    let started = std::time::Instant::now();
    let mapping = match read_mapping(&args.options.uniforms) {
        Ok(m) => m,
        Err(msg) => return usage(msg),
    };
    let assignment = match (&args.assignment, &args.exercise) {
        (Some(path), _) => match Assignment::read(path) {
            Ok(a) => a,
            Err(msg) => return usage(msg),
        },
        (None, Some(id)) => {
            match find(id).and_then(|e| Assignment::single_with(e, args.files.clone(), args.vertex.clone())) {
                Ok(a) => a,
                Err(msg) => return usage(msg),
            }
        }
        (None, None) => return usage(texts::tr(texts::NO_EXERCISE_GIVEN)),
    };
    // The class's language: `--lang` wins, then the assignment's `lang`, then
    // `LIGHTLAB_LANG` or the locale (already the output language).
    if let (false, Some(lang)) = (crate::i18n::output_lang_is_explicit(), assignment.lang) {
        crate::i18n::set_output_lang(lang);
    }
    let one = matches!(args.format, GradeFormat::Gradescope | GradeFormat::Prairielearn);
    if args.worksheet.is_some() && args.format != GradeFormat::Moodle {
        return usage(texts::tr(texts::WORKSHEET_WITHOUT_MOODLE));
    }
    // Outputs are checked before the work: a class's results are not lost after hours.
    let worksheet = if args.format == GradeFormat::Moodle {
        let Some(path) = &args.worksheet else { return usage(texts::tr(texts::MOODLE_WITHOUT_WORKSHEET)) };
        match moodle::Worksheet::read(path, args.grade_column.as_deref(), args.feedback_column.as_deref()) {
            Ok(w) => Some(w),
            Err(msg) => return usage(msg),
        }
    } else {
        None
    };
    // A worksheet from a French or Ukrainian Moodle site: its students read the feedback
    // cells in that language, unless `--lang` or the assignment's `lang` chose another.
    if let (false, None, Some(w)) = (crate::i18n::output_lang_is_explicit(), assignment.lang, &worksheet) {
        crate::i18n::set_output_lang(w.lang());
    }
    let map = match &args.map {
        Some(p) => match moodle::read_map(p) {
            Ok(m) => m,
            Err(msg) => return usage(msg),
        },
        None => Vec::new(),
    };
    if let Some(out) = &args.out {
        if let Err(msg) = check_output_path(out) {
            return usage(msg);
        }
    }
    if let Some(dir) = &args.feedback {
        if let Err(msg) = check_feedback_dir(dir) {
            return usage(msg);
        }
    }
    let (mut jobs, not_graded) = match assignment.jobs(&args.dir, one) {
        Ok(j) => j,
        Err(msg) => return usage(msg),
    };
    feedback::assign_pages(&mut jobs);
    if one {
        let students: std::collections::BTreeSet<&str> = jobs.iter().map(|j| j.student.as_str()).collect();
        if students.len() != 1 {
            // The platform shows the student this results.json: a score of 0 and why,
            // never "the autograder failed" (exit status 1: results written, a problem found).
            let found: Vec<&str> = jobs.iter().map(|j| j.file.as_str()).collect();
            let why = if found.is_empty() {
                texts::tr(texts::ONE_SUBMISSION_NONE)
            } else {
                texts::tr_fill(texts::ONE_SUBMISSION_MANY, &[&found.join(", ")])
            };
            let format = if args.format == GradeFormat::Gradescope { "gradescope" } else { "prairielearn" };
            let held = if found.is_empty() {
                students.len().to_string()
            } else {
                format!("{} ({})", students.len(), found.join(", "))
            };
            eprintln!(
                "{}",
                texts::tr_fill(texts::WARN_ONE_SUBMISSION, &[format, &args.dir.display().to_string(), &held])
            );
            let rows: Vec<Row> = assignment
                .exercises
                .iter()
                .map(|e| Row {
                    file: args
                        .dir
                        .file_name()
                        .map_or_else(|| "submission".into(), |n| n.to_string_lossy().into_owned()),
                    student: "submission".into(),
                    exercise: e.exercise.id,
                    verdict: "error",
                    error: why.clone(),
                    ungradable: true,
                    not_found: true,
                    ..Row::default()
                })
                .collect();
            let graded = Graded {
                totals: assignment.totals(&rows),
                weights: assignment.exercises.iter().map(|e| (e.exercise.id, e.weight)).collect(),
                rows,
                not_graded,
                similar: Vec::new(),
                seconds: started.elapsed().as_secs_f64(),
            };
            let text = if args.format == GradeFormat::Gradescope {
                format!("{:#}\n", formats::gradescope(&graded))
            } else {
                format!("{:#}\n", formats::prairielearn(&graded))
            };
            match &args.out {
                Some(path) => crate::outfile::write_atomically(path, &text)?,
                None => super::output::print(text)?,
            }
            return Ok(super::Outcome::Problems);
        }
    }
    if !not_graded.is_empty() {
        eprintln!("{}", texts::tr_fill(texts::NOT_GRADED, &[&not_graded.join(", ")]));
    }
    let gl = assignment.exercises.iter().any(|e| super::exercise::needs_gl(e.exercise));
    if gl {
        // Fail early, once, when there is no OpenGL at all (exit status 3).
        let ctx = assignment.exercises.iter().find(|e| super::exercise::needs_gl(e.exercise));
        if let Some(e) = ctx {
            context_if_needed(e.exercise)?;
        }
    }
    // Pictures go beside the feedback pages; Gradescope and PrairieLearn embed them, so
    // they draw them in a temporary folder when there are no pages.
    let scratch = std::env::temp_dir().join(format!("lightlab-pictures-{}", std::process::id()));
    let pictures = match (&args.feedback, args.format) {
        (Some(dir), _) => Some(dir.clone()),
        (None, GradeFormat::Prairielearn | GradeFormat::Gradescope) => Some(scratch.clone()),
        _ => None,
    };
    if let Some(dir) = &pictures {
        if let Err(e) = std::fs::create_dir_all(dir) {
            return usage(texts::tr_fill(texts::CANNOT_CREATE, &[&dir.display().to_string(), &e.to_string()]));
        }
    }
    let settings = Settings {
        pictures: pictures.as_deref(),
        cases: args.cases as usize,
        uniforms: args.options.uniforms.as_deref(),
        mapping: &mapping,
        seed: args.options.seed,
        limits: args.options.limits(),
    };
    let threads = args.jobs.map_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()), |j| j as usize);
    let mut rows = run::run_all(&jobs, &settings, gl, threads);
    for row in &mut rows {
        if let Some(e) = assignment.exercises.iter().find(|e| e.exercise.id == row.exercise) {
            row.score = e.policy.score(row);
        }
    }
    for row in rows.iter().filter(|r| !r.picture_note.is_empty()) {
        eprintln!("{}", texts::tr_fill(texts::NOTE_LINE, &[&row.file, &formats::notes(row)]));
    }
    let similar = similar::flag(&jobs, &mut rows);
    for group in &similar {
        eprintln!("{}", texts::tr_fill(texts::NEAR_IDENTICAL, &[&group.join(", ")]));
    }
    let graded = Graded {
        totals: assignment.totals(&rows),
        weights: assignment.exercises.iter().map(|e| (e.exercise.id, e.weight)).collect(),
        rows,
        not_graded,
        similar,
        seconds: started.elapsed().as_secs_f64(),
    };
    if let Some(dir) = &args.feedback {
        feedback::write_all(dir, &graded).map_err(super::CliError::Input)?;
    }
    let text = match args.format {
        // With --files each sub-folder is a student, whatever file the pattern picked: the
        // student column is the row's stable key, as with an assignment.
        GradeFormat::Csv => formats::to_csv(&graded, args.assignment.is_some() || args.files.is_some()),
        GradeFormat::Json => format!("{}\n", formats::to_json(&graded)),
        GradeFormat::Gradescope => format!("{:#}\n", formats::gradescope(&graded)),
        GradeFormat::Prairielearn => format!("{:#}\n", formats::prairielearn(&graded)),
        GradeFormat::Moodle => match worksheet.as_ref().map(|w| w.fill(&graded, &map)) {
            Some(Ok((text, unmatched))) => {
                for s in unmatched {
                    eprintln!("{}", texts::tr_fill(texts::WARN_NO_ROW, &[s.as_str()]));
                }
                text
            }
            Some(Err(msg)) => return usage(msg),
            None => return usage("--format moodle needs --worksheet FILE.csv"),
        },
    };
    if pictures.as_deref() == Some(scratch.as_path()) {
        let _ = std::fs::remove_dir_all(&scratch);
    }
    match &args.out {
        Some(path) => crate::outfile::write_atomically(path, &text)?,
        None => super::output::print(text)?,
    }
    if graded.rows.is_empty() {
        // An empty folder, or a wrong --exercise (shaders for a numeric exercise): exit
        // status 1, so a script notices.
        let msgid = if graded.not_graded.is_empty() { texts::WARN_NOTHING } else { texts::WARN_NOTHING_SEE };
        let ids = assignment.exercises.iter().map(|e| e.exercise.id).collect::<Vec<_>>().join(", ");
        eprintln!("{}", texts::tr_fill(msgid, &[&args.dir.display().to_string(), &ids]));
        return Ok(super::Outcome::Problems);
    }
    Ok(if graded.rows.iter().any(|r| !r.agrees) { super::Outcome::Problems } else { super::Outcome::Success })
}

/// A usage or input error of `grade`, for `return usage(…)`.
fn usage<T>(msg: impl std::fmt::Display) -> Result<T, super::CliError> {
    Err(super::CliError::Input(msg.to_string()))
}

// String error: printed as a usage error by the caller.
/// Refuses an output path whose directory is missing, that is not a regular file, or
/// that cannot be written now (a temporary file is tried), before any work is done.
fn check_output_path(out: &std::path::Path) -> Result<(), String> {
    if let Ok(meta) = std::fs::metadata(out) {
        if !meta.is_file() {
            return Err(texts::tr_fill(texts::OUTPUT_NOT_FILE, &[&out.display().to_string()]));
        }
    }
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    if !dir.is_dir() {
        return Err(texts::tr_fill(texts::OUTPUT_NO_FOLDER, &[&out.display().to_string(), &dir.display().to_string()]));
    }
    crate::outfile::check_writable(out).map_err(|e| format!("-o {}: {e}", out.display()))
}

// String error: printed as a usage error by the caller.
/// Creates the feedback folder and checks that a page can be written in it, before any
/// work is done.
fn check_feedback_dir(dir: &std::path::Path) -> Result<(), String> {
    let shown = dir.display().to_string();
    std::fs::create_dir_all(dir)
        .map_err(|e| texts::tr_fill(texts::FEEDBACK_CANNOT_CREATE, &[&shown, &e.to_string()]))?;
    crate::outfile::check_writable(&dir.join("feedback.html"))
        .map_err(|e| texts::tr_fill(texts::FEEDBACK_CANNOT_WRITE, &[&shown, &e.to_string()]))
}

/// The score of a result under the default policy (see the module docs).
pub fn score(r: &exercises::ExerciseResult) -> u32 {
    let stat = |k: &str| r.stats.get(k).and_then(serde_json::Value::as_u64);
    let row = Row { agrees: r.agrees, defined: stat("defined"), failing: stat("failing"), ..Row::default() };
    Policy::default().score(&row)
}
