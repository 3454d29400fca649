//! TeX through the translation: mdbook-i18n-helpers parses Markdown without math, so
//! `$k_a\,\mathbf{l}$` would reach a msgid as text, lose its backslash escapes and come back
//! with Markdown escapes KaTeX cannot read. Before messages are cut, every `$…$` and
//! `$$…$$` becomes an inline code span holding the TeX verbatim ([`protect`]); after
//! translation those code spans become raw TeX again ([`unprotect_event`]). A msgid
//! therefore holds the TeX source, byte for byte, as `` `$…$` ``, and the PO check compares
//! it like any code span.
//!
//! Inside a code span line breaks read as spaces: display math is kept on one line, which
//! TeX does not mind (the book's TeX has no `%` comments; [`protect`] leaves a span with
//! `%` untouched).

use pulldown_cmark::{CowStr, Event};

/// `markdown` with every math span outside code turned into an inline code span.
#[must_use]
pub fn protect(markdown: &str) -> String {
    let mut out = String::with_capacity(markdown.len() + 64);
    let mut in_fence: Option<String> = None;
    let mut pending = String::new(); // text of the current run of non-fenced lines
    for line in markdown.split_inclusive('\n') {
        let trimmed = line.trim_start();
        let fence: String = trimmed.chars().take_while(|&c| c == '`' || c == '~').collect();
        match &in_fence {
            Some(open) => {
                out.push_str(line);
                if trimmed.starts_with(open.as_str())
                    && trimmed.trim_end().chars().all(|c| c == open.chars().next().unwrap_or('`'))
                {
                    in_fence = None;
                }
            }
            None if fence.len() >= 3 => {
                out.push_str(&protect_text(&pending));
                pending.clear();
                out.push_str(line);
                in_fence = Some(fence);
            }
            None => pending.push_str(line),
        }
    }
    out.push_str(&protect_text(&pending));
    out
}

/// [`protect`] on text without fenced code blocks: inline code spans are kept as they are.
fn protect_text(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut copied = 0;
    while i < b.len() {
        match b[i] {
            b'\\' => i += 2,
            b'`' => {
                // skip an inline code span: a run of n backticks up to the next run of n
                let n = b[i..].iter().take_while(|&&c| c == b'`').count();
                let fence = &text[i..i + n];
                match text[i + n..].find(fence) {
                    Some(end) => i += n + end + n,
                    None => i += n,
                }
            }
            b'$' => {
                let display = b.get(i + 1) == Some(&b'$');
                let delim = if display { "$$" } else { "$" };
                let start = i + delim.len();
                let end = text[start..].find(delim).map(|e| start + e);
                match end {
                    Some(e)
                        if e > start
                            && (display || !text[start..e].contains('\n'))
                            && !text[start..e].contains('%') =>
                    {
                        let tex = &text[i..e + delim.len()];
                        let one_line = tex.replace('\n', " ");
                        let ticks = "`".repeat(longest_backtick_run(&one_line) + 1);
                        out.push_str(&text[copied..i]);
                        out.push_str(&ticks);
                        out.push_str(&one_line);
                        out.push_str(&ticks);
                        i = e + delim.len();
                        copied = i;
                    }
                    _ => i += delim.len(),
                }
            }
            _ => i += 1,
        }
    }
    out.push_str(&text[copied.min(text.len())..]);
    out
}

fn longest_backtick_run(s: &str) -> usize {
    s.split(|c| c != '`').map(str::len).max().unwrap_or(0)
}

/// A code span made by [`protect`] back to raw TeX (as inline HTML, which Markdown writes
/// out verbatim), its numbers written as `lang` writes them ([`tex_numbers`]); every other
/// event unchanged.
#[must_use]
pub fn unprotect_event(event: Event<'_>, lang: super::Lang) -> Event<'_> {
    match event {
        Event::Code(c) if is_math(&c) => {
            let tex = if lang.decimal_comma() { tex_numbers(&c) } else { c.to_string() };
            Event::InlineHtml(CowStr::from(tex))
        }
        e => e,
    }
}

/// TeX with a decimal comma: each point between two digits becomes `{,}` (a comma TeX
/// does not space as punctuation), and when there was one, each comma between two numbers
/// becomes a semicolon, so that a list stays readable: `(1.0, 0.5, -0.31)` →
/// `(1{,}0; 0{,}5; -0{,}31)`. TeX without a decimal point is unchanged (`f(1, 2)`), and so
/// are a command's `\,`.
#[must_use]
pub fn tex_numbers(tex: &str) -> String {
    let chars: Vec<char> = tex.chars().collect();
    let digit = |i: usize| chars.get(i).is_some_and(char::is_ascii_digit);
    let decimal = |i: usize| chars[i] == '.' && i > 0 && digit(i - 1) && digit(i + 1);
    if !(0..chars.len()).any(decimal) {
        return tex.to_owned();
    }
    // the next character after `i` that is not a space, skipping a sign
    let number_after = |i: usize| {
        let mut k = i + 1;
        while chars.get(k) == Some(&' ') {
            k += 1;
        }
        if matches!(chars.get(k), Some('-' | '+' | '−')) {
            k += 1;
        }
        digit(k)
    };
    let mut out = String::with_capacity(tex.len() + 8);
    for (i, &c) in chars.iter().enumerate() {
        match c {
            '.' if decimal(i) => out.push_str("{,}"),
            ',' if i > 0 && digit(i - 1) && number_after(i) => out.push(';'),
            c => out.push(c),
        }
    }
    out
}

/// Whether a code span's text is protected TeX (`$…$` or `$$…$$`).
#[must_use]
pub fn is_math(code: &str) -> bool {
    code.len() >= 2 && code.starts_with('$') && code.ends_with('$')
}

/// TeX's words: the contents of every `\text{…}` in `tex`, and `tex` with those contents
/// taken out (`\text{light}` → `\text{}`).
///
/// A translation may translate the words inside `\text{}` (a subscript "light" reads
/// "lumière" in French) but nothing else of the TeX: the PO check compares the frame byte
/// for byte and the words' numbers like the text's. Braces inside the words nest; an
/// unclosed `\text{` keeps the rest of the span as its words.
#[must_use]
pub fn text_words(tex: &str) -> (String, Vec<&str>) {
    const OPEN: &str = "\\text{";
    let mut frame = String::with_capacity(tex.len());
    let mut words = Vec::new();
    let mut rest = tex;
    while let Some(at) = rest.find(OPEN) {
        let start = at + OPEN.len();
        frame.push_str(&rest[..start]);
        let mut depth = 1usize;
        let mut end = rest.len();
        for (i, c) in rest[start..].char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                _ => {}
            }
            if depth == 0 {
                end = start + i;
                break;
            }
        }
        words.push(&rest[start..end]);
        rest = &rest[end..];
    }
    frame.push_str(rest);
    (frame, words)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn math_becomes_code_and_code_stays() {
        let md = "Here $k_a\\,\\mathbf{l}$ and `$not math$`.\n\n$$\na = b\n$$\n\n```glsl\nx = $y$;\n```\n";
        let p = protect(md);
        assert!(p.contains("`$k_a\\,\\mathbf{l}$`"), "{p}");
        assert!(p.contains("`$$ a = b $$`"), "{p}");
        assert!(p.contains("`$not math$`."), "{p}");
        assert!(p.contains("x = $y$;"), "{p}");
        assert_eq!(protect("a \\$5 and $6"), "a \\$5 and $6");
    }

    #[test]
    fn text_words_leave_the_frame() {
        let (frame, words) = text_words("$c_{\\text{light}} + \\quad(\\text{same for {v}})$");
        assert_eq!(frame, "$c_{\\text{}} + \\quad(\\text{})$");
        assert_eq!(words, ["light", "same for {v}"]);
        assert_eq!(text_words("$\\text{open$"), ("$\\text{".to_string(), vec!["open$"]));
    }

    #[test]
    fn tex_takes_the_decimal_comma_and_its_lists_a_semicolon() {
        assert_eq!(tex_numbers("(1.0, 0.5, -0.31)"), "(1{,}0; 0{,}5; -0{,}31)");
        assert_eq!(tex_numbers("\\cos 12.5°"), "\\cos 12{,}5°");
        assert_eq!(tex_numbers("f(1, 2)"), "f(1, 2)", "no decimal point: nothing changes");
        assert_eq!(tex_numbers("(x, 1.0, y)"), "(x, 1{,}0, y)", "a comma beside a letter stays");
        assert_eq!(tex_numbers("a\\,0.5"), "a\\,0{,}5", "a thin space stays");
        assert_eq!(tex_numbers("1.5"), "1{,}5");
    }
}
