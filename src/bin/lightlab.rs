//! The `lightlab` command line.

use clap::{Parser, Subcommand};

/// Teaches and verifies the lighting math of real-time graphics.
#[derive(Debug, Parser)]
#[command(name = "lightlab", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Run a fragment shader on Mesa llvmpipe against a lighting model.
    #[cfg(feature = "gl")]
    CheckShader(lightlab::cli::check_shader::CheckShaderArgs),
    /// Run the randomized OpenGL oracle and print the per-model error table.
    #[cfg(feature = "gl")]
    Oracle(lightlab::cli::oracle::OracleArgs),
}

fn main() {
    let cli = Cli::parse();
    let code = match cli.command {
        #[cfg(feature = "gl")]
        Some(Command::CheckShader(args)) => lightlab::cli::check_shader::run(&args),
        #[cfg(feature = "gl")]
        Some(Command::Oracle(args)) => lightlab::cli::oracle::run(&args),
        None => {
            eprintln!("lightlab: no subcommand given (see --help)");
            2
        }
    };
    std::process::exit(code);
}
