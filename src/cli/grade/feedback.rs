//! Feedback pages (`grade --feedback DIR`): one Markdown and one HTML page per
//! submission, with the verdict and score, the named mistake with its explanation and a
//! hint, and the worst counterexample in the chapter's names. Everything that comes
//! from the student (file names, compiler messages, names from the shader) is escaped:
//! [`escape_html`] in the HTML, [`escape_markdown`] in the Markdown (which renders inline
//! HTML, so it is escaped too), counterexamples in a fenced block ([`fenced`]). The pages are the
//! student's: they never name other students (near-identical submissions are in the
//! teacher's outputs only).
//!
//! Each page shows the picture of [`super::picture`] when the child drew one (the
//! student's shader, the reference and their difference on the chapter's scene), saved
//! beside the page.

use std::fmt::Write as _;
use std::path::Path;

use super::texts::{self, tr, tr_fill};
use super::{Graded, Row};

/// `s` with `&`, `<` and `>` as entities (both HTML and Markdown render them as markup)
/// and every other character passed to `other`, which pushes it as its output needs.
fn escaped(s: &str, other: impl Fn(char, &mut String)) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out += "&amp;",
            '<' => out += "&lt;",
            '>' => out += "&gt;",
            c => other(c, &mut out),
        }
    }
    out
}

/// `s` with `& < > " '` escaped for HTML text and attributes.
pub fn escape_html(s: &str) -> String {
    escaped(s, |c, out| match c {
        '"' => *out += "&quot;",
        '\'' => *out += "&#39;",
        c => out.push(c),
    })
}

/// `s` as Markdown text that renders as itself and never as HTML or a link: `&`, `<`
/// and `>` become entities (CommonMark renders inline HTML, so a file name or an echoed
/// shader line `<script>` would run in the page), `\`, `` ` ``, `[`, `]` get a backslash
/// (no code span or link starts inside student text), and line ends become spaces (no new
/// block starts). The one escaping of every Markdown output: feedback pages, Gradescope's
/// `md` tests.
pub fn escape_markdown(s: &str) -> String {
    escaped(s, |c, out| match c {
        '\\' | '`' | '[' | ']' => {
            out.push('\\');
            out.push(c);
        }
        '\n' | '\r' => out.push(' '),
        c => out.push(c),
    })
}

/// `s` in a fenced code block (` ```text `) whose fence is longer than any run of
/// backticks in `s`, so nothing in it ends the block; code blocks render no HTML.
pub fn fenced(s: &str) -> String {
    let longest = s.split(|c| c != '`').map(str::len).max().unwrap_or(0);
    let fence = "`".repeat(longest.max(2) + 1);
    format!("{fence}text\n{s}\n{fence}")
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

/// Gives each job's student a page stem ([`page_name`]) that no other student of the
/// class has, even on a case-insensitive disk (`Dup` and `dup` are `Dup` and `dup_`): a
/// `_` is added until the lower-cased stem is new. In the jobs' order, so the same class
/// gives the same names.
pub fn assign_pages(jobs: &mut [super::run::Job]) {
    let mut used = std::collections::HashSet::new();
    let mut pages: std::collections::HashMap<String, String> = std::collections::HashMap::new();
    for job in jobs.iter_mut() {
        let page = pages.entry(job.student.clone()).or_insert_with(|| {
            let mut name = page_name(&job.student);
            while !used.insert(name.to_lowercase()) {
                name.push('_');
            }
            name
        });
        job.page = page.clone();
    }
}

/// The picture file of a page stem for an exercise: `bob-basic-move-light.png`.
pub fn picture_file(page: &str, exercise: &str) -> String {
    format!("{page}-{exercise}.png")
}

/// The picture's caption: the scene of the row's exercise.
fn caption(r: &Row) -> String {
    let spot = crate::exercises::Exercise::by_id(r.exercise)
        .is_some_and(|e| super::picture::scene_of(e) == super::picture::Scene::Spot);
    tr(if spot { texts::CAPTION_SPOT } else { texts::CAPTION })
}

/// The picture's file name, relative to the page.
fn picture_name(r: &Row) -> Option<String> {
    Some(r.picture.as_ref()?.file_name()?.to_string_lossy().into_owned())
}

/// A hint that points to the line of thought, not to the answer.
fn hint(r: &Row) -> String {
    match r.diagnosis.first() {
        Some(d) if d.id == "isolated" => tr(texts::HINT_ISOLATED),
        // the catalogue's first hint (where to look), then where the book explains it
        Some(d) => {
            let first = crate::checker::hints::hints(&d.id).map(|h| tr(h[0]));
            let read = (!d.link.is_empty()).then(|| tr_fill(texts::HINT_READ, &[&d.link]));
            match (first, read) {
                (Some(first), Some(read)) => format!("{first} {read}"),
                (Some(one), None) | (None, Some(one)) => one,
                (None, None) => tr(texts::HINT_CONVENTIONS),
            }
        }
        None if !r.error.is_empty() => tr(texts::HINT_ERROR),
        None => String::new(),
    }
}

/// The Markdown page of a student's rows, in the grading's language ([`texts::lang`]);
/// every student string through [`escape_markdown`] or [`fenced`].
pub fn markdown(student: &str, rows: &[&Row]) -> String {
    let m = escape_markdown;
    let mut s = format!("# {}\n", m(&tr_fill(texts::FEEDBACK_TITLE, &[student])));
    for r in rows {
        let _ = writeln!(
            s,
            "\n## {} ({})\n\n**{}**\n",
            m(r.exercise),
            m(&r.file),
            m(&texts::verdict_line(r.verdict, r.score))
        );
        if !r.error.is_empty() {
            let _ = writeln!(s, "**{}** {}\n", m(&tr(texts::ERROR)), m(&r.error));
        }
        if let Some(d) = r.diagnosis.first() {
            let _ =
                writeln!(s, "**{}** {} ({})\n\n{}\n", m(&tr(texts::MISTAKE)), m(&d.title), m(&d.id), m(&d.explanation));
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "**{}** {}\n", m(&tr(texts::HINT)), m(&h));
        }
        if let Some(name) = picture_name(r) {
            let _ = writeln!(s, "![{}]({})\n\n{}\n", m(&tr(texts::PICTURE_ALT)), m(&name), m(&caption(r)));
        } else if !r.picture_note.is_empty() {
            let _ = writeln!(s, "{}\n", m(&tr_fill(texts::NO_PICTURE, &[&r.picture_note])));
        }
        if !r.counterexample.is_empty() {
            let _ = writeln!(s, "**{}**\n\n{}\n", m(&tr(texts::A_CASE)), fenced(&r.counterexample));
        }
    }
    s
}

/// The HTML body of a student's rows (every student string escaped), without the page
/// around it; `picture_src` gives each row's picture `src` (a file name beside the page,
/// or a data URL for Gradescope).
pub fn html_rows(rows: &[&Row], picture_src: impl Fn(&Row) -> Option<String>) -> String {
    let e = escape_html;
    let mut s = String::new();
    for r in rows {
        let _ = writeln!(
            s,
            "<h2>{} ({})</h2>\n<p><b>{}</b></p>",
            e(r.exercise),
            e(&r.file),
            e(&texts::verdict_line(r.verdict, r.score))
        );
        if !r.error.is_empty() {
            let _ = writeln!(s, "<p><b>{}</b> {}</p>", e(&tr(texts::ERROR)), e(&r.error));
        }
        if let Some(d) = r.diagnosis.first() {
            let _ = writeln!(
                s,
                "<p><b>{}</b> {} ({})</p>\n<p>{}</p>",
                e(&tr(texts::MISTAKE)),
                e(&d.title),
                e(&d.id),
                e(&d.explanation)
            );
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "<p><b>{}</b> {}</p>", e(&tr(texts::HINT)), e(&h));
        }
        if let Some(src) = picture_src(r) {
            let _ = writeln!(
                s,
                "<figure><img src=\"{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>",
                e(&src),
                e(&tr(texts::PICTURE_ALT)),
                e(&caption(r))
            );
        } else if !r.picture_note.is_empty() {
            let _ = writeln!(s, "<p>{}</p>", e(&tr_fill(texts::NO_PICTURE, &[&r.picture_note])));
        }
        if !r.counterexample.is_empty() {
            let _ = writeln!(s, "<p><b>{}</b></p>\n<pre>{}</pre>", e(&tr(texts::A_CASE)), e(&r.counterexample));
        }
    }
    s
}

/// The HTML page of a student's rows (every student string escaped), in the grading's
/// language, its `lang` attribute set.
pub fn html(student: &str, rows: &[&Row]) -> String {
    let title = escape_html(&tr_fill(texts::FEEDBACK_TITLE, &[student]));
    format!(
        "<!DOCTYPE html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\"><title>{title}</title></head><body>\n<h1>{title}</h1>\n{}</body></html>\n",
        texts::lang().code(),
        html_rows(rows, picture_name)
    )
}

// String error: printed by the caller, naming the path.
/// Writes `DIR/<student>.md` and `DIR/<student>.html` for every student.
pub fn write_all(dir: &Path, g: &Graded) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create {}: {e}", dir.display()))?;
    let mut students: Vec<(&str, &str)> = g.rows.iter().map(|r| (r.student.as_str(), r.page.as_str())).collect();
    students.dedup();
    let mut used = std::collections::HashSet::new();
    for (student, page) in students {
        let rows: Vec<&Row> = g.rows.iter().filter(|r| r.student == student).collect();
        // The stem given before the run ([`assign_pages`]), which the pictures share;
        // made unique here too for rows built without one.
        let mut name = if page.is_empty() { page_name(student) } else { page.to_string() };
        while !used.insert(name.to_lowercase()) {
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
