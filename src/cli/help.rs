//! The command line's help in the reader's language.
//!
//! A student who types `lightlab --lang fr exercise check --help` reads French. Every help
//! text of the command tree (a command's about and notes, an argument's help, a possible
//! value's help) is an English msgid, looked up in the same PO files as the verdicts
//! ([`crate::i18n::tr`]). clap's own words (the `Usage:` line, the `Arguments`/`Options`/
//! `Commands` headings, `[default: …]`, `[possible values: …]` and the help of `-h`,
//! `-V` and `help`) are msgids here, written the way clap 4.6 writes them
//! (clap_builder 4.6.7, `output/help_template.rs` and `builder/command.rs`).
//!
//! clap prints its defaults and possible values itself, in English, so a translated
//! argument hides them and carries them at the end of its own help instead.
//! English is left exactly as clap prints it. clap's error messages (an unknown option, a
//! missing value) are written again from their pieces in `cli/usage_error.rs`.

use clap::builder::StyledStr;
use clap::{Arg, Command};

use crate::i18n::catalog::tr_fill;
use crate::i18n::{tr, Lang};

/// The usage line's heading.
pub const USAGE: &str = "Usage:";
/// The subcommands' heading. clap adds the colon right after a heading, so a translation
/// may end with the space its language puts before a colon (French's no-break space); the
/// same holds for [`ARGUMENTS`] and [`OPTIONS`].
pub const COMMANDS: &str = "Commands";
/// The positional arguments' heading.
pub const ARGUMENTS: &str = "Arguments";
/// The options' heading.
pub const OPTIONS: &str = "Options";
/// An argument's default (`{}`: the values, space-separated).
pub const DEFAULT: &str = "[default: {}]";
/// An argument's possible values (`{}`: the values, comma-separated).
pub const POSSIBLE: &str = "[possible values: {}]";
/// The heading of a list of possible values that have their own help.
pub const POSSIBLE_LIST: &str = "Possible values:";
/// One possible value and its help (`{}`: the value, its help).
pub const POSSIBLE_ITEM: &str = "{}: {}";
/// The help texts clap gives its built-in arguments and subcommand (`-h`, `--help`, `-V`,
/// `help`), as clap_builder 4.6.7's `builder/command.rs` writes them.
pub const CLAP_TEXTS: [&str; 6] = [
    "Print help",
    "Print help (see more with '--help')",
    "Print help (see a summary with '-h')",
    "Print version",
    "Print this message or the help of the given subcommand(s)",
    "Print help for the subcommand(s)",
];

/// A command's own help text: how to read it, and how to set it.
type CommandText = (fn(&Command) -> Option<&StyledStr>, fn(Command, String) -> Command);

/// Every text a command carries besides its arguments', read by [`texts`] and rewritten by
/// [`localized`] from this one list.
const COMMAND_TEXTS: [CommandText; 6] = [
    (Command::get_about, |c, s| c.about(s)),
    (Command::get_long_about, |c, s| c.long_about(s)),
    (Command::get_before_help, |c, s| c.before_help(s)),
    (Command::get_before_long_help, |c, s| c.before_long_help(s)),
    (Command::get_after_help, |c, s| c.after_help(s)),
    (Command::get_after_long_help, |c, s| c.after_long_help(s)),
];

/// The language of the whole run: `flag` (`--lang`), else `LIGHTLAB_LANG`, else the locale
/// ([`Lang::from_env`]).
#[must_use]
pub fn chosen_lang(flag: Option<Lang>) -> Lang {
    let from_var = std::env::var("LIGHTLAB_LANG").ok().and_then(|v| v.parse::<Lang>().ok());
    flag.or(from_var).unwrap_or_else(Lang::from_env)
}

/// The language the help is printed in, before clap has parsed anything: the value of the
/// first `--lang X` or `--lang=X` before a `--`, when it names a language; then as
/// [`chosen_lang`]. A bad value is left for clap to report.
#[must_use]
pub fn requested_lang<I: IntoIterator<Item = std::ffi::OsString>>(args: I) -> Lang {
    let args: Vec<String> = args.into_iter().map(|a| a.to_string_lossy().into_owned()).collect();
    let flag = args.iter().take_while(|a| a.as_str() != "--").enumerate().find_map(|(k, a)| {
        let value = match a.strip_prefix("--lang") {
            Some("") => args.get(k + 1).map(String::as_str),
            Some(rest) => rest.strip_prefix('='),
            None => None,
        };
        value.and_then(|v| v.parse::<Lang>().ok())
    });
    chosen_lang(flag)
}

/// `command` with every help text in `lang`. English is returned as it is; any other
/// language builds the tree first (so clap's `help` subcommand and `-h` exist to translate).
#[must_use]
pub fn localized(mut command: Command, lang: Lang) -> Command {
    if lang == Lang::En {
        return command;
    }
    command.build();
    localize(command, lang)
}

/// Every help text of `command` and its subcommands, and clap's own words: the msgids of
/// the translation template.
#[must_use]
pub fn texts(command: &Command) -> Vec<String> {
    let mut out: Vec<String> = [USAGE, COMMANDS, ARGUMENTS, OPTIONS, DEFAULT, POSSIBLE, POSSIBLE_LIST, POSSIBLE_ITEM]
        .into_iter()
        .chain(CLAP_TEXTS)
        .chain([super::EXIT_STATUS_HELP])
        .map(str::to_owned)
        .collect();
    collect_texts(command, &mut out);
    let mut seen = std::collections::BTreeSet::new();
    out.retain(|s| !s.trim().is_empty() && seen.insert(s.clone()));
    out
}

fn collect_texts(command: &Command, out: &mut Vec<String>) {
    out.extend(COMMAND_TEXTS.iter().filter_map(|(get, _)| get(command)).map(StyledStr::to_string));
    for arg in command.get_arguments() {
        out.extend([arg.get_help(), arg.get_long_help()].into_iter().flatten().map(StyledStr::to_string));
        let values = arg.get_possible_values();
        out.extend(values.iter().filter_map(|v| v.get_help()).map(StyledStr::to_string));
    }
    for sub in command.get_subcommands() {
        collect_texts(sub, out);
    }
}

/// One built command and its subcommands, translated.
fn localize(mut command: Command, lang: Lang) -> Command {
    let t = |s: &StyledStr| tr(lang, &s.to_string()).into_owned();
    for (get, set) in COMMAND_TEXTS {
        if let Some(s) = get(&command).map(t) {
            command = set(command, s);
        }
    }
    // clap's default template (help_template.rs, DEFAULT_TEMPLATE) with the heading translated.
    let usage = tr(lang, USAGE);
    command = command
        .help_template(format!(
            "{{before-help}}{{about-with-newline}}\n{usage} {{usage}}\n\n{{all-args}}{{after-help}}"
        ))
        .subcommand_help_heading(tr(lang, COMMANDS).into_owned());
    // Headed arguments are listed by heading, in the order they come; mut_arg moves an
    // argument last, so the positionals go first to keep `Arguments` above `Options`.
    let (positionals, options): (Vec<_>, Vec<_>) =
        command.get_arguments().map(|a| (a.get_id().clone(), a.is_positional())).partition(|(_, p)| *p);
    for (id, _) in positionals {
        command = command.mut_arg(id, |a| localize_arg(a, lang, ARGUMENTS));
    }
    for (id, _) in options {
        command = command.mut_arg(id, |a| localize_arg(a, lang, OPTIONS));
    }
    command.mut_subcommands(|sub| localize(sub, lang))
}

/// One argument's help in `lang` under the translated `heading`, with its defaults and
/// possible values at the end, as clap would add them (help_template.rs, `spec_vals` and
/// `help`): on the same line in `-h`, after a blank line in `--help`, and possible values
/// that have their own help as a list.
fn localize_arg(arg: Arg, lang: Lang, heading: &str) -> Arg {
    let t = |s: &StyledStr| tr(lang, &s.to_string()).into_owned();
    let short = arg.get_help().map(t).unwrap_or_default();
    let long = arg.get_long_help().map(t).unwrap_or_else(|| short.clone());
    let mut specs = Vec::new();
    if arg.get_action().takes_values() && !arg.is_hide_default_value_set() && !arg.get_default_values().is_empty() {
        let values: Vec<String> = arg.get_default_values().iter().map(|v| quoted(&v.to_string_lossy())).collect();
        specs.push(tr_fill(lang, DEFAULT, &[&values.join(" ")]));
    }
    let mut list = String::new();
    let values: Vec<_> = arg.get_possible_values().into_iter().filter(|v| !v.is_hide_set()).collect();
    if !arg.is_hide_possible_values_set() && !values.is_empty() {
        let names: Vec<String> = values.iter().map(|v| quoted(v.get_name())).collect();
        let inline = tr_fill(lang, POSSIBLE, &[&names.join(", ")]);
        if values.iter().any(|v| v.get_help().is_some()) {
            list = tr(lang, POSSIBLE_LIST).into_owned();
            for v in &values {
                let help = v.get_help().map(t).unwrap_or_default();
                list += &format!("\n- {}", tr_fill(lang, POSSIBLE_ITEM, &[v.get_name(), &help]));
            }
        }
        specs.push(inline);
    }
    let short = [short, specs.join(" ")].into_iter().filter(|s| !s.is_empty()).collect::<Vec<_>>().join(" ");
    let long_specs = if list.is_empty() { specs.join(" ") } else { specs[..specs.len() - 1].join(" ") };
    let long = [long, list, long_specs].into_iter().filter(|s| !s.is_empty()).collect::<Vec<_>>().join("\n\n");
    let heading = arg.get_help_heading().map_or_else(|| tr(lang, heading).into_owned(), |h| tr(lang, h).into_owned());
    // A headed list is sorted by display order, then by name: the positionals keep their
    // place on the command line.
    let order = if arg.is_positional() { arg.get_index().unwrap_or(0) } else { arg.get_display_order() };
    let arg = arg.hide_default_value(true).hide_possible_values(true).help_heading(heading).display_order(order);
    if short.is_empty() {
        return arg;
    }
    arg.help(short).long_help(long)
}

/// A value as clap shows it: quoted when it holds a space.
fn quoted(value: &str) -> String {
    if value.contains(char::is_whitespace) {
        format!("{value:?}")
    } else {
        value.to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn os(args: &[&str]) -> Vec<std::ffi::OsString> {
        args.iter().map(std::ffi::OsString::from).collect()
    }

    #[test]
    fn the_help_language_is_read_from_lang_before_parsing() {
        assert_eq!(requested_lang(os(&["lightlab", "--lang", "fr", "exercise", "--help"])), Lang::Fr);
        assert_eq!(requested_lang(os(&["lightlab", "exercise", "check", "--lang=uk", "-h"])), Lang::Uk);
        // after `--` it is an operand, not the option
        let after = requested_lang(os(&["lightlab", "shade", "--", "--lang", "fr"]));
        assert_eq!(after, chosen_lang(None));
        // a bad value is clap's to report; the help falls back as without the flag
        assert_eq!(requested_lang(os(&["lightlab", "--lang", "de", "-h"])), chosen_lang(None));
    }
}
