//! `lightlab exercise`: the exercise catalogue on the command line.
//!
//! - `exercise list [--format json]`: one line per exercise (JSON: `[{id, chapter, title, model}]`,
//!   `model` null for numeric and choice exercises);
//! - `exercise show ID [--starter]`: the statement, then the starter (code, or the question);
//!   with `--starter` the starter alone, a shader that compiles as it is
//!   (`lightlab exercise show ID --starter > mine.frag`);
//! - `exercise check ID FILE [--vertex VERT] [--format json] [--uniforms MAP.toml] [--timeout S]
//!   [--memory MB]`: checks the answer file (a fragment shader, with its vertex shader for a
//!   pair, a number or a letter), diagnosis first; a shader is compiled and run in a child
//!   process under the time and memory limits, as `check-shader` does, so an endless loop
//!   gives the verdict "took too long" and a macro bomb "ran out of memory"; a loop that
//!   reaches the loop guard's cap gives "does not terminate" ([`crate::checker::check::loops`]);
//! - `exercise export [--cases N] [--output FILE]`: the in-page checker's JSON document
//!   ([`crate::exercises::export`]).
//!
//! Exit status: 0 right, 1 wrong (or the shader does not compile, does not terminate, crashes the driver or
//! takes longer than `--timeout`), 2 usage or input error (unknown id, unreadable, empty or
//! binary file, an answer that does not parse), 3 no OpenGL for a shader exercise, 4 the
//! checking child ran out of memory (`--memory`).

use std::path::PathBuf;

use super::check_shader::{print_compile_error, Format};
use super::{CliError, CliResult, Outcome};
use crate::checker::check::{self, CheckError, Mapping};
use crate::checker::diagnose::Submission;
use crate::exercises::{self, Check, Exercise, ExerciseError, EXERCISES};
use crate::gl::{GlContext, ModelId};

/// Arguments of `lightlab exercise`.
#[derive(Debug, Clone, clap::Args)]
pub struct ExerciseArgs {
    /// What to do.
    #[command(subcommand)]
    pub action: Action,
}

/// `list`, `show` or `check`.
#[derive(Debug, Clone, clap::Subcommand)]
pub enum Action {
    /// List the exercises.
    List {
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: Format,
    },
    /// Print an exercise's statement and starter.
    Show {
        /// The exercise id (see `exercise list`).
        id: String,
        /// Print only the starter: for a shader exercise a shader that compiles as it is, to
        /// save and edit (`lightlab exercise show ID --starter > mine.frag`).
        #[arg(long)]
        starter: bool,
    },
    /// Check an answer: a fragment shader, or a text file with a number or a letter.
    Check {
        /// The exercise id.
        id: String,
        /// The answer file.
        file: PathBuf,
        /// A vertex shader handed in with the fragment shader: the pair is checked together
        /// (as `check-shader --vertex`; exercises on basic_lighting).
        #[arg(long, value_name = "VERT")]
        vertex: Option<PathBuf>,
        /// Output format.
        #[arg(long, value_enum, default_value = "text")]
        format: Format,
        /// Number of random cases (shader exercises; 1 to 10^6).
        #[arg(long, default_value_t = 20_000, value_parser = super::child::cases_parser(crate::oracle::cases::MAX_CASES_U64))]
        cases: usize,
        /// The mapping (merged over the exercise's own), the seed and the time limit.
        #[command(flatten)]
        options: super::child::CheckOptions,
        /// Run in this process (the child does; a crash then takes this process down).
        #[arg(long, hide = true)]
        in_process: bool,
        /// Also draw the feedback picture (student, reference, difference) to this PNG
        /// (`grade --feedback` asks its children for it).
        #[arg(long, hide = true, value_name = "FILE.png")]
        picture: Option<PathBuf>,
    },
    /// Print (or write) the in-page checker's data: catalogue, exercises, layouts, bounds,
    /// mutant GLSL and cases.
    Export {
        /// Cases per model (1 to 10^4).
        #[arg(long, default_value_t = 256, value_parser = super::child::cases_parser(crate::oracle::cases::MAX_EXPORT_CASES))]
        cases: usize,
        /// Seed of the case generator.
        #[arg(long, default_value_t = crate::oracle::cases::DEFAULT_SEED)]
        seed: u64,
        /// Write to this file (through a temporary file and a rename) instead of stdout.
        #[arg(long, value_name = "FILE")]
        output: Option<PathBuf>,
    },
}

/// `exercise show`'s lines (English msgids of `po/messages.pot`): the chapter and source,
/// then the model.
pub const SHOW_CHAPTER: &str = "chapter: {}; source: {}";
/// See [`SHOW_CHAPTER`].
pub const SHOW_MODEL: &str = "checked against the model: {}";
/// `exercise list`'s model column for an exercise answered in a text file.
pub const ANSWER_COLUMN: &str = "(answer)";

/// An exercise's starter as `exercise show` prints it: a shader as it is, the sentence and
/// the choices of an answer file in the command line's language.
fn starter_in_language(e: &Exercise) -> String {
    let lang = crate::i18n::output_lang();
    match e.model() {
        Some(_) => e.starter(),
        None => e.answer_starter(|msgid| crate::i18n::tr(lang, msgid).into_owned()),
    }
}

/// The error for an exercise id that names none (`{}`: the id, then the known ids).
pub const UNKNOWN_EXERCISE: &str = "unknown exercise `{}`; exercises: {}";

// String error: one message (naming the known ids) that exercise and grade both print as a usage error.
/// Looks an exercise up; the error lists the ids, in the output's language.
pub fn find(id: &str) -> Result<&'static Exercise, String> {
    Exercise::by_id(id).ok_or_else(|| {
        let ids: Vec<&str> = EXERCISES.iter().map(|e| e.id).collect();
        crate::checker::texts::tr_fill(UNKNOWN_EXERCISE, &[id, &ids.join(", ")])
    })
}

/// The `exercise list --format json` array.
pub fn list_json() -> serde_json::Value {
    serde_json::Value::Array(
        EXERCISES
            .iter()
            .map(|e| serde_json::json!({ "id": e.id, "chapter": e.chapter, "title": e.title, "model": e.model().map(ModelId::name) }))
            .collect(),
    )
}

// String error: one message that exercise and grade both turn into a usage error.
/// Reads a mapping file; errors name the file.
pub fn read_mapping(path: &Option<PathBuf>) -> Result<Mapping, String> {
    match path {
        None => Ok(Mapping::default()),
        Some(p) => super::input::read_limited(p, check::MAX_SOURCE_BYTES)
            .and_then(|b| String::from_utf8(b).map_err(|_| "the file is not UTF-8 text".to_string()))
            .map_err(|e| format!("mapping {}: {e}", p.display()))
            .and_then(|t| check::parse_mapping(&t).map_err(|e| format!("{}: {e}", p.display())))
            .map(|m| Mapping { file: Some(p.display().to_string()), ..m }),
    }
}

/// Whether checking the exercise needs OpenGL.
pub fn needs_gl(e: &Exercise) -> bool {
    matches!(e.check, Check::Shader { .. } | Check::Variant { .. } | Check::Pair { .. })
}

/// An OpenGL context when checking `e` needs one, `None` when it does not (numeric and
/// choice answers). No context where one is needed is an internal failure (exit status 3,
/// see the exit statuses in `lightlab --help`).
///
/// Errors: [`CliError::Internal`] naming the missing context.
pub fn context_if_needed(e: &Exercise) -> Result<Option<GlContext>, CliError> {
    if !needs_gl(e) {
        return Ok(None);
    }
    GlContext::new().map(Some).map_err(|err| CliError::Internal(format!("no OpenGL context: {err}")))
}

/// [`Outcome::Success`] for an answer that agrees, [`Outcome::Problems`] otherwise.
fn outcome(agrees: bool) -> CliResult {
    Ok(if agrees { Outcome::Success } else { Outcome::Problems })
}

/// Re-runs `args` (an `exercise check`) with `--in-process` in a child process under
/// `limits` ([`super::child::relay`]).
fn check_in_child(args: &ExerciseArgs, limits: super::child::Limits, file: &std::path::Path, json: bool) -> CliResult {
    let Action::Check { id, file: path, vertex, format, cases, options, picture, .. } = &args.action else {
        return Err(CliError::Internal("check_in_child called for another action".into()));
    };
    let mut cmd = super::child::this_binary()?;
    cmd.args(["exercise", "check", id]).arg(path).arg("--in-process");
    if let Some(v) = vertex {
        cmd.arg("--vertex").arg(v);
    }
    if let Some(p) = picture {
        cmd.arg("--picture").arg(p);
    }
    cmd.args(["--cases", &cases.to_string()]);
    options.forward(&mut cmd);
    if *format == Format::Json {
        cmd.args(["--format", "json"]);
    }
    super::child::relay(cmd, limits, file, json)
}

/// Runs `lightlab exercise` (see the module docs for the exit status).
///
/// Errors: [`CliError::Input`] for an unknown id, an unreadable answer, vertex shader or
/// mapping, and a check's input errors; [`CliError::Internal`] without OpenGL.
pub fn run(args: &ExerciseArgs) -> CliResult {
    match &args.action {
        Action::List { format: Format::Json } => {
            super::output::println(list_json())?;
            Ok(Outcome::Success)
        }
        Action::List { format: Format::Text } => {
            let lang = crate::i18n::output_lang();
            let mut text = String::new();
            for e in EXERCISES {
                text += &format!(
                    "{:<28} {:<16} {:<16} {}\n",
                    e.id,
                    e.chapter,
                    e.model()
                        .map_or_else(|| crate::i18n::tr(lang, ANSWER_COLUMN).into_owned(), |m| m.name().to_string()),
                    crate::i18n::tr(lang, e.title)
                );
            }
            super::output::print(text)?;
            Ok(Outcome::Success)
        }
        Action::Export { cases, seed, output } => {
            let text = format!("{}\n", exercises::export::browser_json(*cases, *seed));
            match output {
                Some(path) => crate::outfile::write_atomically(path, &text)?,
                None => super::output::print(text)?,
            }
            Ok(Outcome::Success)
        }
        Action::Show { id, starter: true } => {
            super::output::println(starter_in_language(find(id).map_err(CliError::Input)?).trim_end())?;
            Ok(Outcome::Success)
        }
        Action::Show { id, starter: false } => {
            let e = find(id).map_err(CliError::Input)?;
            {
                let lang = crate::i18n::output_lang();
                let title = crate::i18n::tr(lang, e.title);
                let mut text = format!("# {} ({})\n\n", title, e.id);
                text += &crate::i18n::catalog::tr_fill(lang, SHOW_CHAPTER, &[e.chapter, e.source]);
                text.push('\n');
                if let Some(m) = e.model() {
                    text += &crate::i18n::catalog::tr_fill(lang, SHOW_MODEL, &[m.name()]);
                    text.push('\n');
                }
                text += &format!(
                    "\n{}\n\n--- starter ---\n{}",
                    crate::i18n::tr(lang, e.statement),
                    starter_in_language(e).trim_end()
                );
                // A pair exercise is handed in with its vertex shader (`--vertex`).
                if let Some(vertex) = e.vertex_starter() {
                    text += &format!("\n\n--- vertex starter (--vertex) ---\n{}", vertex.trim_end());
                }
                super::output::println(text)?;
                Ok(Outcome::Success)
            }
        }
        Action::Check { id, file, vertex, format, cases, options, in_process, picture } => {
            let (uniforms, seed) = (&options.uniforms, &options.seed);
            let e = find(id).map_err(CliError::Input)?;
            let answer = super::input::read_limited(file, check::MAX_SOURCE_BYTES)
                .map_err(|err| format!("{}: {err}", file.display()))
                .and_then(|b| exercises::text_of(&b).map_err(|err| format!("{}: {err}", file.display())))
                .map_err(CliError::Input)?;
            let vertex_text = vertex
                .as_ref()
                .map(|v| {
                    super::input::read_limited(v, check::MAX_SOURCE_BYTES)
                        .and_then(|b| exercises::text_of(&b).map_err(|err| err.to_string()))
                        .map_err(|err| CliError::Input(format!("vertex shader {}: {err}", v.display())))
                })
                .transpose()?;
            let mut mapping = read_mapping(uniforms).map_err(CliError::Input)?;
            if options.class_mapping {
                mapping.optional_names = mapping.names.keys().cloned().collect();
            }
            if needs_gl(e) && !in_process {
                return check_in_child(args, options.limits(), file, *format == Format::Json);
            }
            if *in_process {
                super::child::report_memory_faults();
            }
            let ctx = context_if_needed(e)?;
            let submission = Submission { fragment: &answer, vertex: vertex_text.as_deref() };
            let result = exercises::check_submission(ctx.as_ref(), e, submission, &mapping, *cases, *seed);
            if let (Some(path), Some(ctx), None, Ok(_)) = (picture, ctx.as_ref(), &vertex_text, &result) {
                if let Err(why) = super::grade::picture::render(ctx, e, &answer, &mapping, *seed, path) {
                    eprintln!("{}{why}", super::grade::run::PICTURE_NOTE);
                }
            }
            match result {
                Ok(r) => {
                    match format {
                        Format::Text => {
                            // a pair's verdict names both files, as check-shader's does
                            let files = match vertex {
                                Some(v) => format!("{} + {}", file.display(), v.display()),
                                None => file.display().to_string(),
                            };
                            super::output::print(format!("{files}: {}", r.text))?
                        }
                        Format::Json => super::output::println(r.to_json())?,
                    }
                    outcome(r.agrees)
                }
                Err(ExerciseError::Check(CheckError::Compile { log, excerpt })) => {
                    print_compile_error(file, &answer, &log, &excerpt, *format)?;
                    outcome(false)
                }
                Err(ExerciseError::Check(CheckError::VertexCompile { log, excerpt })) => {
                    let text = vertex_text.as_deref().unwrap_or_default();
                    print_compile_error(vertex.as_deref().unwrap_or(file), text, &log, &excerpt, *format)?;
                    outcome(false)
                }
                Err(err) => {
                    let ungraded = match &err {
                        ExerciseError::Check(e) => super::check_shader::print_ungraded(file, e, *format),
                        _ => None,
                    };
                    match (ungraded, &err) {
                        (Some(shown), _) => shown.and_then(|()| outcome(false)),
                        (None, ExerciseError::Check(CheckError::Gl(_))) => {
                            Err(CliError::Internal(format!("{}: {err}", file.display())))
                        }
                        (None, _) => Err(CliError::Input(format!("{}: {err}", file.display()))),
                    }
                }
            }
        }
    }
}
