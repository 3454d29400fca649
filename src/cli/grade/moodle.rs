//! Filling Moodle's grading worksheet (Assignment → "Download grading worksheet", a CSV):
//! only the grade and feedback cells of matched rows change; every other byte (header
//! row, other columns, their quoting, line ends, a byte-order mark) is kept.
//!
//! Moodle matches the uploaded columns by the site language's header strings, so the
//! columns are found by Moodle's own strings (or `--grade-column`, `--feedback-column`):
//!
//! | column | English | French | Ukrainian |
//! | --- | --- | --- | --- |
//! | identifier | `Identifier` | `Identifiant` | `Ідентифікатор` |
//! | grade | `Grade` | `Note` | `Оцінка` |
//! | feedback | `Feedback comments` | `Feedback par commentaires` | `Відгук - коментарем` |
//!
//! Which strings: Moodle's offline-grading importer (`mod/assign/feedback/offline/importgradeslib.php`,
//! `init`) finds the identifier by `get_string('recordid', 'assign')`, the grade by
//! `get_string('gradenoun')` (`get_string('grade')` before Moodle 4.1) and each feedback
//! column by its plugin's editor-field description, for comments
//! `get_string('pluginname', 'assignfeedback_comments')`; the worksheet's download
//! (`mod/assign/gradingtable.php`) writes the same strings. The English are Moodle's
//! `lang/en` files. The French and Ukrainian were read in the AMOS language packs
//! mirrored at github.com/projectestac/moodle-langpacks (commit
//! 6340d351fc1339a800835fc90f5f3f769ec97446): see the comment beside each string below.
//! (An earlier reading of the Ukrainian feedback header, `Відгук у коментарях` or
//! `Коментарі відгуку`, was not Moodle's string and is no longer looked for.)
//! `--grade-column` and `--feedback-column` (matched exactly) cover a site whose strings
//! differ (a local customisation of the language pack).
//!
//! A submission matches a worksheet row when `--map` says so (`file,identifier`), when
//! its name is the identifier, or when the identifier's number (`Participant 123456`)
//! appears in its name as `_123456_` or `_123456` (Moodle's "download submissions"
//! folders are `Full Name_123456_assignsubmission_file_`).

use std::path::Path;

use super::feedback::escape_html;
use super::formats::defused;
use super::texts::{self as t, tr, tr_fill};
use super::Graded;
use crate::i18n::Lang;

/// The headers a Moodle site writes in a grading worksheet, in the site's language.
struct SiteHeaders {
    /// The language of the site, so of its students.
    lang: Lang,
    /// The identifier column (`recordid` in the assign plugin's strings).
    identifier: &'static str,
    /// The grade column (`gradenoun`, and `grade` in the grades strings).
    grade: &'static str,
    /// The feedback comments column (`pluginname` of assignfeedback_comments).
    feedback: &'static str,
}

/// Every language's headers. en: Moodle's own `lang/en` strings (mod/assign/lang/en/assign.php,
/// lang/en/moodle.php, mod/assign/feedback/comments/lang/en/assignfeedback_comments.php);
/// fr, uk: the same strings in projectestac/moodle-langpacks (`fr/`, `uk/`).
const SITES: [SiteHeaders; 3] = [
    SiteHeaders { lang: Lang::En, identifier: "Identifier", grade: "Grade", feedback: "Feedback comments" },
    SiteHeaders { lang: Lang::Fr, identifier: "Identifiant", grade: "Note", feedback: "Feedback par commentaires" },
    SiteHeaders {
        lang: Lang::Uk, identifier: "Ідентифікатор", grade: "Оцінка", feedback: "Відгук - коментарем"
    },
];

/// A worksheet, its bytes and where its records and columns are.
#[derive(Debug, Clone)]
pub struct Worksheet {
    text: String,
    /// Byte ranges of each record (line end included); the first is the header.
    spans: Vec<(usize, usize)>,
    /// The identifier cell of each data record.
    ids: Vec<String>,
    /// The language of the identifier column's header: the Moodle site's.
    lang: Lang,
    grade: usize,
    feedback: usize,
}

/// The column of `header` named `asked`, else one of the `known` names; `missing` is the
/// error's msgid ([`t::NO_GRADE_COLUMN`], …).
fn find_column(header: &[String], asked: Option<&str>, known: &[&str], missing: &str) -> Result<usize, String> {
    let wanted: Vec<&str> = match asked {
        Some(a) => vec![a],
        None => known.to_vec(),
    };
    header
        .iter()
        .position(|h| wanted.contains(&h.trim()))
        .ok_or_else(|| tr_fill(missing, &[&header.join(", "), &wanted.join(", ")]))
}

impl Worksheet {
    /// The language of the Moodle site the worksheet comes from, read from its identifier
    /// column's header (`Identifier`, `Identifiant`, `Ідентифікатор`): the language its
    /// students read Moodle in.
    pub fn lang(&self) -> Lang {
        self.lang
    }

    // String error: a usage error naming the file.
    /// Reads a worksheet and finds its columns.
    pub fn read(path: &Path, grade: Option<&str>, feedback: Option<&str>) -> Result<Worksheet, String> {
        let at_file = |e: &str| tr_fill(t::WORKSHEET_FILE, &[&path.display().to_string(), e]);
        let bytes = crate::cli::input::read_limited(path, 64 << 20).map_err(|e| at_file(&e))?;
        let text = String::from_utf8(bytes).map_err(|_| at_file(&tr(t::NOT_UTF8)))?;
        Worksheet::parse(text, grade, feedback).map_err(|e| at_file(&e))
    }

    // String error: the caller adds the file's name.
    /// Parses a worksheet's text.
    pub fn parse(text: String, grade: Option<&str>, feedback: Option<&str>) -> Result<Worksheet, String> {
        let bom = if text.starts_with('\u{feff}') { 3 } else { 0 };
        let mut reader =
            csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(&text.as_bytes()[bom..]);
        let mut starts = Vec::new();
        let mut records = Vec::new();
        let mut record = csv::StringRecord::new();
        loop {
            match reader.read_record(&mut record) {
                Ok(true) => {
                    starts.push(bom + record.position().map_or(0, |p| p.byte() as usize));
                    records.push(record.iter().map(String::from).collect::<Vec<_>>());
                }
                Ok(false) => break,
                Err(e) => return Err(tr_fill(t::NOT_CSV, &[&e.to_string()])),
            }
        }
        // The csv reader reads an unclosed quote to the end of the file as one field: a
        // record whose quotes do not pair up is that mistake, named at its line.
        for &start in &starts {
            let end = starts.iter().find(|&&s| s > start).copied().unwrap_or(text.len());
            if text[start..end].matches('"').count() % 2 == 1 {
                let line = text[..start].matches('\n').count() + 1;
                return Err(tr_fill(t::QUOTE_NOT_CLOSED, &[&line.to_string()]));
            }
        }
        let Some(header) = records.first() else { return Err(tr(t::WORKSHEET_EMPTY)) };
        // A header cell never spans lines: one that does swallowed the next line through a
        // quote opened and closed in the wrong places.
        if let Some(cell) = header.iter().find(|h| h.contains(['\n', '\r'])) {
            let first = cell.lines().next().unwrap_or_default();
            return Err(tr_fill(t::HEADER_RUNS_ON, &[first]));
        }
        let id = find_column(header, None, &SITES.map(|s| s.identifier), t::NO_IDENTIFIER_COLUMN)?;
        let lang = SITES.iter().find(|s| header[id].trim() == s.identifier).map_or(Lang::En, |s| s.lang);
        let grade = find_column(header, grade, &SITES.map(|s| s.grade), t::NO_GRADE_COLUMN)?;
        let feedback = find_column(header, feedback, &SITES.map(|s| s.feedback), t::NO_FEEDBACK_COLUMN)?;
        let mut spans = Vec::new();
        for (k, &s) in starts.iter().enumerate() {
            let end = starts.get(k + 1).copied().unwrap_or(text.len());
            spans.push((if k == 0 { 0 } else { s }, end));
        }
        let ids = records[1..].iter().map(|r| r.get(id).cloned().unwrap_or_default()).collect();
        Ok(Worksheet { text, spans, ids, lang, grade, feedback })
    }

    /// The worksheet with each matched student's grade and feedback cells filled, and the
    /// students no row matched.
    // String error: printed as a usage error.
    pub fn fill(&self, g: &Graded, map: &[(String, String)]) -> Result<(String, Vec<String>), String> {
        let mut cells: Vec<Option<(String, String)>> = vec![None; self.ids.len()];
        let mut unmatched = Vec::new();
        for t in &g.totals {
            let row = self.ids.iter().position(|id| matches(id, &t.student, map));
            let Some(row) = row else {
                unmatched.push(t.student.clone());
                continue;
            };
            let single = g.weights.len() == 1 && (g.weights[0].1 - 100.0).abs() < f64::EPSILON;
            let grade = if single { format!("{}", t.points.round()) } else { format!("{:.2}", t.points) };
            let mut feedback = String::new();
            for r in g.rows.iter().filter(|r| r.student == t.student) {
                if !feedback.is_empty() {
                    feedback.push(' ');
                }
                feedback += &super::texts::cell_verdict(r.exercise, r.verdict, r.score);
                if let Some(d) = r.diagnosis.first() {
                    feedback += &format!(": {}. {}", d.title, d.explanation);
                } else if !r.error.is_empty() {
                    feedback += &format!(": {}", r.error);
                }
                if !feedback.ends_with('.') {
                    feedback.push('.');
                }
            }
            // Moodle stores and shows the comment as HTML: the student's text is escaped.
            cells[row] = Some((grade, defused(&escape_html(&feedback))));
        }
        let mut out = String::with_capacity(self.text.len());
        out += &self.text[..self.spans.first().map_or(self.text.len(), |s| s.1)];
        for (k, &(start, end)) in self.spans.iter().enumerate().skip(1) {
            let raw = &self.text[start..end];
            match &cells[k - 1] {
                None => out += raw,
                Some((grade, feedback)) => {
                    out += &replace_fields(raw, &[(self.grade, grade.as_str()), (self.feedback, feedback.as_str())])
                }
            }
        }
        Ok((out, unmatched))
    }
}

/// Whether the worksheet identifier `id` is `student`'s (module docs).
fn matches(id: &str, student: &str, map: &[(String, String)]) -> bool {
    if let Some((_, mapped)) = map.iter().find(|(file, _)| file == student) {
        return mapped == id;
    }
    if id == student {
        return true;
    }
    let digits: String = id.chars().filter(char::is_ascii_digit).collect();
    !digits.is_empty()
        && (student == digits || student.contains(&format!("_{digits}_")) || student.ends_with(&format!("_{digits}")))
}

/// One raw CSV record (line end included) with fields replaced, every other byte kept; a
/// field that was quoted stays quoted, a new value with a comma, quote or line end is
/// quoted.
fn replace_fields(raw: &str, new: &[(usize, &str)]) -> String {
    let body = raw.trim_end_matches(['\r', '\n']);
    let ending = &raw[body.len()..];
    // Field boundaries outside quotes.
    let mut bounds = vec![0usize];
    let mut quoted = false;
    for (i, c) in body.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => bounds.push(i + 1),
            _ => {}
        }
    }
    let mut fields: Vec<String> = Vec::new();
    for (k, &s) in bounds.iter().enumerate() {
        let e = bounds.get(k + 1).map_or(body.len(), |&n| n - 1);
        fields.push(body[s..e].to_string());
    }
    for &(col, value) in new {
        while fields.len() <= col {
            fields.push(String::new());
        }
        let was_quoted = fields[col].starts_with('"');
        fields[col] = if was_quoted || value.contains([',', '"', '\n', '\r']) {
            format!("\"{}\"", value.replace('"', "\"\""))
        } else {
            value.to_string()
        };
    }
    format!("{}{ending}", fields.join(","))
}

// String error: a usage error naming the file.
/// Reads a `--map` CSV: `file,identifier` rows (a header row `file,identifier` is skipped).
pub fn read_map(path: &Path) -> Result<Vec<(String, String)>, String> {
    let at_file = |e: &str| tr_fill(t::MAP_FILE, &[&path.display().to_string(), e]);
    let bytes = crate::cli::input::read_limited(path, 16 << 20).map_err(|e| at_file(&e))?;
    let mut reader = csv::ReaderBuilder::new().has_headers(false).flexible(true).from_reader(bytes.as_slice());
    let mut out = Vec::new();
    for (k, rec) in reader.records().enumerate() {
        let rec = rec.map_err(|e| at_file(&e.to_string()))?;
        match (rec.get(0), rec.get(1)) {
            (Some("file"), Some("identifier")) if k == 0 => {}
            (Some(f), Some(i)) => out.push((f.trim().to_string(), i.trim().to_string())),
            _ => return Err(at_file(&tr_fill(t::MAP_LINE, &[&(k + 1).to_string()]))),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_replaced_and_the_rest_kept() {
        let raw = "\"Participant 1\",\"Alice\",,\"old, text\"\r\n";
        assert_eq!(replace_fields(raw, &[(2, "87"), (3, "new")]), "\"Participant 1\",\"Alice\",87,\"new\"\r\n");
        assert!(matches("Participant 123456", "Alice Smith_123456_assignsubmission_file_", &[]));
        assert!(!matches("Participant 12", "bob_123_x", &[]));
    }

    /// The site's language is read from the identifier column's header, whatever the
    /// grade and feedback columns are called.
    #[test]
    fn the_worksheet_says_its_sites_language() {
        for (header, lang) in [
            ("Identifier,Grade,Feedback comments", Lang::En),
            ("Identifiant,Note,Feedback par commentaires", Lang::Fr),
            ("Ідентифікатор,Оцінка,Відгук - коментарем", Lang::Uk),
            ("\u{feff}\"Identifiant\",Points,Remarques", Lang::Fr),
        ] {
            let w = Worksheet::parse(format!("{header}\nx,1,\n"), Some("Points"), Some("Remarques"))
                .or_else(|_| Worksheet::parse(format!("{header}\nx,1,\n"), None, None))
                .unwrap_or_else(|e| panic!("{header}: {e}"));
            assert_eq!(w.lang(), lang, "{header}");
        }
    }
}
