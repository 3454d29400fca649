//! The checker's sentences as English msgids of `po/messages.pot`, and their lookup in the
//! command line's language ([`crate::i18n::output_lang`]; English without the `book`
//! feature, which carries the PO files).

/// The verdict sentences of [`super::diagnose::Diagnosed::format`] (English msgids of `po/messages.pot`;
/// `{}`: the model's name, then the finding's title).
pub const AGREES: &str = "Your shader agrees with the model {}.";
/// See [`AGREES`].
pub const DISAGREES: &str = "Your shader disagrees with the model {}.";
/// See [`AGREES`].
pub const DISAGREES_ISOLATED: &str = "Your shader disagrees with the model {}: {}.";
/// See [`AGREES`].
pub const DISAGREES_LIKELY: &str = "Your shader disagrees with the model {}. Most likely:";
/// The verdict sentences of an exercise checked against its reference solution (the
/// model's shader with the exercise's change made), in the order of [`AGREES`],
/// [`DISAGREES`], [`DISAGREES_ISOLATED`], [`DISAGREES_LIKELY`]; `{}`: the exercise's id.
pub const SOLUTION_SENTENCES: [&str; 4] = [
    "Your shader agrees with the reference solution of {}.",
    "Your shader disagrees with the reference solution of {}.",
    "Your shader disagrees with the reference solution of {}: {}.",
    "Your shader disagrees with the reference solution of {}. Most likely:",
];
/// The verdict line of a check against an exercise's reference solution, agreeing then
/// disagreeing (as [`crate::checker::check::report::REPORT_AGREES`] for a model).
pub const SOLUTION_VERDICT: [&str; 2] =
    ["verdict: AGREES with the reference solution of {}", "verdict: DISAGREES with the reference solution of {}"];
/// See [`AGREES`].
pub const SEE_THE_BOOK: &str = "see the book: {}";
/// The evidence of a catalogue mistake: cases it reproduces, defined cases, the largest
/// difference, and the cases where the correct shader differs from the mistake.
pub const EVIDENCE: &str = "this mistake reproduces your output on {} of {} defined cases (largest difference {}); \
                            the correct shader differs from it on {} defined cases";

/// `msgid` in the command line's language.
#[cfg(feature = "book")]
pub(crate) fn tr(msgid: &str) -> String {
    crate::i18n::tr(crate::i18n::output_lang(), msgid).into_owned()
}

#[cfg(not(feature = "book"))]
pub(crate) fn tr(msgid: &str) -> String {
    msgid.to_owned()
}

/// `msgid` in the command line's language, then each `{}` filled in order.
pub fn tr_fill(msgid: &str, args: &[&str]) -> String {
    crate::blanks::fill(&tr(msgid), args)
}
