//! The `lightlab` command line (minimal dispatcher on the `tables` branch;
//! the book branch's rewrite adds the other subcommands).

use std::process::ExitCode;

use clap::{Parser, Subcommand};

/// Teaches and verifies the lighting math of real-time graphics.
#[derive(Parser)]
#[command(name = "lightlab", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Shade fragments given as JSON lines (stdin or a file); print one JSON line per case.
    Shade(lightlab::cli::shade::ShadeArgs),
}

fn main() -> ExitCode {
    match Cli::parse().command {
        Some(Command::Shade(args)) => lightlab::cli::shade::run(&args),
        None => {
            eprintln!("lightlab: no subcommand given; try `lightlab --help`");
            ExitCode::from(2)
        }
    }
}
