//! The measured data the book draws: the CSVs in `book/data/` (written by `lightlab study`
//! and `lightlab bench --csv`), read from disk at build time.
//!
//! They used to be compiled in with `include_str!`, so after `lightlab study` rewrote them
//! the book still drew the old charts until `lightlab` itself was rebuilt. Now
//! every build reads the files on disk, an error names the missing or malformed file, and
//! the generate cache is keyed on their bytes ([`BookData::fingerprint`]): unchanged CSVs
//! give a byte-identical book, changed ones redraw their charts.

use std::path::{Path, PathBuf};

use super::FigureError;

/// The files under `book/data/` that generators read, relative to it.
pub const FILES: [&str; 7] = [
    "study/sphere-multi.csv",
    "study/sphere-gbuffer.csv",
    "study/floor-lights.csv",
    "bench/roofline.csv",
    "bench/scaling.csv",
    "bench/specialisations.csv",
    "bench/sweep.csv",
];

/// The data folder of one book: `<book root>/data`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BookData {
    dir: PathBuf,
}

impl BookData {
    /// The data of the book whose root (the folder holding `book.toml`) is `root`.
    pub fn of_book(root: &Path) -> BookData {
        BookData { dir: root.join("data") }
    }

    /// The data of this source tree's book (`book/data` beside `Cargo.toml`), for tests
    /// and tools that run from the repository.
    pub fn in_repository() -> BookData {
        BookData { dir: Path::new(env!("CARGO_MANIFEST_DIR")).join("book").join("data") }
    }

    /// The path of `rel` (one of [`FILES`]).
    pub fn path(&self, rel: &str) -> PathBuf {
        self.dir.join(rel)
    }

    /// The text of `rel`. Errors: [`FigureError::Invalid`] naming the path when it is
    /// missing, unreadable or not UTF-8.
    pub fn read(&self, rel: &str) -> Result<String, FigureError> {
        let path = self.path(rel);
        std::fs::read_to_string(&path).map_err(|e| {
            FigureError::Invalid(format!(
                "{}: {e} (the book draws its charts from this file; `lightlab study` or `lightlab bench --csv` writes it)",
                path.display()
            ))
        })
    }

    /// A hash of every file of [`FILES`] (a missing one hashes as missing), which the
    /// generate cache adds to its key.
    pub fn fingerprint(&self) -> u64 {
        // FNV-1a over (name, length, bytes) of each file: stable across runs and builds.
        let mut h: u64 = 0xcbf2_9ce4_8422_2325;
        let mut eat = |bytes: &[u8]| {
            for b in bytes {
                h ^= u64::from(*b);
                h = h.wrapping_mul(0x0000_0100_0000_01b3);
            }
        };
        for rel in FILES {
            eat(rel.as_bytes());
            match std::fs::read(self.path(rel)) {
                Ok(bytes) => {
                    eat(&(bytes.len() as u64).to_le_bytes());
                    eat(&bytes);
                }
                Err(_) => eat(b"\0missing"),
            }
        }
        h
    }
}
