//! Running this binary again in a child process under a time limit, so that a shader that
//! never ends, or one that crashes the OpenGL driver, gives a verdict instead of taking
//! `lightlab` down. `check-shader` and `exercise check` re-run themselves with the hidden
//! `--in-process` flag; `grade` runs `exercise check --in-process` once per file.

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::{CliError, CliResult, Outcome};

/// The options every shader check shares (`check-shader`, `exercise check`, `grade`).
#[derive(Debug, Clone, clap::Args)]
pub struct CheckOptions {
    /// A TOML file mapping the shader's names to the model's (`[names]`) and fixing
    /// quantities in every case (`[values]`): ones the shader hard-codes, or uniforms it
    /// declares (a teacher's own values). A quantity the shader neither declares nor fixes
    /// takes the chapter's value (attenuation 1, 0.09, 0.032; cut-offs cos 12.5°, cos
    /// 17.5°; ...), and the report's notes say which.
    #[arg(long, value_name = "FILE.toml")]
    pub uniforms: Option<std::path::PathBuf>,
    /// Seed of the case generator (the same cases for every shader checked with it).
    #[arg(long, default_value_t = crate::gl::cases::DEFAULT_SEED)]
    pub seed: u64,
    /// Seconds one shader's compile and run may take before the verdict is "took too long"
    /// (an endless loop).
    #[arg(long, default_value_t = 120)]
    pub timeout: u64,
}

impl CheckOptions {
    /// The options as arguments for a child run (`--uniforms`, `--seed`; the time limit is
    /// the parent's).
    pub fn forward(&self, cmd: &mut Command) {
        if let Some(u) = &self.uniforms {
            cmd.arg("--uniforms").arg(u);
        }
        cmd.args(["--seed", &self.seed.to_string()]);
    }
}

/// How a child process ended.
pub enum ChildEnd {
    /// It exited with a status.
    Exited {
        /// Its exit status.
        code: i32,
        /// What it printed on standard output.
        stdout: String,
        /// What it printed on standard error.
        stderr: String,
    },
    /// It ran past the time limit and was killed.
    TimedOut,
    /// It died by a signal (the text names it).
    Crashed(String),
}

/// This binary, to re-run. Errors: [`CliError::Internal`] when its path cannot be found.
pub fn this_binary() -> Result<Command, CliError> {
    std::env::current_exe()
        .map(Command::new)
        .map_err(|e| CliError::Internal(format!("cannot find the lightlab binary to re-run: {e}")))
}

// String error: the callers put the message in a grade row's `error` cell or an
// internal-error line; both are text.
/// Runs `cmd` with no standard input, collects both outputs, and kills it after `timeout`.
pub fn run_child(mut cmd: Command, timeout: Duration) -> Result<ChildEnd, String> {
    let mut child = cmd
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start the checking process: {e}"))?;
    let pipe = |r: Option<Box<dyn Read + Send>>| {
        std::thread::spawn(move || {
            let mut buf = Vec::new();
            if let Some(mut r) = r {
                let _ = r.read_to_end(&mut buf);
            }
            String::from_utf8_lossy(&buf).into_owned()
        })
    };
    let out = pipe(child.stdout.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    let err = pipe(child.stderr.take().map(|s| Box::new(s) as Box<dyn Read + Send>));
    let deadline = Instant::now() + timeout;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => return Err(format!("waiting for the checking process: {e}")),
        }
    };
    let (stdout, stderr) = (out.join().unwrap_or_default(), err.join().unwrap_or_default());
    Ok(match status {
        None => ChildEnd::TimedOut,
        Some(s) => match s.code() {
            Some(code) => ChildEnd::Exited { code, stdout, stderr },
            None => ChildEnd::Crashed(s.to_string()),
        },
    })
}

/// Runs `cmd` (this binary with `--in-process`) under `timeout` seconds and relays it: its
/// output and exit status as they are; a timeout or a crash becomes a verdict about
/// `file` (exit status 1), in text or as a JSON object `{verdict, error}` when `json`.
pub fn relay(cmd: Command, timeout: u64, file: &std::path::Path, json: bool) -> CliResult {
    let end = run_child(cmd, Duration::from_secs(timeout)).map_err(CliError::Internal)?;
    let failed = |verdict: &str, why: String| {
        if json {
            format!("{}\n", serde_json::json!({ "verdict": verdict, "error": why }))
        } else {
            format!("verdict: {}\n{}: {why}\n", verdict.to_uppercase(), file.display())
        }
    };
    let (text, code) = match end {
        ChildEnd::TimedOut => (
            failed(
                "took too long",
                format!("compiling and running it took more than {timeout} s (--timeout): an endless loop?"),
            ),
            1,
        ),
        ChildEnd::Crashed(status) => (
            failed(
                "does not compile",
                format!(
                    "the OpenGL driver crashed compiling or running it ({status}); a very long expression or \
                     deep nesting overflows Mesa's compiler"
                ),
            ),
            1,
        ),
        ChildEnd::Exited { code, stdout, stderr } => {
            eprint!("{stderr}");
            (stdout, code)
        }
    };
    super::output::print(text)?;
    // The child printed its own messages; its status is passed on as it is.
    match code {
        0 => Ok(Outcome::Success),
        1 => Ok(Outcome::Problems),
        other => Err(CliError::Reported(u8::try_from(other).unwrap_or(3))),
    }
}
