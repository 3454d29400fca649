//! clap's usage errors (an unknown option, a bad value, a missing argument) in the reader's
//! language.
//!
//! clap writes its errors in English and has no hook to translate them, but a
//! [`clap::Error`] carries its kind and the pieces of its message: the argument, the value,
//! the possible values, a suggestion, the usage line ([`clap::error::ContextKind`]). In
//! French and Ukrainian [`localized`] writes the message again from those pieces, with
//! msgids of our own looked up like every other text ([`crate::i18n::tr`]), and the names
//! in the language's quotation marks ([`Lang::quoted`]); English keeps
//! clap's own message, exactly as clap prints it.
//!
//! The pieces are kept as the user typed them or as the command defines them: option
//! names, values and the usage line's syntax are not words. A value parser's own reason
//! (clap's range check: `2000 is not in 1..=1000`) is kept too, after the translated
//! sentence.

use clap::error::{ContextKind, ContextValue, ErrorKind};

use crate::i18n::catalog::tr_fill;
use crate::i18n::{tr, Lang};

/// The error's line (`{}`: the message).
pub const ERROR: &str = "error: {}";
/// An option or argument the command does not have (`{}`: as typed).
pub const UNKNOWN_ARGUMENT: &str = "unexpected argument {}";
/// A subcommand the command does not have (`{}`: as typed).
pub const UNKNOWN_SUBCOMMAND: &str = "unknown subcommand {}";
/// A value refused (`{}`: the value, then the option).
pub const INVALID_VALUE: &str = "invalid value {} for {}";
/// An option given with an empty value (`{}`: the option).
pub const VALUE_MISSING: &str = "{} needs a value, and none was given";
/// The heading of the required arguments that are missing, one per line below it.
pub const MISSING_ARGUMENTS: &str = "these required arguments are missing:";
/// A command given without the subcommand it needs (`{}`: the command).
pub const MISSING_SUBCOMMAND: &str = "{} needs a subcommand";
/// A value past the last one an option takes (`{}`: the value, then the option).
pub const EXTRA_VALUE: &str = "unexpected value {} for {}: it takes no more";
/// An option given the wrong number of values (`{}`: the option, the number it takes, the
/// number given).
pub const VALUE_COUNT: &str = "{} takes {} values, {} given";
/// An option given twice (`{}`: the option).
pub const TWICE: &str = "{} cannot be given more than once";
/// Two options that exclude each other (`{}`: the option, then the other one or ones).
pub const CONFLICT: &str = "{} cannot be used with {}";
/// An option that must be written `--option=value` (`{}`: the option).
pub const NO_EQUALS: &str = "{} needs its value after an equals sign (=)";
/// The list of a command's subcommands (`{}`: their names, comma-separated).
pub const SUBCOMMANDS: &str = "[subcommands: {}]";
/// clap's suggestion of a near option (`{}`: the option).
pub const SIMILAR_ARGUMENT: &str = "tip: a similar option exists: {}";
/// clap's suggestion of a near subcommand (`{}`: the subcommand).
pub const SIMILAR_SUBCOMMAND: &str = "tip: a similar subcommand exists: {}";
/// clap's suggestion of a near value (`{}`: the value).
pub const SIMILAR_VALUE: &str = "tip: a similar value exists: {}";
/// Another suggestion of clap's (`{}`: clap's words).
pub const TIP: &str = "tip: {}";
/// The last line (`{}`: `--help`).
pub const MORE: &str = "For more information, try {}.";

/// Every msgid above, for the translation template.
pub const TEXTS: [&str; 18] = [
    ERROR,
    UNKNOWN_ARGUMENT,
    UNKNOWN_SUBCOMMAND,
    INVALID_VALUE,
    VALUE_MISSING,
    MISSING_ARGUMENTS,
    MISSING_SUBCOMMAND,
    EXTRA_VALUE,
    VALUE_COUNT,
    TWICE,
    CONFLICT,
    NO_EQUALS,
    SUBCOMMANDS,
    SIMILAR_ARGUMENT,
    SIMILAR_SUBCOMMAND,
    SIMILAR_VALUE,
    TIP,
    MORE,
];

/// `error` as the text to print on standard error in `lang`, ending with a newline; `None`
/// when clap's own message is the one to print: in English, for `--help` and `--version`
/// (not errors), and for an error whose pieces clap did not record.
#[must_use]
pub fn localized(error: &clap::Error, lang: Lang) -> Option<String> {
    if lang == Lang::En || !error.use_stderr() {
        return None;
    }
    let fill = |msgid: &str, args: &[&str]| tr_fill(lang, msgid, args);
    let mut out = fill(ERROR, &[&message(error, lang)?]);
    let tips = [
        (ContextKind::SuggestedArg, SIMILAR_ARGUMENT),
        (ContextKind::SuggestedSubcommand, SIMILAR_SUBCOMMAND),
        (ContextKind::SuggestedValue, SIMILAR_VALUE),
    ];
    let mut tip_lines: Vec<String> =
        tips.iter().filter_map(|&(kind, msgid)| Some(fill(msgid, &[&quoted_list(error.get(kind)?, lang)?]))).collect();
    if let Some(ContextValue::StyledStrs(others)) = error.get(ContextKind::Suggested) {
        tip_lines.extend(others.iter().map(|s| fill(TIP, &[&s.to_string()])));
    }
    if !tip_lines.is_empty() {
        out.push('\n');
        for line in tip_lines {
            out.push_str("\n  ");
            out.push_str(&line);
        }
    }
    if let Some(ContextValue::StyledStr(usage)) = error.get(ContextKind::Usage) {
        let usage = usage.to_string();
        let usage = match usage.strip_prefix(super::help::USAGE) {
            Some(rest) => format!("{}{rest}", tr(lang, super::help::USAGE)),
            None => usage,
        };
        out.push_str("\n\n");
        out.push_str(&usage);
    }
    out.push_str("\n\n");
    out.push_str(&fill(MORE, &[&lang.quoted("--help")]));
    out.push('\n');
    Some(out)
}

/// The error's first line without its `error:` label, or `None` for a kind this module
/// does not write (clap's English is printed instead).
fn message(error: &clap::Error, lang: Lang) -> Option<String> {
    let fill = |msgid: &str, args: &[&str]| tr_fill(lang, msgid, args);
    let string = |kind| match error.get(kind) {
        Some(ContextValue::String(s)) => Some(s.clone()),
        _ => None,
    };
    let name = |kind| string(kind).map(|s| lang.quoted(&s));
    let number = |kind| match error.get(kind) {
        Some(ContextValue::Number(n)) => Some(n.to_string()),
        _ => None,
    };
    let list = |kind, msgid: &str| match error.get(kind) {
        Some(ContextValue::Strings(values)) if !values.is_empty() => {
            format!("\n  {}", fill(msgid, &[&values.join(", ")]))
        }
        _ => String::new(),
    };
    let arg = name(ContextKind::InvalidArg);
    let value = string(ContextKind::InvalidValue);
    let possible = || list(ContextKind::ValidValue, super::help::POSSIBLE);
    Some(match error.kind() {
        ErrorKind::UnknownArgument => fill(UNKNOWN_ARGUMENT, &[&arg?]),
        ErrorKind::InvalidSubcommand => fill(UNKNOWN_SUBCOMMAND, &[&name(ContextKind::InvalidSubcommand)?]),
        ErrorKind::InvalidValue if value.as_deref() == Some("") => fill(VALUE_MISSING, &[&arg?]) + &possible(),
        ErrorKind::InvalidValue => fill(INVALID_VALUE, &[&lang.quoted(&value?), &arg?]) + &possible(),
        ErrorKind::ValueValidation => {
            let sentence = fill(INVALID_VALUE, &[&lang.quoted(&value?), &arg?]);
            match std::error::Error::source(error) {
                Some(reason) => format!("{sentence}: {reason}"),
                None => sentence,
            }
        }
        ErrorKind::MissingRequiredArgument => match error.get(ContextKind::InvalidArg) {
            Some(ContextValue::Strings(missing)) => {
                missing.iter().fold(tr(lang, MISSING_ARGUMENTS).into_owned(), |acc, m| format!("{acc}\n  {m}"))
            }
            _ => return None,
        },
        ErrorKind::MissingSubcommand => {
            fill(MISSING_SUBCOMMAND, &[&name(ContextKind::InvalidSubcommand)?])
                + &list(ContextKind::ValidSubcommand, SUBCOMMANDS)
        }
        ErrorKind::TooManyValues => fill(EXTRA_VALUE, &[&lang.quoted(&value?), &arg?]),
        ErrorKind::TooFewValues => {
            fill(VALUE_COUNT, &[&arg?, &number(ContextKind::MinValues)?, &number(ContextKind::ActualNumValues)?])
        }
        ErrorKind::WrongNumberOfValues => fill(
            VALUE_COUNT,
            &[&arg?, &number(ContextKind::ExpectedNumValues)?, &number(ContextKind::ActualNumValues)?],
        ),
        ErrorKind::ArgumentConflict => {
            let this = string(ContextKind::InvalidArg).or_else(|| string(ContextKind::InvalidSubcommand))?;
            match error.get(ContextKind::PriorArg) {
                Some(ContextValue::String(prior)) if *prior == this => fill(TWICE, &[&lang.quoted(&this)]),
                Some(prior) => fill(CONFLICT, &[&lang.quoted(&this), &quoted_list(prior, lang)?]),
                None => return None,
            }
        }
        ErrorKind::NoEquals => fill(NO_EQUALS, &[&arg?]),
        _ => return None,
    })
}

/// One name or several, each in `lang`'s quotation marks ([`Lang::quoted`]), joined by commas.
fn quoted_list(value: &ContextValue, lang: Lang) -> Option<String> {
    match value {
        ContextValue::String(s) => Some(lang.quoted(s)),
        ContextValue::Strings(v) if !v.is_empty() => {
            Some(v.iter().map(|s| lang.quoted(s)).collect::<Vec<_>>().join(", "))
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The error clap gives for `args` (after the program's name), with the command's help in `lang`.
    fn error_of(args: &[&str], lang: Lang) -> clap::Error {
        let argv = std::iter::once("lightlab").chain(args.iter().copied());
        let command = crate::cli::args::command(lang);
        match command.try_get_matches_from(argv) {
            Ok(_) => panic!("{args:?} parsed without an error"),
            Err(e) => e,
        }
    }

    #[test]
    fn english_keeps_clap_s_own_message() {
        let e = error_of(&["bench", "--nope"], Lang::En);
        assert_eq!(localized(&e, Lang::En), None);
    }

    #[test]
    fn help_and_version_are_not_errors() {
        let e = error_of(&["--help"], Lang::Fr);
        assert_eq!(localized(&e, Lang::Fr), None);
    }

    #[test]
    fn an_unknown_option_is_named_in_french_with_the_usage_and_the_tip() {
        let e = error_of(&["bench", "--rums", "3"], Lang::Fr);
        let text = localized(&e, Lang::Fr).expect("a French message");
        assert!(text.starts_with("erreur"), "{text}");
        assert!(text.contains("--rums"), "the option as typed: {text}");
        assert!(text.contains("--runs"), "clap's suggestion: {text}");
        assert!(text.contains("lightlab bench"), "the usage line: {text}");
        assert!(!text.contains("Usage:") && !text.contains("For more information"), "no English left: {text}");
        assert!(text.ends_with('\n'));
    }

    #[test]
    fn a_bad_value_lists_the_possible_ones_in_ukrainian() {
        let e = error_of(&["--lang", "de", "bench"], Lang::Uk);
        let text = localized(&e, Lang::Uk).expect("a Ukrainian message");
        assert!(text.contains("«de»"), "the value in Ukrainian quotation marks: {text}");
        for lang in ["en", "fr", "uk"] {
            assert!(text.contains(lang), "possible value {lang}: {text}");
        }
        assert!(!text.contains("invalid value") && !text.contains("possible values"), "no English left: {text}");
    }

    #[test]
    fn a_range_check_keeps_its_reason_after_the_translated_sentence() {
        let e = error_of(&["bench", "--runs", "0"], Lang::Fr);
        let text = localized(&e, Lang::Fr).expect("a French message");
        assert!(text.contains("--runs") && text.contains('0'), "{text}");
        let first = text.lines().next().unwrap_or_default();
        assert!(first.contains(": "), "the parser's reason follows the sentence: {text}");
    }

    #[test]
    fn an_unknown_subcommand_is_named() {
        let e = error_of(&["benhc"], Lang::Fr);
        let text = localized(&e, Lang::Fr).expect("a French message");
        assert!(text.contains("benhc") && text.contains("bench"), "{text}");
    }

    #[test]
    fn every_text_has_a_translation_in_each_language() {
        for lang in [Lang::Fr, Lang::Uk] {
            for msgid in TEXTS {
                assert_ne!(tr(lang, msgid), msgid, "{msgid} has no {lang:?} translation");
            }
        }
    }
}
