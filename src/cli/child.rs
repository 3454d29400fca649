//! Running this binary again in a child process under a time limit, so that a shader that
//! never ends, or one that crashes the OpenGL driver, gives a verdict instead of taking
//! `lightlab` down. `check-shader` and `exercise check` re-run themselves with the hidden
//! `--in-process` flag; `grade` runs `exercise check --in-process` once per submission.
//!
//! # Containment (Unix)
//!
//! Before the child runs the shader, [`run_child`] sets, in the child (`pre_exec`):
//!
//! | limit | value | why |
//! | --- | --- | --- |
//! | `RLIMIT_AS` | `--memory` MiB ([`DEFAULT_MEMORY_MB`] by default) | a shader of nested `#define`s grew a child to 3.9 GB, a local `float a[4000000]` to 5.2 GB |
//! | `RLIMIT_CPU` | `--timeout` × cores + 1 s | a backstop under the wall-clock limit, which llvmpipe's threads share |
//! | its own process group (`setpgid(0, 0)`) | | on a timeout the whole group is killed, so nothing it started lives on |
//! | `PR_SET_PDEATHSIG` = `SIGKILL` (Linux) | | a `grade` killed with `kill -9` takes its children with it |
//!
//! A child that runs out of address space is reported as "ran out of memory: the limit
//! is N MiB (--memory)" ([`out_of_memory_message`]), not as a compile error or a driver
//! crash. It is recognised by the allocator's or Mesa's message on its standard error.
//! Mesa's compiler often has no message: an allocation fails and it dies by `SIGSEGV`, or
//! by `SIGABRT` when LLVM's `std::bad_alloc` reaches Rust.
//! So the child itself, at a memory fault, compares its peak address space with its limit
//! and says so on standard error ([`report_memory_faults`]); the parent's own sampling of
//! `/proc` every 10 ms is a second witness, which a loaded machine can make miss the
//! few tens of milliseconds the child spends at its peak.

use std::io::Read;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::{CliError, CliResult, Outcome};
use crate::checker::texts::tr_fill;

/// Default time limit of one shader check, in seconds. The book states it (chapter 12
/// and the appendix "Grading a class"); a test reads the book for this number.
pub const DEFAULT_TIMEOUT_S: u64 = 120;

/// Default address-space limit of one checking child, in MB (2 GiB). Measured here
/// (`VmPeak`, llvmpipe on 2 cores): `exercise check` of 20 000 cases reserves about 620 MB
/// of address space, `check-shader` of 10⁶ cases about 960 MB; 2048 leaves room for the
/// largest models, while a macro bomb reaches it in seconds. The smallest accepted limit
/// is 512 MB: under about 460 MB Mesa cannot even start and crashes.
pub const DEFAULT_MEMORY_MB: u64 = 2048;

/// The clap parser of a `--cases` count in `1..=max` (every command's `--cases`): a count
/// out of range is a usage error before anything runs.
#[must_use]
pub fn cases_parser(max: u64) -> clap::builder::RangedU64ValueParser<usize> {
    clap::builder::RangedU64ValueParser::<usize>::new().range(1..=max)
}

/// The options every shader check shares (`check-shader`, `exercise check`, `grade`).
#[derive(Debug, Clone, clap::Args)]
pub struct CheckOptions {
    /// A TOML file mapping the shader's names to the model's (`[names]`) and fixing
    /// quantities in every case (`[values]`): ones the shader hard-codes, or uniforms it
    /// declares (a teacher's own values). A quantity the shader neither declares nor fixes
    /// takes the chapter's value (attenuation 1, 0.09, 0.032; cut-offs cos 12.5°, cos
    /// 17.5°; ...), and the report's notes say which. `[rules]` `forbid = [...]` and
    /// `require = [...]` name quantities the shader must not or must declare (the verdict
    /// is then "does not follow the exercise"). The format is in the book's verification
    /// chapter.
    #[arg(long, value_name = "FILE.toml")]
    pub uniforms: Option<std::path::PathBuf>,
    /// Seed of the case generator (the same cases for every shader checked with it).
    #[arg(long, default_value_t = crate::oracle::cases::DEFAULT_SEED)]
    pub seed: u64,
    /// Seconds one shader's compile and run may take before the verdict is "took too long"
    /// (an endless loop); at least 1.
    #[arg(long, default_value_t = DEFAULT_TIMEOUT_S, value_parser = clap::value_parser!(u64).range(1..))]
    pub timeout: u64,
    /// Address space one checking process may use, in MiB (512 to 1048576); a shader that
    /// needs more is reported as "ran out of memory: the limit is N MiB".
    #[arg(long, value_name = "MB", default_value_t = DEFAULT_MEMORY_MB,
          value_parser = clap::value_parser!(u64).range(512..=1 << 20))]
    pub memory: u64,
    /// `--uniforms` is one mapping for a whole class (`grade` passes this to each checking
    /// child): a `[names]` key the shader does not declare is skipped, not an error.
    #[arg(long, hide = true)]
    pub class_mapping: bool,
}

impl CheckOptions {
    /// The options as arguments for a child run (`--uniforms`, `--class-mapping`, `--seed`;
    /// the time and memory limits are the parent's).
    pub fn forward(&self, cmd: &mut Command) {
        if let Some(u) = &self.uniforms {
            cmd.arg("--uniforms").arg(u);
        }
        if self.class_mapping {
            cmd.arg("--class-mapping");
        }
        cmd.args(["--seed", &self.seed.to_string()]);
    }

    /// The child's limits.
    pub fn limits(&self) -> Limits {
        Limits { timeout_s: self.timeout, memory_mb: self.memory }
    }
}

/// The limits of one checking child.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock seconds before the child's group is killed.
    pub timeout_s: u64,
    /// Address space, in MB.
    pub memory_mb: u64,
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
    /// It ran past the time limit (wall clock or processor time) and was killed.
    TimedOut,
    /// It ran out of its address space (`--memory`).
    OutOfMemory,
    /// It died by a signal (the text names it).
    Crashed(String),
}

/// The sentence of a child killed at its time limit (English msgid of `po/messages.pot`;
/// `{}`: the limit in seconds).
pub const TIMED_OUT: &str = "took longer than {} s (--timeout): an endless loop, or a very slow shader";
/// The sentence of a child that ran out of its address space (`{}`: the limit in MiB).
pub const OUT_OF_MEMORY: &str = "ran out of memory: the limit is {} MiB (--memory); a huge array, macros that \
                                 expand without end, or more --cases than the limit holds";
/// The sentence of a child that died by a signal (`{}`: the signal).
pub const CRASHED: &str = "the OpenGL driver crashed compiling or running it ({}); a very long expression, deep \
                           nesting or a huge local array overflows Mesa's compiler or its stack";
/// The text output's verdict line (`{}`: one of [`VERDICTS`], translated).
pub const VERDICT_LINE: &str = "verdict: {}";
/// The verdicts of a child stopped by a limit, as the text output shows them (msgids); JSON
/// keeps the lower-case English word.
pub const VERDICTS: [&str; 5] =
    ["TOOK TOO LONG", "RAN OUT OF MEMORY", "DOES NOT COMPILE", "DOES NOT TERMINATE", "DOES NOT FOLLOW THE EXERCISE"];
/// The sentence of a shader whose loop reached the loop guard's cap
/// ([`crate::checker::check::loops`]; `{}`: the cap, the cases that reached it, the cases run).
pub const DOES_NOT_TERMINATE: &str = "a loop ran past {} iterations in {} of {} cases: on a GPU this shader would \
                                      hang (llvmpipe ends every loop after 65 535 iterations, so its output only \
                                      looked finished)";

impl ChildEnd {
    /// The sentence for a submission's row when the child did not exit by itself, in the
    /// command line's language.
    pub fn limit_message(&self, limits: Limits) -> Option<String> {
        match self {
            ChildEnd::TimedOut => Some(tr_fill(TIMED_OUT, &[&limits.timeout_s.to_string()])),
            ChildEnd::OutOfMemory => Some(out_of_memory_message(limits.memory_mb)),
            ChildEnd::Crashed(status) => Some(tr_fill(CRASHED, &[status])),
            ChildEnd::Exited { .. } => None,
        }
    }
}

/// The sentence of a child that ran out of its address space: its own verdict, never a
/// compile error or a driver crash (the limit is `--memory` MiB: the flag's number is
/// multiplied by 2^20), in the command line's language.
pub fn out_of_memory_message(memory_mb: u64) -> String {
    tr_fill(OUT_OF_MEMORY, &[&memory_mb.to_string()])
}

/// This binary, to re-run. Errors: [`CliError::Internal`] when its path cannot be found.
pub fn this_binary() -> Result<Command, CliError> {
    std::env::current_exe()
        .map(Command::new)
        .map_err(|e| CliError::Internal(format!("cannot find the lightlab binary to re-run: {e}")))
}

// String error: the callers put the message in a grade row's `error` cell or an
// internal-error line; both are text.
/// Runs `cmd` with no standard input, collects both outputs, and kills its process group
/// after `limits.timeout_s` seconds; the child runs under the limits of the module docs.
pub fn run_child(mut cmd: Command, limits: Limits) -> Result<ChildEnd, String> {
    contain(&mut cmd, limits);
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
    // `None`: a limit past the end of `Instant`'s range, that is no limit (`--timeout`
    // near 2^64 must not overflow).
    let deadline = Instant::now().checked_add(Duration::from_secs(limits.timeout_s));
    let mut peak_kb = 0u64;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) if deadline.is_some_and(|d| Instant::now() >= d) => {
                kill_group(&mut child);
                break None;
            }
            Ok(None) => {
                peak_kb = peak_kb.max(vm_peak_kb(child.id()).unwrap_or(0));
                std::thread::sleep(Duration::from_millis(10));
            }
            Err(e) => return Err(format!("waiting for the checking process: {e}")),
        }
    };
    let (stdout, stderr) = (out.join().unwrap_or_default(), err.join().unwrap_or_default());
    Ok(match status {
        None => ChildEnd::TimedOut,
        Some(s) => {
            let near_limit = at_limit(peak_kb, limits.memory_mb.saturating_mul(1 << 20));
            // An exit status is the child's own verdict (0, 1) or message (2, 3), unless
            // it says an allocation failed; a signal is a crash, the processor-time
            // limit, or the memory limit (its message, or a peak near the limit).
            match s.code() {
                Some(code @ (0 | 1)) => ChildEnd::Exited { code, stdout, stderr },
                Some(_) if out_of_memory(&stderr) => ChildEnd::OutOfMemory,
                Some(code) => ChildEnd::Exited { code, stdout, stderr },
                None if cpu_limit(&s) => ChildEnd::TimedOut,
                None if out_of_memory(&stderr) || near_limit => ChildEnd::OutOfMemory,
                None => ChildEnd::Crashed(s.to_string()),
            }
        }
    })
}

/// Whether a child's standard error says an allocation failed: Rust's allocator, LLVM,
/// C++ and glibc each have their sentence, and OpenGL its error `GL_OUT_OF_MEMORY`
/// (0x0505, which llvmpipe raises when a texture no longer fits under the limit).
#[must_use]
pub fn out_of_memory(stderr: &str) -> bool {
    ["memory allocation of", "out of memory", "Out of memory", "bad_alloc", "Cannot allocate memory", "GL error 0x0505"]
        .iter()
        .any(|m| stderr.contains(m))
}

#[cfg(unix)]
fn cpu_limit(status: &std::process::ExitStatus) -> bool {
    use std::os::unix::process::ExitStatusExt;
    status.signal() == Some(libc::SIGXCPU)
}

#[cfg(not(unix))]
fn cpu_limit(_: &std::process::ExitStatus) -> bool {
    false
}

/// The child's peak address space (`VmPeak` in `/proc/PID/status`), in kB; `None` where
/// there is no `/proc`.
fn vm_peak_kb(pid: u32) -> Option<u64> {
    vm_peak_of(&std::fs::read(format!("/proc/{pid}/status")).ok()?)
}

/// What a checking child writes on standard error when it dies by a memory fault with
/// its address space at the limit: it contains "out of memory", which [`out_of_memory`]
/// recognises.
pub const FAULT_AT_LIMIT: &str =
    "lightlab: memory fault with the address space at its limit (--memory): out of memory\n";

/// The share of the address-space limit from which a peak counts as "at the limit": 9/10.
/// Measured here (`VmPeak`, `--memory 512`, a local `float a[4000000]`): Mesa's compiler
/// reached 507 MiB of 512, 99 %, then died by `SIGSEGV`; the checks that pass stay under
/// half of the default limit (see [`DEFAULT_MEMORY_MB`]).
const AT_LIMIT: (u64, u64) = (9, 10);

/// Whether a peak address space of `peak_kb` kB is at a limit of `limit_bytes` bytes.
#[must_use]
pub fn at_limit(peak_kb: u64, limit_bytes: u64) -> bool {
    peak_kb.saturating_mul(1024).saturating_mul(AT_LIMIT.1) >= limit_bytes.saturating_mul(AT_LIMIT.0)
}

/// The `VmPeak:` value of a `/proc/PID/status` text, in kB. Works on bytes, with no
/// allocation, because a signal handler calls it.
#[must_use]
pub fn vm_peak_of(status: &[u8]) -> Option<u64> {
    const KEY: &[u8] = b"VmPeak:";
    let start = status.windows(KEY.len()).position(|w| w == KEY)? + KEY.len();
    let digits = status[start..].iter().skip_while(|b| **b == b' ' || **b == b'\t');
    let mut value: Option<u64> = None;
    for b in digits.take_while(|b| b.is_ascii_digit()) {
        value = Some(value.unwrap_or(0).checked_mul(10)?.checked_add(u64::from(b - b'0'))?);
    }
    value
}

/// In a checking child (`--in-process`): on `SIGSEGV`, `SIGBUS` or `SIGABRT` (LLVM's
/// `std::bad_alloc` reaching Rust aborts with "Rust cannot catch foreign exceptions"), write
/// [`FAULT_AT_LIMIT`] on standard error if the peak address space is at the
/// `RLIMIT_AS` limit, then let the fault take its course (the handler that was there
/// before, Rust's stack-overflow report or the default, runs as it would have). Without
/// a limit, or below it, the handler writes nothing.
#[cfg(target_os = "linux")]
pub fn report_memory_faults() {
    use std::sync::OnceLock;
    static BEFORE: OnceLock<[libc::sigaction; 3]> = OnceLock::new();
    const SIGNALS: [libc::c_int; 3] = [libc::SIGSEGV, libc::SIGBUS, libc::SIGABRT];

    extern "C" fn on_fault(signal: libc::c_int, _: *mut libc::siginfo_t, _: *mut libc::c_void) {
        let mut buf = [0u8; 4096];
        let mut len = 0;
        // SAFETY: open, read, close, getrlimit, write and sigaction are async-signal-safe
        // system calls; `buf` is on this handler's stack, and the path is a C string.
        unsafe {
            let fd = libc::open(c"/proc/self/status".as_ptr(), libc::O_RDONLY);
            if fd >= 0 {
                while len < buf.len() {
                    let n = libc::read(fd, buf[len..].as_mut_ptr().cast(), buf.len() - len);
                    if n <= 0 {
                        break;
                    }
                    len += n as usize;
                }
                libc::close(fd);
            }
            let mut limit = libc::rlimit { rlim_cur: 0, rlim_max: 0 };
            let limited = libc::getrlimit(libc::RLIMIT_AS, &mut limit) == 0 && limit.rlim_cur != libc::RLIM_INFINITY;
            // `rlim_t` is u64 here and u32 on some targets: the cast is for those.
            #[allow(clippy::unnecessary_cast)]
            let cur = limit.rlim_cur as u64;
            if limited && vm_peak_of(&buf[..len]).is_some_and(|kb| at_limit(kb, cur)) {
                libc::write(2, FAULT_AT_LIMIT.as_ptr().cast(), FAULT_AT_LIMIT.len());
            }
            // Put the previous handler back; returning re-runs the faulting instruction,
            // which faults again into it.
            if let (Some(before), Some(i)) = (BEFORE.get(), SIGNALS.iter().position(|s| *s == signal)) {
                libc::sigaction(signal, &before[i], std::ptr::null_mut());
            } else {
                libc::signal(signal, libc::SIG_DFL);
            }
        }
    }

    // SAFETY: sigaction with a zeroed, then filled, struct; the handler is an
    // `extern "C"` function of the right signature (SA_SIGINFO).
    unsafe {
        let mut before: [libc::sigaction; 3] = std::mem::zeroed();
        let mut action: libc::sigaction = std::mem::zeroed();
        action.sa_sigaction = on_fault as *const () as usize;
        action.sa_flags = libc::SA_SIGINFO | libc::SA_ONSTACK;
        libc::sigemptyset(&mut action.sa_mask);
        for (i, signal) in SIGNALS.iter().enumerate() {
            libc::sigaction(*signal, std::ptr::null(), &mut before[i]);
        }
        if BEFORE.set(before).is_ok() {
            for signal in SIGNALS {
                libc::sigaction(signal, &action, std::ptr::null_mut());
            }
        }
    }
}

/// Elsewhere a fault stays a crash; the parent's `/proc` sampling is Linux-only too.
#[cfg(not(target_os = "linux"))]
pub fn report_memory_faults() {}

/// Sets the child's limits, process group and parent-death signal (module docs).
#[cfg(unix)]
fn contain(cmd: &mut Command, limits: Limits) {
    use std::os::unix::process::CommandExt;
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get() as u64);
    let bytes = limits.memory_mb.saturating_mul(1 << 20);
    let cpu_s = limits.timeout_s.saturating_mul(cores).saturating_add(1);
    // SAFETY: the getpid call happens here, in the parent, before the fork.
    let parent = unsafe { libc::getpid() };
    let hook = move || -> std::io::Result<()> {
        // SAFETY: between fork and exec only async-signal-safe calls are allowed; setpgid,
        // prctl, getppid and setrlimit are system calls that allocate nothing.
        unsafe {
            if libc::setpgid(0, 0) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            #[cfg(target_os = "linux")]
            {
                if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL as libc::c_ulong, 0, 0, 0) != 0 {
                    return Err(std::io::Error::last_os_error());
                }
                // The parent died between the fork and the prctl: the signal will never come.
                if libc::getppid() != parent {
                    return Err(std::io::Error::other("the parent ended"));
                }
            }
            let address = libc::rlimit { rlim_cur: bytes as libc::rlim_t, rlim_max: bytes as libc::rlim_t };
            if libc::setrlimit(libc::RLIMIT_AS, &address) != 0 {
                return Err(std::io::Error::last_os_error());
            }
            // The soft limit sends SIGXCPU, the hard one (a second later) SIGKILL.
            let cpu =
                libc::rlimit { rlim_cur: cpu_s as libc::rlim_t, rlim_max: cpu_s.saturating_add(1) as libc::rlim_t };
            if libc::setrlimit(libc::RLIMIT_CPU, &cpu) != 0 {
                return Err(std::io::Error::last_os_error());
            }
        }
        Ok(())
    };
    let _ = parent;
    // SAFETY: the hook only makes async-signal-safe system calls (see above).
    unsafe {
        cmd.pre_exec(hook);
    }
}

#[cfg(not(unix))]
fn contain(_: &mut Command, _: Limits) {}

/// Kills the child's whole process group (it leads its own), then reaps the child.
fn kill_group(child: &mut std::process::Child) {
    #[cfg(unix)]
    if let Ok(pid) = libc::pid_t::try_from(child.id()) {
        // SAFETY: kill has no memory effects; `-pid` names the group the child leads.
        unsafe {
            libc::kill(-pid, libc::SIGKILL);
        }
    }
    let _ = child.kill();
    let _ = child.wait();
}

/// Runs `cmd` (this binary with `--in-process`) under `limits` and relays it: its
/// output and exit status as they are; a timeout, a memory overrun or a crash becomes a
/// verdict about `file`, in text or as a JSON object `{verdict, error}` when `json`, with
/// exit status 1, or [`super::OUT_OF_MEMORY_STATUS`] (4) for the memory overrun.
pub fn relay(cmd: Command, limits: Limits, file: &std::path::Path, json: bool) -> CliResult {
    let end = run_child(cmd, limits).map_err(CliError::Internal)?;
    let failed = |verdict: &str, why: String| {
        if json {
            format!("{}\n", serde_json::json!({ "verdict": verdict, "error": why }))
        } else {
            let shown = tr_fill(VERDICT_LINE, &[&crate::checker::texts::tr(&verdict.to_uppercase())]);
            format!("{shown}\n{}: {why}\n", file.display())
        }
    };
    let why = end.limit_message(limits).unwrap_or_default();
    let (text, code) = match end {
        ChildEnd::TimedOut => (failed("took too long", why), 1),
        ChildEnd::OutOfMemory => (failed("ran out of memory", why), i32::from(super::OUT_OF_MEMORY_STATUS)),
        ChildEnd::Crashed(_) => (failed("does not compile", why), 1),
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

#[cfg(test)]
mod oom_tests {
    #[test]
    fn the_peak_is_read_from_proc_status() {
        let status = b"Name:\tlightlab\nVmPeak:\t  519168 kB\nVmSize:\t  400000 kB\n";
        assert_eq!(super::vm_peak_of(status), Some(519_168));
        assert_eq!(super::vm_peak_of(b"VmSize:\t1 kB\n"), None);
        assert_eq!(super::vm_peak_of(b"VmPeak:\t kB\n"), None);
        // a value past u64 is no value, not a wrapped one
        assert_eq!(super::vm_peak_of(b"VmPeak:\t99999999999999999999999 kB"), None);
    }

    #[test]
    fn at_the_limit_means_nine_tenths_of_it() {
        let limit = 512u64 << 20;
        assert!(super::at_limit(507 * 1024, limit)); // the measured Mesa fault (module docs)
        assert!(super::at_limit(512 * 1024 * 9 / 10 + 1, limit));
        assert!(!super::at_limit(400 * 1024, limit));
        // huge numbers saturate instead of overflowing (a panic in a signal handler)
        assert!(super::at_limit(u64::MAX, limit));
        assert!(!super::at_limit(1, u64::MAX));
    }

    #[test]
    fn opengl_out_of_memory_is_running_out_of_memory() {
        let gl = "lightlab check-shader: internal error: OpenGL: glTexImage2D(RGBA32F) failed: GL error 0x0505";
        assert!(super::out_of_memory(gl));
        assert!(!super::out_of_memory("GL error 0x0502 (invalid operation)"));
    }
}
