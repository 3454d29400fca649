//! Scratch folders for the library's unit tests.
//!
//! Tests of one binary run in parallel threads of one process, so a folder named after the
//! process alone is shared: one test's cleanup then deletes another's files mid-test (CI saw
//! exactly that). Every [`Scratch`] has its own name: the tag, the process id and a counter.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// A test's own empty folder under the system's temporary directory, removed when dropped
/// (at the end of the test, passed or panicked); it dereferences to its path.
pub(crate) struct Scratch(PathBuf);

impl Scratch {
    /// A new empty folder `lightlab-<tag>-<pid>-<n>`, unique within the process.
    pub(crate) fn new(tag: &str) -> Scratch {
        static NEXT: AtomicUsize = AtomicUsize::new(0);
        let n = NEXT.fetch_add(1, Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("lightlab-{tag}-{}-{n}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create a scratch folder");
        Scratch(dir)
    }
}

impl std::ops::Deref for Scratch {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.0
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

#[cfg(test)]
mod tests {
    use super::Scratch;

    #[test]
    fn two_scratches_of_one_tag_are_two_folders_and_each_goes_with_its_owner() {
        let a = Scratch::new("same");
        let b = Scratch::new("same");
        assert_ne!(a.to_path_buf(), b.to_path_buf());
        let kept = b.to_path_buf();
        drop(a);
        assert!(kept.is_dir(), "dropping one scratch must not remove another");
        drop(b);
        assert!(!kept.exists());
    }
}
