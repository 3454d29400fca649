//! Output files that respect their target, and one writer at a time.
//!
//! | function | what it does |
//! | --- | --- |
//! | [`write_atomically`] | writes a temporary file beside the target, then renames it over the target |
//! | [`check_writable`] | before the work: the target could be written now (a temporary file is created and removed) |
//! | [`lock_dir`] | takes an exclusive lock on a directory's lock file; a second run waits and says who holds it |
//!
//! Rules of [`write_atomically`]:
//! - the target must be a regular file or absent; a symbolic link is followed to its
//!   target (the link stays a link, the file it points to is replaced);
//! - a directory, device, FIFO or socket is refused with an error naming the path
//!   (writing `-o /dev/full` never replaces the device node);
//! - the temporary file `.<name>.<pid>-<n>.lightlab-tmp` sits in the target's own
//!   directory (so the rename is atomic), is removed on every error, and temporary
//!   files of the same target left by a killed process are removed on the next write;
//! - a reader sees the old bytes or the new bytes, never a mix.
//!
//! File data is not `fsync`ed: the rename is atomic against a killed process, not
//! against a power cut.

use std::fs::{File, OpenOptions};
use std::io::{ErrorKind, Read, Seek, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

/// Why an output could not be written.
#[derive(Debug, thiserror::Error)]
pub enum OutputError {
    /// The target is not a regular file (a directory, device, FIFO or socket), or has
    /// no file name. The user's path is wrong: an input error.
    #[error("{}: {reason}", path.display())]
    Refused {
        /// The path as given.
        path: PathBuf,
        /// What it is and what was expected.
        reason: String,
    },
    /// An I/O operation failed; `action` says which ("create a temporary file in").
    #[error("{}: cannot {action}: {source}", path.display())]
    Io {
        /// The path the operation was on.
        path: PathBuf,
        /// The operation.
        action: &'static str,
        /// The operating system's error.
        source: std::io::Error,
    },
}

impl OutputError {
    /// Whether the error comes from the path the user gave (refused target, missing
    /// or read-only directory) rather than from the system (disk full, I/O error).
    pub fn is_user_error(&self) -> bool {
        match self {
            OutputError::Refused { .. } => true,
            OutputError::Io { source, .. } => matches!(
                source.kind(),
                ErrorKind::NotFound
                    | ErrorKind::PermissionDenied
                    | ErrorKind::ReadOnlyFilesystem
                    | ErrorKind::NotADirectory
                    | ErrorKind::IsADirectory
                    | ErrorKind::InvalidFilename
            ),
        }
    }
}

fn io_error<'a>(path: &'a Path, action: &'static str) -> impl FnOnce(std::io::Error) -> OutputError + 'a {
    move |source| OutputError::Io { path: path.to_path_buf(), action, source }
}

/// Symbolic links followed before giving up (as Linux's `MAXSYMLINKS`).
const MAX_LINKS: usize = 40;

/// The file a write to `path` lands in: `path` with symbolic links followed (the last
/// link's target may be absent).
fn resolve(path: &Path) -> Result<PathBuf, OutputError> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&current) {
            Ok(m) if m.file_type().is_symlink() => {
                let target = std::fs::read_link(&current).map_err(io_error(path, "read the symbolic link"))?;
                current = match current.parent() {
                    Some(dir) if target.is_relative() => dir.join(target),
                    _ => target,
                };
            }
            _ => return Ok(current),
        }
    }
    Err(OutputError::Refused { path: path.to_path_buf(), reason: "too many levels of symbolic links".into() })
}

/// What a non-regular file is, for the refusal message.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_dir() {
        return "a directory";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_block_device() || t.is_char_device() {
            return "a device";
        }
        if t.is_fifo() {
            return "a FIFO";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

static COUNTER: AtomicU64 = AtomicU64::new(0);

const TMP_SUFFIX: &str = ".lightlab-tmp";

/// Write `bytes` to `path` through a temporary file in the same directory, then rename.
///
/// The target must be a regular file or absent; symbolic links are followed. Errors
/// name the path: a directory, device, FIFO or socket is [`OutputError::Refused`]; a
/// missing or read-only directory is an [`OutputError::Io`] naming it. No temporary
/// file is left behind on error, and stale ones of the same target (from a killed
/// process) are removed. An existing target keeps its permissions.
pub fn write_atomically(path: &Path, bytes: impl AsRef<[u8]>) -> Result<(), OutputError> {
    let Target { target, existing, dir, prefix } = target_of(path)?;
    remove_stale(&dir, &prefix);
    let tmp = temp_path(&dir, &prefix);
    let result = write_new(&tmp, bytes.as_ref(), existing.as_ref())
        .and_then(|()| std::fs::rename(&tmp, &target).map_err(io_error(path, "rename the temporary file onto")));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Checks, before any work, that [`write_atomically`] could write `path` now: the target
/// is a regular file or absent, its directory exists, and a temporary file can be created
/// there (one is created and removed at once). A command that works for hours checks its
/// outputs first, so its results are not lost at the end.
///
/// Errors: as [`write_atomically`]'s, naming the path.
pub fn check_writable(path: &Path) -> Result<(), OutputError> {
    let Target { dir, prefix, .. } = target_of(path)?;
    let tmp = temp_path(&dir, &prefix);
    OpenOptions::new().write(true).create_new(true).open(&tmp).map_err(io_error(&dir, "create a temporary file in"))?;
    let _ = std::fs::remove_file(&tmp);
    Ok(())
}

/// Where [`write_atomically`] writes: the resolved target, its metadata when it exists,
/// its directory and the prefix of its temporary files.
struct Target {
    target: PathBuf,
    existing: Option<std::fs::Metadata>,
    dir: PathBuf,
    prefix: String,
}

/// The [`Target`] of `path`, refused when it is not a regular file or its directory is
/// not a directory.
fn target_of(path: &Path) -> Result<Target, OutputError> {
    let target = resolve(path)?;
    let existing = match std::fs::metadata(&target) {
        Ok(meta) if meta.is_file() => Some(meta),
        Ok(meta) => {
            let kind = kind_of(&meta);
            return Err(OutputError::Refused {
                path: path.to_path_buf(),
                reason: format!("is {kind}; lightlab writes only regular files"),
            });
        }
        Err(e) if e.kind() == ErrorKind::NotFound => None,
        Err(e) => return Err(io_error(path, "look at the output")(e)),
    };
    let Some(name) = target.file_name() else {
        return Err(OutputError::Refused { path: path.to_path_buf(), reason: "has no file name".into() });
    };
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    match std::fs::metadata(&dir) {
        Ok(m) if m.is_dir() => {}
        Ok(_) => {
            return Err(OutputError::Refused { path: dir, reason: "is not a directory (the output's parent)".into() })
        }
        Err(e) => return Err(io_error(&dir, "use the output's directory")(e)),
    }
    let prefix = format!(".{}.", name.to_string_lossy());
    Ok(Target { target, existing, dir, prefix })
}

/// A fresh temporary file name in `dir` for the target whose temporary files start with `prefix`.
fn temp_path(dir: &Path, prefix: &str) -> PathBuf {
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    dir.join(format!("{prefix}{}-{n}{TMP_SUFFIX}", std::process::id()))
}

/// Create `tmp` (which must not exist), write `bytes`, copy the permissions of
/// `existing`.
fn write_new(tmp: &Path, bytes: &[u8], existing: Option<&std::fs::Metadata>) -> Result<(), OutputError> {
    let dir = tmp.parent().unwrap_or(Path::new("."));
    let mut file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(tmp)
        .map_err(io_error(dir, "create a temporary file in"))?;
    file.write_all(bytes).map_err(io_error(tmp, "write"))?;
    if let Some(meta) = existing {
        file.set_permissions(meta.permissions()).map_err(io_error(tmp, "set the permissions of"))?;
    }
    Ok(())
}

/// Remove `dir/<prefix><pid>-<n>.lightlab-tmp` files whose process is gone.
/// Best effort: failures are ignored (a stale file is harmless).
fn remove_stale(dir: &Path, prefix: &str) {
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let Some(rest) = name.to_str().and_then(|n| n.strip_prefix(prefix)).and_then(|r| r.strip_suffix(TMP_SUFFIX))
        else {
            continue;
        };
        let Some(pid) = rest.split_once('-').and_then(|(pid, _)| pid.parse::<u32>().ok()) else {
            continue;
        };
        if !process_alive(pid) {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Whether process `pid` exists. Linux: `/proc/<pid>`; elsewhere only the current
/// process counts as alive (another one's temporary file is treated as stale).
fn process_alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    let proc_dir = Path::new("/proc");
    proc_dir.join("self").exists() && proc_dir.join(pid.to_string()).exists()
}

/// An exclusive lock on a directory, held until dropped.
#[derive(Debug)]
pub struct DirLock {
    _file: File,
    path: PathBuf,
}

impl DirLock {
    /// The lock file.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

/// The lock file's name inside a locked directory.
pub const LOCK_FILE: &str = ".lightlab.lock";

/// Lock `dir` (created if absent) for one writer: an exclusive `flock` on
/// `dir/.lightlab.lock`, which then holds the holder's process id.
///
/// When another process holds the lock, `waiting` is called once with a message
/// naming the lock file and the holder's pid, then the call blocks until the lock is
/// free. The lock is released when the returned guard is dropped or the process
/// ends (even by `kill -9`), so a stale lock file never blocks anyone.
pub fn lock_dir(dir: &Path, waiting: impl FnOnce(&str)) -> Result<DirLock, OutputError> {
    if let Ok(meta) = std::fs::metadata(dir) {
        if !meta.is_dir() {
            let reason = if meta.is_file() {
                "is a file, not a directory".to_string()
            } else {
                format!("is {}, not a directory", kind_of(&meta))
            };
            return Err(OutputError::Refused { path: dir.to_path_buf(), reason });
        }
    }
    std::fs::create_dir_all(dir).map_err(io_error(dir, "create the directory"))?;
    let path = dir.join(LOCK_FILE);
    let mut file = OpenOptions::new()
        .read(true)
        .write(true)
        .create(true)
        .truncate(false)
        .open(&path)
        .map_err(io_error(&path, "open the lock file"))?;
    match file.try_lock() {
        Ok(()) => {}
        Err(std::fs::TryLockError::WouldBlock) => {
            let mut holder = String::new();
            let _ = file.read_to_string(&mut holder);
            let holder = holder.trim();
            let who = if holder.is_empty() { String::new() } else { format!(" (held by process {holder})") };
            waiting(&format!("waiting for the lock on {}{who}", path.display()));
            file.lock().map_err(io_error(&path, "lock"))?;
        }
        Err(std::fs::TryLockError::Error(e)) => return Err(io_error(&path, "lock")(e)),
    }
    // Best effort: the pid is only for the waiting message of a second run.
    let _ = file.set_len(0).and_then(|()| file.rewind()).and_then(|()| write!(file, "{}", std::process::id()));
    Ok(DirLock { _file: file, path })
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::scratch::Scratch;

    fn scratch(name: &str) -> Scratch {
        Scratch::new(&format!("outfile-{name}"))
    }

    fn entries(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = std::fs::read_dir(dir)
            .expect("read dir")
            .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn writes_new_and_replaces_regular_files_leaving_no_temporaries() {
        let dir = scratch("regular");
        let path = dir.join("a.txt");
        write_atomically(&path, "one").expect("new file");
        write_atomically(&path, "two").expect("replace");
        assert_eq!(std::fs::read_to_string(&path).expect("read"), "two");
        assert_eq!(entries(&dir), ["a.txt"]);
    }

    #[cfg(unix)]
    #[test]
    fn follows_symlinks_and_keeps_them() {
        let dir = scratch("symlink");
        let real = dir.join("real.txt");
        std::fs::write(&real, "old").expect("write");
        let link = dir.join("link.txt");
        std::os::unix::fs::symlink("real.txt", &link).expect("symlink");
        write_atomically(&link, "new").expect("through link");
        assert!(std::fs::symlink_metadata(&link).expect("meta").file_type().is_symlink());
        assert_eq!(std::fs::read_to_string(&real).expect("read"), "new");
        // A dangling link creates its target.
        let dangling = dir.join("dangling.txt");
        std::os::unix::fs::symlink("made.txt", &dangling).expect("symlink");
        write_atomically(&dangling, "x").expect("dangling");
        assert_eq!(std::fs::read_to_string(dir.join("made.txt")).expect("read"), "x");
    }

    #[test]
    fn refuses_directories_and_devices_naming_the_path() {
        let dir = scratch("refuse");
        let sub = dir.join("sub");
        std::fs::create_dir(&sub).expect("mkdir");
        let err = write_atomically(&sub, "x").expect_err("a directory");
        assert!(err.to_string().contains(&sub.display().to_string()) && err.to_string().contains("directory"), "{err}");
        assert!(err.is_user_error());
        assert_eq!(entries(&dir), ["sub"], "no temporary left");
        #[cfg(unix)]
        {
            let err = write_atomically(Path::new("/dev/null"), "x").expect_err("a device");
            assert!(err.to_string().starts_with("/dev/null: is a device"), "{err}");
        }
    }

    #[test]
    fn missing_directory_is_named() {
        let dir = scratch("missing");
        let path = dir.join("no").join("such").join("out.png");
        let err = write_atomically(&path, "x").expect_err("missing dir");
        assert!(err.to_string().contains(&dir.join("no").join("such").display().to_string()), "{err}");
        assert!(err.is_user_error());
    }

    #[test]
    fn stale_temporaries_of_dead_processes_are_removed() {
        let dir = scratch("stale");
        // pid 0 is never a user process's id; u32::MAX is above any pid_max.
        let stale = dir.join(format!(".out.txt.{}-0{TMP_SUFFIX}", u32::MAX));
        std::fs::write(&stale, "partial").expect("write");
        let other = dir.join(".other.txt.1-0.lightlab-tmp");
        std::fs::write(&other, "not ours").expect("write");
        write_atomically(&dir.join("out.txt"), "done").expect("write");
        assert_eq!(entries(&dir), [".other.txt.1-0.lightlab-tmp", "out.txt"]);
    }

    #[test]
    fn lock_is_exclusive_and_released_on_drop() {
        let dir = scratch("lock");
        let guard = lock_dir(&dir, |_| panic!("no one else holds it")).expect("lock");
        assert_eq!(std::fs::read_to_string(guard.path()).expect("pid"), std::process::id().to_string());
        // A second handle in the same process conflicts, as another process would.
        let other = File::options().read(true).write(true).open(guard.path()).expect("open");
        assert!(matches!(other.try_lock(), Err(std::fs::TryLockError::WouldBlock)));
        drop(guard);
        other.try_lock().expect("free after drop");
    }
}
