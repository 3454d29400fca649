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

/// After a mistake's evidence: the mistakes that give the same output, and why.
pub const SAME_OUTPUT: &str = "; gives the same output as {} ({})";
/// A note under the report (a fixed quantity, an inactive uniform, ...).
pub const NOTE: &str = "note: {}";
/// The notes of a check ([`crate::checker::check`]): the mapping fixed a quantity (name,
/// value, and [`NOTE_FIXED_RECEIVED`] when the shader's uniform receives it).
pub const NOTE_FIXED_BY_MAPPING: &str = "{} fixed to {} by the mapping{}";
/// See [`NOTE_FIXED_BY_MAPPING`].
pub const NOTE_FIXED_RECEIVED: &str = " (the shader's uniform receives it)";
/// A quantity the shader does not declare, fixed to the chapter's value (name, value).
pub const NOTE_NOT_DECLARED_FIXED: &str = "{} is not declared by the shader: fixed to the chapter's {}";
/// A quantity the shader does not declare and the chapter gives no value (name).
pub const NOTE_NOT_DECLARED_RANDOM: &str = "{} is not declared by the shader and the chapter gives it no value: it \
                                            stays random (fix it with [values] if the shader hard-codes it)";
/// A uniform the driver optimized away (its name).
pub const NOTE_INACTIVE: &str = "uniform {} is not used by the shader (inactive)";
/// A quantity the cases vary that the shader declares but never reads (the shader's name,
/// the model's name).
pub const NOTE_NEVER_READ: &str = "`{}` is declared but never read: the shader's colour cannot follow the model's {}, \
                                   which the cases vary (is a constant written in its place?)";

/// The labels of a counterexample block's lines ([`localize_counterexample`]): a quantity
/// the shader does not declare (its `name = value`).
pub const CE_NOT_DECLARED: &str = "(not declared) {}";
/// The expected colour: what it comes from ([`crate::checker::check::report::EXPECTED_F64`]
/// or [`CE_REFERENCE_SOLUTION`]), then the colour.
pub const CE_EXPECTED: &str = "expected ({}) = {}";
/// The shader's colour.
pub const CE_GOT: &str = "got (llvmpipe) = {}";
/// The scene of a multiple-lights case (its group number).
pub const CE_SCENE: &str = "scene: group {} (0 = the chapter's lights)";
/// A vertex of a pair's triangle (its number, its attributes).
pub const CE_VERTEX: &str = "vertex {}: {}";
/// The barycentric weights of a pair's sample (the weights).
pub const CE_WEIGHTS: &str = "weights = {}";
/// A matrix input, written column by column (its name, its columns).
pub const CE_COLUMNS: &str = "{} = columns {}";
/// The statistics of a check against a reference solution: defined cases, cases beyond
/// twice the bound, the bound, the largest difference.
pub const SOLUTION_CASES: &str = "cases: {} defined, {} beyond 2 × the bound {} (largest difference {})";
/// What a variant exercise's expected colour comes from.
pub const CE_REFERENCE_SOLUTION: &str = "reference solution on llvmpipe";

/// A fragment shader that writes no colour: no `out` variable, no `gl_FragColor`.
pub const NO_COLOUR_OUTPUT: &str =
    "the shader writes no color: declare an `out vec4` variable (as the tutorials' `out vec4 FragColor;`) and write it in `main`";
/// Several `out` variables and none at location 0 (`{}`: their names).
pub const SEVERAL_OUTPUTS: &str =
    "the shader declares several `out` variables ({}); mark the color with `layout(location = 0)`";
/// A shader without `main`.
pub const NO_MAIN: &str = "the shader has no `void main()`";

/// Every msgid of this file, for the translation template.
pub const ALL: &[&str] = &[
    NO_COLOUR_OUTPUT,
    SEVERAL_OUTPUTS,
    NO_MAIN,
    AGREES,
    DISAGREES,
    DISAGREES_ISOLATED,
    DISAGREES_LIKELY,
    SEE_THE_BOOK,
    EVIDENCE,
    SAME_OUTPUT,
    NOTE,
    NOTE_FIXED_BY_MAPPING,
    NOTE_FIXED_RECEIVED,
    NOTE_NOT_DECLARED_FIXED,
    NOTE_NOT_DECLARED_RANDOM,
    NOTE_INACTIVE,
    NOTE_NEVER_READ,
    CE_NOT_DECLARED,
    CE_EXPECTED,
    CE_GOT,
    CE_SCENE,
    CE_VERTEX,
    CE_WEIGHTS,
    CE_COLUMNS,
    CE_REFERENCE_SOLUTION,
    SOLUTION_CASES,
];

/// A counterexample block (`describe_case` of the check's report writes it in
/// English: the JSON outputs and `grade` read that form) in the command line's language:
/// each line's label is translated, and the names, values and indentation are kept (values
/// keep their decimal point: they are GLSL-like vectors a learner pastes back).
#[must_use]
pub fn localize_counterexample(block: &str) -> String {
    localize_counterexample_in(block, &tr)
}

/// [`localize_counterexample`] with the translation `tr` (a test passes a language's).
#[must_use]
pub fn localize_counterexample_in(block: &str, tr: &dyn Fn(&str) -> String) -> String {
    block.lines().map(|l| localize_counterexample_line(l, tr)).collect::<Vec<_>>().join("\n")
}

/// One line of [`localize_counterexample`]; a line without a known label is kept.
#[must_use]
pub fn localize_counterexample_line(line: &str, tr: &dyn Fn(&str) -> String) -> String {
    let fill = |msgid: &str, args: &[&str]| crate::blanks::fill(&tr(msgid), args);
    let body = line.trim_start();
    let indent = &line[..line.len() - body.len()];
    let matrix = |body: &str| match body.split_once(" = columns ") {
        Some((name, columns)) => fill(CE_COLUMNS, &[name, columns]),
        None => body.to_owned(),
    };
    let translated = if let Some(rest) = body.strip_prefix("(not declared) ") {
        fill(CE_NOT_DECLARED, &[&matrix(rest)])
    } else if let Some((source, value)) = body.strip_prefix("expected (").and_then(|r| r.split_once(") = ")) {
        fill(CE_EXPECTED, &[&tr(source), value])
    } else if let Some(value) = body.strip_prefix("got (llvmpipe) = ") {
        fill(CE_GOT, &[value])
    } else if let Some(group) =
        body.strip_prefix("scene: group ").and_then(|r| r.strip_suffix(" (0 = the chapter's lights)"))
    {
        fill(CE_SCENE, &[group])
    } else if let Some((k, rest)) = body.strip_prefix("vertex ").and_then(|r| r.split_once(": ")) {
        fill(CE_VERTEX, &[k, rest])
    } else if let Some(w) = body.strip_prefix("weights = ") {
        fill(CE_WEIGHTS, &[w])
    } else {
        matrix(body)
    };
    format!("{indent}{translated}")
}

/// A number, or numbers without words (`4.9e-1`), as the command line's language writes
/// them in a sentence: a decimal comma in French and Ukrainian
/// ([`crate::i18n::Lang::numbers_in`]).
#[cfg(feature = "book")]
#[must_use]
pub fn number(text: &str) -> String {
    crate::i18n::output_lang().numbers_in(text)
}

/// [`number`] without the `book` feature (which carries the languages): the text as it is.
#[cfg(not(feature = "book"))]
#[must_use]
pub fn number(text: &str) -> String {
    text.to_owned()
}

/// `x` with `digits` decimals, in scientific notation when `scientific` (`1.250e-3`); an
/// exact zero is `0` (not `0.000e0`), an infinite error `∞` (a result that overflowed or
/// was NaN) and NaN `NaN`, the same in every language.
pub fn shown(x: f64, digits: usize, scientific: bool) -> String {
    match x {
        0.0 => "0".into(),
        x if x.is_nan() => "NaN".into(),
        x if x.is_infinite() => if x > 0.0 { "∞" } else { "−∞" }.into(),
        x if scientific => format!("{x:.digits$e}"),
        x => format!("{x:.digits$}"),
    }
}

/// [`shown`] in scientific notation, in the command line's number style ([`number`]):
/// a measured difference or bound.
#[must_use]
pub fn measured(x: f64, digits: usize) -> String {
    number(&shown(x, digits, true))
}

/// The colon after a label in the command line's language (French puts a no-break space
/// before it; a msgid of punctuation alone would not be translated).
#[cfg(feature = "book")]
#[must_use]
pub fn colon() -> &'static str {
    crate::i18n::output_lang().colon()
}

/// [`colon`] without the `book` feature: English's.
#[cfg(not(feature = "book"))]
#[must_use]
pub fn colon() -> &'static str {
    ":"
}

/// `msgid` in the command line's language.
#[cfg(feature = "book")]
pub(crate) fn tr(msgid: &str) -> String {
    crate::i18n::tr(crate::i18n::output_lang(), msgid).into_owned()
}

#[cfg(not(feature = "book"))]
pub(crate) fn tr(msgid: &str) -> String {
    msgid.to_owned()
}

/// A driver's compile log as the learner reads it: lightlab's own note on GLSL versions
/// ([`crate::gl::batch::VERSION_NOTE`]) in their language; the driver's lines stay as the
/// driver wrote them.
#[must_use]
pub fn compile_log(log: &str) -> String {
    use crate::gl::batch::VERSION_NOTE;
    log.replace(VERSION_NOTE, &tr(VERSION_NOTE))
}

/// `msgid` in the command line's language, then each `{}` filled in order.
pub fn tr_fill(msgid: &str, args: &[&str]) -> String {
    crate::blanks::fill(&tr(msgid), args)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errors_show_zero_and_infinity_as_such() {
        assert_eq!(shown(0.0, 3, true), "0");
        assert_eq!(shown(f64::INFINITY, 3, true), "∞");
        assert_eq!(shown(f64::NEG_INFINITY, 1, false), "−∞");
        assert_eq!(shown(f64::NAN, 1, false), "NaN");
        assert_eq!(shown(1.25e-3, 3, true), "1.250e-3");
        assert_eq!(shown(2.5, 1, false), "2.5");
    }

    /// The English block keeps its text: every label the describe functions write is known.
    #[test]
    fn an_english_counterexample_is_kept_line_for_line() {
        let block =
            "  lightPos = (1.0, 2.0, 3.0)\n  (not declared) shininess = 32.0\n  model = columns [[1.0, 0.0]]\n  \
                     scene: group 2 (0 = the chapter's lights)\n  \
                     expected (f64) = [0.5, 0.25, 0.0]\n  got (llvmpipe) = [1.0, 0.0, 0.0]";
        assert_eq!(localize_counterexample(block), block);
    }

    #[cfg(feature = "book")]
    #[test]
    fn a_french_counterexample_translates_its_labels_and_keeps_names_and_values() {
        let block =
            "  lightPos = (1.5, 2.0, 3.0)\n  (not declared) shininess = 32.0\n  expected (f64) = [0.5, 0.25, 0.0]\n  \
                     got (llvmpipe) = [1.0, 0.0, 0.0]\n  vertex 0: aPos = [1.0, 0.0, 0.0]\n  \
                     model = columns [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]\n  \
                     (not declared) view = columns [[2.0, 0.0, 0.0, 0.0]]";
        // the French catalogue directly: the output language is process-wide, and other
        // tests running beside this one read it
        let fr = localize_counterexample_in(block, &|m| crate::i18n::tr(crate::i18n::Lang::Fr, m).into_owned());
        for english in ["not declared", "expected", "got (", "vertex 0:", "columns"] {
            assert!(!fr.contains(english), "{english} left in:\n{fr}");
        }
        for kept in [
            "  lightPos = (1.5, 2.0, 3.0)",
            "shininess = 32.0",
            "[0.5, 0.25, 0.0]",
            "(llvmpipe)",
            "(f64)",
            "aPos = [1.0",
            "model = colonnes [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0]]",
            "view = colonnes [[2.0",
        ] {
            assert!(fr.contains(kept), "{kept} lost:\n{fr}");
        }
        assert_eq!(fr.lines().count(), block.lines().count());
    }
}
