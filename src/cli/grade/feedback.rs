//! Feedback pages (`grade --feedback DIR`): one Markdown and one HTML page per
//! submission, with the verdict and score, the named mistake with its explanation and a
//! hint, and the worst counterexample in the chapter's names. Everything that comes
//! from the student (file names, compiler messages) is HTML-escaped. The pages are the
//! student's: they never name other students (near-identical submissions are in the
//! teacher's outputs only).
//!
//! Each page shows the picture of [`super::picture`] when the child drew one (the
//! student's shader, the reference and their difference on the chapter's scene), saved
//! beside the page.

use std::fmt::Write as _;
use std::path::Path;

use super::{Graded, Row};

/// `s` with `& < > " '` escaped for HTML text and attributes.
pub fn escape_html(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out += "&amp;",
            '<' => out += "&lt;",
            '>' => out += "&gt;",
            '"' => out += "&quot;",
            '\'' => out += "&#39;",
            c => out.push(c),
        }
    }
    out
}

/// A file name for a student's page: letters, digits, `-`, `_` and `.` kept, the rest `_`.
pub fn page_name(student: &str) -> String {
    let s: String =
        student.chars().map(|c| if c.is_alphanumeric() || c == '-' || c == '_' { c } else { '_' }).collect();
    if s.is_empty() || s.starts_with('.') {
        format!("_{s}")
    } else {
        s
    }
}

/// The caption of the picture.
const CAPTION: &str = "Left: your shader; middle: the reference; right: the difference (black: none; red, yellow, \
                       white: up to 0.25 and more), on the Basic lighting scene: a full-screen quad lit from (1.2, 1, 2).";

/// The picture's file name, relative to the page.
fn picture_name(r: &Row) -> Option<String> {
    Some(r.picture.as_ref()?.file_name()?.to_string_lossy().into_owned())
}

/// A hint that points to the line of thought, not to the answer.
fn hint(r: &Row) -> String {
    match r.diagnosis.first() {
        Some(d) if d.id == "isolated" => {
            "Look at the term and the light the check isolated: write down, for one of the cases below, what each \
             factor of that term should be, and compare with what your shader computes."
                .into()
        }
        Some(d) if !d.link.is_empty() => format!(
            "Read the book's section on this mistake ({}) and ask which vector or factor in your shader plays the role it \
             describes.",
            d.link
        ),
        Some(_) => "Compare each vector in your shader with the chapter's conventions (unit length, pointing away from \
                    the surface)."
            .into(),
        None if !r.error.is_empty() => "Fix the error above first: the check can only judge a shader that compiles \
                                        and runs."
            .into(),
        None => String::new(),
    }
}

/// The Markdown page of a student's rows.
pub fn markdown(student: &str, rows: &[&Row]) -> String {
    let mut s = format!("# Feedback: {student}\n");
    for r in rows {
        let _ = writeln!(
            s,
            "\n## {} ({})\n\n**Verdict:** {} — **score** {} / 100\n",
            r.exercise, r.file, r.verdict, r.score
        );
        if !r.error.is_empty() {
            let _ = writeln!(s, "**Error:** {}\n", r.error);
        }
        if let Some(d) = r.diagnosis.first() {
            let _ = writeln!(s, "**Mistake:** {} ({})\n\n{}\n", d.title, d.id, d.explanation);
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "**Hint:** {h}\n");
        }
        if let Some(name) = picture_name(r) {
            let _ = writeln!(s, "![your shader, the reference, the difference]({name})\n\n{CAPTION}\n");
        }
        if !r.counterexample.is_empty() {
            let _ = writeln!(s, "**A case where it differs:**\n\n```text\n{}\n```\n", r.counterexample);
        }
    }
    s
}

/// The HTML page of a student's rows (every student string escaped).
pub fn html(student: &str, rows: &[&Row]) -> String {
    let e = escape_html;
    let mut s = format!(
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Feedback: {0}</title></head><body>\n<h1>Feedback: {0}</h1>\n",
        e(student)
    );
    for r in rows {
        let _ = writeln!(
            s,
            "<h2>{} ({})</h2>\n<p><b>Verdict:</b> {} — <b>score</b> {} / 100</p>",
            e(r.exercise),
            e(&r.file),
            e(r.verdict),
            r.score
        );
        if !r.error.is_empty() {
            let _ = writeln!(s, "<p><b>Error:</b> {}</p>", e(&r.error));
        }
        if let Some(d) = r.diagnosis.first() {
            let _ = writeln!(s, "<p><b>Mistake:</b> {} ({})</p>\n<p>{}</p>", e(&d.title), e(&d.id), e(&d.explanation));
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "<p><b>Hint:</b> {}</p>", e(&h));
        }
        if let Some(name) = picture_name(r) {
            let _ = writeln!(
                s,
                "<figure><img src=\"{}\" alt=\"your shader, the reference, the difference\"><figcaption>{}</figcaption></figure>",
                e(&name),
                e(CAPTION)
            );
        }
        if !r.counterexample.is_empty() {
            let _ = writeln!(s, "<p><b>A case where it differs:</b></p>\n<pre>{}</pre>", e(&r.counterexample));
        }
    }
    s += "</body></html>\n";
    s
}

// String error: printed by the caller, naming the path.
/// Writes `DIR/<student>.md` and `DIR/<student>.html` for every student.
pub fn write_all(dir: &Path, g: &Graded) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let mut students: Vec<&str> = g.rows.iter().map(|r| r.student.as_str()).collect();
    students.dedup();
    let mut used = std::collections::HashSet::new();
    for student in students {
        let rows: Vec<&Row> = g.rows.iter().filter(|r| r.student == student).collect();
        let mut name = page_name(student);
        while !used.insert(name.clone()) {
            name.push('_');
        }
        for (ext, text) in [("md", markdown(student, &rows)), ("html", html(student, &rows))] {
            let path = dir.join(format!("{name}.{ext}"));
            crate::outfile::write_atomically(&path, text).map_err(|e| e.to_string())?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn student_text_is_escaped_in_html() {
        let row = Row {
            file: "<script>x</script>.frag".into(),
            error: "a < b & \"c\"".into(),
            verdict: "error",
            ..Row::default()
        };
        let page = html("<img onerror=1>", &[&row]);
        assert!(!page.contains("<script>") && !page.contains("<img"), "{page}");
        assert!(page.contains("&lt;script&gt;") && page.contains("a &lt; b &amp; &quot;c&quot;"));
        assert_eq!(page_name("../evil"), "___evil");
    }
}
