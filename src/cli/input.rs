//! Reading a user's input file with its limits applied before the work: only a regular
//! file is opened (a FIFO given as a shader would block the reader for ever, a device
//! never ends), and at most `limit + 1` bytes are read, so a 1.5 GB file costs 4 MiB of
//! memory and an error, not 3.5 GB and a crash.

use std::io::Read;
use std::path::Path;

// In the output's language: these errors reach a student's row and page.
use crate::checker::texts::{tr, tr_fill};

/// A file that cannot be opened or read (`{}`: the system's reason).
pub const CANNOT_READ: &str = "cannot read: {}";
/// A path that is not a regular file (`{}`: what it is, one of [`KINDS`]).
pub const NOT_REGULAR: &str = "{}: only regular files are read";
/// A file over the limit (`{}`: the limit in bytes).
pub const TOO_LARGE: &str = "the file is larger than the limit of {} bytes";
/// What a path is when it is not a regular file: a FIFO, a device, a socket, a directory,
/// anything else.
pub const KINDS: [&str; 5] = ["a FIFO (named pipe)", "a device", "a socket", "a directory", "not a regular file"];
/// Every msgid of this module, for the translation template.
pub const TEXTS: [&str; 8] = [CANNOT_READ, NOT_REGULAR, TOO_LARGE, KINDS[0], KINDS[1], KINDS[2], KINDS[3], KINDS[4]];

/// What a path is, in words ([`KINDS`]), when it is not a regular file.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return KINDS[0];
        }
        if t.is_char_device() || t.is_block_device() {
            return KINDS[1];
        }
        if t.is_socket() {
            return KINDS[2];
        }
    }
    if t.is_dir() {
        KINDS[3]
    } else {
        KINDS[4]
    }
}

fn cannot_read(e: &std::io::Error) -> String {
    tr_fill(CANNOT_READ, &[&e.to_string()])
}

fn not_regular(meta: &std::fs::Metadata) -> String {
    tr_fill(NOT_REGULAR, &[&tr(kind_of(meta))])
}

// String error: every caller puts the message in a row's cell or prefixes it with the
// file's role ("shader", "mapping") in a usage error.
/// The bytes of `path` (symbolic links followed), refusing anything but a regular file
/// and any file over `limit` bytes; errors say which, in words.
pub fn read_limited(path: &Path, limit: usize) -> Result<Vec<u8>, String> {
    let meta = std::fs::metadata(path).map_err(|e| cannot_read(&e))?;
    if !meta.is_file() {
        return Err(not_regular(&meta));
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // The path may have been swapped for a FIFO since the check: never block in open.
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(|e| cannot_read(&e))?;
    let meta = file.metadata().map_err(|e| cannot_read(&e))?;
    if !meta.is_file() {
        return Err(not_regular(&meta));
    }
    let mut bytes = Vec::new();
    file.take(limit as u64 + 1).read_to_end(&mut bytes).map_err(|e| cannot_read(&e))?;
    if bytes.len() > limit {
        return Err(tr_fill(TOO_LARGE, &[&limit.to_string()]));
    }
    Ok(bytes)
}
