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

/// The entity of `&`, `<` or `>`, the characters both HTML and Markdown render as markup.
fn entity(c: char) -> Option<&'static str> {
    match c {
        '&' => Some("&amp;"),
        '<' => Some("&lt;"),
        '>' => Some("&gt;"),
        _ => None,
    }
}

/// `s` with `&`, `<` and `>` as entities ([`entity`]) and every other character passed to
/// `other`, which pushes it as its output needs.
fn escaped(s: &str, other: impl Fn(char, &mut String)) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match entity(c) {
            Some(e) => out += e,
            None => other(c, &mut out),
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
/// shader line `<script>` would run in the page), `\`, `` ` ``, `[`, `]`, `*` and an `_`
/// at a word's edge get a backslash (no code span, link or emphasis starts inside student
/// text), and line ends become spaces (no new
/// block starts). The one escaping of every Markdown output: feedback pages, Gradescope's
/// `md` tests.
pub fn escape_markdown(s: &str) -> String {
    // An `_` inside a word (`lighting_old.frag`) never starts emphasis in CommonMark, so
    // it stays as written; one next to a space or punctuation is escaped.
    let chars: Vec<char> = s.chars().collect();
    let word = |k: Option<usize>| k.and_then(|k| chars.get(k)).is_some_and(|c| c.is_alphanumeric());
    let mut out = String::with_capacity(s.len());
    for (k, &c) in chars.iter().enumerate() {
        if let Some(e) = entity(c) {
            out += e;
            continue;
        }
        match c {
            '_' if word(k.checked_sub(1)) && word(Some(k + 1)) => out.push(c),
            '\\' | '`' | '[' | ']' | '*' | '_' => {
                out.push('\\');
                out.push(c);
            }
            '\n' | '\r' => out.push(' '),
            c => out.push(c),
        }
    }
    out
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

/// The page's head for a phone as for a desktop: the page is laid out at the screen's
/// width (without the viewport line a phone lays it out 980 px wide and shrinks the
/// text), a counterexample's long line wraps instead of scrolling sideways (its matrices
/// run past a phone's width), and the 488-pixel picture shrinks to the width of a
/// 390-pixel phone instead of overflowing it.
const PAGE_STYLE: &str = concat!(
    "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\">",
    "<style>pre{white-space:pre-wrap;overflow-wrap:anywhere}",
    "figure{margin:1em 0}img{max-width:100%;height:auto}</style>"
);

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

/// The ids of a wrong number or letter (`exercises::check`): mistakes in the answer, not
/// in a shader.
const ANSWER_IDS: &[&str] = &["wrong-choice", "answer-too-high", "answer-too-low"];

/// A hint that points to the line of thought, not to the answer: the check's own first
/// hint (a catalogue mistake's, or the isolation's), then where the book explains it. A
/// wrong answer is sent back to its statement; an error row gets a hint only when the
/// submission itself failed (it does not compile, run or end): a file not handed in, or
/// several that match, says what to do in the error.
fn hint(r: &Row) -> String {
    let h = match r.diagnosis.first() {
        Some(d) if ANSWER_IDS.contains(&d.id.as_str()) => tr(texts::HINT_ANSWER),
        Some(d) => {
            let first = (!d.hint.is_empty()).then(|| d.hint.clone());
            let first = first.or_else(|| crate::checker::hints::hints(&d.id).map(|h| tr(h[0])));
            let read = (!d.link.is_empty()).then(|| tr_fill(texts::HINT_READ, &[&d.link]));
            match (first, read) {
                (Some(first), Some(read)) => format!("{first} {read}"),
                (Some(one), None) | (None, Some(one)) => one,
                (None, None) if d.id == "isolated" => tr(texts::HINT_ISOLATED),
                (None, None) => tr(texts::HINT_CONVENTIONS),
            }
        }
        // An answer file's error says what to write; "compiles and runs" is for shaders.
        None if r.ungradable
            && !r.not_found
            && crate::exercises::Exercise::by_id(r.exercise).is_some_and(|e| e.model().is_some()) =>
        {
            tr(texts::HINT_ERROR)
        }
        None => String::new(),
    };
    // The isolation's hints are written to follow "hint 1/3:" in lower case.
    let mut chars = h.chars();
    chars.next().map_or(String::new(), |c| c.to_uppercase().chain(chars).collect())
}

/// The label of a row's finding: "Mistake:" for a catalogue mistake or a wrong answer,
/// "Where it differs:" for what the check measured without naming a mistake (an isolation,
/// or a difference it could not narrow).
fn finding_label(d: &super::Diagnosis) -> String {
    tr(if named(d) { texts::MISTAKE } else { texts::DIFFERENCE })
}

/// Whether the finding is a named mistake, whose id the page shows after its title.
fn named(d: &super::Diagnosis) -> bool {
    ANSWER_IDS.contains(&d.id.as_str()) || crate::checker::mistakes::Mistake::by_id(&d.id).is_some()
}

/// Our sentences (titles, explanations, hints) mark code with backticks: `` `viewDir` ``.
/// Each matched pair becomes a code span, whose content a Markdown renderer shows as it is
/// (no HTML, no link, even when a name in it came from the student's shader), and the rest
/// goes through [`escape_markdown`]. A backtick without its pair is escaped, and so is a
/// span holding `<`, `>` or `&`.
pub fn markdown_with_code(s: &str) -> String {
    // A span holding `<`, `>` or `&` stays escaped text: no raw tag is ever in the page's
    // source, for renderers that are not strict about code spans.
    with_code(s, escape_markdown, |code| {
        if code.contains(['<', '>', '&']) {
            escape_markdown(&format!("`{code}`"))
        } else {
            format!("`{code}`")
        }
    })
}

/// As [`markdown_with_code`], for HTML: `<code>` around each span, everything escaped.
pub fn html_with_code(s: &str) -> String {
    with_code(s, escape_html, |code| format!("<code>{}</code>", escape_html(code)))
}

/// Splits `s` at backticks: a code span is the text between two backticks on one line.
fn with_code(s: &str, text: impl Fn(&str) -> String, code: impl Fn(&str) -> String) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(open) = rest.find('`') {
        let after = &rest[open + 1..];
        match after.find('`') {
            Some(close) if close > 0 && !after[..close].contains(['\n', '\r']) => {
                out += &text(&rest[..open]);
                out += &code(&after[..close]);
                rest = &after[close + 1..];
            }
            _ => {
                out += &text(&rest[..=open]);
                rest = after;
            }
        }
    }
    out + &text(rest)
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
            let _ = writeln!(s, "**{}** {}\n", m(&tr(texts::ERROR)), markdown_with_code(&r.error));
        }
        if let Some(d) = r.diagnosis.first() {
            let id = if named(d) { format!(" ({})", m(&d.id)) } else { String::new() };
            let (title, why) = (markdown_with_code(&d.title), markdown_with_code(&d.explanation));
            let _ = writeln!(s, "**{}** {title}{id}\n\n{why}\n", m(&finding_label(d)));
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "**{}** {}\n", m(&tr(texts::HINT)), markdown_with_code(&h));
        }
        if let Some(name) = picture_name(r) {
            // the picture's name is [`picture_file`]'s: letters, digits, `-`, `_` and `.` only,
            // written as it is (a link destination is no place for escapes)
            let _ = writeln!(s, "![{}]({name})\n\n{}\n", m(&tr(texts::PICTURE_ALT)), m(&caption(r)));
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
            let _ = writeln!(s, "<p><b>{}</b> {}</p>", e(&tr(texts::ERROR)), html_with_code(&r.error));
        }
        if let Some(d) = r.diagnosis.first() {
            let id = if named(d) { format!(" ({})", e(&d.id)) } else { String::new() };
            let (title, why) = (html_with_code(&d.title), html_with_code(&d.explanation));
            let _ = writeln!(s, "<p><b>{}</b> {title}{id}</p>\n<p>{why}</p>", e(&finding_label(d)));
        }
        let h = hint(r);
        if !h.is_empty() {
            let _ = writeln!(s, "<p><b>{}</b> {}</p>", e(&tr(texts::HINT)), html_with_code(&h));
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
        "<!DOCTYPE html>\n<html lang=\"{}\"><head><meta charset=\"utf-8\"><title>{title}</title>{PAGE_STYLE}</head><body>\n<h1>{title}</h1>\n{}</body></html>\n",
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

    fn page_of(row: Row) -> String {
        markdown("s", &[&row])
    }

    /// The counterexample's block wraps its long lines: the page's head styles every
    /// `pre` so, and the block is a `pre`.
    #[test]
    fn the_counterexample_wraps() {
        let row = Row { verdict: "disagrees", counterexample: "model = columns [[1.0, 2.0]]".into(), ..Row::default() };
        let page = html("s", &[&row]);
        let head = &page[..page.find("<body>").unwrap()];
        assert!(head.contains("pre{white-space:pre-wrap"), "{page}");
        assert!(page.contains("<pre>model = columns [[1.0, 2.0]]</pre>"), "{page}");
    }

    /// On a phone the page is laid out at the screen's width and the picture shrinks to
    /// it (it is 488 pixels wide, a phone 390).
    #[test]
    fn the_page_fits_a_phone() {
        let page = html("s", &[&Row::default()]);
        let head = &page[..page.find("<body>").unwrap()];
        assert!(head.contains("name=\"viewport\" content=\"width=device-width"), "{head}");
        assert!(head.contains("img{max-width:100%;height:auto}"), "{head}");
    }

    /// A wrong letter is sent back to the statement, not to the shader conventions; a
    /// file not handed in gets no "fix the error" hint, a shader that does not compile
    /// does; a difference that names no mistake is not labelled "Mistake" and shows no id.
    #[test]
    fn each_kind_of_row_gets_its_own_label_and_hint() {
        let d = |id: &str, hint: &str| super::super::Diagnosis {
            id: id.into(),
            title: "t".into(),
            hint: hint.into(),
            ..Default::default()
        };
        let wrong = page_of(Row { verdict: "disagrees", diagnosis: vec![d("wrong-choice", "")], ..Row::default() });
        assert!(wrong.contains(texts::HINT_ANSWER) && !wrong.contains(texts::HINT_CONVENTIONS), "{wrong}");
        assert!(wrong.contains("**Mistake:** t (wrong-choice)"), "{wrong}");
        let missing = page_of(Row { verdict: "error", error: "no file matches `x`".into(), ..Row::default() });
        assert!(!missing.contains("Hint:"), "{missing}");
        let broken = page_of(Row {
            exercise: "basic-move-light",
            verdict: "error",
            error: "does not compile".into(),
            ungradable: true,
            ..Row::default()
        });
        assert!(broken.contains(texts::HINT_ERROR), "{broken}");
        let none_found = page_of(Row {
            exercise: "basic-move-light",
            verdict: "error",
            error: "no submission found".into(),
            ungradable: true,
            not_found: true,
            ..Row::default()
        });
        assert!(!none_found.contains("Hint:"), "nothing of the student's to fix:\n{none_found}");
        let letters = page_of(Row {
            exercise: "casters-swap-comparison",
            verdict: "error",
            error: "the file holds 2 different letters".into(),
            ungradable: true,
            ..Row::default()
        });
        assert!(!letters.contains("Hint:"), "an answer file's error says what to write:\n{letters}");
        let isolated =
            page_of(Row { verdict: "disagrees", diagnosis: vec![d("isolated", "look at `x`")], ..Row::default() });
        assert!(isolated.contains("**Where it differs:** t\n"), "{isolated}");
        assert!(
            isolated.contains("**Hint:** Look at `x`"),
            "the check's own hint, capitalised, code kept:\n{isolated}"
        );
        let named = page_of(Row { verdict: "disagrees", diagnosis: vec![d("ambient-missing", "")], ..Row::default() });
        assert!(named.contains("(ambient-missing)") && named.contains("**Mistake:**"), "{named}");
    }

    /// Backtick pairs are code, whatever is inside, and nothing in them renders as
    /// markup; an unpaired backtick or one that would span a line break stays text.
    #[test]
    fn backtick_pairs_become_code_and_nothing_inside_renders() {
        assert_eq!(html_with_code("look at `viewDir` here"), "look at <code>viewDir</code> here");
        assert_eq!(html_with_code("`<img onerror=1>` & x"), "<code>&lt;img onerror=1&gt;</code> &amp; x");
        assert_eq!(markdown_with_code("look at `viewDir` [x]"), "look at `viewDir` \\[x\\]");
        assert_eq!(markdown_with_code("a ` b"), "a \\` b");
        assert_eq!(markdown_with_code("`<b>`"), "\\`&lt;b&gt;\\`", "no raw tag, even in code");
        assert_eq!(markdown_with_code("*star* _u_ `*x*`"), "\\*star\\* \\_u\\_ `*x*`", "no emphasis outside code");
        assert_eq!(escape_markdown("lighting_old.frag _x"), "lighting_old.frag \\_x", "an inner `_` stays");
        assert_eq!(markdown_with_code("a `b\nc` d"), "a \\`b c\\` d");
        assert_eq!(html_with_code("``"), "``");
    }
}
