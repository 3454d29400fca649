//! `lightlab oracle`: run the randomized OpenGL oracle and print the per-model table, or
//! print the models' packed layouts as JSON (`--layouts`, no OpenGL needed; the schema is
//! in [`crate::gl::layout`]).
//!
//! Exit status: 0 when every model is within its bound (or the layouts were printed), 1
//! when one is not, 2 on a usage error (`--cases` outside 1 to 10^7), 3 when OpenGL is
//! missing, a draw fails or stdout cannot be written.

use crate::gl::{cases, layout, oracle, GlContext};

/// Output format of `lightlab oracle`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum OracleFormat {
    /// Fixed-width text.
    Text,
    /// Markdown (the book's table).
    Markdown,
}

/// Arguments of `lightlab oracle`.
#[derive(Debug, Clone, clap::Args)]
pub struct OracleArgs {
    /// Cases per model (1 to 10^7).
    #[arg(long, default_value_t = oracle::DEFAULT_CASES)]
    pub cases: usize,
    /// Seed of the case generator.
    #[arg(long, default_value_t = cases::DEFAULT_SEED)]
    pub seed: u64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = OracleFormat::Text)]
    pub format: OracleFormat,
    /// Print every model's packed layout as JSON instead of running the oracle.
    #[arg(long)]
    pub layouts: bool,
}

/// Writes `text` to stdout through [`super::output`]: a closed pipe is quiet, a full
/// stdout is a message; either way the exit status is the one [`super::output`] documents.
fn emit(text: &str) -> i32 {
    match super::output::print(text) {
        Ok(()) => 0,
        Err(e) => super::output::report_status(e),
    }
}

/// Runs the oracle (or prints the layouts); returns the exit status (see the module docs).
pub fn run(args: &OracleArgs) -> i32 {
    if args.layouts {
        return emit(&layout::export_json());
    }
    if args.cases == 0 || args.cases > cases::MAX_CASES {
        eprintln!("error: --cases must be in 1..={} (got {})", cases::MAX_CASES, args.cases);
        return 2;
    }
    let ctx = match GlContext::new() {
        Ok(ctx) => ctx,
        Err(e) => {
            eprintln!("error: no OpenGL context: {e}");
            return 3;
        }
    };
    match oracle::run(&ctx, args.cases, args.seed) {
        Ok(report) => {
            let text = match args.format {
                OracleFormat::Text => oracle::format_text(&report),
                OracleFormat::Markdown => oracle::format_markdown(&report),
            };
            if let Err(e) = super::output::print(text) {
                return super::output::report_status(e);
            }
            i32::from(!report.passes())
        }
        Err(e) => {
            eprintln!("error: {e}");
            3
        }
    }
}
