//! One writer at a time for an output tree: an exclusive advisory lock on a lock file.
//!
//! [`OutputLock::acquire`] opens (or creates) the lock file, tries to take the
//! operating system's exclusive file lock (`flock` on Unix, `LockFileEx` on Windows,
//! through [`std::fs::File::lock`]), and when another process holds it, reports the
//! holder through a callback and waits. The holder writes its process id and
//! program name into the file, so the waiting process can say whom it waits for. The
//! lock is released when the [`OutputLock`] is dropped, or by the operating system
//! when the process dies, so a killed build never leaves a stale lock behind. The lock
//! file itself stays (deleting it would let two processes lock two different files).
//!
//! The book build locks `book/.lightlab.lock`; `lightlab study` locks
//! `<out>/.lightlab.lock`.

use std::fs::{File, OpenOptions, TryLockError};
use std::io::{Read as _, Seek as _, SeekFrom, Write as _};
use std::path::{Path, PathBuf};

/// The lock file's name inside a locked directory: `.lightlab.lock`.
pub const LOCK_FILE_NAME: &str = ".lightlab.lock";

/// The lock file could not be created, locked or written.
#[derive(Debug, thiserror::Error)]
#[error("locking {}: {source}", .path.display())]
pub struct LockError {
    /// The lock file.
    pub path: PathBuf,
    /// The underlying error.
    pub source: std::io::Error,
}

/// An exclusive lock, held until dropped.
#[derive(Debug)]
pub struct OutputLock {
    file: File,
    path: PathBuf,
}

impl OutputLock {
    /// Take the exclusive lock on `path` (created with its parent directories when
    /// missing). When another process holds it, `on_wait` is called once with a
    /// description of the holder (`"held by process 1234 (lightlab)"`, or
    /// `"held by another process"` when the file does not say), then this call blocks
    /// until the lock is free.
    ///
    /// Errors name the lock file: a directory that cannot be created, a file that
    /// cannot be opened, or a file system without locking.
    pub fn acquire(path: &Path, on_wait: impl FnOnce(&str)) -> Result<OutputLock, LockError> {
        let err = |source| LockError { path: path.to_path_buf(), source };
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            std::fs::create_dir_all(parent).map_err(err)?;
        }
        let mut file =
            OpenOptions::new().read(true).write(true).create(true).truncate(false).open(path).map_err(err)?;
        match file.try_lock() {
            Ok(()) => {}
            Err(TryLockError::WouldBlock) => {
                on_wait(&holder(&mut file));
                file.lock().map_err(err)?;
            }
            Err(TryLockError::Error(e)) => return Err(err(e)),
        }
        let me = format!("{} {}\n", std::process::id(), program_name());
        file.set_len(0)
            .and_then(|_| file.seek(SeekFrom::Start(0)))
            .and_then(|_| file.write_all(me.as_bytes()))
            .map_err(err)?;
        Ok(OutputLock { file, path: path.to_path_buf() })
    }

    /// The lock file.
    pub fn path(&self) -> &Path {
        &self.path
    }
}

impl Drop for OutputLock {
    fn drop(&mut self) {
        // Best effort: closing the file releases the lock anyway.
        let _ = self.file.set_len(0);
        let _ = self.file.unlock();
    }
}

/// "held by process N (name)" from the lock file's content, written by the holder.
fn holder(file: &mut File) -> String {
    let mut text = String::new();
    let _ = file.seek(SeekFrom::Start(0)).and_then(|_| file.take(200).read_to_string(&mut text));
    let mut words = text.split_whitespace();
    match (words.next().and_then(|p| p.parse::<u32>().ok()), words.next()) {
        (Some(pid), Some(name)) => format!("held by process {pid} ({name})"),
        (Some(pid), None) => format!("held by process {pid}"),
        _ => "held by another process".to_owned(),
    }
}

/// The running program's file name, for the lock file (`?` when unknown; lossy when
/// not UTF-8).
fn program_name() -> String {
    std::env::current_exe()
        .ok()
        .and_then(|p| p.file_name().map(|n| n.to_string_lossy().replace(char::is_whitespace, "_")))
        .unwrap_or_else(|| "?".to_owned())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::mpsc;
    use std::time::Duration;

    #[test]
    fn a_second_holder_waits_and_is_told_who_holds_the_lock() {
        let dir = std::env::temp_dir().join(format!("lightlab-lock-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let path = dir.join("sub").join(".lightlab.lock");
        let first = OutputLock::acquire(&path, |_| panic!("nobody holds it yet")).unwrap();
        let (told, heard) = mpsc::channel();
        let (got, acquired) = mpsc::channel();
        let p = path.clone();
        let waiter = std::thread::spawn(move || {
            // File locks belong to the open file description, so a second open in this
            // process conflicts with the first exactly as another process would.
            let lock = OutputLock::acquire(&p, |who| told.send(who.to_owned()).unwrap()).unwrap();
            got.send(()).unwrap();
            drop(lock);
        });
        let who = heard.recv().unwrap();
        assert_eq!(who, format!("held by process {} ({})", std::process::id(), program_name()));
        // Not a timing assertion: the waiter cannot have the lock while `first` lives,
        // whatever the delay; the delay only gives a wrong implementation the chance to show.
        assert!(acquired.recv_timeout(Duration::from_millis(200)).is_err(), "two holders at once");
        drop(first);
        acquired.recv().unwrap();
        waiter.join().unwrap();
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn an_unusable_path_is_an_error_naming_it() {
        let file = std::env::temp_dir().join(format!("lightlab-lock-file-{}", std::process::id()));
        std::fs::write(&file, b"x").unwrap();
        let e = OutputLock::acquire(&file.join("a.lock"), |_| {}).unwrap_err();
        assert!(e.to_string().contains(&*file.to_string_lossy()), "{e}");
        let _ = std::fs::remove_file(&file);
    }
}
