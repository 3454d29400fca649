//! `lightlab i18n extract|check`: the translations' workflow (see [`crate::i18n`]).
//!
//! - `extract`: writes `po/messages.pot` from the book and the Rust strings, and merges it
//!   into `po/fr.po` and `po/uk.po` (what `msgmerge` does, in process);
//! - `check [--lang fr|uk]`: every problem of the PO files against the template, one line
//!   each (`book/src/…:line: "first words": what is wrong`), then a count per language.
//!   Exit 0 when there is none, 1 otherwise.

use std::path::PathBuf;

use super::{output, CliError, CliResult, Outcome};
use crate::i18n::{self, Lang};

/// Arguments of `lightlab i18n`.
#[derive(clap::Args, Debug, Clone)]
pub struct I18nArgs {
    /// What to do.
    #[command(subcommand)]
    pub action: I18nAction,
    /// The book directory [default: the `book/` found from the working directory upward].
    #[arg(long, value_name = "DIR", global = true)]
    pub root: Option<PathBuf>,
}

/// `extract` or `check`.
#[derive(clap::Subcommand, Debug, Clone)]
pub enum I18nAction {
    /// Rewrite po/messages.pot from the English and merge it into every PO file.
    Extract,
    /// Copy the translations of PO files (a translator's part) into `po/<lang>.po`: each
    /// message of FILE that the template has and FILE translates replaces the old one.
    Merge {
        /// The language of the files.
        #[arg(long)]
        lang: Lang,
        /// The PO files to take translations from.
        #[arg(required = true)]
        files: Vec<PathBuf>,
    },
    /// List what is missing or wrong in the PO files.
    Check {
        /// Only this language.
        #[arg(long)]
        lang: Option<Lang>,
        /// Check this PO file (a part of a translation into `--lang`) instead of
        /// `po/<lang>.po`: only the messages it holds are checked.
        #[arg(long, value_name = "FILE", requires = "lang")]
        po: Option<PathBuf>,
    },
}

impl clap::ValueEnum for Lang {
    fn value_variants<'a>() -> &'a [Self] {
        &Lang::ALL
    }

    fn to_possible_value(&self) -> Option<clap::builder::PossibleValue> {
        Some(clap::builder::PossibleValue::new(self.code()))
    }
}

/// Run `lightlab i18n`.
pub fn run(args: &I18nArgs) -> CliResult {
    let root = match &args.root {
        Some(r) => r.clone(),
        None => super::find_book_dir()?,
    };
    match &args.action {
        I18nAction::Extract => {
            // the chapters include generated tables: make them current first
            crate::book::generate_for(&root).map_err(|e| CliError::Internal(e.to_string()))?;
            let drawn = crate::book::drawn_words(&root).map_err(|e| CliError::Internal(e.to_string()))?;
            let rust = super::messages::rust_messages();
            let report = i18n::extract::extract(&root, &rust, &drawn).map_err(CliError::Input)?;
            let mut text = format!("po/messages.pot: {} messages\n", report.messages);
            for (lang, kept, empty) in report.merged {
                text += &format!("po/{lang}.po: {kept} translated, {empty} to translate\n");
            }
            output::print(text)?;
            Ok(Outcome::Success)
        }
        I18nAction::Merge { lang, files } => {
            let path = i18n::extract::po_dir(&root).join(format!("{}.po", lang.code()));
            let mut parts = Vec::new();
            for f in files {
                parts.push(
                    i18n::catalog::parse_po_file(f).map_err(|e| CliError::Input(format!("{}: {e}", f.display())))?,
                );
            }
            let taken = i18n::extract::merge_translations(&path, &parts).map_err(CliError::Input)?;
            output::print(format!("{}: {taken} translations taken from {} files\n", path.display(), files.len()))?;
            Ok(Outcome::Success)
        }
        I18nAction::Check { lang, po } => {
            let dir = i18n::extract::po_dir(&root);
            let pot = i18n::catalog::parse_po_file(&dir.join("messages.pot"))
                .map_err(|e| CliError::Input(format!("{}: {e}", dir.join("messages.pot").display())))?;
            if let (Some(file), Some(l)) = (po, lang) {
                let part = i18n::catalog::parse_po_file(file)
                    .map_err(|e| CliError::Input(format!("{}: {e}", file.display())))?;
                let problems = i18n::check::check_part(&pot, &part, *l);
                let mut text: String = problems.iter().map(|p| format!("{l}: {p}\n")).collect();
                text +=
                    &format!("{l}: {} problems in {} messages of {}\n", problems.len(), part.count(), file.display());
                output::print(text)?;
                return Ok(if problems.is_empty() { Outcome::Success } else { Outcome::Problems });
            }
            let mut text = String::new();
            let mut total = 0;
            for l in Lang::ALL.into_iter().filter(|l| l.is_translation() && lang.is_none_or(|x| x == *l)) {
                let path = dir.join(format!("{}.po", l.code()));
                let po = i18n::catalog::parse_po_file(&path)
                    .map_err(|e| CliError::Input(format!("{}: {e}", path.display())))?;
                let problems = i18n::check::check(&pot, &po, l);
                for p in &problems {
                    text += &format!("{l}: {p}\n");
                }
                text += &format!("{l}: {} problems in {} messages\n", problems.len(), pot.count());
                total += problems.len();
            }
            output::print(text)?;
            Ok(if total == 0 { Outcome::Success } else { Outcome::Problems })
        }
    }
}
