//! `lightlab`: the command line of the lightlab crate.
//!
//! With no subcommand it builds the book, exactly as `lightlab book` does, so
//! `cargo run --release` from the repository root produces `book/build/`.
//!
//! The book directory (the one holding `book.toml`) is `--root DIR`, or else the
//! `book/` directory found from the working directory upward, as cargo finds
//! `Cargo.toml` ([`lightlab::cli::find_book_dir`]); never the checkout the binary
//! was compiled in.

use clap::FromArgMatches;

use lightlab::cli::args::{BookArgs, Cli, Command};
use lightlab::cli::{self, CliError, CliResult, Outcome};
use std::io::Write;
use std::process::ExitCode;

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
    // The help is printed while parsing, so its language is read from the raw arguments.
    let lang = cli::help::requested_lang(std::env::args_os());
    let parsed = cli::args::command(lang).try_get_matches().and_then(|m| Cli::from_arg_matches(&m));
    let cli = match parsed {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version print to stdout and succeed; usage errors exit 2.
            let status = if e.use_stderr() { 2 } else { 0 };
            if let Some(text) = cli::usage_error::localized(&e, lang) {
                // Not eprint!: it panics when standard error is closed.
                let _ = std::io::Write::write_all(&mut std::io::stderr(), text.as_bytes());
                return ExitCode::from(status);
            }
            return match e.print() {
                Ok(()) => ExitCode::from(status),
                // `lightlab --help > /dev/full`: the help could not be written.
                Err(err) => cli::exit_code("", Err(cli::output::stdout_error(err))),
            };
        }
    };
    if let (Some(_), Some(flag)) = (&cli.command, book_flag(&cli.book)) {
        // The global --lang and --hints may come before a subcommand; the book's may not.
        let message = lightlab::i18n::catalog::tr_fill(lang, cli::BOOK_FLAG_FIRST, &[flag]);
        let line = lightlab::i18n::catalog::tr_fill(lang, cli::usage_error::ERROR, &[&message]);
        let _ = writeln!(std::io::stderr(), "{line}");
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

/// The output language: `--lang`, else `LIGHTLAB_LANG`, else the locale
/// ([`cli::help::chosen_lang`]). An explicit choice is put into `LIGHTLAB_LANG` for the
/// child processes that check shaders.
fn set_language(flag: Option<lightlab::i18n::Lang>) {
    let lang = cli::help::chosen_lang(flag);
    if flag.is_some() {
        // SAFETY: called once at start, before any thread is spawned (edition 2021: safe fn).
        std::env::set_var("LIGHTLAB_LANG", lang.code());
        lightlab::i18n::set_output_lang_explicit();
    }
    lightlab::i18n::set_output_lang(lang);
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
