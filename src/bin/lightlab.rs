//! The `lightlab` command line.

#[cfg(feature = "book")]
mod app {
    use clap::{Parser, Subcommand};

    /// lightlab: the lighting math of real-time graphics, implemented and verified.
    #[derive(Parser)]
    #[command(name = "lightlab", version)]
    pub struct Cli {
        #[command(subcommand)]
        pub command: Option<Command>,
    }

    /// Subcommands.
    #[derive(Subcommand)]
    pub enum Command {
        /// Render a preset or a scene file to a PNG with the CPU rasterizer.
        Render(lightlab::cli::render::RenderArgs),
        /// Time the benchmark scenes (same output format as llvmpipe_bench.py).
        Bench(lightlab::cli::bench::BenchArgs),
    }

    pub fn main() -> std::process::ExitCode {
        let cli = Cli::parse();
        let result = match &cli.command {
            Some(Command::Render(a)) => lightlab::cli::render::run(a),
            Some(Command::Bench(a)) => lightlab::cli::bench::run(a),
            None => Ok(()),
        };
        match result {
            Ok(()) => std::process::ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("error: {e}");
                std::process::ExitCode::FAILURE
            }
        }
    }
}

#[cfg(feature = "book")]
fn main() -> std::process::ExitCode {
    app::main()
}

#[cfg(not(feature = "book"))]
fn main() {
    eprintln!("lightlab was built without the `book` feature: no command line");
}
