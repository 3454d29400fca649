//! Reading a number or a letter out of an answer file as learners write one: `45.28`,
//! `45,28`, `answer: 45.28°`, `(b)`, `Réponse : b`, a Cyrillic `а` typed on a Ukrainian
//! keyboard. The file must give one answer: several different numbers or letters
//! (`45.28 or 90`, `b or c`, `b, c`) are refused with a message saying so, never read as
//! their first one, so hedging earns nothing.

use super::letter;
use crate::checker::texts::{number, tr, tr_fill};

/// Numbers as the command line's language writes them, in a list: `45.28, 90`, or
/// `45,28; 90` where the decimal mark is a comma.
fn numbers_list(numbers: &[f64]) -> String {
    let separator = if number("0.5").contains(',') { "; " } else { ", " };
    numbers.iter().map(|x| number(&x.to_string())).collect::<Vec<_>>().join(separator)
}

/// A numeric answer as learners write it: `45.28`, or with a decimal comma, `45,28` (French
/// and Ukrainian write decimals so). `None` for anything else, `nan` and `inf` included: an
/// answer is a finite number.
#[must_use]
pub fn parse_answer_number(token: &str) -> Option<f64> {
    let token = token.trim();
    let comma = token.matches(',').count() == 1 && !token.contains('.');
    let normalized = if comma { token.replace(',', ".") } else { token.to_owned() };
    let looks_numeric = normalized.chars().all(|c| c.is_ascii_digit() || matches!(c, '.' | '-' | '+' | 'e' | 'E'));
    normalized.parse::<f64>().ok().filter(|v| v.is_finite() && looks_numeric)
}

/// The file's tokens: runs between white space, with the punctuation learners put around
/// an answer stripped (`(b)`, `b.`, `45.28°`, `« b »`), and `/` separating two (`b/c`).
fn tokens(text: &str) -> impl Iterator<Item = &str> {
    const AROUND: &[char] = &['(', ')', '[', ']', '{', '}', ':', ';', '!', '?', '"', '\'', '«', '»', '°', '*', '`'];
    text.split(|c: char| c.is_whitespace() || c == '/')
        .map(|t| t.trim_matches(AROUND).trim_end_matches(['.', ',']).trim_matches(AROUND))
        .filter(|t| !t.is_empty())
}

/// The numbers an answer file holds, in order, each once (`45.28 (45,28)` holds one).
fn numbers(text: &str) -> Vec<f64> {
    let mut found: Vec<f64> = Vec::new();
    for v in tokens(text).filter_map(parse_answer_number) {
        if !found.contains(&v) {
            found.push(v);
        }
    }
    found
}

/// The one number of an answer file; an error saying what is wrong otherwise.
pub fn number_in(text: &str) -> Result<f64, String> {
    if looks_like_a_shader(text) {
        return Err(tr(SHADER_FOR_NUMBER));
    }
    match numbers(text).as_slice() {
        [one] => Ok(*one),
        [] => Err(match tokens(text).next() {
            Some(first) => tr_fill(NOT_A_NUMBER, &[first]),
            None => tr(NO_NUMBER),
        }),
        several => Err(tr_fill(SEVERAL_NUMBERS, &[&several.len().to_string(), &numbers_list(several)])),
    }
}

/// The Latin letter a token stands for: a one-letter token, either case, Cyrillic
/// look-alikes of a, b, c and e included (`а`, `В`, `с`, `е`: the same keys on a
/// Ukrainian keyboard layout).
fn letter_of(token: &str) -> Option<char> {
    let mut chars = token.chars();
    let c = chars.next()?;
    if chars.next().is_some() {
        return None;
    }
    let latin = match c {
        'а' | 'А' => 'a',
        'В' => 'b',
        'с' | 'С' => 'c',
        'е' | 'Е' => 'e',
        c => c.to_ascii_lowercase(),
    };
    latin.is_ascii_lowercase().then_some(latin)
}

/// The choice (0 = `a`) an answer file gives among `n` choices; an error saying what is
/// wrong otherwise. One-letter words out of the range (`x`, `y`) are not choices.
pub fn choice_in(text: &str, n: usize) -> Result<usize, String> {
    if looks_like_a_shader(text) {
        return Err(tr(SHADER_FOR_LETTER));
    }
    let mut found: Vec<usize> = Vec::new();
    for k in tokens(text).filter_map(letter_of).map(|c| c as usize - 'a' as usize).filter(|&k| k < n) {
        if !found.contains(&k) {
            found.push(k);
        }
    }
    match found.as_slice() {
        [one] => Ok(*one),
        [] => Err(tr_fill(NO_LETTER, &[&letter(n.saturating_sub(1)).to_string()])),
        several => Err(tr_fill(
            SEVERAL_LETTERS,
            &[
                &several.len().to_string(),
                &several.iter().map(|&k| letter(k).to_string()).collect::<Vec<_>>().join(", "),
            ],
        )),
    }
}

/// A shader handed in for a number (msgid; the errors below are in the command line's
/// language, as a class's rows are).
pub const SHADER_FOR_NUMBER: &str =
    "this file looks like a shader; this exercise's answer is one number in a text file";
/// A shader handed in for a letter.
pub const SHADER_FOR_LETTER: &str =
    "this file looks like a shader; this exercise's answer is one letter in a text file";
/// A word where the number should be (the word).
pub const NOT_A_NUMBER: &str = "`{}` is not a number (the answer file holds one number, such as `45.28` or `45,28`)";
/// An answer file without a number.
pub const NO_NUMBER: &str = "the file holds no number (write one number, such as `45.28` or `45,28`)";
/// Several numbers (how many, the numbers).
pub const SEVERAL_NUMBERS: &str = "the file holds {} different numbers ({}): write one, your answer";
/// An answer file without a letter of the choices (the last letter: `a to {}`).
pub const NO_LETTER: &str = "the file holds no letter a to {} (write the letter of your choice, such as b)";
/// Several letters (how many, the letters).
pub const SEVERAL_LETTERS: &str = "the file holds {} different letters ({}): write one, your choice";
/// The messages above, for the translation template.
pub const TEXTS: [&str; 7] =
    [SHADER_FOR_NUMBER, SHADER_FOR_LETTER, NOT_A_NUMBER, NO_NUMBER, SEVERAL_NUMBERS, NO_LETTER, SEVERAL_LETTERS];

/// Whether `text` is a shader handed in for a number or a letter (it has `void main` or
/// a `#version` line).
fn looks_like_a_shader(text: &str) -> bool {
    text.contains("void main") || text.lines().any(|l| l.trim_start().starts_with("#version"))
}

#[cfg(test)]
mod tests {
    use super::{choice_in, number_in, parse_answer_number};

    #[test]
    fn decimal_commas_are_numbers_and_nan_is_not() {
        assert_eq!(parse_answer_number("45,28"), Some(45.28));
        assert_eq!(parse_answer_number("45.28"), Some(45.28));
        assert_eq!(parse_answer_number("-1,5e2"), Some(-150.0));
        for bad in ["nan", "inf", "-inf", "NaN", "1,2,3", "1.2,3", "", "x"] {
            assert_eq!(parse_answer_number(bad), None, "{bad}");
        }
    }

    #[test]
    fn one_number_however_written() {
        for (text, want) in [
            ("45.28", 45.28),
            ("45,28\n", 45.28),
            ("answer: 45.28°", 45.28),
            ("Réponse : 45,28.", 45.28),
            ("  (45.28)  ", 45.28),
            ("45.28 (45,28)", 45.28),
            ("-1.5e2", -150.0),
        ] {
            assert_eq!(number_in(text), Ok(want), "{text:?}");
        }
    }

    #[test]
    fn hedged_or_missing_numbers_are_refused() {
        for text in ["45.28 or 90", "45.28\n46", "45.28, 90", "1/2", "x"] {
            let e = number_in(text).expect_err(text);
            assert!(e.contains("numbers") || e.contains("is not a number"), "{text:?}: {e}");
        }
        assert!(number_in("#version 330 core\nvoid main() {}\n").unwrap_err().contains("shader"));
        assert!(number_in("nan").unwrap_err().contains("`nan` is not a number"));
    }

    #[test]
    fn one_letter_however_written() {
        for (text, want) in [
            ("b", 1),
            ("B\n", 1),
            ("(b)", 1),
            ("answer: b", 1),
            ("Réponse : (c).", 2),
            ("відповідь: а", 0),    // Cyrillic а
            ("В", 1),               // Cyrillic capital ve, the B key
            ("b) it goes dark", 1), // the choice's own words follow
        ] {
            assert_eq!(choice_in(text, 3), Ok(want), "{text:?}");
        }
    }

    #[test]
    fn hedged_or_missing_letters_are_refused() {
        // the red-team's cases: "bc" and "b or c" got full credit, "answer: b" read as (a)
        for text in ["bc", "b or c", "b, c", "(a) or (b)", "b/c", "b\nc", "", "x", "abc"] {
            let e = choice_in(text, 3).expect_err(text);
            assert!(e.contains("letters") || e.contains("no letter"), "{text:?}: {e}");
        }
        assert!(choice_in("d", 3).is_err(), "d is out of a to c");
        assert!(choice_in("void main() {}", 3).unwrap_err().contains("shader"));
    }
}
