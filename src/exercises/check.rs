//! Checking an answer to an exercise: a shader, a number or a choice.

use crate::checker::texts;
use std::fmt::Write as _;

use super::{letter, Check, Exercise};
use crate::checker::check::{self, CheckError, Mapping};
use crate::checker::diagnose::{self, Finding, Submission};
use crate::gl::GlContext;
use crate::gl::ModelId;

/// Why an answer could not be checked.
#[derive(Debug, Clone, PartialEq)]
pub enum ExerciseError {
    /// Bad input: an empty or binary file, a number that does not parse, an unknown id.
    Input(String),
    /// The shader check failed to run or the shader does not compile (see [`CheckError`]).
    Check(CheckError),
}

impl std::fmt::Display for ExerciseError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            ExerciseError::Input(m) => write!(f, "{m}"),
            ExerciseError::Check(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for ExerciseError {}

impl From<CheckError> for ExerciseError {
    fn from(e: CheckError) -> Self {
        ExerciseError::Check(e)
    }
}

/// The outcome of a check, whatever the exercise's kind.
#[derive(Debug, Clone, PartialEq)]
pub struct ExerciseResult {
    /// The exercise's id.
    pub exercise: &'static str,
    /// Whether the answer is right.
    pub agrees: bool,
    /// Statistics (shader checks) or the answer given (numeric and choice checks).
    pub stats: serde_json::Value,
    /// Up to 3 cases that disagree, printable.
    pub counterexamples: Vec<String>,
    /// The diagnosis, best first; empty when the answer is right.
    pub diagnosis: Vec<Finding>,
    /// Notes of the check (fixed quantities, inactive uniforms).
    pub notes: Vec<String>,
    /// The plain-words report.
    pub text: String,
}

impl ExerciseResult {
    /// `{exercise, verdict, stats, counterexamples, notes, diagnosis}`, as `check-shader
    /// --format json` plus the exercise id.
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "exercise": self.exercise,
            "verdict": if self.agrees { "agrees" } else { "disagrees" },
            "stats": self.stats,
            "counterexamples": self.counterexamples,
            "notes": self.notes,
            "diagnosis": self.diagnosis.iter().map(diagnose::finding_json).collect::<Vec<_>>(),
        })
    }
}

/// The text of a shader or answer file: errors for an empty file (only white space) and
/// for a binary one (a NUL byte), naming the byte offset.
///
/// Text as editors save it is accepted:
/// - a UTF-8 byte-order mark (Windows Notepad writes one) is dropped;
/// - a file with a UTF-16 byte-order mark (Notepad's "Unicode") is decoded from UTF-16;
/// - bytes that are not UTF-8 (a comment written in Windows-1252 or Windows-1251, as
///   Notepad's "ANSI" saves French or Ukrainian) become U+FFFD: harmless in a comment,
///   and outside one the check names their line and column
///   ([`crate::checker::check::characters`]) instead of refusing the whole file;
/// - CRLF line ends become LF, so line numbers and the driver see the file as a Unix
///   editor would.
///
/// Every command that reads a shader (`check-shader`, `exercise check`, `grade`) reads it
/// through here.
pub fn text_of(bytes: &[u8]) -> Result<String, ExerciseError> {
    let text = match utf16(bytes)? {
        Some(text) => text,
        None => {
            let bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
            if let Some(k) = bytes.iter().position(|&b| b == 0) {
                return Err(ExerciseError::Input(texts::tr_fill(FILE_NOT_TEXT, &[&k.to_string()])));
            }
            String::from_utf8_lossy(bytes).into_owned()
        }
    };
    if text.trim().is_empty() {
        return Err(ExerciseError::Input(texts::tr(FILE_EMPTY)));
    }
    Ok(if text.contains('\r') { text.replace("\r\n", "\n") } else { text })
}

/// A file that starts with a UTF-16 byte-order mark (`FF FE` little-endian, `FE FF`
/// big-endian), decoded; `None` without one. An odd length or an unpaired surrogate is an
/// error naming the byte offset.
fn utf16(bytes: &[u8]) -> Result<Option<String>, ExerciseError> {
    let little = match bytes {
        [0xFF, 0xFE, ..] => true,
        [0xFE, 0xFF, ..] => false,
        _ => return Ok(None),
    };
    let body = &bytes[2..];
    if body.len() % 2 == 1 {
        return Err(ExerciseError::Input(texts::tr_fill(FILE_UTF16_ODD, &[&bytes.len().to_string()])));
    }
    let units = body.chunks_exact(2).map(|p| {
        if little {
            u16::from_le_bytes([p[0], p[1]])
        } else {
            u16::from_be_bytes([p[0], p[1]])
        }
    });
    let mut text = String::with_capacity(body.len() / 2);
    for (k, c) in char::decode_utf16(units).enumerate() {
        match c {
            Ok('\0') => return Err(ExerciseError::Input(texts::tr_fill(FILE_NOT_TEXT, &[&(2 + 2 * k).to_string()]))),
            Ok(c) => text.push(c),
            Err(_) => {
                return Err(ExerciseError::Input(texts::tr_fill(FILE_UTF16_SURROGATE, &[&(2 + 2 * k).to_string()])))
            }
        }
    }
    Ok(Some(text))
}

fn mapping_of(toml: &str) -> Result<Mapping, ExerciseError> {
    if toml.is_empty() {
        Ok(Mapping::default())
    } else {
        Ok(check::parse_mapping(toml)?)
    }
}

/// Checks `answer` (the file's text) for `exercise`. Shader checks need `ctx` and run `n`
/// cases from `seed`; `extra` names more shader names for the `--uniforms` mapping
/// (merged over the exercise's own).
///
/// Errors: [`ExerciseError::Input`] for an unparsable number or letter, or a shader check
/// without a context; [`ExerciseError::Check`] for the shader check's errors (compile
/// errors included, with the file's line numbers).
pub fn check_exercise(
    ctx: Option<&GlContext>,
    exercise: &'static Exercise,
    answer: &str,
    extra: &Mapping,
    n: usize,
    seed: u64,
) -> Result<ExerciseResult, ExerciseError> {
    check_submission(ctx, exercise, Submission { fragment: answer, vertex: None }, extra, n, seed)
}

/// [`check_exercise`] for a submission that may hand in a vertex shader too: a shader
/// exercise then checks the pair ([`diagnose::check_and_diagnose`]); any other exercise
/// refuses the vertex shader with [`ExerciseError::Input`].
pub fn check_submission(
    ctx: Option<&GlContext>,
    exercise: &'static Exercise,
    submission: Submission<'_>,
    extra: &Mapping,
    n: usize,
    seed: u64,
) -> Result<ExerciseResult, ExerciseError> {
    let answer = submission.fragment;
    if let (Check::Pair { .. }, None) = (exercise.check, submission.vertex) {
        return Err(ExerciseError::Input(texts::tr_fill(PAIR_NEEDS_VERTEX, &[exercise.id])));
    }
    if submission.vertex.is_some() && !matches!(exercise.check, Check::Shader { .. } | Check::Pair { .. }) {
        return Err(ExerciseError::Input(texts::tr_fill(NO_VERTEX_WANTED, &[exercise.id])));
    }
    match exercise.check {
        Check::Shader { model, mapping } => {
            let ctx = ctx.ok_or_else(|| ExerciseError::Input("a shader check needs OpenGL".into()))?;
            let mapping = merged(mapping_of(mapping)?, extra);
            let d = diagnose::check_and_diagnose(ctx, submission, model, &mapping, n, seed)?;
            Ok(diagnosed_result(exercise, &d))
        }
        Check::Pair { model } => {
            let ctx = ctx.ok_or_else(|| ExerciseError::Input("a shader check needs OpenGL".into()))?;
            let d = diagnose::check_and_diagnose(ctx, submission, model.model(), extra, n, seed)?;
            Ok(diagnosed_result(exercise, &d))
        }
        Check::Variant { model, mapping, .. } => {
            let ctx = ctx.ok_or_else(|| ExerciseError::Input("a shader check needs OpenGL".into()))?;
            let mapping = merged(mapping_of(mapping)?, extra);
            let functions = exercise.functions().ok_or_else(|| {
                ExerciseError::Check(CheckError::Usage(format!("exercise {}: its edits do not apply", exercise.id)))
            })?;
            variant(ctx, exercise, model, &functions, answer, &mapping, n, seed)
        }
        Check::Numeric { answer: want, tolerance, unit } => {
            let given = super::answer_text::number_in(answer).map_err(ExerciseError::Input)?;
            let want = want();
            let texts = NumberTexts::new(tolerance, unit);
            let agrees = (given - want).abs() <= tolerance;
            let shown = given.to_string();
            let diagnosis = if agrees {
                Vec::new()
            } else {
                let finding = if given > want { &texts.too_high } else { &texts.too_low };
                vec![in_language_finding(finding.finding(GIVEN), &texts::number(&shown))]
            };
            let text = if agrees {
                in_language(&texts.right).replace(GIVEN, &texts::number(&shown))
            } else if given > want {
                in_language(&texts.too_high.text())
            } else {
                in_language(&texts.too_low.text())
            };
            Ok(ExerciseResult {
                exercise: exercise.id,
                agrees,
                stats: serde_json::json!({ "given": given, "tolerance": tolerance }),
                counterexamples: Vec::new(),
                diagnosis,
                notes: Vec::new(),
                text,
            })
        }
        Check::Choice { choices, answer: want } => {
            let k = super::answer_text::choice_in(answer, choices.len()).map_err(ExerciseError::Input)?;
            let (agrees, diagnosis, text) = choice_verdict(choices, want(), k);
            let diagnosis = diagnosis.into_iter().map(|f| in_language_finding(f, "")).collect();
            let text = in_language(&text);
            Ok(ExerciseResult {
                exercise: exercise.id,
                agrees,
                stats: serde_json::json!({ "given": letter(k).to_string() }),
                counterexamples: Vec::new(),
                diagnosis,
                notes: Vec::new(),
                text,
            })
        }
    }
}

/// The result of a shader or pair check, from its diagnosis.
fn diagnosed_result(exercise: &'static Exercise, d: &diagnose::Diagnosed) -> ExerciseResult {
    let json = d.to_json();
    ExerciseResult {
        exercise: exercise.id,
        agrees: d.agrees(),
        stats: json["stats"].clone(),
        counterexamples: d.report.counterexamples.clone(),
        diagnosis: d.diagnosis.clone(),
        notes: d.report.notes.clone(),
        text: d.format(),
    }
}

/// A verdict text of a number or choice exercise in the command line's language. Its
/// sentences are the page's words (the page shows the same verdicts, [`NumberTexts`] and
/// [`choice_verdict`]), so the PO files translate each; a trailing newline is kept.
fn in_language(text: &str) -> String {
    let body = text.trim_end_matches('\n');
    texts::tr(body) + &text[body.len()..]
}

/// A number or choice finding in the command line's language ([`in_language`]), with
/// [`GIVEN`] filled with `given` (the number as the language writes it).
fn in_language_finding(f: Finding, given: &str) -> Finding {
    Finding { title: texts::tr(&f.title), evidence: texts::tr(&f.evidence).replace(GIVEN, given), ..f }
}

/// A submission with no text (a msgid).
pub const FILE_EMPTY: &str = "the file is empty";
/// A submission with a NUL character (its byte offset).
pub const FILE_NOT_TEXT: &str = "the file is not text (a NUL character at byte {})";
/// A UTF-16 file (byte-order mark) of odd length (its length).
pub const FILE_UTF16_ODD: &str = "the file starts as UTF-16 text but has an odd length ({} bytes): save it as UTF-8";
/// A UTF-16 file with an unpaired surrogate (its byte offset).
pub const FILE_UTF16_SURROGATE: &str = "the UTF-16 file has an unpaired surrogate at byte {}: save it as UTF-8";
/// A pair exercise given a fragment shader alone (the exercise id).
pub const PAIR_NEEDS_VERTEX: &str = "exercise {} is checked as a pair: hand in the vertex shader too (--vertex VERT)";
/// A vertex shader given to an exercise that takes none (the exercise id).
pub const NO_VERTEX_WANTED: &str = "exercise {} takes a fragment shader alone; a vertex shader was handed in with it";
/// The submissions' messages above, for the translation template.
pub const FILE_TEXTS: [&str; 6] =
    [FILE_EMPTY, FILE_NOT_TEXT, FILE_UTF16_ODD, FILE_UTF16_SURROGATE, PAIR_NEEDS_VERTEX, NO_VERTEX_WANTED];

/// Where a numeric answer's texts show the reader's number.
pub const GIVEN: &str = "{given}";

/// A finding about a numeric answer, with [`GIVEN`] where the reader's number goes.
#[derive(Debug, Clone, PartialEq)]
pub struct NumberFinding {
    /// `answer-too-high` or `answer-too-low`.
    pub id: &'static str,
    /// Its title.
    pub title: &'static str,
    /// What was measured, with [`GIVEN`].
    pub evidence: String,
}

impl NumberFinding {
    /// The verdict's text.
    pub fn text(&self) -> String {
        format!("Not yet: {}.\n", self.title)
    }

    /// The finding for the reader's number `given` (as shown).
    pub fn finding(&self, given: &str) -> Finding {
        Finding {
            id: self.id.into(),
            title: self.title.into(),
            evidence: self.evidence.replace(GIVEN, given),
            link: String::new(),
            hints: Vec::new(),
            site: None,
            second: None,
        }
    }
}

/// The texts of a numeric exercise's verdicts, the same on the command line and in the
/// page (which fills in [`GIVEN`] itself: it is the only part that depends on the answer).
#[derive(Debug, Clone, PartialEq)]
pub struct NumberTexts {
    /// The text when the answer is within the tolerance.
    pub right: String,
    /// The finding when it is too high.
    pub too_high: NumberFinding,
    /// The finding when it is too low.
    pub too_low: NumberFinding,
}

impl NumberTexts {
    /// The texts for an answer accepted within `tolerance` (in `unit`, which may be empty).
    pub fn new(tolerance: f64, unit: &str) -> NumberTexts {
        let unit = if unit.is_empty() { String::new() } else { format!(" {unit}") };
        let evidence = format!("{GIVEN}{unit} is more than {tolerance}{unit} away from the crate's answer");
        NumberTexts {
            right: format!("Right: {GIVEN}{unit} (within {tolerance}{unit}).\n"),
            too_high: NumberFinding {
                id: "answer-too-high",
                title: "your number is too high",
                evidence: evidence.clone(),
            },
            too_low: NumberFinding { id: "answer-too-low", title: "your number is too low", evidence },
        }
    }
}

/// The verdict on choice `k` (0 = `a`) of `choices` when `want` is right: whether it
/// agrees, the finding, and the text.
pub fn choice_verdict(choices: &[&str], want: usize, k: usize) -> (bool, Vec<Finding>, String) {
    if k == want {
        return (true, Vec::new(), format!("Right: ({}).\n", letter(k)));
    }
    let finding = Finding {
        id: "wrong-choice".into(),
        title: format!("({}) is not it", letter(k)),
        evidence: format!("you chose ({}) {}", letter(k), choices.get(k).copied().unwrap_or("")),
        link: String::new(),
        hints: Vec::new(),
        site: None,
        second: None,
    };
    let text = format!("Not yet: {}.\n", finding.title);
    (false, vec![finding], text)
}

fn merged(mut base: Mapping, extra: &Mapping) -> Mapping {
    base.names.extend(extra.names.iter().map(|(k, v)| (k.clone(), v.clone())));
    base.values.extend(extra.values.iter().map(|(k, v)| (k.clone(), *v)));
    for key in extra.values.keys() {
        base.vectors.remove(key);
    }
    base.vectors.extend(extra.vectors.iter().cloned());
    base.lines.extend(extra.lines.iter().map(|(k, v)| (k.clone(), *v)));
    base.forbid.extend(extra.forbid.iter().cloned());
    base.require.extend(extra.require.iter().cloned());
    base.optional_names.extend(extra.optional_names.iter().cloned());
    if extra.file.is_some() {
        base.file.clone_from(&extra.file);
    }
    base
}

#[allow(clippy::too_many_arguments)]
fn variant(
    ctx: &GlContext,
    exercise: &'static Exercise,
    model_id: ModelId,
    functions: &str,
    answer: &str,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Result<ExerciseResult, ExerciseError> {
    let model = model_id.case_model();
    let shader = check::compile_shader(ctx, answer, model_id, mapping)?;
    let groups = shader.generate(n, seed)?;
    let learner = shader.run(&groups)?;
    let target = diagnose::run_functions(ctx, model, functions, &groups)?;
    let tolerance = 2.0 * model.bound;
    let agreement = diagnose::compare_outputs(model, &groups, &learner, &target, tolerance);
    let agrees = agreement.defined > 0 && agreement.mismatches == 0;
    let failing: Vec<(usize, usize)> = worst_mismatches(model, &groups, &learner, &target, tolerance, usize::MAX)
        .into_iter()
        .map(|(_, g, i)| (g, i))
        .collect();
    let typical = |&(g, i): &(usize, usize)| crate::checker::check::report::typical(model, &groups[g].rows[i]);
    let counterexamples: Vec<String> = crate::checker::check::report::teaching_order(&failing, typical)
        .into_iter()
        .take(3)
        .map(|(g, i)| {
            let want: Vec<f64> = target[g][i][..3].iter().map(|&x| f64::from(x)).collect();
            shader.describe(&groups, (g, i), &want, texts::CE_REFERENCE_SOLUTION, &learner[g][i])
        })
        .collect();
    let candidates = super::change::left_out(exercise, &crate::checker::texts::tr);
    let against = diagnose::Against {
        base: functions,
        target: diagnose::Target::Functions { ctx, functions },
        extra: &candidates,
    };
    let diagnosis = if agrees {
        Vec::new()
    } else {
        diagnose::diagnose_against(ctx, &shader, &against, answer, &groups, &learner)?
    };
    let notes = shader.report(&groups, &learner).notes;
    let mut text = diagnose::format_diagnosis(diagnose::Subject::Solution(exercise.id), agrees, &diagnosis);
    text.push('\n');
    let verdict = crate::checker::texts::SOLUTION_VERDICT[usize::from(!agrees)];
    let _ = writeln!(text, "{}", crate::checker::texts::tr_fill(verdict, &[exercise.id]));
    let cases = [
        agreement.defined.to_string(),
        agreement.mismatches.to_string(),
        texts::measured(model.bound, 2),
        texts::measured(agreement.max_diff, 3),
    ];
    let _ = writeln!(text, "{}", texts::tr_fill(texts::SOLUTION_CASES, &cases.each_ref().map(String::as_str)));
    for n in &notes {
        let _ = writeln!(text, "{}", texts::tr_fill(texts::NOTE, &[n]));
    }
    for (k, c) in counterexamples.iter().enumerate() {
        let header = texts::tr_fill(crate::checker::check::report::REPORT_COUNTEREXAMPLE, &[&(k + 1).to_string()]);
        let _ = writeln!(text, "\n{header}\n{}", texts::localize_counterexample(c));
    }
    Ok(ExerciseResult {
        exercise: exercise.id,
        agrees,
        stats: serde_json::json!({
            "defined": agreement.defined,
            "failing": agreement.mismatches,
            "bound": 2.0 * model.bound,
            "max_abs": agreement.max_diff,
        }),
        counterexamples,
        diagnosis,
        notes,
        text,
    })
}

/// The `k` defined cases where `a` and `b` differ beyond `tolerance` (at the values'
/// magnitude, [`crate::checker::outputs::differ`]), the largest difference first, as `(difference, group, case)`: the difference is the largest of the three
/// channels' `|a - b|`, infinite where one side is finite and the other is not (two
/// non-finite values agree, as in [`diagnose::compare_outputs`]). Ties keep the cases' order.
fn worst_mismatches(
    model: &crate::oracle::cases::CaseModel,
    groups: &[crate::oracle::cases::Group],
    a: &[Vec<[f32; 4]>],
    b: &[Vec<[f32; 4]>],
    tolerance: f64,
    k: usize,
) -> Vec<(f64, usize, usize)> {
    let mut bad = Vec::new();
    for (g, group) in groups.iter().enumerate() {
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, group.scene.as_ref()) != crate::oracle::cases::Class::Defined {
                continue;
            }
            let channels = (0..3).map(|c| (f64::from(a[g][i][c]), f64::from(b[g][i][c])));
            let beyond = channels.clone().any(|(x, y)| match (x.is_finite(), y.is_finite()) {
                (true, true) => crate::checker::outputs::differ(x, y, tolerance),
                (false, false) => false,
                _ => true,
            });
            let diff = channels
                .map(|(x, y)| match (x.is_finite(), y.is_finite()) {
                    (true, true) => (x - y).abs(),
                    (false, false) => 0.0,
                    _ => f64::INFINITY,
                })
                .fold(0.0, f64::max);
            if beyond {
                bad.push((diff, g, i));
            }
        }
    }
    bad.sort_by(|x, y| y.0.total_cmp(&x.0));
    bad.truncate(k);
    bad
}

#[cfg(test)]
mod worst_tests {
    use super::worst_mismatches;
    use crate::gl::ModelId;
    use crate::oracle::cases::{generate_cases, Class};

    #[test]
    fn the_worst_case_comes_first_not_the_first_one() {
        let model = ModelId::BasicLighting.case_model();
        let groups = generate_cases(model, 200, 7, &[]).unwrap();
        let b: Vec<Vec<[f32; 4]>> = groups.iter().map(|g| vec![[0.5; 4]; g.rows.len()]).collect();
        let mut a = b.clone();
        let defined: Vec<(usize, usize)> = groups
            .iter()
            .enumerate()
            .flat_map(|(g, group)| {
                group
                    .rows
                    .iter()
                    .enumerate()
                    .filter(move |(_, r)| model.classify(r, group.scene.as_ref()) == Class::Defined)
                    .map(move |(i, _)| (g, i))
            })
            .collect();
        assert!(defined.len() >= 4, "{} defined cases", defined.len());
        // The first mismatch is small, a later one is the largest, one is NaN against a number.
        let (first, worst, nan, small) = (defined[0], defined[2], defined[3], defined[1]);
        a[first.0][first.1][0] = 0.6;
        a[worst.0][worst.1][2] = 1.4;
        a[small.0][small.1][1] = 0.5 + 1e-6;
        let found = worst_mismatches(model, &groups, &a, &b, 1e-3, 3);
        let at: Vec<(usize, usize)> = found.iter().map(|&(_, g, i)| (g, i)).collect();
        assert_eq!(at, vec![worst, first], "{found:?}");
        assert!((found[0].0 - 0.9).abs() < 1e-6, "{found:?}");
        a[nan.0][nan.1][1] = f32::NAN;
        let found = worst_mismatches(model, &groups, &a, &b, 1e-3, 1);
        assert_eq!((found[0].1, found[0].2), nan, "a NaN against a number is the worst: {found:?}");
    }
}
