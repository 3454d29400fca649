//! `lightlab oracle`: run the randomized OpenGL oracle and print the per-model table, or
//! print the models' packed layouts as JSON (`--layouts`, no OpenGL needed; the schema is
//! in [`crate::gl::layout`]).
//!
//! Exit status: 0 when every model is within its bound (or the layouts were printed), 1
//! when one is not, 2 on a usage error (`--cases` outside 1 to 10^6), 3 when OpenGL is
//! missing, a draw fails or stdout cannot be written.

use super::{CliError, CliResult, Outcome};
use crate::gl::{layout, GlContext};
use crate::oracle::{self, cases};

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
    /// Cases per model (1 to 10^6).
    #[arg(long, default_value_t = oracle::DEFAULT_CASES, value_parser = super::child::cases_parser(cases::MAX_CASES_U64))]
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

/// Runs the oracle (or prints the layouts); see the module docs for the exit status.
pub fn run(args: &OracleArgs) -> CliResult {
    if args.layouts {
        super::output::print(layout::export_json())?;
        return Ok(Outcome::Success);
    }
    if args.cases == 0 || args.cases > cases::MAX_CASES {
        return Err(CliError::Usage(format!("--cases must be in 1..={} (got {})", cases::MAX_CASES, args.cases)));
    }
    let ctx = GlContext::new().map_err(|e| CliError::Internal(format!("no OpenGL context: {e}")))?;
    let report = oracle::run(&ctx, args.cases, args.seed).map_err(|e| CliError::Internal(e.to_string()))?;
    let text = match args.format {
        OracleFormat::Text => oracle::format_text(&report),
        OracleFormat::Markdown => oracle::format_markdown(&report),
    };
    super::output::print(text)?;
    Ok(Outcome::from_ok(report.passes()))
}
