//! Writing to standard output without panicking.
//!
//! `println!` panics when standard output is closed (`lightlab render --list | true`)
//! or full (`> /dev/full`). Every subcommand prints through this module instead:
//!
//! | write error | result | exit status |
//! | --- | --- | --- |
//! | `EPIPE` (the reader went away) | [`CliError::StdoutClosed`]: stop quietly | 0 |
//! | anything else (`ENOSPC`, `EIO`, …) | [`CliError::Internal`] naming standard output | 3 |
//!
//! ```no_run
//! use lightlab::cli::{output, CliResult, Outcome};
//! fn run() -> CliResult {
//!     output::println("one line")?;
//!     let mut out = output::stdout();
//!     for i in 0..3 {
//!         out.line(i)?;
//!     }
//!     out.finish()?;
//!     Ok(Outcome::Success)
//! }
//! ```

use std::fmt::Display;
use std::io::Write;

use super::CliError;

/// The error for a failed write to standard output: `StdoutClosed` for a closed
/// pipe, else an internal error naming standard output.
pub fn stdout_error(e: std::io::Error) -> CliError {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        CliError::StdoutClosed
    } else {
        CliError::Internal(format!("cannot write to standard output: {e}"))
    }
}

/// For subcommands that return an `i32` status: print `e` (unless standard output
/// was merely closed) and return its exit status.
pub fn report_status(e: CliError) -> i32 {
    if !matches!(e, CliError::StdoutClosed | CliError::Reported(_)) {
        eprintln!("lightlab: {e}");
    }
    i32::from(e.status())
}

/// Write `text` to standard output and flush it.
pub fn print(text: impl Display) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    write!(out, "{text}").and_then(|()| out.flush()).map_err(stdout_error)
}

/// Write `text` and a newline to standard output and flush it.
pub fn println(text: impl Display) -> Result<(), CliError> {
    print(format_args!("{text}\n"))
}

/// A buffered standard output whose writes return [`CliError`]s. Call
/// [`finish`](Stdout::finish) at the end: a write error can surface only at the flush.
pub struct Stdout {
    inner: std::io::BufWriter<std::io::StdoutLock<'static>>,
}

/// A buffered, locked standard output for many lines.
pub fn stdout() -> Stdout {
    Stdout { inner: std::io::BufWriter::new(std::io::stdout().lock()) }
}

impl Stdout {
    /// Write `text` followed by a newline.
    pub fn line(&mut self, text: impl Display) -> Result<(), CliError> {
        writeln!(self.inner, "{text}").map_err(stdout_error)
    }

    /// Write `text` as it is.
    pub fn text(&mut self, text: impl Display) -> Result<(), CliError> {
        write!(self.inner, "{text}").map_err(stdout_error)
    }

    /// The underlying writer, for code that writes `std::io::Write`; map its errors
    /// with [`stdout_error`].
    pub fn writer(&mut self) -> &mut impl Write {
        &mut self.inner
    }

    /// Flush what is buffered.
    pub fn finish(mut self) -> Result<(), CliError> {
        self.inner.flush().map_err(stdout_error)
    }
}
