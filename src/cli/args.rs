//! The command line's arguments ([`Cli`]) and their help in the reader's language
//! ([`command`]). They live in the library, not in the binary, so the translation template
//! takes every help text from the same definitions the binary parses with
//! ([`super::help::texts`]).

use std::path::PathBuf;

use clap::{Args, CommandFactory, Parser, Subcommand};

use crate::i18n::Lang;

/// The command line in `lang`: [`Cli`]'s help translated ([`super::help::localized`]), and
/// every subcommand's help ending with the exit-status table, after its own notes unless
/// those already state its exit statuses (as `shade`'s do).
#[must_use]
pub fn command(lang: Lang) -> clap::Command {
    let english = Cli::command();
    let own_table: Vec<String> = english
        .get_subcommands()
        .filter(|sub| sub.get_after_help().is_some_and(|h| h.to_string().contains("EXIT STATUS")))
        .map(|sub| sub.get_name().to_owned())
        .collect();
    let table = crate::i18n::tr(lang, super::EXIT_STATUS_HELP).into_owned();
    super::help::localized(english, lang).mut_subcommands(|sub| {
        if own_table.iter().any(|name| name == sub.get_name()) || sub.get_name() == "help" {
            return sub;
        }
        match sub.get_after_help().map(|h| h.to_string()) {
            Some(own) => sub.after_help(format!("{own}\n\n{table}")),
            None => sub.after_help(table.clone()),
        }
    })
}

/// The lighting math of real-time graphics, verified.
#[derive(Parser, Debug)]
#[command(
    name = "lightlab",
    version,
    about = "The lighting math of real-time graphics, verified.",
    long_about = "The lighting math of real-time graphics (LearnOpenGL Lighting, opengl-tutorial 8, \
ogldev 19), implemented, verified and explained.\n\n\
With no subcommand, lightlab builds the book: it generates every figure and table into \
book/src/generated/, renders the HTML (mdBook + KaTeX, fully offline) and prints the path \
of the built index.html. It finds the book from the working directory upward (book/book.toml, \
as cargo finds Cargo.toml); elsewhere pass --root DIR.",
    after_help = super::EXIT_STATUS_HELP
)]
pub struct Cli {
    /// The subcommand; none builds the book.
    #[command(subcommand)]
    pub command: Option<Command>,

    /// The book's options, given without a subcommand.
    #[command(flatten)]
    pub book: BookArgs,

    /// The language of the verdicts, diagnoses and statements (exercise, check-shader,
    /// grade): en, fr or uk. Default: LIGHTLAB_LANG, else the first of LC_ALL, LC_MESSAGES
    /// and LANG that is set (uk_UA.UTF-8 gives uk); other locales give English. JSON keys
    /// and mistake ids stay English.
    #[arg(long, global = true, value_name = "LANG")]
    pub lang: Option<crate::i18n::Lang>,

    /// Print all three hints of each mistake the checker names (exercise check,
    /// check-shader), or of where the isolation step found the difference when no mistake
    /// of the catalogue matches: where to look, the idea, the fix. Without it, the first hint.
    #[arg(long, global = true)]
    pub hints: bool,
}

/// The subcommands. Add a variant and a match arm in `run` to add one; its help gets
/// the exit-status table from [`command`].
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Build the book (also what `lightlab` with no subcommand does).
    Book(BookArgs),
    /// Shade fragments given as JSON lines (stdin or a file); print one JSON line per case.
    Shade(super::shade::ShadeArgs),
    /// Render a preset or a scene file to a PNG with the CPU rasterizer.
    Render(super::render::RenderArgs),
    /// Time the benchmark scenes (same output format as llvmpipe_bench.py).
    Bench(super::bench::BenchArgs),
    /// Run a fragment shader on Mesa llvmpipe against a lighting model (exit 0 agrees,
    /// 1 disagrees, 2 usage error).
    #[cfg(feature = "gl")]
    CheckShader(super::check_shader::CheckShaderArgs),
    /// Run the randomized OpenGL oracle and print the per-model error table.
    #[cfg(feature = "gl")]
    Oracle(super::oracle::OracleArgs),
    /// The exercises: list, show, check an answer (exit 0 right, 1 wrong, 2 usage error).
    #[cfg(feature = "gl")]
    Exercise(super::exercise::ExerciseArgs),
    /// Grade a class folder (a file, a pair or a folder per student) against an exercise or an
    /// assignment: CSV, JSON, Gradescope, PrairieLearn or a Moodle worksheet; feedback pages.
    #[cfg(feature = "gl")]
    Grade(super::grade::GradeArgs),
    /// Run the speed-against-accuracy study; print its tables and write its CSVs.
    Study(super::study::StudyArgs),
    /// The translations: re-extract po/messages.pot and merge it into the PO files, or check them.
    I18n(super::i18n::I18nArgs),
}

/// Options of `lightlab book`.
#[derive(Args, Debug, Clone)]
pub struct BookArgs {
    /// The book directory, holding book.toml [default: the book/ directory of the
    /// project found from the working directory upward, as cargo finds Cargo.toml]
    #[arg(long, value_name = "DIR")]
    pub root: Option<PathBuf>,

    /// Regenerate every figure and table, ignoring the cache.
    #[arg(long)]
    pub force: bool,

    /// Print only the path of index.html (and errors).
    #[arg(long, short)]
    pub quiet: bool,

    /// Leave the exercises' reference solutions out (for a course that grades them): the
    /// appendix's folded solutions and the page data's `solution`. The in-page checker
    /// still carries its reference shader (see the book's appendix "Grading a class").
    #[arg(long)]
    pub no_solutions: bool,
}
