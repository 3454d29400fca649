//! The results: the Pareto front, the CSV files and the tables.

use super::*;
use crate::table::Table;

/// The cost-error pair a row is ranked by: (median ms/frame, mean error in levels).
pub fn cost_error(row: &Row) -> (f64, f64) {
    (row.timing.ms_median, row.error.mean_levels)
}

/// Relative difference below which two mean errors count as equal (1 %): rows
/// that share the geometry and differ only in rounding (the three normal-matrix
/// placements, the kernel against scalar code) would otherwise split hairs.
pub const ERROR_TIE: f64 = 0.01;

/// Absolute difference (8-bit levels) below which two mean errors count as equal:
/// a thousandth of a level cannot show in an 8-bit image.
pub const ERROR_TIE_LEVELS: f64 = 1e-3;

/// Whether row `q` dominates row `r` (same scene; at most as costly and at most as
/// wrong, errors within [`ERROR_TIE`] or [`ERROR_TIE_LEVELS`] counting as equal; strictly better in one).
pub fn dominates(q: &Row, r: &Row) -> bool {
    let ((qc, qe), (rc, re)) = (cost_error(q), cost_error(r));
    let tie = (qe - re).abs() <= (ERROR_TIE * qe.max(re)).max(ERROR_TIE_LEVELS);
    let err_le = qe <= re || tie;
    let err_lt = qe < re && !tie;
    q.scene == r.scene && qc <= rc && err_le && (qc < rc || err_lt)
}

/// For each row, whether it is on the Pareto front of its scene: no row dominates it ([`dominates`]).
pub fn pareto(rows: &[Row]) -> Vec<bool> {
    rows.iter().map(|r| !rows.iter().any(|q| dominates(q, r))).collect()
}

/// The CSV header line (after the `#` comment lines of the machine).
pub const CSV_HEADER: &str =
    "scene,group,method,fragments,ms_median,ms_min,ms_max,ns_per_fragment,max_err_levels,mean_err_levels,share_over_1_level,mean_flip,pixels_compared";

/// A study CSV that cannot be written or read back. Every variant names the line
/// (1-based, counting the `#` lines) where that applies.
#[derive(Debug, thiserror::Error)]
pub enum StudyCsvError {
    /// A `#` line that is not `# key: value`.
    #[error("line {line}: expected '# key: value'")]
    Comment {
        /// The line.
        line: usize,
    },
    /// `# cores:` is not a whole number.
    #[error("line {line}: cores {value:?} is not a whole number")]
    Cores {
        /// The line.
        line: usize,
        /// The value found.
        value: String,
    },
    /// The first line after the comments is not [`CSV_HEADER`].
    #[error("line {line}: expected the header {CSV_HEADER:?}")]
    Header {
        /// The line.
        line: usize,
    },
    /// No header line at all.
    #[error("no header line")]
    NoHeader,
    /// A record with the wrong number of fields or a field that is not a number.
    #[error("line {line}: {message}")]
    Record {
        /// The line.
        line: usize,
        /// What is wrong, from the CSV reader (it names the field).
        message: String,
    },
    /// The CSV writer failed.
    #[error("writing the CSV: {0}")]
    Write(String),
}

/// One line of the CSV, column for column with [`CSV_HEADER`].
#[derive(serde::Deserialize)]
pub(super) struct Record {
    pub(super) scene: String,
    pub(super) group: String,
    pub(super) method: String,
    pub(super) fragments: usize,
    pub(super) ms_median: f64,
    pub(super) ms_min: f64,
    pub(super) ms_max: f64,
    // Derived (ms_median / fragments); written for readers of the file, not read back.
    #[serde(rename = "ns_per_fragment")]
    pub(super) _ns_per_fragment: f64,
    pub(super) max_err_levels: f64,
    pub(super) mean_err_levels: f64,
    share_over_1_level: f64,
    pub(super) mean_flip: f64,
    pub(super) pixels_compared: usize,
}

/// One scene's rows as CSV: `# key: value` lines for the machine, the header, one
/// line per row (RFC 4180 quoting through the `csv` crate, `\n` line ends).
///
/// Numbers are written with fixed precision (milliseconds to 4 decimals, errors
/// with 4 significant decimals in scientific form), so a rerun on the same
/// measurements gives the same bytes.
pub fn to_csv(machine: &Machine, rows: &[Row]) -> Result<String, StudyCsvError> {
    let head = format!(
        "# cpu: {}\n# cores: {}\n# isa: {}\n# frame: {}\n",
        machine.cpu, machine.cores, machine.isa, machine.frame
    );
    let write_err = |e: &dyn std::fmt::Display| StudyCsvError::Write(e.to_string());
    let mut w = csv::WriterBuilder::new().terminator(csv::Terminator::Any(b'\n')).from_writer(head.into_bytes());
    w.write_record(CSV_HEADER.split(',')).map_err(|e| write_err(&e))?;
    for r in rows {
        let e = &r.error;
        w.write_record([
            r.scene.clone(),
            r.group.clone(),
            r.method.clone(),
            r.fragments.to_string(),
            format!("{:.4}", r.timing.ms_median),
            format!("{:.4}", r.timing.ms_min),
            format!("{:.4}", r.timing.ms_max),
            format!("{:.3}", r.ns_per_fragment()),
            format!("{:.4e}", e.max_levels),
            format!("{:.4e}", e.mean_levels),
            format!("{:.4e}", e.over_one),
            format!("{:.4e}", e.flip),
            e.pixels.to_string(),
        ])
        .map_err(|e| write_err(&e))?;
    }
    let bytes = w.into_inner().map_err(|e| write_err(&e))?;
    String::from_utf8(bytes).map_err(|e| write_err(&e))
}

/// Parse [`to_csv`]'s output: the leading `# key: value` lines (unknown keys are
/// skipped), the header, the rows. Errors name the line and field.
pub fn from_csv(text: &str) -> Result<(Machine, Vec<Row>), StudyCsvError> {
    let mut machine = Machine { cpu: String::new(), cores: 0, isa: String::new(), frame: String::new() };
    let mut comments = 0;
    let mut body = text;
    while let Some(rest) = body.strip_prefix('#') {
        let line = comments + 1;
        let (this, next) = rest.split_once('\n').unwrap_or((rest, ""));
        let this = this.strip_suffix('\r').unwrap_or(this);
        let (k, v) =
            this.strip_prefix(' ').and_then(|kv| kv.split_once(": ")).ok_or(StudyCsvError::Comment { line })?;
        match k {
            "cpu" => machine.cpu = v.to_owned(),
            "cores" => machine.cores = v.parse().map_err(|_| StudyCsvError::Cores { line, value: v.to_owned() })?,
            "isa" => machine.isa = v.to_owned(),
            "frame" => machine.frame = v.to_owned(),
            _ => {}
        }
        comments += 1;
        body = next;
    }
    if body.is_empty() {
        return Err(StudyCsvError::NoHeader);
    }
    let mut reader = csv::ReaderBuilder::new().has_headers(true).from_reader(body.as_bytes());
    let header_ok = reader.headers().is_ok_and(|h| h.iter().eq(CSV_HEADER.split(',')));
    if !header_ok {
        return Err(StudyCsvError::Header { line: comments + 1 });
    }
    let mut rows = Vec::new();
    for result in reader.deserialize::<Record>() {
        let r = result.map_err(|e| {
            let line = comments + e.position().map_or(0, |p| p.line() as usize);
            let message = match e.kind() {
                csv::ErrorKind::Deserialize { err, .. } => match err.field() {
                    Some(k) => {
                        format!("field {} ({}): {err}", k + 1, CSV_HEADER.split(',').nth(k as usize).unwrap_or("?"))
                    }
                    None => err.to_string(),
                },
                csv::ErrorKind::UnequalLengths { len, .. } => format!("{len} fields, expected 13"),
                _ => e.to_string(),
            };
            StudyCsvError::Record { line, message }
        })?;
        rows.push(Row {
            scene: r.scene,
            group: r.group,
            method: r.method,
            fragments: r.fragments,
            timing: Timing { ms_median: r.ms_median, ms_min: r.ms_min, ms_max: r.ms_max },
            error: PixelErrorStats {
                max_levels: r.max_err_levels,
                mean_levels: r.mean_err_levels,
                over_one: r.share_over_1_level,
                flip: r.mean_flip,
                pixels: r.pixels_compared,
            },
        });
    }
    Ok((machine, rows))
}

/// `x` with three significant digits (`0` for zero, scientific below 0.001).
pub fn sig(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if x.abs() < 1e-3 {
        return format!("{x:.2e}");
    }
    let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The rows of one scene as a [`Table`] (method, cost, error, Pareto mark), with no note.
pub fn table(title: &str, rows: &[Row]) -> Table {
    let front = pareto(rows);
    let header = [
        "method",
        "ms/frame median [min, max]",
        "ns/fragment",
        "max err (levels)",
        "mean err (levels)",
        "% > 1/255",
        "mean FLIP",
        "Pareto",
    ];
    let mut out = Table::new(title, "", &header);
    for (r, on) in rows.iter().zip(front) {
        let t = &r.timing;
        let e = &r.error;
        out.push(vec![
            r.method.clone(),
            format!("{:.2} [{:.2}, {:.2}]", t.ms_median, t.ms_min, t.ms_max),
            format!("{:.1}", r.ns_per_fragment()),
            sig(e.max_levels),
            sig(e.mean_levels),
            sig(100.0 * e.over_one),
            sig(e.flip),
            if on { "●".into() } else { String::new() },
        ]);
    }
    out
}
