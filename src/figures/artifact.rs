//! Generated files and the registry that lists them.
//!
//! An [`Artifact`] is one generator and the paths of the files it writes, relative to
//! the book's `src/generated/` directory. Most generators write one file
//! ([`Artifact::file`]); a generator that computes several files from one piece of
//! work (an image and the caption that quotes numbers measured on it) writes them all
//! from one run ([`Artifact::files`]), so the work is done once per build.
//!
//! Each topic module keeps its own list (`pub fn artifacts() -> Vec<Artifact>`), and
//! the book build concatenates the lists (`book::artifacts`). A new topic adds one line
//! there (`all.extend(my_topic::artifacts())`). A list looks like this:
//!
//! ```
//! use lightlab::figures::artifact::Artifact;
//!
//! fn artifacts() -> Vec<Artifact> {
//!     vec![
//!         Artifact::file("notes/hello.md", || Ok::<_, String>(b"hello\n".to_vec())),
//!         Artifact::files(["pair/a.txt", "pair/b.txt"], || Ok::<_, String>([b"a".to_vec(), b"b".to_vec()])),
//!     ]
//! }
//! assert_eq!(artifacts()[1].paths(), ["pair/a.txt", "pair/b.txt"]);
//! ```
//!
//! Generators must be pure: their bytes may depend only on code compiled into the
//! binary (no clock, no unseeded randomness, no reading files that can change). Their
//! errors are any `std::error::Error` (or a `String`); the book names the artifact's
//! paths next to the message.

use std::collections::BTreeSet;
use std::fmt;
use std::path::{Component, Path};
use std::sync::Arc;

use crate::i18n::Lang;

/// The error a generator may return: any error type, or a `String` message.
pub type BoxError = Box<dyn std::error::Error + Send + Sync>;

/// A generator's work: the bytes of each of its files, in the order of its paths.
type MakeFn = dyn Fn() -> Result<Vec<Vec<u8>>, BoxError> + Send + Sync;

/// One generator and the files it writes.
#[derive(Clone)]
pub struct Artifact {
    paths: Vec<String>,
    make: Arc<MakeFn>,
    /// The language of the words in the files, for a [`Artifact::localized`] generator.
    lang: Option<Lang>,
}

impl fmt::Debug for Artifact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Artifact").field("paths", &self.paths).field("lang", &self.lang).finish_non_exhaustive()
    }
}

impl Artifact {
    /// A generator of one file at `path` (relative, `/`-separated, for example
    /// `"charts/specular-falloff.png"`; no `..`, no leading `/`).
    pub fn file<E: Into<BoxError>>(
        path: impl Into<String>,
        make: impl Fn() -> Result<Vec<u8>, E> + Send + Sync + 'static,
    ) -> Artifact {
        Artifact {
            paths: vec![path.into()],
            make: Arc::new(move || make().map(|b| vec![b]).map_err(Into::into)),
            lang: None,
        }
    }

    /// A generator of `N` files from one run: `make` returns their bytes in the order
    /// of `paths`.
    pub fn files<const N: usize, E: Into<BoxError>>(
        paths: [&str; N],
        make: impl Fn() -> Result<[Vec<u8>; N], E> + Send + Sync + 'static,
    ) -> Artifact {
        Artifact {
            paths: paths.iter().map(|p| (*p).to_owned()).collect(),
            make: Arc::new(move || make().map(Vec::from).map_err(Into::into)),
            lang: None,
        }
    }

    /// A generator of as many files as `paths` names, from one run: `make` returns
    /// their bytes in the order of `paths` (a different count is an error when it
    /// runs). For lists known only at run time; prefer [`Artifact::files`] otherwise.
    pub fn many<E: Into<BoxError>>(
        paths: Vec<String>,
        make: impl Fn() -> Result<Vec<Vec<u8>>, E> + Send + Sync + 'static,
    ) -> Artifact {
        Artifact { paths, make: Arc::new(move || make().map_err(Into::into)), lang: None }
    }

    /// Files that carry words (a chart's axes, a diagram's labels, a live figure's
    /// caption): one generator per language, the English at `paths` and each translation
    /// at `<code>/<path>` (`fr/charts/x.png`). `make` draws its words in the language it is
    /// given, through [`crate::i18n::tr`]; a translated chapter shows its language's copy
    /// (see [`crate::i18n::localize`]).
    pub fn localized<E: Into<BoxError>>(
        paths: Vec<String>,
        make: impl Fn(Lang) -> Result<Vec<Vec<u8>>, E> + Send + Sync + 'static,
    ) -> Vec<Artifact> {
        let make = Arc::new(make);
        Lang::ALL
            .into_iter()
            .map(|lang| {
                let make = Arc::clone(&make);
                let paths = paths
                    .iter()
                    .map(|p| if lang.is_translation() { format!("{}/{p}", lang.code()) } else { p.clone() })
                    .collect();
                Artifact { paths, make: Arc::new(move || make(lang).map_err(Into::into)), lang: Some(lang) }
            })
            .collect()
    }

    /// The language of a [`Artifact::localized`] generator; `None` for files without words.
    #[must_use]
    pub fn lang(&self) -> Option<Lang> {
        self.lang
    }

    /// The paths this generator writes, in the order of [`Artifact::make`]'s output.
    pub fn paths(&self) -> &[String] {
        &self.paths
    }

    /// Run the generator: one byte vector per path. A generator that returns the
    /// wrong number of files is an error (it cannot happen through the constructors).
    pub fn make(&self) -> Result<Vec<Vec<u8>>, BoxError> {
        let files = (self.make)()?;
        if files.len() != self.paths.len() {
            return Err(format!("{} files made for {} paths", files.len(), self.paths.len()).into());
        }
        Ok(files)
    }
}

/// Why a registry is not valid.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum RegistryError {
    /// A path is empty, absolute, has `..` or `\`.
    #[error("artifact path '{0}' must be a relative path without '..'")]
    BadPath(String),
    /// Two artifacts (or one artifact twice) name the same path.
    #[error("artifact path '{0}' is registered twice")]
    Repeated(String),
}

/// Reject empty, absolute, `..`-containing or repeated paths across `all`.
pub fn check_paths(all: &[Artifact]) -> Result<(), RegistryError> {
    let mut seen = BTreeSet::new();
    for path in all.iter().flat_map(Artifact::paths) {
        let plain = Path::new(path).components().all(|c| matches!(c, Component::Normal(_)));
        if path.is_empty() || !plain || path.contains('\\') {
            return Err(RegistryError::BadPath(path.clone()));
        }
        if !seen.insert(path.as_str()) {
            return Err(RegistryError::Repeated(path.clone()));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_paths_are_rejected() {
        for bad in ["", "../x.png", "/abs.png", "a/../b.png", "a\\b.png"] {
            let a = [Artifact::file(bad, || Ok::<_, String>(Vec::new()))];
            assert_eq!(check_paths(&a), Err(RegistryError::BadPath(bad.to_owned())), "{bad:?}");
        }
        let twice = [
            Artifact::files(["a.png", "b.png"], || Ok::<_, String>([vec![], vec![]])),
            Artifact::file("a.png", || Ok::<_, String>(vec![])),
        ];
        assert_eq!(check_paths(&twice), Err(RegistryError::Repeated("a.png".to_owned())));
    }

    #[test]
    fn localized_generators_get_their_language_and_a_path_per_language() {
        let all =
            Artifact::localized(vec!["charts/x.txt".to_owned()], |lang| Ok::<_, String>(vec![lang.code().into()]));
        let paths: Vec<&str> = all.iter().flat_map(Artifact::paths).map(String::as_str).collect();
        assert_eq!(paths, ["charts/x.txt", "fr/charts/x.txt", "uk/charts/x.txt"]);
        let made: Vec<Vec<u8>> = all.iter().flat_map(|a| a.make().unwrap()).collect();
        assert_eq!(made, [b"en".to_vec(), b"fr".to_vec(), b"uk".to_vec()]);
        assert_eq!(all[1].lang(), Some(Lang::Fr));
        assert_eq!(Artifact::file("a", || Ok::<_, String>(vec![])).lang(), None);
        check_paths(&all).unwrap();
    }

    #[test]
    fn files_come_back_in_path_order_and_errors_pass_through() {
        let pair = Artifact::files(["x", "y"], || Ok::<_, String>([b"1".to_vec(), b"2".to_vec()]));
        assert_eq!(pair.make().unwrap(), vec![b"1".to_vec(), b"2".to_vec()]);
        let failing = Artifact::file("z", || Err::<Vec<u8>, _>("no data".to_owned()));
        assert_eq!(failing.make().unwrap_err().to_string(), "no data");
    }
}
