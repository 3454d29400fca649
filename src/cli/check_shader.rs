//! `lightlab check-shader FILE.frag --model NAME`: run a user's fragment shader on Mesa
//! llvmpipe over random cases of a model and compare it with the `f64` reference.
//! The logic is in [`crate::checker::check`].
//!
//! The shader is compiled and run in a child process (this binary again, with a hidden
//! flag) under a time limit (`--timeout`), so a driver crash (Mesa's compiler overflows
//! its stack on an expression of 100 000 terms) or a shader that never ends gives a
//! verdict instead of taking `lightlab` down.
//!
//! When the shader disagrees, the output leads with the diagnosis in plain words: the
//! catalogue mistakes whose mutants reproduce its output, or the term, light and inputs the
//! difference is confined to ([`crate::checker::diagnose`]). `--format json` prints one object
//! `{verdict, model, stats, counterexamples, notes, diagnosis: [{id, title, evidence, link}]}`
//! The verdict is `agrees` or `disagrees`; a compile error is `"verdict": "does not compile"`
//! with `compile_error: {log, lines}`; a child stopped by a limit is `took too long` or
//! `ran out of memory` with `error` (the text output's verdict line, in lower case); a
//! shader whose loop reaches the loop guard's cap ([`crate::checker::check::loops`]) is
//! `does not terminate`, with `error`, and its output is not graded.
//!
//! Exit status:
//!
//! | code | meaning |
//! | --- | --- |
//! | 0 | the shader agrees on every defined case |
//! | 1 | it disagrees, does not compile, does not terminate, crashes the driver, or takes longer than `--timeout` |
//! | 2 | usage or input error: unknown model, unreadable, empty or binary file, bad mapping, a name the model does not know, `--cases` outside 1 to 10^6, storage above the limits |
//! | 3 | internal failure: OpenGL missing, a draw failed, lightlab's rewrite did not compile |
//! | 4 | the checking child ran out of memory (`--memory`) |

use std::path::PathBuf;

use super::{CliError, CliResult, Outcome};
use crate::checker::check::{self, CheckError, Mapping};
use crate::checker::diagnose::{self, Submission};
use crate::gl::{GlContext, ModelId};

/// Output format of `check-shader` and `exercise`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Plain words, the diagnosis first.
    Text,
    /// One JSON object.
    Json,
}

/// Arguments of `lightlab check-shader`.
#[derive(Debug, Clone, clap::Args)]
pub struct CheckShaderArgs {
    /// The fragment shader to check (a complete GLSL file with `#version` and `main`).
    pub file: PathBuf,
    /// The model to compare with: basic_lighting, materials, lighting_maps, directional,
    /// point, spot, multiple_lights, opengl_tutorial8, ogldev19, normal_matrix, blinn_phong,
    /// lighting_maps_emission.
    /// With --vertex: basic_lighting (Phong per fragment) or gouraud (Phong per vertex).
    /// Parsed here, once: an unknown name is a usage error listing the models.
    #[arg(long)]
    pub model: ModelId,
    /// The vertex shader of a pair: both are checked together on random triangles, the
    /// values the vertex shader writes interpolated for the fragment shader (its attributes
    /// aPos and aNormal; uniforms model, view, projection and the lighting).
    #[arg(long, value_name = "VERT")]
    pub vertex: Option<PathBuf>,
    /// Number of random cases (1 to 10^6).
    #[arg(long, default_value_t = 100_000, value_parser = super::child::cases_parser(crate::oracle::cases::MAX_CASES_U64))]
    pub cases: usize,
    /// The mapping, the seed and the time limit.
    #[command(flatten)]
    pub options: super::child::CheckOptions,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
    /// Run in this process (the child does; a crash then takes this process down).
    #[arg(long, hide = true)]
    pub in_process: bool,
}

fn read(path: &std::path::Path, what: &str) -> Result<String, CliError> {
    let bytes = super::input::read_limited(path, check::MAX_SOURCE_BYTES).map_err(|e| {
        match e.strip_prefix("cannot read: ") {
            Some(why) => CliError::Input(format!("cannot read {what} {}: {why}", path.display())),
            None => CliError::Input(format!("{what} {}: {e}", path.display())),
        }
    })?;
    crate::exercises::text_of(&bytes).map_err(|e| CliError::Input(format!("{what} {}: {e}", path.display())))
}

/// The verdict of a shader whose output is not graded, as printed by `check-shader` and
/// `exercise check`: `verdict: WORD` and the sentence `why` (already in the command line's
/// language), or JSON `{verdict, error}` with the other keys empty, as a compile error's.
/// `verdict` is one of [`super::child::VERDICTS`]; JSON has it in lower case.
///
/// Errors: stdout closed or full ([`super::output::println`]).
fn print_refused(file: &std::path::Path, verdict: &str, why: &str, format: Format) -> Result<(), CliError> {
    use super::child::VERDICT_LINE;
    use crate::checker::texts::tr_fill;
    match format {
        Format::Text => {
            let shown = tr_fill(VERDICT_LINE, &[&crate::checker::texts::tr(verdict)]);
            super::output::println(format!("{shown}\n{}: {why}", file.display()))
        }
        Format::Json => super::output::println(serde_json::json!({
            "verdict": verdict.to_lowercase(),
            "error": why,
            "stats": null,
            "counterexamples": [],
            "diagnosis": [],
        })),
    }
}

/// The verdict of a check that ended without grading the output, or `None` for the other
/// errors: a loop past the loop guard's cap ([`CheckError::DoesNotTerminate`]), or a
/// broken exercise rule ([`CheckError::BreaksRule`]).
///
/// Errors: stdout closed or full.
pub fn print_ungraded(file: &std::path::Path, e: &CheckError, format: Format) -> Option<Result<(), CliError>> {
    use super::child::{DOES_NOT_TERMINATE, VERDICTS};
    use crate::checker::texts::tr_fill;
    match e {
        CheckError::DoesNotTerminate { cases, of } => {
            let cap = crate::checker::check::loops::LOOP_CAP.to_string();
            let why = tr_fill(DOES_NOT_TERMINATE, &[&cap, &cases.to_string(), &of.to_string()]);
            Some(print_refused(file, VERDICTS[3], &why, format))
        }
        CheckError::BreaksRule { rule: (msgid, name) } => {
            Some(print_refused(file, VERDICTS[4], &tr_fill(msgid, &[name]), format))
        }
        _ => None,
    }
}

/// The note under a compile error when the file is no shader at all (an answer file, a
/// note to the teacher): it has no `main` and no `;`.
pub const NOT_A_SHADER: &str =
    "note: this file has no main() and no statement: it is not a shader (an answer file?); this check wants a \
     fragment shader";

/// Whether `text` cannot be a shader: no `main` and no `;` anywhere (a number, a letter, a
/// sentence).
#[must_use]
pub fn not_a_shader(text: &str) -> bool {
    crate::checker::check::glsl::parse(text).main.is_none() && !text.contains(';')
}

/// A compile error as printed by `check-shader` and `exercise check`; JSON when asked.
///
/// Errors: stdout closed or full ([`super::output::println`]).
/// `file` is the shader that did not compile and `text` its text, as the check read it.
pub fn print_compile_error(
    file: &std::path::Path,
    text: &str,
    log: &str,
    excerpt: &str,
    format: Format,
) -> Result<(), CliError> {
    match format {
        Format::Text => {
            use super::child::{VERDICTS, VERDICT_LINE};
            use crate::checker::texts::{tr, tr_fill};
            let verdict = tr_fill(VERDICT_LINE, &[&tr(VERDICTS[2])]);
            let note = if not_a_shader(text) { format!("\n{}", tr(NOT_A_SHADER)) } else { String::new() };
            let log = crate::checker::texts::compile_log(log);
            super::output::println(format!("{verdict}\n{}:\n{}\n{excerpt}{note}", file.display(), log.trim_end()))
        }
        Format::Json => {
            let v = serde_json::json!({
                "verdict": "does not compile",
                "compile_error": { "log": log.trim_end(), "lines": excerpt },
                "stats": null,
                "counterexamples": [],
                "diagnosis": [],
            });
            super::output::println(v)
        }
    }
}

fn check_error(e: CheckError) -> CliError {
    match e {
        CheckError::Usage(m) => CliError::Input(m),
        other => CliError::Internal(other.to_string()),
    }
}

/// Runs the check and prints the verdict (see the module docs for the exit status).
pub fn run(args: &CheckShaderArgs) -> CliResult {
    let source = read(&args.file, "shader")?;
    let mapping = match &args.options.uniforms {
        None => Mapping::default(),
        Some(path) => check::parse_mapping(&read(path, "mapping")?)
            .map(|m| Mapping { file: Some(path.display().to_string()), ..m })
            .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?,
    };
    match &args.vertex {
        Some(_) => check::pair::PairModel::for_model(args.model).map(|_| ()),
        None => check::model_for_check(args.model).map(|_| ()),
    }
    .and_then(|()| check::check_cases(args.cases))
    .map_err(check_error)?;
    if args.in_process {
        super::child::report_memory_faults();
        let vertex = match &args.vertex {
            Some(path) => Some(read(path, "vertex shader")?),
            None => None,
        };
        run_here(args, Submission { fragment: &source, vertex: vertex.as_deref() }, &mapping)
    } else {
        run_in_child(args)
    }
}

fn run_here(args: &CheckShaderArgs, submission: Submission<'_>, mapping: &Mapping) -> CliResult {
    let ctx = GlContext::new().map_err(|e| CliError::Internal(format!("no OpenGL context: {e}")))?;
    match diagnose::check_and_diagnose(&ctx, submission, args.model, mapping, args.cases, args.options.seed) {
        Ok(d) => {
            let files = match &args.vertex {
                Some(v) => format!("{} with {}", args.file.display(), v.display()),
                None => args.file.display().to_string(),
            };
            match args.format {
                Format::Text => super::output::println(format!("{files}: {}", d.format().trim_end()))?,
                Format::Json => super::output::println(d.to_json())?,
            }
            Ok(Outcome::from_ok(d.agrees()))
        }
        Err(CheckError::Compile { log, excerpt }) => {
            print_compile_error(&args.file, submission.fragment, &log, &excerpt, args.format)?;
            Ok(Outcome::Problems)
        }
        Err(CheckError::VertexCompile { log, excerpt }) => {
            let vertex = args.vertex.as_deref().unwrap_or(&args.file);
            print_compile_error(vertex, submission.vertex.unwrap_or_default(), &log, &excerpt, args.format)?;
            Ok(Outcome::Problems)
        }
        Err(e) => match print_ungraded(&args.file, &e, args.format) {
            Some(printed) => printed.map(|()| Outcome::Problems),
            None => Err(check_error(e)),
        },
    }
}

/// Runs this binary with `--in-process` on the same arguments and relays it
/// ([`super::child::relay`]).
fn run_in_child(args: &CheckShaderArgs) -> CliResult {
    let mut cmd = super::child::this_binary()?;
    cmd.arg("check-shader").arg(&args.file).arg("--model").arg(args.model.name());
    args.options.forward(&mut cmd);
    if let Some(v) = &args.vertex {
        cmd.arg("--vertex").arg(v);
    }
    cmd.args(["--cases", &args.cases.to_string(), "--in-process"]);
    if args.format == Format::Json {
        cmd.args(["--format", "json"]);
    }
    super::child::relay(cmd, args.options.limits(), &args.file, args.format == Format::Json)
}
