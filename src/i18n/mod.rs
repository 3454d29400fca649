//! The book and the checker in the learners' languages: English, French and Ukrainian.
//!
//! One home for every string: English is the source text (the book's Markdown and the
//! Rust strings a reader sees), and `po/fr.po`, `po/uk.po` hold the translations, keyed by
//! the English text (gettext's msgid). The book build translates each chapter with them
//! ([`translate`]), the command line looks its messages up in the same files ([`tr`]).
//!
//! | piece | what it does |
//! | --- | --- |
//! | [`Lang`] | the three languages, their codes and the default from `LC_ALL`/`LANG` |
//! | [`translate`] | the mdBook preprocessor: mdbook-i18n-helpers' message grouping, with an untranslated paragraph shown in English under a visible mark |
//! | [`extract`] | `lightlab i18n extract`: `po/messages.pot` from the book (mdbook-i18n-helpers' xgettext renderer, in process) and the Rust strings, then each PO file merged with it |
//! | [`check`] | the PO checks: complete, not fuzzy, the same numbers, code, links and TeX as the English |
//! | [`catalog`] | the PO files compiled into the binary, for [`tr`] |
//! | [`glossary`] | the seeds' terms in three languages, with seed and line |
//! | [`localize`] | a translated chapter points at its language's copy of a generated chart, diagram or live figure |
//!
//! # How a contributor updates a translation
//! 1. Change the English text (a chapter, or a string in Rust).
//! 2. `cargo run --release -- i18n extract`: rewrites `po/messages.pot` and merges it into
//!    `po/fr.po` and `po/uk.po` (a message whose English changed comes back empty, its old
//!    translation kept as a comment to start from; see [`extract::merge`]).
//! 3. Translate the empty messages (any PO editor: Poedit, Lokalize, or a text editor).
//! 4. `cargo run --release -- i18n check` lists what is missing or wrong, by message and
//!    line; `cargo test` runs the same checks.
//!
//! Until then the book shows the changed paragraph in English with a "not yet translated"
//! mark: a stale translation is never shown, because a msgid is the whole English text.

pub mod catalog;
pub mod check;
pub mod chrome;
pub mod extract;
pub mod glossary;
pub mod localize;
pub mod math;
pub mod translate;

use std::fmt;
use std::str::FromStr;
use std::sync::atomic::{AtomicU8, Ordering};

pub use catalog::tr;

/// A language of the book and the command line.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Lang {
    /// English, the source text.
    En,
    /// French, the language of LearnOpenGL's translation, opengl-tutorial 8 and ogldev 19 in
    /// the seeds.
    Fr,
    /// Ukrainian, the language of the university lab in the seeds.
    Uk,
}

impl Lang {
    /// Every language, English first (the book at `build/`, the others at `build/<code>/`).
    pub const ALL: [Lang; 3] = [Lang::En, Lang::Fr, Lang::Uk];

    /// The ISO 639-1 code: `en`, `fr`, `uk` (the `lang` attribute, the PO file's name).
    #[must_use]
    pub fn code(self) -> &'static str {
        match self {
            Lang::En => "en",
            Lang::Fr => "fr",
            Lang::Uk => "uk",
        }
    }

    /// The language's own name, for the picker.
    #[must_use]
    pub fn native_name(self) -> &'static str {
        match self {
            Lang::En => "English",
            Lang::Fr => "Français",
            Lang::Uk => "Українська",
        }
    }

    /// The translations, or `None` for English (the source).
    #[must_use]
    pub fn is_translation(self) -> bool {
        self != Lang::En
    }

    /// The colon after a label: French puts a no-break space (U+00A0) before it, as the
    /// French PO file does in every message.
    #[must_use]
    pub fn colon(self) -> &'static str {
        if self == Lang::Fr {
            "\u{a0}:"
        } else {
            ":"
        }
    }

    /// `text` in this language's quotation marks: English writes a name the user typed in
    /// straight quotes, as clap does (`'--runs'`); French in guillemets with no-break spaces
    /// inside (`«\u{a0}--runs\u{a0}»`), and Ukrainian in guillemets without them
    /// (`«--runs»`), as the PO files quote.
    #[must_use]
    pub fn quoted(self, text: &str) -> String {
        match self {
            Lang::En => format!("'{text}'"),
            Lang::Fr => format!("«\u{a0}{text}\u{a0}»"),
            Lang::Uk => format!("«{text}»"),
        }
    }

    /// Whether numbers in this language may use a decimal comma (`45,28`).
    #[must_use]
    pub fn decimal_comma(self) -> bool {
        self != Lang::En
    }

    /// The separator between the numbers of a list as this language writes it: `, ` in
    /// English; a semicolon in French (`1,0 ; 0,5`, a no-break space before it) and
    /// Ukrainian (`1,0; 0,5`), where a comma would read as a decimal sign.
    #[must_use]
    pub fn list_separator(self) -> &'static str {
        match self {
            Lang::En => ", ",
            Lang::Fr => "\u{a0}; ",
            Lang::Uk => "; ",
        }
    }

    /// A number's minus sign: the hyphen-minus in English (as the code samples write it), the
    /// minus sign `−` (U+2212) in French and Ukrainian.
    #[must_use]
    pub fn minus_sign(self) -> char {
        if self.decimal_comma() {
            '−'
        } else {
            '-'
        }
    }

    /// `text`, a number or numbers without words (`0.05`, `12.5°`, `(1, 0.5, 0.31)`,
    /// `262,144`), as this language writes it. English keeps it as it is; French and
    /// Ukrainian write
    /// - a decimal point between two digits as a comma: `0,05`;
    /// - a list's separator (a comma and a space) as a semicolon, so that the commas left
    ///   are decimal signs: `(1 ; 0,5)` in French, with a no-break space before it, and
    ///   `(1; 0,5)` in Ukrainian;
    /// - a comma that groups thousands (a digit before it, exactly three after) as a narrow
    ///   no-break space: `262 144`;
    /// - a hyphen that is a number's sign (a digit after it; nothing, a space, a bracket, `=`
    ///   or `;` before it) as the minus sign `−`: `(−0,5 ; 0)`. A hyphen between two digits
    ///   or in an exponent (`1e-7`) stays.
    ///
    /// Text with any other comma is left as it is: it is not English, and a guess could
    /// change a number.
    #[must_use]
    pub fn numbers_in(self, text: &str) -> String {
        if !self.decimal_comma() {
            return text.to_owned();
        }
        let chars: Vec<char> = text.chars().collect();
        let digit = |i: usize| chars.get(i).is_some_and(char::is_ascii_digit);
        let between_digits = |i: usize| i > 0 && digit(i - 1) && digit(i + 1);
        let groups_thousands = |i: usize| between_digits(i) && (1..=3).all(|k| digit(i + k)) && !digit(i + 4);
        let sign = |i: usize| {
            let before = if i == 0 { None } else { chars.get(i - 1) };
            digit(i + 1) && before.is_none_or(|c| SIGN_FOLLOWS.contains(*c))
        };
        let mut out = String::with_capacity(text.len() + 8);
        for (i, &c) in chars.iter().enumerate() {
            match c {
                '.' if between_digits(i) => out.push(','),
                // the space after the comma is the separator's own, and is kept
                ',' if chars.get(i + 1) == Some(&' ') => out.push_str(self.list_separator().trim_end_matches(' ')),
                ',' if groups_thousands(i) => out.push('\u{202f}'),
                '-' if sign(i) => out.push(self.minus_sign()),
                ',' => return text.to_owned(),
                _ => out.push(c),
            }
        }
        out
    }

    /// The language of a POSIX locale name (`uk_UA.UTF-8`, `fr_FR`, `fr`, `C`), or `None`
    /// for a locale none of the three languages matches.
    #[must_use]
    pub fn from_locale(locale: &str) -> Option<Lang> {
        let code = locale.split(['_', '.', '@', '-']).next().unwrap_or("").to_ascii_lowercase();
        Lang::ALL.into_iter().find(|l| l.code() == code)
    }

    /// The default language of the command line, as command-line tools choose it: the first
    /// of `LC_ALL`, `LC_MESSAGES` and `LANG` that is set and not empty decides; a locale of
    /// another language (or `C`, `POSIX`) gives English.
    #[must_use]
    pub fn from_env() -> Lang {
        Lang::from_env_vars(|name| std::env::var(name).ok())
    }

    /// [`Lang::from_env`] with the environment given as a function (for tests).
    #[must_use]
    pub fn from_env_vars(get: impl Fn(&str) -> Option<String>) -> Lang {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .filter_map(|name| get(name))
            .find(|v| !v.is_empty())
            .and_then(|v| Lang::from_locale(&v))
            .unwrap_or(Lang::En)
    }
}

/// The characters after which a hyphen followed by a digit is a number's sign (and not a
/// hyphen between two numbers or in an exponent), for [`Lang::numbers_in`] and the page
/// scripts' `number()`, which read it from `texts.js`.
pub const SIGN_FOLLOWS: &str = " \u{a0}([=;/";

/// The command line's output language (see [`set_output_lang`]).
static OUTPUT_LANG: AtomicU8 = AtomicU8::new(0);

/// Sets the language the command line writes its sentences in, as gettext's `setlocale`
/// does for a C program: once, at start, from `--lang` or the environment.
pub fn set_output_lang(lang: Lang) {
    OUTPUT_LANG.store(lang as u8, Ordering::Relaxed);
}

/// Whether the output language was chosen on the command line (`--lang`).
static OUTPUT_LANG_EXPLICIT: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Records that the output language comes from `--lang`: a file's own setting (an
/// assignment's `lang`) then gives way to it.
pub fn set_output_lang_explicit() {
    OUTPUT_LANG_EXPLICIT.store(true, Ordering::Relaxed);
}

/// Whether `--lang` chose the output language ([`set_output_lang_explicit`]).
#[must_use]
pub fn output_lang_is_explicit() -> bool {
    OUTPUT_LANG_EXPLICIT.load(Ordering::Relaxed)
}

/// The command line's output language ([`Lang::En`] until [`set_output_lang`]).
#[must_use]
pub fn output_lang() -> Lang {
    match OUTPUT_LANG.load(Ordering::Relaxed) {
        1 => Lang::Fr,
        2 => Lang::Uk,
        _ => Lang::En,
    }
}

impl fmt::Display for Lang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.code())
    }
}

/// An unknown language code (the message lists the known ones).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct UnknownLang(pub String);

impl fmt::Display for UnknownLang {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "unknown language `{}`: use one of en, fr, uk", self.0)
    }
}

impl std::error::Error for UnknownLang {}

impl FromStr for Lang {
    type Err = UnknownLang;

    fn from_str(s: &str) -> Result<Lang, UnknownLang> {
        Lang::ALL.into_iter().find(|l| l.code() == s.trim()).ok_or_else(|| UnknownLang(s.to_owned()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_take_the_languages_decimal_sign() {
        assert_eq!(Lang::Fr.numbers_in("0.05"), "0,05");
        assert_eq!(Lang::Uk.numbers_in("12.5°/17.5°"), "12,5°/17,5°");
        assert_eq!(Lang::En.numbers_in("0.05"), "0.05");
        // a list's commas become semicolons, so that its decimal commas read as such
        assert_eq!(Lang::Fr.numbers_in("(1, 0.5, -0.31)"), "(1\u{a0}; 0,5\u{a0}; −0,31)");
        // a number's sign is a minus sign; a hyphen in an exponent or between digits is not
        assert_eq!(Lang::Uk.numbers_in("-2.0 = 1e-7 [-1, 3-4]"), "−2,0 = 1e-7 [−1; 3-4]");
        assert_eq!(Lang::En.numbers_in("-2.0"), "-2.0");
        assert_eq!(Lang::Uk.numbers_in("[1.0, 0.5]"), "[1,0; 0,5]");
        assert_eq!(Lang::En.numbers_in("(1, 0.5)"), "(1, 0.5)");
        // thousands are grouped by a narrow no-break space; a comma that is neither is kept
        assert_eq!(Lang::Fr.numbers_in("262,144 (1,024.5)"), "262\u{202f}144 (1\u{202f}024,5)");
        assert_eq!(Lang::Uk.numbers_in("1,5 and 0.5"), "1,5 and 0.5", "an unknown comma leaves the text");
        assert_eq!(Lang::Uk.numbers_in("1,2345"), "1,2345", "four digits after a comma group nothing");
        assert_eq!(Lang::Fr.numbers_in(".5 and 3."), ".5 and 3.", "only a point between digits");
    }

    #[test]
    fn locales_pick_the_language() {
        assert_eq!(Lang::from_locale("uk_UA.UTF-8"), Some(Lang::Uk));
        assert_eq!(Lang::from_locale("fr_CA"), Some(Lang::Fr));
        assert_eq!(Lang::from_locale("C"), None);
        let env = |vars: &'static [(&'static str, &'static str)]| {
            move |name: &str| vars.iter().find(|(n, _)| *n == name).map(|(_, v)| v.to_string())
        };
        assert_eq!(Lang::from_env_vars(env(&[("LANG", "uk_UA.UTF-8")])), Lang::Uk);
        // LC_ALL overrides LANG; an empty LC_ALL does not
        assert_eq!(Lang::from_env_vars(env(&[("LC_ALL", "fr_FR.UTF-8"), ("LANG", "uk_UA")])), Lang::Fr);
        assert_eq!(Lang::from_env_vars(env(&[("LC_ALL", ""), ("LANG", "uk_UA")])), Lang::Uk);
        assert_eq!(Lang::from_env_vars(env(&[("LANG", "de_DE.UTF-8")])), Lang::En);
        assert_eq!(Lang::from_env_vars(env(&[])), Lang::En);
    }

    #[test]
    fn codes_round_trip() {
        for l in Lang::ALL {
            assert_eq!(l.code().parse::<Lang>(), Ok(l));
        }
        assert!("de".parse::<Lang>().unwrap_err().to_string().contains("en, fr, uk"));
    }
}
