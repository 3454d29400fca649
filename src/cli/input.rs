//! Reading a user's input file with its limits applied before the work: only a regular
//! file is opened (a FIFO given as a shader would block the reader for ever, a device
//! never ends), and at most `limit + 1` bytes are read, so a 1.5 GB file costs 4 MiB of
//! memory and an error, not 3.5 GB and a crash.

use std::io::Read;
use std::path::Path;

/// What a path is, in words, when it is not a regular file.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    if t.is_dir() {
        "a directory"
    } else {
        "not a regular file"
    }
}

// String error: every caller puts the message in a row's cell or prefixes it with the
// file's role ("shader", "mapping") in a usage error.
/// The bytes of `path` (symbolic links followed), refusing anything but a regular file
/// and any file over `limit` bytes; errors say which, in words.
pub fn read_limited(path: &Path, limit: usize) -> Result<Vec<u8>, String> {
    let meta = std::fs::metadata(path).map_err(|e| format!("cannot read: {e}"))?;
    if !meta.is_file() {
        return Err(format!("{}: only regular files are read", kind_of(&meta)));
    }
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // The path may have been swapped for a FIFO since the check: never block in open.
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(|e| format!("cannot read: {e}"))?;
    let meta = file.metadata().map_err(|e| format!("cannot read: {e}"))?;
    if !meta.is_file() {
        return Err(format!("{}: only regular files are read", kind_of(&meta)));
    }
    let mut bytes = Vec::new();
    file.take(limit as u64 + 1).read_to_end(&mut bytes).map_err(|e| format!("cannot read: {e}"))?;
    if bytes.len() > limit {
        return Err(format!("the file is larger than the limit of {limit} bytes"));
    }
    Ok(bytes)
}
