//! `lightlab`: the command line of the lightlab crate.
//!
//! With no subcommand it builds the book, exactly as `lightlab book` does, so
//! `cargo run --release` from the repository root produces `book/build/`.
//!
//! The book directory (the one holding `book.toml`) is, in order: `--root DIR`;
//! `./book` when the current directory has `book/book.toml` (the repository root);
//! otherwise the `book/` directory of the crate this binary was compiled from
//! (`CARGO_MANIFEST_DIR` at compile time).

use clap::{Args, Parser, Subcommand};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The lighting math of real-time graphics, verified.
#[derive(Parser, Debug)]
#[command(
    name = "lightlab",
    version,
    about = "The lighting math of real-time graphics, verified.",
    long_about = "The lighting math of real-time graphics (LearnOpenGL Lighting, opengl-tutorial 8, \
ogldev 19), implemented, verified and explained.\n\n\
With no subcommand, lightlab builds the book: it generates every figure and table into \
book/src/generated/, renders the HTML (mdBook + KaTeX, fully offline) and prints the path \
of the built index.html. Run it from the repository root, or pass --root.",
    args_conflicts_with_subcommands = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,

    #[command(flatten)]
    book: BookArgs,
}

/// The subcommands. Add a variant and a match arm in `run` to add one.
#[derive(Subcommand, Debug)]
enum Command {
    /// Build the book (also what `lightlab` with no subcommand does).
    Book(BookArgs),
    /// Shade fragments given as JSON lines (stdin or a file); print one JSON line per case.
    Shade(lightlab::cli::shade::ShadeArgs),
    /// Render a preset or a scene file to a PNG with the CPU rasterizer.
    Render(lightlab::cli::render::RenderArgs),
    /// Time the benchmark scenes (same output format as llvmpipe_bench.py).
    Bench(lightlab::cli::bench::BenchArgs),
    /// Run a fragment shader on Mesa llvmpipe against a lighting model (exit 0 agrees,
    /// 1 disagrees, 2 usage error).
    #[cfg(feature = "gl")]
    CheckShader(lightlab::cli::check_shader::CheckShaderArgs),
    /// Run the randomized OpenGL oracle and print the per-model error table.
    #[cfg(feature = "gl")]
    Oracle(lightlab::cli::oracle::OracleArgs),
    /// The exercises: list, show, check an answer (exit 0 right, 1 wrong, 2 usage error).
    #[cfg(feature = "gl")]
    Exercise(lightlab::cli::exercise::ExerciseArgs),
    /// Grade a directory of answers to one exercise: one CSV or JSON row per file.
    #[cfg(feature = "gl")]
    Grade(lightlab::cli::grade::GradeArgs),
    /// Run the speed-against-accuracy study; print its tables and write its CSVs.
    Study(lightlab::cli::study::StudyArgs),
}

/// Options of `lightlab book`.
#[derive(Args, Debug, Clone)]
struct BookArgs {
    /// The book directory, holding book.toml [default: ./book if it exists, else the
    /// book/ directory of the source tree this binary was built from]
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,

    /// Regenerate every figure and table, ignoring the cache.
    #[arg(long)]
    force: bool,

    /// Print only the path of index.html (and errors).
    #[arg(long, short)]
    quiet: bool,
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version print to stdout and succeed; usage errors fail.
            let _ = e.print();
            // Usage errors exit with 2, as every subcommand documents.
            return if e.use_stderr() { ExitCode::from(2) } else { ExitCode::SUCCESS };
        }
    };
    init_logging();
    run(cli)
}

/// Dispatch a subcommand; each returns its own exit status.
fn run(cli: Cli) -> ExitCode {
    match cli.command {
        None => report(book(&cli.book)),
        Some(Command::Book(args)) => report(book(&args)),
        Some(Command::Shade(args)) => lightlab::cli::shade::run(&args),
        Some(Command::Render(args)) => report(lightlab::cli::render::run(&args).map_err(|e| e.to_string())),
        Some(Command::Bench(args)) => report(lightlab::cli::bench::run(&args).map_err(|e| e.to_string())),
        #[cfg(feature = "gl")]
        Some(Command::CheckShader(args)) => exit_code(lightlab::cli::check_shader::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Oracle(args)) => exit_code(lightlab::cli::oracle::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Exercise(args)) => exit_code(lightlab::cli::exercise::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Grade(args)) => exit_code(lightlab::cli::grade::run(&args)),
        Some(Command::Study(args)) => report(lightlab::cli::study::run(&args)),
    }
}

/// An `i32` status (0, 1 or 2) as an `ExitCode`.
#[cfg(feature = "gl")]
fn exit_code(code: i32) -> ExitCode {
    ExitCode::from(u8::try_from(code).unwrap_or(2))
}

/// Print an error of a subcommand that returns `Result` and map it to exit status 1.
fn report(result: Result<(), String>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("lightlab: error: {e}");
            ExitCode::FAILURE
        }
    }
}

/// `lightlab book`: build, then print the path of the built `index.html` on stdout.
fn book(args: &BookArgs) -> Result<(), String> {
    let root = args.root.clone().unwrap_or_else(default_root);
    let opts = lightlab::book::BuildOptions { root, force: args.force, quiet: args.quiet };
    let report = lightlab::book::build(&opts)?;
    let index = report.index_html.canonicalize().unwrap_or(report.index_html);
    println!("{}", index.display());
    Ok(())
}

/// `./book` when the current directory holds `book/book.toml`, else the source tree's.
fn default_root() -> PathBuf {
    let here = Path::new("book");
    if here.join("book.toml").is_file() {
        here.to_path_buf()
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("book")
    }
}

/// Show warnings of the libraries (mdBook's missing includes, for example) on stderr.
/// `RUST_LOG` overrides the level, e.g. `RUST_LOG=info`.
fn init_logging() {
    use tracing_subscriber::filter::{EnvFilter, LevelFilter};
    let filter = EnvFilter::builder().with_default_directive(LevelFilter::WARN.into()).from_env_lossy();
    let _ = tracing_subscriber::fmt()
        .with_writer(std::io::stderr)
        .with_env_filter(filter)
        .with_ansi(std::io::IsTerminal::is_terminal(&std::io::stderr()))
        .without_time()
        .with_target(false)
        .try_init();
}
