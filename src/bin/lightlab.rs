//! `lightlab`: the command line of the lightlab crate.
//!
//! With no subcommand it builds the book, exactly as `lightlab book` does, so
//! `cargo run --release` from the repository root produces `book/build/`.
//!
//! The book directory (the one holding `book.toml`) is `--root DIR`, or else the
//! `book/` directory found from the working directory upward, as cargo finds
//! `Cargo.toml` ([`lightlab::cli::find_book_dir`]); never the checkout the binary
//! was compiled in.

use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand};
use std::path::PathBuf;

use lightlab::cli::{self, CliError, CliResult, Outcome};
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
of the built index.html. It finds the book from the working directory upward (book/book.toml, \
as cargo finds Cargo.toml); elsewhere pass --root DIR.",
    after_help = cli::EXIT_STATUS_HELP
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,

    #[command(flatten)]
    book: BookArgs,

    /// The language of the verdicts, diagnoses and statements (exercise, check-shader,
    /// grade): en, fr or uk. Default: LIGHTLAB_LANG, else the first of LC_ALL, LC_MESSAGES
    /// and LANG that is set (uk_UA.UTF-8 gives uk); other locales give English. JSON keys
    /// and mistake ids stay English.
    #[arg(long, global = true, value_name = "LANG")]
    lang: Option<lightlab::i18n::Lang>,

    /// Print all three hints of each mistake the checker names (exercise check,
    /// check-shader), or of where the isolation step found the difference when no mistake
    /// of the catalogue matches: where to look, the idea, the fix. Without it, the first hint.
    #[arg(long, global = true)]
    hints: bool,
}

/// The subcommands. Add a variant and a match arm in `run` to add one; its help gets
/// the exit-status table from [`with_exit_status_help`].
#[derive(Subcommand, Debug)]
enum Command {
    /// Build the book (also what `lightlab` with no subcommand does).
    Book(BookArgs),
    /// Shade fragments given as JSON lines (stdin or a file); print one JSON line per case.
    Shade(cli::shade::ShadeArgs),
    /// Render a preset or a scene file to a PNG with the CPU rasterizer.
    Render(cli::render::RenderArgs),
    /// Time the benchmark scenes (same output format as llvmpipe_bench.py).
    Bench(cli::bench::BenchArgs),
    /// Run a fragment shader on Mesa llvmpipe against a lighting model (exit 0 agrees,
    /// 1 disagrees, 2 usage error).
    #[cfg(feature = "gl")]
    CheckShader(cli::check_shader::CheckShaderArgs),
    /// Run the randomized OpenGL oracle and print the per-model error table.
    #[cfg(feature = "gl")]
    Oracle(cli::oracle::OracleArgs),
    /// The exercises: list, show, check an answer (exit 0 right, 1 wrong, 2 usage error).
    #[cfg(feature = "gl")]
    Exercise(cli::exercise::ExerciseArgs),
    /// Grade a class folder (a file, a pair or a folder per student) against an exercise or an
    /// assignment: CSV, JSON, Gradescope, PrairieLearn or a Moodle worksheet; feedback pages.
    #[cfg(feature = "gl")]
    Grade(cli::grade::GradeArgs),
    /// Run the speed-against-accuracy study; print its tables and write its CSVs.
    Study(cli::study::StudyArgs),
    /// The translations: re-extract po/messages.pot and merge it into the PO files, or check them.
    I18n(cli::i18n::I18nArgs),
}

/// Options of `lightlab book`.
#[derive(Args, Debug, Clone)]
struct BookArgs {
    /// The book directory, holding book.toml [default: the book/ directory of the
    /// project found from the working directory upward, as cargo finds Cargo.toml]
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,

    /// Regenerate every figure and table, ignoring the cache.
    #[arg(long)]
    force: bool,

    /// Print only the path of index.html (and errors).
    #[arg(long, short)]
    quiet: bool,

    /// Leave the exercises' reference solutions out (for a course that grades them): the
    /// appendix's folded solutions and the page data's `solution`. The in-page checker
    /// still carries its reference shader (see the book's appendix "Grading a class").
    #[arg(long)]
    no_solutions: bool,
}

fn main() -> ExitCode {
    cli::install_panic_hook();
    // A panic anywhere below is reported by the hook and exits 3, never 101.
    std::panic::catch_unwind(main_unguarded).unwrap_or(ExitCode::from(cli::PANIC_STATUS))
}

fn main_unguarded() -> ExitCode {
    // The exit-status tests need a panic on demand to check that it exits 3.
    if std::env::var_os("LIGHTLAB_TEST_PANIC").is_some() {
        panic!("LIGHTLAB_TEST_PANIC is set");
    }
    let parsed = with_exit_status_help(Cli::command()).try_get_matches().and_then(|m| Cli::from_arg_matches(&m));
    let cli = match parsed {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version print to stdout and succeed; usage errors exit 2.
            let status = if e.use_stderr() { 2 } else { 0 };
            return match e.print() {
                Ok(()) => ExitCode::from(status),
                // `lightlab --help > /dev/full`: the help could not be written.
                Err(err) => cli::exit_code("", Err(cli::output::stdout_error(err))),
            };
        }
    };
    if let (Some(_), Some(flag)) = (&cli.command, book_flag(&cli.book)) {
        // The global --lang and --hints may come before a subcommand; the book's may not.
        eprintln!("error: {flag} builds the book: give it without a subcommand, or after `book`");
        return ExitCode::from(2);
    }
    init_logging();
    set_language(cli.lang);
    if cli.hints {
        // SAFETY: called once at start, before any thread is spawned (edition 2021: safe fn);
        // the checking children read it too.
        std::env::set_var(lightlab::checker::hints::HINTS_VAR, "all");
    }
    run(cli)
}

/// The first book option given before a subcommand (`lightlab --root x shade`), if any.
fn book_flag(book: &BookArgs) -> Option<&'static str> {
    [
        (book.root.is_some(), "--root"),
        (book.force, "--force"),
        (book.quiet, "--quiet"),
        (book.no_solutions, "--no-solutions"),
    ]
    .into_iter()
    .find_map(|(given, flag)| given.then_some(flag))
}

/// The output language: `--lang`, else `LIGHTLAB_LANG`, else the locale. An explicit choice
/// is put into `LIGHTLAB_LANG` for the child processes that check shaders.
fn set_language(flag: Option<lightlab::i18n::Lang>) {
    use lightlab::i18n::Lang;
    let from_var = std::env::var("LIGHTLAB_LANG").ok().and_then(|v| v.parse::<Lang>().ok());
    let lang = flag.or(from_var).unwrap_or_else(Lang::from_env);
    if flag.is_some() {
        // SAFETY: called once at start, before any thread is spawned (edition 2021: safe fn).
        std::env::set_var("LIGHTLAB_LANG", lang.code());
        lightlab::i18n::set_output_lang_explicit();
    }
    lightlab::i18n::set_output_lang(lang);
}

/// Every subcommand's help ends with the exit-status table: after its own notes, unless
/// those already state its exit statuses (as `shade`'s do).
fn with_exit_status_help(command: clap::Command) -> clap::Command {
    command.mut_subcommands(|sub| match sub.get_after_help().map(|h| h.to_string()) {
        Some(own) if own.contains("EXIT STATUS") => sub,
        Some(own) => sub.after_help(format!("{own}\n\n{}", cli::EXIT_STATUS_HELP)),
        None => sub.after_help(cli::EXIT_STATUS_HELP),
    })
}

/// Dispatch a subcommand; every result goes through the one mapping [`cli::exit_code`].
fn run(cli: Cli) -> ExitCode {
    match cli.command {
        None => cli::exit_code("book", book(&cli.book)),
        Some(Command::Book(args)) => cli::exit_code("book", book(&args)),
        Some(Command::Shade(args)) => cli::exit_code("shade", cli::shade::run(&args)),
        Some(Command::Render(args)) => cli::exit_code("render", boxed(cli::render::run(&args))),
        Some(Command::Bench(args)) => cli::exit_code("bench", boxed(cli::bench::run(&args))),
        #[cfg(feature = "gl")]
        Some(Command::CheckShader(args)) => cli::exit_code("check-shader", cli::check_shader::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Oracle(args)) => cli::exit_code("oracle", cli::oracle::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Exercise(args)) => cli::exit_code("exercise", cli::exercise::run(&args)),
        #[cfg(feature = "gl")]
        Some(Command::Grade(args)) => cli::exit_code("grade", cli::grade::run(&args)),
        Some(Command::Study(args)) => cli::exit_code("study", cli::study::run(&args)),
        Some(Command::I18n(args)) => cli::exit_code("i18n", cli::i18n::run(&args)),
    }
}

/// Adapter for a subcommand that still returns `Result<(), Box<dyn Error>>`: see
/// [`CliError::from_boxed`].
fn boxed(result: Result<(), Box<dyn std::error::Error>>) -> CliResult {
    result.map(|()| Outcome::Success).map_err(CliError::from_boxed)
}

/// `lightlab book`: build, then print the path of the built `index.html` on stdout.
fn book(args: &BookArgs) -> CliResult {
    let root = match &args.root {
        Some(root) => root.clone(),
        None => cli::find_book_dir()
            .map_err(|e| CliError::Usage(format!("{e}, or pass --root DIR (the directory holding book.toml)")))?,
    };
    if !root.join("book.toml").is_file() {
        return Err(CliError::Usage(format!("--root {}: no book.toml in that directory", root.display())));
    }
    let opts =
        lightlab::book::BuildOptions { root, force: args.force, quiet: args.quiet, no_solutions: args.no_solutions };
    let report = lightlab::book::build(&opts).map_err(|e| {
        if e.is_user_error() {
            CliError::Input(e.to_string())
        } else {
            CliError::Internal(e.to_string())
        }
    })?;
    let index = report.index_html.canonicalize().unwrap_or(report.index_html);
    cli::output::println(index.display())?;
    Ok(Outcome::Success)
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
