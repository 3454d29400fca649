//! `lightlab check-shader FILE.frag --model NAME`: run a user's fragment shader on Mesa
//! llvmpipe over random cases of a model and compare it with the `f64` reference.
//! The logic is in [`crate::gl::check`].
//!
//! When the shader disagrees, the output leads with the diagnosis in plain words: the
//! catalogue mistakes whose mutants reproduce its output, or the term, light and inputs the
//! difference is confined to ([`crate::gl::diagnose`]). `--format json` prints one object
//! `{verdict, model, stats, counterexamples, notes, diagnosis: [{id, title, evidence, link}]}`
//! (a compile error adds `compile_error: {log, lines}`).
//!
//! Exit status: 0 when the shader agrees on every defined case, 1 when it does not (or does
//! not compile: the driver's errors are printed with the file's line numbers), 2 on a usage
//! error (unknown model, unreadable, empty or binary file, bad mapping, a name the model
//! does not know) or when OpenGL is missing.

use std::path::PathBuf;

use crate::gl::check::{self, CheckError, Mapping};
use crate::gl::diagnose;
use crate::gl::GlContext;

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
    /// point, spot, multiple_lights, opengl_tutorial8, ogldev19, normal_matrix.
    #[arg(long)]
    pub model: String,
    /// A TOML file mapping the shader's names to the model's (`[names]`) and fixing
    /// quantities the shader hard-codes (`[values]`).
    #[arg(long, value_name = "FILE.toml")]
    pub uniforms: Option<PathBuf>,
    /// Number of random cases.
    #[arg(long, default_value_t = 100_000)]
    pub cases: usize,
    /// Seed of the case generator.
    #[arg(long, default_value_t = crate::gl::cases::DEFAULT_SEED)]
    pub seed: u64,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
}

fn read(path: &PathBuf, what: &str) -> Result<String, String> {
    let bytes = std::fs::read(path).map_err(|e| format!("cannot read {what} {}: {e}", path.display()))?;
    crate::exercises::text_of(&bytes).map_err(|e| format!("{what} {}: {e}", path.display()))
}

/// A compile error as printed by `check-shader` and `exercise check`; JSON when asked.
///
/// Errors: stdout closed or full ([`super::output::println`]).
pub fn print_compile_error(
    file: &std::path::Path,
    log: &str,
    excerpt: &str,
    format: Format,
) -> Result<(), super::CliError> {
    match format {
        Format::Text => super::output::println(format!(
            "verdict: DOES NOT COMPILE\n{}:\n{}\n{excerpt}",
            file.display(),
            log.trim_end()
        )),
        Format::Json => {
            let v = serde_json::json!({
                "verdict": "disagrees",
                "compile_error": { "log": log.trim_end(), "lines": excerpt },
                "stats": null,
                "counterexamples": [],
                "diagnosis": [],
            });
            super::output::println(v)
        }
    }
}

/// Runs the check and prints the verdict; returns the exit status (0, 1 or 2).
pub fn run(args: &CheckShaderArgs) -> i32 {
    let source = match read(&args.file, "shader") {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return 2;
        }
    };
    let mapping = match &args.uniforms {
        None => Mapping::default(),
        Some(path) => match read(path, "mapping").map_err(CheckError::Usage).and_then(|t| check::parse_mapping(&t)) {
            Ok(m) => m,
            Err(e) => {
                let name = path.display();
                eprintln!("error: {name}: {e}");
                return 2;
            }
        },
    };
    if let Err(e) = check::model_for_check(&args.model) {
        eprintln!("error: {e}");
        return 2;
    }
    if args.cases == 0 {
        eprintln!("error: --cases must be at least 1");
        return 2;
    }
    let ctx = match GlContext::new() {
        Ok(ctx) => ctx,
        Err(e) => {
            eprintln!("error: no OpenGL context: {e}");
            return 2;
        }
    };
    match diagnose::check_and_diagnose(&ctx, &source, &args.model, &mapping, args.cases, args.seed) {
        Ok(d) => {
            let text = match args.format {
                Format::Text => format!("{}: {}", args.file.display(), d.format().trim_end()),
                Format::Json => d.to_json().to_string(),
            };
            if let Err(e) = super::output::println(text) {
                return super::output::report_status(e);
            }
            i32::from(!d.agrees())
        }
        Err(CheckError::Compile { log, excerpt }) => {
            if let Err(e) = print_compile_error(&args.file, &log, &excerpt, args.format) {
                return super::output::report_status(e);
            }
            1
        }
        Err(e) => {
            eprintln!("error: {e}");
            2
        }
    }
}
