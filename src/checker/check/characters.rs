//! Characters a learner pastes from a web page or a PDF: a no-break space (U+00A0)
//! before a declaration, a typographic quote or minus. GLSL source is ASCII outside its
//! comments, and Mesa stops reading at the first other byte, so the shader "compiles" to
//! a prefix and fails to link with "lacks `main`", which named neither the line nor the
//! character. Every shader a command checks is read here first, and such a character is
//! reported as a compile error at its line and column (comments may hold any text).

/// The name of a non-ASCII character learners meet, for the message.
fn name(c: char) -> Option<&'static str> {
    Some(match c {
        '\u{00A0}' => "no-break space",
        '\u{2000}'..='\u{200A}' => "typographic space",
        '\u{200B}' => "zero-width space",
        '\u{202F}' => "narrow no-break space",
        '\u{205F}' => "medium mathematical space",
        '\u{3000}' => "ideographic space",
        '\u{FEFF}' => "zero-width no-break space (byte-order mark)",
        '\u{2018}' | '\u{2019}' | '\u{201C}' | '\u{201D}' => "typographic quote",
        '\u{2212}' => "minus sign",
        '\u{2013}' | '\u{2014}' => "dash",
        '\u{FFFD}' => "byte that is not UTF-8 (the file was saved in another encoding, such as Windows-1252)",
        _ => return None,
    })
}

/// What to do about `c`.
fn advice(c: char) -> &'static str {
    match c {
        '\u{00A0}' | '\u{2000}'..='\u{200A}' | '\u{202F}' | '\u{205F}' | '\u{3000}' => "replace it with a space",
        '\u{200B}' | '\u{FEFF}' => "delete it",
        '\u{2212}' | '\u{2013}' | '\u{2014}' => "replace it with `-`",
        '\u{FFFD}' => "save the file as UTF-8",
        _ => "GLSL holds ASCII only outside comments: retype it",
    }
}

/// The first character outside comments that is not ASCII, with its 1-based line and
/// column (in characters): `(line, column, character)`.
#[must_use]
pub fn first_non_ascii(source: &str) -> Option<(usize, usize, char)> {
    let (mut line, mut column) = (1, 0);
    let mut chars = source.chars().peekable();
    let mut block = false; // inside /* */
    let mut comment = false; // inside //
    while let Some(c) = chars.next() {
        column += 1;
        if c == '\n' {
            (line, column, comment) = (line + 1, 0, false);
            continue;
        }
        if block {
            if c == '*' && chars.peek() == Some(&'/') {
                chars.next();
                column += 1;
                block = false;
            }
            continue;
        }
        if comment {
            continue;
        }
        match (c, chars.peek()) {
            ('/', Some('/')) => comment = true,
            ('/', Some('*')) => {
                chars.next();
                column += 1;
                block = true;
            }
            _ if !c.is_ascii() => return Some((line, column, c)),
            _ => {}
        }
    }
    None
}

/// The compile log for the first non-ASCII character outside comments, in Mesa's form
/// (`0:LINE(COLUMN): error: ...`, so the excerpt shows that line): for U+00A0,
/// `U+00A0 no-break space at line 7, column 1: replace it with a space`. `None` when the
/// source is ASCII outside its comments.
#[must_use]
pub fn log(source: &str) -> Option<String> {
    let (line, column, c) = first_non_ascii(source)?;
    let what = match name(c) {
        Some(n) => format!("U+{:04X} {n}", c as u32),
        None => format!("U+{:04X} `{c}`", c as u32),
    };
    Some(format!("0:{line}({column}): error: {what} at line {line}, column {column}: {}\n", advice(c)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_no_break_space_is_named_at_its_line_and_column() {
        let src = "#version 330 core\n// déjà vu \u{a0} in a comment\n/* é\n\u{a0} */\nuniform\u{a0}vec3 lightPos;\n";
        assert_eq!(first_non_ascii(src), Some((5, 8, '\u{a0}')));
        assert_eq!(
            log(src).unwrap(),
            "0:5(8): error: U+00A0 no-break space at line 5, column 8: replace it with a space\n"
        );
        assert_eq!(
            log("\u{a0}uniform float x;").unwrap().lines().next().unwrap(),
            "0:1(1): error: U+00A0 no-break space at line 1, column 1: replace it with a space"
        );
        assert!(log("float x = 1.0 \u{2212} y;").unwrap().contains("U+2212 minus sign at line 1, column 15"));
        assert!(log("vec3 é;").unwrap().contains("U+00E9 `é`"));
        assert_eq!(log("void main() {} // ok é\n/* ok é */"), None);
    }

    #[test]
    fn a_byte_that_is_not_utf8_is_named_outside_comments_only() {
        // `text_of` reads a Windows-1252 0xE8 as U+FFFD: harmless in a comment
        assert_eq!(log("// lumi\u{FFFD}re\nvoid main() {}"), None);
        let e = log("float lumi\u{FFFD}re = 1.0;").unwrap();
        assert!(e.contains("line 1, column 11") && e.contains("save the file as UTF-8"), "{e}");
    }
}
