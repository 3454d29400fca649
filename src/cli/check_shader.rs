//! `lightlab check-shader FILE.frag --model NAME`: run a user's fragment shader on Mesa
//! llvmpipe over random cases of a model and compare it with the `f64` reference.
//! The logic is in [`crate::gl::check`].
//!
//! Exit status: 0 when the shader agrees on every defined case, 1 when it does not (or does
//! not compile: the driver's errors are printed with the file's line numbers), 2 on a usage
//! error (unknown model, unreadable file, bad mapping, a name the model does not know) or
//! when OpenGL is missing.

use std::path::PathBuf;

use crate::gl::check::{self, CheckError, Mapping};
use crate::gl::GlContext;

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
}

fn read(path: &PathBuf, what: &str) -> Result<String, String> {
    std::fs::read_to_string(path).map_err(|e| format!("cannot read {what} {}: {e}", path.display()))
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
    match check::check_shader(&ctx, &source, &args.model, &mapping, args.cases, args.seed) {
        Ok(report) => {
            let text = format!("{}: {}", args.file.display(), report.format().trim_end());
            if let Err(e) = super::output::println(text) {
                return super::output::report_status(e);
            }
            i32::from(!report.agrees())
        }
        Err(CheckError::Compile { log, excerpt }) => {
            let text = format!("verdict: DOES NOT COMPILE\n{}:\n{}\n{excerpt}", args.file.display(), log.trim_end());
            if let Err(e) = super::output::println(text) {
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
