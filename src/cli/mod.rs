//! The `lightlab` command line's subcommands, each as a library module so the
//! binary stays a thin dispatcher and tests can call the logic directly.
//!
//! | subcommand | module |
//! | --- | --- |
//! | `lightlab shade` | [`shade`] |
//! | `lightlab render` | [`render`] |
//! | `lightlab bench` | [`bench`](mod@bench) |
//! | `lightlab check-shader` (feature `gl`) | `check_shader` |
//! | `lightlab oracle` (feature `gl`) | `oracle` |
//! | `lightlab exercise` (feature `gl`) | `exercise` |
//! | `lightlab grade` (feature `gl`) | `grade` |
//! | `lightlab study` | [`study`] |
//!
//! The arguments themselves are [`args::Cli`]; [`args::command`] gives them with their help
//! in the reader's language ([`help`]).
//!
//! # One error convention
//!
//! Every subcommand's `run` returns a [`CliResult`], and [`exit_code`] is the one
//! place that turns it into the process's exit status:
//!
//! | status | meaning | value |
//! | --- | --- | --- |
//! | 0 | success | `Ok(Outcome::Success)` |
//! | 1 | the work ran and found a problem (a disagreement, bad lines in a batch) | `Ok(Outcome::Problems)` |
//! | 2 | usage or input error (bad argument, unreadable or invalid input, unwritable output path) | [`CliError::Usage`], [`CliError::Input`] |
//! | 3 | internal failure (a bug, a missing system facility, output that cannot be written) | [`CliError::Internal`], a panic |
//!
//! A closed standard output (`lightlab render --list | head -1`) is not an error:
//! the run stops quietly with status 0 ([`CliError::StdoutClosed`]).

pub mod args;
pub mod bench;
pub mod help;
pub mod i18n;
pub mod output;
pub mod render;
pub mod shade;
pub mod study;
pub mod usage_error;

#[cfg(feature = "gl")]
pub mod check_shader;
#[cfg(feature = "gl")]
pub mod child;
#[cfg(feature = "gl")]
pub mod exercise;
#[cfg(feature = "gl")]
pub mod grade;
#[cfg(feature = "gl")]
pub mod input;
pub mod messages;
#[cfg(feature = "gl")]
pub mod oracle;

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The exit-status table, printed by `lightlab --help` and repeated in the README.
pub const EXIT_STATUS_HELP: &str = "\
EXIT STATUS (every subcommand):
  0  success
  1  the work ran and found a problem (a disagreement, bad lines in a batch)
  2  usage or input error (bad argument, unreadable or invalid input, unwritable output path)
  3  internal failure (a bug, OpenGL missing, standard output full), with a message
  4  a checked shader ran out of memory (--memory; check-shader, exercise check)";

/// Exit status of `check-shader` and `exercise check` when the checking child ran out of
/// its address space (`--memory`): neither a verdict on the shader (1) nor a failure of
/// lightlab (3), but a limit the user can raise.
pub const OUT_OF_MEMORY_STATUS: u8 = 4;

/// How a subcommand that ran to the end went.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Everything agreed or succeeded (exit status 0).
    Success,
    /// The work ran and found a problem: a disagreement, bad lines in a batch (exit status 1).
    Problems,
}

impl Outcome {
    /// `Success` when `ok`, else `Problems`.
    pub fn from_ok(ok: bool) -> Outcome {
        if ok {
            Outcome::Success
        } else {
            Outcome::Problems
        }
    }
}

/// Why a subcommand could not do its work.
#[derive(Debug, thiserror::Error)]
pub enum CliError {
    /// A bad argument or a missing option (exit status 2).
    #[error("{0}")]
    Usage(String),
    /// An input that cannot be read or is not valid, or an output path that cannot
    /// be written; the message names the path, line and field (exit status 2).
    #[error("{0}")]
    Input(String),
    /// A failure that is not the user's input: a bug, a missing system facility,
    /// standard output full (exit status 3).
    #[error("internal error: {0}")]
    Internal(String),
    /// Standard output was closed by its reader (`| head`): stop quietly (exit status 0).
    #[error("standard output closed")]
    StdoutClosed,
    /// The subcommand already printed its message; exit with this status. Only for
    /// subcommands not yet converted to typed errors.
    #[error("(reported above)")]
    Reported(u8),
}

impl CliError {
    /// The exit status of this error: 2 for usage and input errors, 3 for internal
    /// failures, 0 for a closed standard output.
    pub fn status(&self) -> u8 {
        match self {
            CliError::Usage(_) | CliError::Input(_) => 2,
            CliError::Internal(_) => 3,
            CliError::StdoutClosed => 0,
            CliError::Reported(status) => *status,
        }
    }
}

impl From<crate::outfile::OutputError> for CliError {
    /// A refused target or a missing or read-only directory is an input error (2);
    /// any other write failure (disk full, I/O error) is internal (3).
    fn from(e: crate::outfile::OutputError) -> Self {
        if e.is_user_error() {
            CliError::Input(e.to_string())
        } else {
            CliError::Internal(e.to_string())
        }
    }
}

impl CliError {
    /// A boxed error of a subcommand not yet converted to [`CliError`]: a `CliError`
    /// or an [`OutputError`](crate::outfile::OutputError) inside keeps its meaning;
    /// anything else is an input error (bad argument, unreadable or invalid file).
    pub fn from_boxed(e: Box<dyn std::error::Error>) -> CliError {
        match e.downcast::<CliError>() {
            Ok(e) => *e,
            Err(e) => match e.downcast::<crate::outfile::OutputError>() {
                Ok(e) => CliError::from(*e),
                Err(e) => CliError::Input(e.to_string()),
            },
        }
    }
}

/// What every `cli::<subcommand>::run` returns.
pub type CliResult = Result<Outcome, CliError>;

/// A usage or input error's line on standard error, in the output's language (`{}`:
/// `lightlab SUBCOMMAND`, then the message).
pub const ERROR_LINE: &str = "{}: error: {}";

/// An internal failure's line on standard error, in the output's language (`{}`:
/// `lightlab SUBCOMMAND`, then the message).
pub const INTERNAL_LINE: &str = "{}: {} (please report this)";

/// The usage error of a book option given before a subcommand (`{}`: the option), as
/// the message of [`usage_error::ERROR`].
pub const BOOK_FLAG_FIRST: &str = "{} builds the book: give it without a subcommand, or after `book`";

/// The one mapping from a subcommand's result to the process's exit status; an error
/// is printed to standard error as `lightlab <subcommand>: <message>`.
///
/// `Ok(Success)` → 0, `Ok(Problems)` → 1, `Usage`/`Input` → 2, `Internal` → 3,
/// `StdoutClosed` → 0 with nothing printed.
pub fn exit_code(subcommand: &str, result: CliResult) -> ExitCode {
    match result {
        Ok(Outcome::Success) => ExitCode::SUCCESS,
        Ok(Outcome::Problems) => ExitCode::from(1),
        Err(e) => {
            if !matches!(e, CliError::StdoutClosed | CliError::Reported(_)) {
                let prefix =
                    if subcommand.is_empty() { "lightlab".to_string() } else { format!("lightlab {subcommand}") };
                // Not eprintln!: it panics when standard error is closed.
                let mut stderr = std::io::stderr();
                let _ = if matches!(e, CliError::Internal(_)) {
                    writeln!(stderr, "{}", crate::checker::texts::tr_fill(INTERNAL_LINE, &[&prefix, &e.to_string()]))
                } else {
                    writeln!(stderr, "{}", crate::checker::texts::tr_fill(ERROR_LINE, &[&prefix, &e.to_string()]))
                };
            }
            ExitCode::from(e.status())
        }
    }
}

/// Exit status of a panic that reached the top of the binary.
pub const PANIC_STATUS: u8 = 3;

/// Install a panic hook that reports a panic as an internal error ("internal error …
/// please report") on standard error instead of Rust's default message. The binary
/// also catches the unwind and exits with [`PANIC_STATUS`], never 101.
pub fn install_panic_hook() {
    std::panic::set_hook(Box::new(|info| {
        let message = crate::error::panic_text(info.payload());
        let place = info.location().map(|l| format!(" at {}:{}", l.file(), l.line())).unwrap_or_default();
        // Not eprintln!: a panic inside the hook would abort.
        let _ = writeln!(
            std::io::stderr(),
            "lightlab: internal error: panic{place}: {message}\n\
             lightlab: this is a bug in lightlab, please report it with the command that caused it"
        );
    }));
}

/// The book directory (the one holding `book.toml`) of the project that contains the
/// working directory: the first ancestor `A` of the working directory (itself
/// included) with a file `A/book/book.toml`, as cargo finds `Cargo.toml`.
///
/// The binary never falls back to the checkout it was compiled in. Returns a usage
/// error when no ancestor has one or the working directory cannot be read; callers
/// add which option to pass instead (`--root`, `--out`).
pub fn find_book_dir() -> Result<PathBuf, CliError> {
    let cwd =
        std::env::current_dir().map_err(|e| CliError::Usage(format!("cannot read the working directory ({e})")))?;
    find_book_dir_from(&cwd).ok_or_else(|| {
        CliError::Usage(format!(
            "no book/book.toml in {} or any directory above it: run lightlab inside the lightlab project",
            cwd.display()
        ))
    })
}

/// [`find_book_dir`] starting from `start` instead of the working directory; `None`
/// when no ancestor of `start` holds `book/book.toml`.
pub fn find_book_dir_from(start: &Path) -> Option<PathBuf> {
    start.ancestors().map(|a| a.join("book")).find(|b| b.join("book.toml").is_file())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_error_has_its_status() {
        assert_eq!(CliError::Usage("x".into()).status(), 2);
        assert_eq!(CliError::Input("x".into()).status(), 2);
        assert_eq!(CliError::Internal("x".into()).status(), 3);
        assert_eq!(CliError::StdoutClosed.status(), 0);
    }

    #[test]
    fn boxed_errors_keep_their_meaning() {
        let closed: Box<dyn std::error::Error> = Box::new(CliError::StdoutClosed);
        assert!(matches!(CliError::from_boxed(closed), CliError::StdoutClosed));
        let refused = crate::outfile::write_atomically(std::path::Path::new("/"), "x").expect_err("a directory");
        assert!(matches!(CliError::from_boxed(Box::new(refused)), CliError::Input(_)));
        let other: Box<dyn std::error::Error> = "unknown preset".into();
        assert!(matches!(CliError::from_boxed(other), CliError::Input(m) if m == "unknown preset"));
    }

    #[test]
    fn broken_pipe_is_quiet_and_other_write_errors_are_internal() {
        let pipe = std::io::Error::from(std::io::ErrorKind::BrokenPipe);
        assert!(matches!(output::stdout_error(pipe), CliError::StdoutClosed));
        let full = std::io::Error::from(std::io::ErrorKind::StorageFull);
        assert!(matches!(output::stdout_error(full), CliError::Internal(m) if m.contains("standard output")));
    }
}
