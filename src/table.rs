//! A worked table and its renderings: the low layer that the chapter tables
//! ([`crate::tables`]), the errata and the study all build on.
//!
//! | item | meaning |
//! | --- | --- |
//! | [`Table`] | a title, a note (sources, units, what to notice), headers with units, rows of formatted cells |
//! | [`Format`] | which rendering: `text` (aligned columns), `markdown` (the book), `csv` (spreadsheets) |
//! | [`num`], [`vec3`], [`constant`], … | cell formatting with a fixed number of decimals |
//!
//! Cells are formatted when the table is built, with a fixed number of
//! decimals per column ([`num`], [`vec3`]), so every rendering of a table shows
//! the same digits and every run prints the same bytes.

use glam::Vec3;

/// One worked table.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Table {
    /// One-line title.
    pub title: String,
    /// Caption: source, units and what the reader should notice.
    pub note: String,
    /// Column headers, units in parentheses.
    pub headers: Vec<String>,
    /// Rows of formatted cells; every row has `headers.len()` cells.
    pub rows: Vec<Vec<String>>,
}

/// How [`Table`]s are rendered.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Aligned plain text for a terminal.
    Text,
    /// GitHub-flavoured Markdown tables, as the book includes them.
    Markdown,
    /// Comma-separated values (RFC 4180 quoting), one block per table.
    Csv,
}

impl Format {
    /// Parse `text`, `markdown` (or `md`) or `csv`; `None` otherwise.
    pub fn from_name(name: &str) -> Option<Format> {
        match name {
            "text" => Some(Format::Text),
            "markdown" | "md" => Some(Format::Markdown),
            "csv" => Some(Format::Csv),
            _ => None,
        }
    }

    // String error: the message goes straight to the example binaries' stderr; a core module stays free of thiserror.
    /// Read `--format NAME` or `--format=NAME` from command-line arguments
    /// (without the program name); the default is [`Format::Text`].
    ///
    /// Errors (a message for the user): an unknown format, `--format`
    /// without a value, or any other argument.
    pub fn from_args(args: impl IntoIterator<Item = String>) -> Result<Format, String> {
        let mut format = Format::Text;
        let mut args = args.into_iter();
        while let Some(arg) = args.next() {
            let value = if arg == "--format" {
                args.next().ok_or("--format needs a value: text, markdown or csv")?
            } else if let Some(v) = arg.strip_prefix("--format=") {
                v.to_string()
            } else {
                return Err(format!("unknown argument {arg:?}; usage: [--format text|markdown|csv]"));
            };
            format = Format::from_name(&value)
                .ok_or_else(|| format!("unknown format {value:?}; expected text, markdown or csv"))?;
        }
        Ok(format)
    }
}

impl Table {
    /// A table with the given title, note and headers, and no rows yet.
    pub fn new(title: impl Into<String>, note: impl Into<String>, headers: &[&str]) -> Table {
        Table {
            title: title.into(),
            note: note.into(),
            headers: headers.iter().map(|h| h.to_string()).collect(),
            rows: Vec::new(),
        }
    }

    /// Append a row.
    ///
    /// A row with the wrong number of cells is padded with empty cells or
    /// truncated (a `debug_assert!` reports it in tests).
    pub fn push(&mut self, cells: Vec<String>) {
        debug_assert_eq!(cells.len(), self.headers.len(), "row {cells:?} does not match headers {:?}", self.headers);
        let mut cells = cells;
        cells.resize(self.headers.len(), String::new());
        self.rows.push(cells);
    }

    /// The table in the chosen format.
    pub fn render(&self, format: Format) -> String {
        match format {
            Format::Text => self.to_text(),
            Format::Markdown => self.to_markdown(),
            Format::Csv => self.to_csv(),
        }
    }

    /// Columns whose every cell is a number (or empty, or `—`) are right-aligned.
    fn numeric_columns(&self) -> Vec<bool> {
        (0..self.headers.len())
            .map(|c| {
                self.rows.iter().all(|r| {
                    let cell = r[c].trim();
                    cell.is_empty() || cell == "—" || cell.parse::<f64>().is_ok()
                })
            })
            .collect()
    }

    /// Aligned plain text: title, underline, note, headers, a rule, rows.
    pub fn to_text(&self) -> String {
        let widths: Vec<usize> = (0..self.headers.len())
            .map(|c| {
                let cells = std::iter::once(&self.headers[c]).chain(self.rows.iter().map(|r| &r[c]));
                cells.map(|s| s.chars().count()).max().unwrap_or(0)
            })
            .collect();
        let numeric = self.numeric_columns();
        let line = |cells: &[String]| {
            let padded: Vec<String> = cells
                .iter()
                .zip(&widths)
                .zip(&numeric)
                .map(|((cell, &w), &right)| {
                    let pad = " ".repeat(w - cell.chars().count());
                    if right {
                        format!("{pad}{cell}")
                    } else {
                        format!("{cell}{pad}")
                    }
                })
                .collect();
            padded.join("  ").trim_end().to_string()
        };
        let mut out = format!("{}\n{}\n", self.title, "=".repeat(self.title.chars().count()));
        for note_line in wrap(&self.note, NOTE_WIDTH) {
            out.push_str(&note_line);
            out.push('\n');
        }
        out.push('\n');
        out.push_str(&line(&self.headers));
        out.push('\n');
        out.push_str(&widths.iter().map(|&w| "-".repeat(w)).collect::<Vec<_>>().join("  "));
        out.push('\n');
        for row in &self.rows {
            out.push_str(&line(row));
            out.push('\n');
        }
        out
    }

    /// A Markdown section: `### title`, the note as a paragraph, a pipe table.
    pub fn to_markdown(&self) -> String {
        // a reader's infinity is ∞ (the text and CSV forms keep Rust's `inf`, which programs read)
        let escape = |s: &str| match s {
            "inf" => "∞".to_owned(),
            "-inf" => "−∞".to_owned(),
            s => s.replace('|', "\\|"),
        };
        let row =
            |cells: &[String]| format!("| {} |\n", cells.iter().map(|c| escape(c)).collect::<Vec<_>>().join(" | "));
        let mut out = format!("### {}\n\n", self.title);
        if !self.note.is_empty() {
            out.push_str(&self.note);
            out.push_str("\n\n");
        }
        out.push_str(&row(&self.headers));
        let rule: Vec<String> =
            self.numeric_columns().iter().map(|&right| if right { "---:" } else { "---" }.to_string()).collect();
        out.push_str(&format!("| {} |\n", rule.join(" | ")));
        for r in &self.rows {
            out.push_str(&row(r));
        }
        out
    }

    /// CSV: a `# title` comment line, the header line, the rows.
    pub fn to_csv(&self) -> String {
        let field = |s: &String| {
            if s.contains([',', '"', '\n']) {
                format!("\"{}\"", s.replace('"', "\"\""))
            } else {
                s.clone()
            }
        };
        let line = |cells: &[String]| cells.iter().map(field).collect::<Vec<_>>().join(",") + "\n";
        let mut out = format!("# {}\n", self.title);
        out.push_str(&line(&self.headers));
        for r in &self.rows {
            out.push_str(&line(r));
        }
        out
    }
}

/// The width at which [`Table::to_text`] wraps notes, in characters.
const NOTE_WIDTH: usize = 100;

/// Greedy word wrap; a word longer than `width` gets a line of its own.
fn wrap(text: &str, width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut current = String::new();
    for word in text.split_whitespace() {
        if !current.is_empty() && current.chars().count() + 1 + word.chars().count() > width {
            lines.push(std::mem::take(&mut current));
        }
        if !current.is_empty() {
            current.push(' ');
        }
        current.push_str(word);
    }
    if !current.is_empty() {
        lines.push(current);
    }
    lines
}

/// Several tables in one format, separated by a blank line.
pub fn render(tables: &[Table], format: Format) -> String {
    tables.iter().map(|t| t.render(format)).collect::<Vec<_>>().join("\n")
}

/// A number with a fixed count of decimals.
///
/// Deterministic: `-0.000` prints as `0.000`, NaN as `NaN`, infinities as
/// `inf` and `-inf`.
pub fn num(x: f64, decimals: usize) -> String {
    if x.is_nan() {
        return "NaN".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    let s = format!("{x:.decimals$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

/// An `f32` with a fixed count of decimals (see [`num`]).
pub fn num32(x: f32, decimals: usize) -> String {
    num(f64::from(x), decimals)
}

/// A vector as `(x, y, z)`, each component with [`num32`].
pub fn vec3(v: Vec3, decimals: usize) -> String {
    format!("({}, {}, {})", num32(v.x, decimals), num32(v.y, decimals), num32(v.z, decimals))
}

/// An input constant as written: the shortest decimal that reads back as the
/// same `f32` (`0.09`, `0.000007`).
pub fn constant(x: f32) -> String {
    format!("{x}")
}

/// An input vector as written, with [`constant`] components.
pub fn constant3(v: Vec3) -> String {
    format!("({}, {}, {})", constant(v.x), constant(v.y), constant(v.z))
}

/// A row of lit terms: the `lead` cells, then `t`'s ambient, diffuse, specular and
/// their sum ([`vec3`], 4 decimals each), then the `tail` cells.
pub fn terms_row(lead: &[&str], t: &crate::phong::Terms, tail: &[String]) -> Vec<String> {
    let terms = [t.ambient, t.diffuse, t.specular, t.sum()].map(|v| vec3(v, 4));
    lead.iter().map(|s| s.to_string()).chain(terms).chain(tail.iter().cloned()).collect()
}

/// An 8-bit color as `(r, g, b)`.
pub fn rgb8(c: [u8; 3]) -> String {
    format!("({}, {}, {})", c[0], c[1], c[2])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn num_is_deterministic_and_has_no_negative_zero() {
        assert_eq!(num(-0.00001, 3), "0.000");
        assert_eq!(num(-0.5, 1), "-0.5");
        assert_eq!(num(f64::NAN, 2), "NaN");
        assert_eq!(num(f64::NEG_INFINITY, 2), "-inf");
        assert_eq!(constant(0.000007), "0.000007");
    }

    #[test]
    fn renderings_agree_on_cells() {
        let mut t = Table::new("T", "n", &["name", "x (u)"]);
        t.push(vec!["a|b".into(), "1.50".into()]);
        t.push(vec!["c,d".into(), "-2.00".into()]);
        assert_eq!(t.to_text(), "T\n=\nn\n\nname  x (u)\n----  -----\na|b    1.50\nc,d   -2.00\n");
        assert!(t.to_markdown().contains("| a\\|b | 1.50 |"));
        assert!(t.to_markdown().contains("| --- | ---: |"));
        assert_eq!(t.to_csv(), "# T\nname,x (u)\na|b,1.50\n\"c,d\",-2.00\n");
    }

    #[test]
    fn a_reader_sees_infinity_as_the_sign_and_a_program_reads_inf() {
        let mut t = Table::new("T", "", &["x", "y"]);
        t.push(vec![num(f64::INFINITY, 2), num(f64::NEG_INFINITY, 2)]);
        assert!(t.to_markdown().contains("| ∞ | −∞ |"), "{}", t.to_markdown());
        assert!(t.to_csv().ends_with("inf,-inf\n"));
        assert!(t.to_markdown().contains("| ---: | ---: |"), "still numbers");
    }

    #[test]
    fn format_from_args() {
        let args = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<Vec<_>>();
        assert_eq!(Format::from_args(args(&[])), Ok(Format::Text));
        assert_eq!(Format::from_args(args(&["--format", "csv"])), Ok(Format::Csv));
        assert_eq!(Format::from_args(args(&["--format=markdown"])), Ok(Format::Markdown));
        assert!(Format::from_args(args(&["--format"])).is_err());
        assert!(Format::from_args(args(&["--format", "pdf"])).is_err());
        assert!(Format::from_args(args(&["-x"])).is_err());
    }
}
