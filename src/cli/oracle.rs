//! `lightlab oracle`: run the randomized OpenGL oracle and print the per-model table.

use crate::gl::{cases, oracle, GlContext};

/// Output format of `lightlab oracle`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// Fixed-width text.
    Text,
    /// Markdown (the book's table).
    Markdown,
}

/// Arguments of `lightlab oracle`.
#[derive(Debug, Clone, clap::Args)]
pub struct OracleArgs {
    /// Cases per model.
    #[arg(long, default_value_t = oracle::DEFAULT_CASES)]
    pub cases: usize,
    /// Seed of the case generator.
    #[arg(long, default_value_t = cases::DEFAULT_SEED)]
    pub seed: u64,
    /// Output format.
    #[arg(long, value_enum, default_value_t = Format::Text)]
    pub format: Format,
}

/// Runs the oracle; exit status 0 when every model is within its bound, 1 when one is
/// not, 2 when OpenGL is missing or a draw fails.
pub fn run(args: &OracleArgs) -> i32 {
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
    match oracle::run(&ctx, args.cases, args.seed) {
        Ok(report) => {
            let text = match args.format {
                Format::Text => oracle::format_text(&report),
                Format::Markdown => oracle::format_markdown(&report),
            };
            if let Err(e) = super::output::print(text) {
                return super::output::report_status(e);
            }
            i32::from(!report.passes())
        }
        Err(e) => {
            eprintln!("error: {e}");
            2
        }
    }
}
