//! `lightlab study [--quick] [--out DIR]`: run the speed-against-accuracy study.
//!
//! Prints one table per scene (method, ms/frame median [min, max], ns/fragment,
//! max and mean error in 8-bit levels, % of pixels off by more than one level,
//! mean FLIP, Pareto mark), shows progress on stderr, and writes one CSV per
//! scene (`DIR/<scene>.csv`, default `book/data/study/`) headed by the machine
//! description, and its cost-against-error chart (`DIR/<scene>.png`). Files are
//! written to a temporary name, then renamed. The book draws its own charts and
//! tables from the committed CSVs. A lock file (`DIR/.lightlab.lock`) keeps two
//! studies from writing the same directory at once: the second waits and says which
//! process it waits for.

use std::path::{Path, PathBuf};
use std::time::Instant;

use crate::study::speed::{run_study, to_csv, Machine, Row, StudyOptions, SCENES};
use crate::tables::{render, Format};

/// Arguments of `lightlab study`.
#[derive(clap::Args, Debug, Clone)]
pub struct StudyArgs {
    /// A small frame and one-frame runs (seconds; for tests and CI).
    #[arg(long)]
    pub quick: bool,
    /// Directory for the CSVs [default: book/data/study].
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// The default output directory: `book/data/study` under the current directory
/// when it holds `book/book.toml`, else under this crate's source tree.
pub fn default_out() -> PathBuf {
    let here = Path::new("book");
    let book = if here.join("book.toml").is_file() {
        here.to_path_buf()
    } else {
        Path::new(env!("CARGO_MANIFEST_DIR")).join("book")
    };
    book.join("data").join("study")
}

/// Write `bytes` to `path` through a temporary file in the same directory.
fn write_atomic(path: &Path, bytes: impl AsRef<[u8]>) -> Result<(), String> {
    // A name of its own per target and process (`.sphere-multi.csv.tmp123`), never
    // shared between a CSV and its chart.
    let mut name = std::ffi::OsString::from(".");
    name.push(path.file_name().unwrap_or_default());
    name.push(format!(".tmp{}", std::process::id()));
    let tmp = path.with_file_name(name);
    std::fs::write(&tmp, bytes).map_err(|e| format!("writing {}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, path).map_err(|e| format!("renaming to {}: {e}", path.display()))
}

/// Run the study and write the CSVs into `out`; returns the machine and rows.
pub fn study(opts: &StudyOptions, out: &Path, quiet: bool) -> Result<(Machine, Vec<Row>), String> {
    std::fs::create_dir_all(out).map_err(|e| format!("--out {}: {e}", out.display()))?;
    // One study per output directory at a time: a second one waits and says for whom.
    let lock_path = out.join(crate::lock::LOCK_FILE_NAME);
    let _lock = crate::lock::OutputLock::acquire(&lock_path, |holder| {
        if !quiet {
            eprintln!("waiting for the lock {} ({holder})", lock_path.display());
        }
    })
    .map_err(|e| e.to_string())?;
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
        let csv = to_csv(&machine, &scene_rows).map_err(|e| format!("{scene}.csv: {e}"))?;
        write_atomic(&out.join(format!("{scene}.csv")), csv)?;
        let chart = crate::figures::study_charts::chart_png_of(scene, &scene_rows).map_err(|e| e.to_string())?;
        write_atomic(&out.join(format!("{scene}.png")), chart)?;
    }
    Ok((machine, rows))
}

/// Run `lightlab study`.
pub fn run(args: &StudyArgs) -> Result<(), String> {
    let opts = if args.quick { StudyOptions::quick() } else { StudyOptions::full() };
    let out = args.out.clone().unwrap_or_else(default_out);
    let (machine, rows) = study(&opts, &out, false)?;
    println!(
        "machine: {} ({} threads), kernel ISA {}, frame {}",
        machine.cpu, machine.cores, machine.isa, machine.frame
    );
    for scene in SCENES {
        let scene_rows: Vec<Row> = rows.iter().filter(|r| r.scene == scene).cloned().collect();
        let t = crate::study::speed::table(scene, &scene_rows);
        println!("\n{}", render(&[t], Format::Text));
    }
    println!("CSVs and charts (<scene>.csv, <scene>.png) written to {}", out.display());
    Ok(())
}
