//! `lightlab study [--quick] [--out DIR]`: run the speed-against-accuracy study.
//!
//! Prints one table per scene (method, ms/frame median [min, max], ns/fragment,
//! max and mean error in 8-bit levels, % of pixels off by more than one level,
//! mean FLIP, Pareto mark), shows progress on stderr, and writes one CSV per
//! scene (`DIR/<scene>.csv`, default `book/data/study/`) headed by the machine
//! description, and its cost-against-error chart (`DIR/<scene>.png`). Files are
//! written to a temporary name, then renamed; `DIR` is locked for the run, so a
//! second study on the same directory waits. The book draws its own charts and
//! tables from the committed CSVs.

use std::path::{Path, PathBuf};
use std::time::Instant;

use super::{output, CliError, CliResult, Outcome};
use crate::outfile::write_atomically;
use crate::study::speed::{run_study, to_csv, Machine, Row, StudyOptions, SCENES};
use crate::table::{render, Format};

/// Arguments of `lightlab study`.
#[derive(clap::Args, Debug, Clone)]
pub struct StudyArgs {
    /// A small frame and one-frame runs (seconds; for tests and CI).
    #[arg(long)]
    pub quick: bool,
    /// Directory for the CSVs and charts [default: book/data/study of the project found
    /// from the working directory upward, as cargo finds Cargo.toml].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// The default output directory: `book/data/study` beside the `book/book.toml` found
/// from the working directory upward ([`super::find_book_dir`]); a usage error asking
/// for `--out` when there is none.
pub fn default_out() -> Result<PathBuf, CliError> {
    let book = super::find_book_dir().map_err(|e| CliError::Usage(format!("{e}, or pass --out DIR")))?;
    Ok(book.join("data").join("study"))
}

/// Run the study and write the CSVs and charts into `out`; returns the machine and rows.
///
/// `out` is created if absent and locked ([`crate::outfile::lock_dir`]) for the whole
/// run, so a second `lightlab study --out` on the same directory waits (and says who
/// holds the lock) instead of mixing its files with this one's. Each file is written
/// with [`write_atomically`]; every path is checked writable before the study runs.
pub fn study(opts: &StudyOptions, out: &Path, quiet: bool) -> Result<(Machine, Vec<Row>), CliError> {
    let _lock = crate::outfile::lock_dir(out, |message| eprintln!("lightlab study: {message}"))?;
    // Before the minutes of measuring: every output path must be writable now.
    for scene in SCENES {
        for ext in ["csv", "png"] {
            crate::outfile::check_writable(&out.join(format!("{scene}.{ext}")))?;
        }
    }
    let machine = Machine::detect(opts.width, opts.height);
    let start = Instant::now();
    let mut step = 0;
    let mut progress = |msg: &str| {
        step += 1;
        if !quiet {
            eprintln!("[{:6.1} s] {step:2}. {msg}", start.elapsed().as_secs_f64());
        }
    };
    let rows = run_study(opts, &mut progress);
    for scene in SCENES {
        let scene_rows: Vec<Row> = rows.iter().filter(|r| r.scene == scene).cloned().collect();
        let csv = to_csv(&machine, &scene_rows).map_err(|e| CliError::Internal(format!("{scene}.csv: {e}")))?;
        write_atomically(&out.join(format!("{scene}.csv")), csv)?;
        let chart = crate::figures::study_charts::chart_png_of(scene, &scene_rows, crate::i18n::output_lang())
            .map_err(|e| CliError::Internal(format!("chart of {scene}: {e}")))?;
        write_atomically(&out.join(format!("{scene}.png")), chart)?;
    }
    Ok((machine, rows))
}

/// Run `lightlab study`: `Success`, or an error (an unwritable `--out` is an input error).
pub fn run(args: &StudyArgs) -> CliResult {
    let opts = if args.quick { StudyOptions::quick() } else { StudyOptions::full() };
    let out = match &args.out {
        Some(dir) => dir.clone(),
        None => default_out()?,
    };
    let (machine, rows) = study(&opts, &out, false)?;
    let mut stdout = output::stdout();
    stdout.line(format_args!(
        "machine: {} ({} threads), kernel ISA {}, frame {}",
        machine.cpu, machine.cores, machine.isa, machine.frame
    ))?;
    for scene in SCENES {
        let scene_rows: Vec<Row> = rows.iter().filter(|r| r.scene == scene).cloned().collect();
        let t = crate::study::speed::table(scene, &scene_rows);
        stdout.line(format_args!("\n{}", render(&[t], Format::Text)))?;
    }
    stdout.line(format_args!("CSVs and charts (<scene>.csv, <scene>.png) written to {}", out.display()))?;
    stdout.finish()?;
    Ok(Outcome::Success)
}
