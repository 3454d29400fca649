//! The outputs of `grade`: csv, json, Gradescope's and PrairieLearn's `results.json`.
//!
//! Sources of the two platforms' formats:
//! - Gradescope, "Autograder Specifications" (gradescope-autograders.readthedocs.io/en/latest/specs/):
//!   top-level `score`, `execution_time` (seconds), `output`, `output_format`
//!   (`text`, `html`, `simple_format`, `md`, `ansi`), `tests[]` with `name`, `score`,
//!   `max_score`, `status` (`passed`, `failed`), `output`, `output_format` and
//!   `visibility` (`hidden`, `after_due_date`, `after_published`, `visible`);
//! - PrairieLearn, `docs/externalGrading.md`: `gradable`, `score` in [0, 1], `message`,
//!   `output`, `tests[]` with `name`, `description`, `points`, `max_points`, `message`,
//!   `output`; with `gradable: false`, `format_errors` (a string or a list of strings).

use std::fmt::Write as _;

use super::feedback::{escape_html, escape_markdown, fenced, html_rows};
use super::texts::{self, tr, tr_fill};
use super::{Graded, Row};

/// A cell a spreadsheet cannot read as a formula: one that starts with `=`, `+`, `-`,
/// `@`, a tab or a carriage return gets a leading `'` (OWASP, "CSV Injection").
pub fn defused(s: &str) -> String {
    if s.starts_with(['=', '+', '-', '@', '\t', '\r']) {
        format!("'{s}")
    } else {
        s.to_string()
    }
}

/// One CSV field: [`defused`], then quoted when it holds a comma, quote or line end.
pub fn csv_field(s: &str) -> String {
    let s = defused(s);
    if s.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s
    }
}

fn points(x: f64) -> String {
    let s = format!("{x:.2}");
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

fn mistake(r: &Row) -> (String, String) {
    match r.diagnosis.first() {
        Some(d) => (d.title.clone(), d.explanation.clone()),
        None => (String::new(), String::new()),
    }
}

/// The rows as CSV, header first (module docs of [`super`]); with `assignment`, each
/// row starts with `student,exercise,weight,points` and each student has a `TOTAL` row.
pub fn to_csv(g: &Graded, assignment: bool) -> String {
    let mut s = String::new();
    if assignment {
        s += "student,exercise,weight,points,";
    }
    s += "file,verdict,score,diagnosis,counterexample,error,mistake,explanation,similar_to\n";
    let weight = |id: &str| g.weights.iter().find(|(e, _)| *e == id).map_or(0.0, |(_, w)| *w);
    for r in &g.rows {
        if assignment {
            let w = weight(r.exercise);
            let _ = write!(
                s,
                "{},{},{},{},",
                csv_field(&r.student),
                r.exercise,
                points(w),
                points(w * f64::from(r.score) / 100.0)
            );
        }
        let (title, why) = mistake(r);
        let ids: Vec<&str> = r.diagnosis.iter().map(|d| d.id.as_str()).collect();
        let fields = [
            csv_field(&r.file),
            r.verdict.to_string(),
            r.score.to_string(),
            csv_field(&ids.join(";")),
            csv_field(&r.counterexample),
            csv_field(&r.error),
            csv_field(&title),
            csv_field(&why),
            csv_field(&r.similar_to.join(";")),
        ];
        s += &fields.join(",");
        s.push('\n');
    }
    if assignment {
        for t in &g.totals {
            let _ =
                writeln!(s, "{},TOTAL,{},{},,,,,,,,,", csv_field(&t.student), points(t.max_points), points(t.points));
        }
    }
    s
}

/// A row's notes for the teacher: why its feedback picture is missing (a key of the JSON
/// rows, and a line on standard error; the CSV keeps the columns scripts read).
pub fn notes(r: &Row) -> String {
    if r.picture_note.is_empty() {
        String::new()
    } else {
        format!("no feedback picture: {}", r.picture_note)
    }
}

fn row_json(r: &Row) -> serde_json::Value {
    serde_json::json!({
        "file": r.file, "student": r.student, "exercise": r.exercise, "verdict": r.verdict, "score": r.score,
        "diagnosis": r.diagnosis.iter().map(|d| d.id.as_str()).collect::<Vec<_>>(),
        "mistake": r.diagnosis.first().map(|d| serde_json::json!({
            "id": d.id, "title": d.title, "explanation": d.explanation, "link": d.link,
        })),
        "counterexample": r.counterexample, "error": r.error, "similar_to": r.similar_to, "notes": notes(r),
    })
}

/// The `--format json` document. For one exercise (no `--assignment`), the array of row
/// objects `grade` has always written, so scripts that read it keep working (each row also
/// carries `mistake`, `similar_to`, `notes` and the diagnosis' titles and explanations;
/// the files not graded are on stderr). For an assignment, `{rows, totals, not_graded,
/// similar, seconds}`.
pub fn to_json(g: &Graded) -> serde_json::Value {
    if g.weights.len() <= 1 {
        return serde_json::Value::Array(g.rows.iter().map(row_json).collect());
    }
    serde_json::json!({
        "rows": g.rows.iter().map(row_json).collect::<Vec<_>>(),
        "totals": g.totals.iter().map(|t| serde_json::json!({
            "student": t.student, "points": t.points, "max_points": t.max_points,
        })).collect::<Vec<_>>(),
        "not_graded": g.not_graded,
        "similar": g.similar,
        "seconds": g.seconds,
    })
}

/// A row in Markdown, in the grading's language: verdict, mistake and explanation,
/// counterexample or error; every string through [`escape_markdown`], the counterexample
/// [`fenced`] (Gradescope renders `md` output, inline HTML included).
pub fn row_markdown(r: &Row) -> String {
    let m = escape_markdown;
    let mut s = format!("**{}**\n", m(&texts::verdict_line(r.verdict, r.score)));
    if !r.error.is_empty() {
        let _ = writeln!(s, "\n{}", m(&r.error));
    }
    if let Some(d) = r.diagnosis.first() {
        let (title, why) =
            (super::feedback::markdown_with_code(&d.title), super::feedback::markdown_with_code(&d.explanation));
        let _ = writeln!(s, "\n**{title}**: {why}");
    }
    if !r.counterexample.is_empty() {
        let _ = writeln!(s, "\n{}\n\n{}", m(&tr(texts::A_CASE)), fenced(&r.counterexample));
    }
    s
}

fn weight_of(g: &Graded, id: &str) -> f64 {
    g.weights.iter().find(|(e, _)| *e == id).map_or(100.0, |(_, w)| *w)
}

/// A row's points and its exercise's weight (the maximum), as Gradescope's `score` and
/// `max_score` and PrairieLearn's `points` and `max_points`.
fn row_points(g: &Graded, r: &Row) -> (f64, f64) {
    let max = weight_of(g, r.exercise);
    (max * f64::from(r.score) / 100.0, max)
}

/// The files not graded, as a sentence (empty when there are none).
fn not_graded(g: &Graded) -> String {
    if g.not_graded.is_empty() {
        String::new()
    } else {
        tr_fill(texts::NOT_GRADED, &[&g.not_graded.join(", ")])
    }
}

fn summary(g: &Graded) -> String {
    let mut s = String::new();
    let skipped = not_graded(g);
    if !skipped.is_empty() {
        let _ = writeln!(s, "{}\n", escape_markdown(&skipped));
    }
    for r in &g.rows {
        let _ = writeln!(s, "### {} ({})\n\n{}", r.exercise, escape_markdown(&r.file), row_markdown(r));
    }
    s
}

/// The feedback page as Gradescope shows it: the HTML of [`super::feedback::html_rows`]
/// with each picture as a data URL, after the files not graded.
fn gradescope_page(g: &Graded) -> String {
    let rows: Vec<&Row> = g.rows.iter().collect();
    let skipped = not_graded(g);
    let mut s = String::new();
    if !skipped.is_empty() {
        let _ = writeln!(s, "<p>{}</p>", escape_html(&skipped));
    }
    s + &html_rows(&rows, picture_url)
}

/// Gradescope's `results.json` for one submission: one test per exercise (its output in
/// Markdown), and the feedback page with its picture as the submission's `output`.
///
/// The page is HTML (`output_format: "html"`) because a picture has to travel inside the
/// JSON: the specification (gradescope-autograders.readthedocs.io/en/latest/specs/, the
/// `output_format` of the submission and of each test) offers `text`, `html`,
/// `simple_format`, `md` and `ansi`;
/// an image given by a file path in `md` output is not shown, and an `<img>` whose `src`
/// is a base64 data URL in `html` output is (gradescope/autograder_samples discussion
/// 108, "Displaying images in the autograder output", answered by embedding the image
/// data into HTML). Every student string in the page is HTML-escaped.
pub fn gradescope(g: &Graded) -> serde_json::Value {
    let tests: Vec<serde_json::Value> = g
        .rows
        .iter()
        .map(|r| {
            let (points, max) = row_points(g, r);
            serde_json::json!({
                "name": format!("{} ({})", r.exercise, escape_markdown(&r.file)),
                "score": points,
                "max_score": max,
                "status": if r.agrees { "passed" } else { "failed" },
                "output": row_markdown(r),
                "output_format": "md",
                "visibility": "visible",
            })
        })
        .collect();
    let score: f64 = g.totals.iter().map(|t| t.points).sum();
    serde_json::json!({
        "score": score,
        "execution_time": g.seconds.ceil() as u64,
        "output": gradescope_page(g),
        "output_format": "html",
        "test_output_format": "md",
        "visibility": "visible",
        "tests": tests,
    })
}

/// A row's picture as a `data:image/png;base64,` URL (PrairieLearn's `images[].url`,
/// Gradescope's `<img src>`).
fn picture_url(r: &Row) -> Option<String> {
    let bytes = std::fs::read(r.picture.as_ref()?).ok()?;
    Some(format!("data:image/png;base64,{}", crate::live::assets::base64(&bytes)))
}

/// PrairieLearn's `results.json` for one submission: `gradable: false` (the attempt is
/// not counted) when a shader does not compile or is empty.
pub fn prairielearn(g: &Graded) -> serde_json::Value {
    let errors: Vec<String> =
        g.rows.iter().filter(|r| r.ungradable).map(|r| format!("{}: {}", r.file, r.error)).collect();
    if !errors.is_empty() {
        return serde_json::json!({
            "gradable": false,
            "format_errors": errors,
            "message": tr(texts::PL_UNGRADABLE),
        });
    }
    let (points, max): (f64, f64) = g.totals.iter().fold((0.0, 0.0), |(p, m), t| (p + t.points, m + t.max_points));
    let tests: Vec<serde_json::Value> = g
        .rows
        .iter()
        .map(|r| {
            let (points, max) = row_points(g, r);
            serde_json::json!({
                "name": r.exercise,
                "description": r.file,
                "points": points,
                "max_points": max,
                "message": r.diagnosis.first().map_or_else(|| r.error.clone(), |d| format!("{}: {}", d.title, d.explanation)),
                "output": row_markdown(r),
                "images": picture_url(r).map(|url| vec![serde_json::json!({
                    "label": tr(texts::PICTURE_ALT),
                    "url": url,
                })]).unwrap_or_default(),
            })
        })
        .collect();
    let score = if max > 0.0 { (points / max).clamp(0.0, 1.0) } else { 0.0 };
    let message = if g.rows.iter().all(|r| r.agrees) { texts::PL_AGREES } else { texts::PL_DISAGREES };
    serde_json::json!({
        "gradable": true,
        "score": score,
        "message": tr(message),
        "output": summary(g),
        "tests": tests,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formulas_are_defused_in_every_cell() {
        for bad in ["=HYPERLINK(\"x\")", "+1", "-1+2", "@SUM(A1)", "\tx", "\rx"] {
            assert!(csv_field(bad).trim_start_matches('"').starts_with('\''), "{bad}");
        }
        assert_eq!(csv_field("alice.frag"), "alice.frag");
        assert_eq!(csv_field("a,b"), "\"a,b\"");
    }
}
