//! Naming the mistake: when a learner's shader disagrees with its model, which known
//! mistake gives the same output, or else which term, light and inputs disagree.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | learner | the checked shader's outputs on the cases |
//! | mutant | the model's function file with one [`crate::checker::mistakes`] entry applied, run on the same cases |
//! | match | learner and mutant within `2·bound` on every defined case but at most [`MISMATCH_SHARE`] of them |
//! | switch | a term (ambient, diffuse, specular) or a light zeroed through the case inputs |
//! | split | the defined cases divided by a sign (N·L, R·V) or a region (inside the spot cone) |
//!
//! # The procedure
//! 1. Every mutant of the model runs on the learner's cases (same rows, same uniforms). A
//!    mutant names the mistake when it matches the learner and is closer to the learner than
//!    the reference is (fewer mismatching cases): one that agrees with the reference on
//!    these cases is invisible here (for example `shininess-ignored` when the shader
//!    hard-codes 32 and the check fixes the shininess to the chapter's 32), while one that
//!    changes only the few cases on which the learner disagrees (a clamp that acts on one
//!    case in a thousand) explains them. Every mutant that matches is reported, fewest
//!    mismatches first.
//! 2. If none matches, or the best leaves more than [`EXACT_SHARE`] of the cases
//!    unexplained, pairs of mutants are tried ([`super::two_mistakes`]): "two mistakes: …
//!    and …". A pair replaces a matching single mistake only when it leaves fewer than
//!    half as many cases unexplained.
//! 3. If none matches, the learner's shader runs again with one term or light switched off
//!    (its inputs zeroed in the cases or the scene, only for quantities the shader
//!    declares); a switch that removes every disagreement locates it. The failing cases
//!    are then split by sign; a sign that holds for every failing case, but not for every
//!    case, is reported ("only when N·L < 0").
//!
//! The bound of a match is `2·bound`: the learner and the mutant each stay within the
//! model's bound of the exact mutant's value (the bound is a rounding bound; see
//! [`crate::oracle::cases::bounds`]).

use std::fmt::Write as _;

use super::check::{self, CheckError, CheckReport, CompiledShader, Mapping};
pub use super::isolation::Target;
use super::mistakes::Mistake;
use super::texts::{colon, tr, SAME_OUTPUT};
pub use super::texts::{tr_fill, AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, EVIDENCE, SEE_THE_BOOK};
pub use super::verdict::{case_fails, expected_values, Finding};
use crate::gl::context::GlContext;
use crate::gl::model_id::ModelId;
use crate::oracle::cases::{CaseModel, Group};

pub use super::outputs::{compare_outputs, run_body, run_functions, run_mutants, Agreement, MISMATCH_SHARE};

/// Step 1 of the procedure: the catalogue mistakes whose mutants of `base` (the function
/// file the learner should match) match `learner`.
///
/// Errors: as [`run_mutants`].
pub fn matching_mistakes(
    ctx: &GlContext,
    model: &CaseModel,
    base: &str,
    groups: &[Group],
    learner: &[Vec<[f32; 4]>],
) -> Result<Vec<Finding>, CheckError> {
    let against = Against { base, target: Target::Model, extra: &[] };
    Ok(findings(scored_mistakes(ctx, model, &against, "", groups, learner)?))
}

/// A candidate outside the catalogue: a function file of the model and the finding that
/// names it (an exercise's reference solution with its change, or part of it, not made).
#[derive(Debug, Clone)]
pub struct Candidate {
    /// The function file.
    pub functions: String,
    /// The finding when it matches (its evidence is filled in by the diagnosis).
    pub finding: Finding,
    /// The edits that turn the base into `functions`, one step per entry, for the
    /// tie-break by the learner's text ([`text_score`]).
    pub edits: Vec<Vec<(&'static str, &'static str)>>,
}

/// What a learner's shader is diagnosed against: the function file it should match (its
/// model's own, or an exercise's reference solution), what the isolation step compares it
/// with, and candidates beyond the catalogue.
#[derive(Clone, Copy)]
pub struct Against<'a> {
    /// The function file the learner should match; the catalogue's mutants are made from it.
    pub base: &'a str,
    /// What the isolation step compares the learner with.
    pub target: Target<'a>,
    /// Candidates tried beside the catalogue's mutants.
    pub extra: &'a [Candidate],
}

/// A text without comments and white space, for comparing the learner's text with a
/// mutant's edits whatever the spacing.
#[must_use]
pub fn squashed(text: &str) -> String {
    super::check::glsl::blank_comments(text).chars().filter(|c| !c.is_whitespace()).collect()
}

/// The part of `edited` that an edit changed, with its context up to the nearest `=`, `,`,
/// `;`, `{` or `}` on each side: `normalize(light.direction))` for θ's
/// `dot(lightDir, normalize(-light.direction))` made `dot(lightDir, normalize(light.direction))`.
/// The learner's own names for the rest of the line (`dot(L, …)`) then do not hide it.
/// `original` and `edited` are [`squashed`].
fn changed_part(original: &str, edited: &str) -> String {
    let prefix = original.chars().zip(edited.chars()).take_while(|(a, b)| a == b).count();
    let (o, e): (Vec<char>, Vec<char>) = (original.chars().collect(), edited.chars().collect());
    let max_suffix = o.len().min(e.len()) - prefix;
    let suffix = o.iter().rev().zip(e.iter().rev()).take(max_suffix).take_while(|(a, b)| a == b).count();
    let delimiter = |c: &char| matches!(c, '=' | ',' | ';' | '{' | '}');
    let start = e[..prefix].iter().rposition(delimiter).map_or(0, |k| k + 1);
    let end = e[e.len() - suffix..].iter().position(delimiter).map_or(e.len(), |k| e.len() - suffix + k);
    e[start..end].iter().collect()
}

/// The shortest changed part [`text_score`] takes as a sign of an edit: 8 characters
/// (`reflect(lightDir` has 16; a part as short as `0.0)` occurs in any shader).
const SHORTEST_PART: usize = 8;

/// What shows one step of an edit in a learner's text: the texts that show the edit made
/// (its replacement, whole and as its changed part, `changed_part`) and the texts that
/// show the base's line kept ([`squashed`] all). The page's checker scores the reader's
/// text with the same lists (`src/live/exercises.rs` exports them as `signs`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct StepSigns {
    /// Texts that show the edit made.
    pub edit: Vec<String>,
    /// Texts that show the base's line kept.
    pub base: Vec<String>,
}

/// The [`StepSigns`] of each step of `steps` that applies to `base` ([`squashed`]). Only the
/// alternatives whose text occurs in the base count; a replacement the base already
/// contains says nothing, and a changed part shorter than `SHORTEST_PART` is left out.
#[must_use]
pub fn text_signs<'e>(steps: impl IntoIterator<Item = &'e [(&'e str, &'e str)]>, base: &str) -> Vec<StepSigns> {
    let mut out = Vec::new();
    for step in steps {
        let mut signs = StepSigns { edit: Vec::new(), base: Vec::new() };
        for (from, to) in step.iter().map(|(from, to)| (squashed(from), squashed(to))) {
            if from.is_empty() || !base.contains(from.as_str()) || base.contains(to.as_str()) {
                continue;
            }
            let (part_from, part_to) = (changed_part(&to, &from), changed_part(&from, &to));
            if part_to.chars().count() >= SHORTEST_PART && !base.contains(part_to.as_str()) {
                signs.edit.push(part_to);
            }
            if part_from.chars().count() >= SHORTEST_PART {
                signs.base.push(part_from);
            }
            if !to.is_empty() {
                signs.edit.push(to);
            }
            signs.base.push(from);
        }
        if !signs.edit.is_empty() || !signs.base.is_empty() {
            out.push(signs);
        }
    }
    out
}

/// How far the learner's text shows a mutant's edits: for each step that applies to `base`
/// ([`text_signs`]), +1 when a text showing the edit occurs in `learner`, else −1 when a
/// text showing the base's line does (the learner wrote that line as the base has it). A
/// replacement is looked for whole and as its changed part with its context
/// (`changed_part`), so a line the learner wrote with other names still shows its edit.
/// `base` and `learner` are [`squashed`]; white space in the edits is ignored too.
///
/// Two mutants with the same output (an [`super::mistakes::EQUIVALENT`] group:
/// `reflect(lightDir, norm)` gives the output of a reversed `viewDir`) are told apart by
/// this score: the one whose edit the learner wrote comes first.
#[must_use]
pub fn text_score<'e>(steps: impl IntoIterator<Item = &'e [(&'e str, &'e str)]>, base: &str, learner: &str) -> i32 {
    score_of(&text_signs(steps, base), learner)
}

/// [`text_score`] from the signs.
#[must_use]
pub fn score_of(signs: &[StepSigns], learner: &str) -> i32 {
    let occurs = |texts: &[String]| texts.iter().any(|t| learner.contains(t.as_str()));
    signs
        .iter()
        .map(|s| {
            if occurs(&s.edit) {
                1
            } else if occurs(&s.base) {
                -1
            } else {
                0
            }
        })
        .sum()
}

/// [`matching_mistakes`] with each finding's agreement with the learner, best first: fewest
/// mismatches, then the highest [`text_score`] against `text` (the learner's source; empty
/// when unknown), then the smallest largest difference.
fn scored_mistakes(
    ctx: &GlContext,
    model: &CaseModel,
    against: &Against<'_>,
    text: &str,
    groups: &[Group],
    learner: &[Vec<[f32; 4]>],
) -> Result<Vec<(Agreement, Finding)>, CheckError> {
    if model.shader.is_none() {
        return Ok(Vec::new());
    }
    let base = against.base;
    let reference = run_functions(ctx, model, base, groups)?;
    let tolerance = 2.0 * model.bound;
    let (base_sq, text_sq) = (squashed(base), squashed(text));
    // how far the learner is from the reference: a mutant must come closer
    let baseline = compare_outputs(model, groups, &reference, learner, tolerance);
    let evidence_of = |vs_learner: &Agreement, vs_reference: &Agreement| {
        tr_fill(
            EVIDENCE,
            &[
                &(vs_learner.defined - vs_learner.mismatches).to_string(),
                &vs_learner.defined.to_string(),
                &super::texts::measured(vs_learner.max_diff, 1),
                &vs_reference.mismatches.to_string(),
            ],
        )
    };
    let mut found: Vec<(Agreement, i32, Finding)> = Vec::new();
    for (mutant, outputs) in run_mutants(ctx, model, base, groups)? {
        let vs_reference = compare_outputs(model, groups, &outputs, &reference, tolerance);
        let vs_learner = compare_outputs(model, groups, &outputs, learner, tolerance);
        if vs_learner.matches() && vs_learner.mismatches < baseline.mismatches {
            let label = mutant.label();
            let same = mutant.equivalence().map_or(String::new(), |e| {
                let others: Vec<&str> = e.ids.iter().copied().filter(|id| *id != label).collect();
                tr_fill(SAME_OUTPUT, &[&others.join(", "), &tr(e.reason)])
            });
            let evidence = evidence_of(&vs_learner, &vs_reference) + &same;
            let steps = mutant.mistake.steps_for(model.id).unwrap_or_default();
            let score = text_score(steps.iter().copied(), &base_sq, &text_sq);
            found.push((vs_learner, score, Finding::of_mutant(&mutant, evidence)));
        }
    }
    for candidate in against.extra {
        // a candidate that does not compile (a step group left out that another needs) is not one
        let Ok(outputs) = run_functions(ctx, model, &candidate.functions, groups) else { continue };
        let vs_reference = compare_outputs(model, groups, &outputs, &reference, tolerance);
        let vs_learner = compare_outputs(model, groups, &outputs, learner, tolerance);
        if vs_learner.matches() && vs_learner.mismatches < baseline.mismatches {
            let score = text_score(candidate.edits.iter().map(Vec::as_slice), &base_sq, &text_sq);
            let finding = Finding { evidence: evidence_of(&vs_learner, &vs_reference), ..candidate.finding.clone() };
            found.push((vs_learner, score, finding));
        }
    }
    found.sort_by(|a, b| {
        a.0.mismatches.cmp(&b.0.mismatches).then(b.1.cmp(&a.1)).then(a.0.max_diff.total_cmp(&b.0.max_diff))
    });
    Ok(found.into_iter().map(|(a, _, f)| (a, f)).collect())
}

/// The share of defined cases a single mistake may leave unexplained and still be taken
/// as the whole story: 1 in 10 000. The cases on which a learner and a mutant take
/// different sides of a discontinuity are a few in 10^5 (see [`MISMATCH_SHARE`]); a
/// single mistake that leaves more unexplained, while still matching, may hide a second
/// mistake that changes few cases (a point light's ambient left unattenuated beside the
/// spot's Blinn lobe: 91 of 98 504 cases), so the pairs are tried too.
pub const EXACT_SHARE: f64 = 1e-4;

/// The findings of scored findings, in their order.
fn findings(scored: Vec<(Agreement, Finding)>) -> Vec<Finding> {
    scored.into_iter().map(|(_, f)| f).collect()
}

/// Whether `a` leaves at most [`EXACT_SHARE`] of its defined cases unexplained.
fn explains_all(a: &Agreement) -> bool {
    a.mismatches as f64 <= EXACT_SHARE * a.defined as f64
}

/// Whether the best pair is reported instead of the best single mistake: when no single
/// mistake matches, or when the pair leaves fewer than half as many cases unexplained.
fn pair_explains_more(single: Option<&Agreement>, pair: Option<&Agreement>) -> bool {
    match (single, pair) {
        (_, None) => false,
        (None, Some(_)) => true,
        (Some(single), Some(pair)) => 2 * pair.mismatches < single.mismatches,
    }
}

/// The diagnosis of a shader that disagrees: the matching mistakes, best first; if none
/// matches, one `isolated` finding. Empty when the report agrees. `text` is the shader's
/// source, which breaks ties between mistakes with the same output ([`text_score`]).
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn diagnose(
    ctx: &GlContext,
    shader: &CompiledShader<'_>,
    text: &str,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
    report: &CheckReport,
) -> Result<Vec<Finding>, CheckError> {
    if report.agrees() {
        return Ok(Vec::new());
    }
    let model = shader.model();
    let Some(s) = model.shader else {
        return Ok(vec![super::isolation::isolate(shader, groups, outputs)?]);
    };
    diagnose_against(
        ctx,
        shader,
        &Against { base: s.functions(), target: Target::Model, extra: &[] },
        text,
        groups,
        outputs,
    )
}

/// [`diagnose`] of a shader known to disagree with `against` (its model, or an exercise's
/// reference solution with the candidates that leave the exercise's change out): the
/// catalogue's mutants of `against.base` and `against.extra`, then pairs, then the
/// isolation step against `against.target`.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn diagnose_against(
    ctx: &GlContext,
    shader: &CompiledShader<'_>,
    against: &Against<'_>,
    text: &str,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
) -> Result<Vec<Finding>, CheckError> {
    let model = shader.model();
    let found = scored_mistakes(ctx, model, against, text, groups, outputs)?;
    let best_single = found.first().map(|(a, _)| *a);
    if best_single.as_ref().is_some_and(explains_all) {
        return Ok(findings(found));
    }
    // no single mistake, or one that leaves cases unexplained: two mistakes may explain more
    let pairs = super::two_mistakes::matching_pairs(ctx, model, against.base, groups, outputs)?.0;
    if pair_explains_more(best_single.as_ref(), pairs.first().map(|(a, _)| a)) {
        return Ok(findings(pairs));
    }
    if !found.is_empty() {
        return Ok(findings(found));
    }
    Ok(vec![super::isolation::isolate_against(shader, &against.target, groups, outputs)?])
}

/// What a learner hands in: a complete fragment shader, and optionally the vertex shader
/// it pairs with (then both are checked together: [`check::pair`]). A `&str` is a fragment
/// shader alone.
#[derive(Debug, Clone, Copy)]
pub struct Submission<'s> {
    /// The fragment shader.
    pub fragment: &'s str,
    /// Its vertex shader, if handed in.
    pub vertex: Option<&'s str>,
}

impl<'s> From<&'s str> for Submission<'s> {
    fn from(fragment: &'s str) -> Self {
        Submission { fragment, vertex: None }
    }
}

impl<'s> From<&'s String> for Submission<'s> {
    fn from(fragment: &'s String) -> Self {
        Submission { fragment, vertex: None }
    }
}

/// A check with its diagnosis.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosed {
    /// The check's verdict and statistics.
    pub report: CheckReport,
    /// The diagnosis, best first; empty when the shader agrees.
    pub diagnosis: Vec<Finding>,
}

/// Checks `source` (a complete fragment shader) against `model` on `n` cases from
/// `seed` ([`check::CompiledShader::check`]), then runs [`diagnose`] on the same cases; a
/// submission with a vertex shader is checked as a pair on triangles
/// ([`check::pair::CompiledPair::check`], [`check::pair::diagnose_pair`]).
///
/// Compiles the user's file as it is on the driver, in the calling process (`lightlab
/// check-shader` runs this in a child process so a driver crash or a runaway shader cannot
/// take it down).
///
/// Errors: [`CheckError::Usage`] (`gouraud` without a vertex shader, a model with no pair
/// reference with one, `n` outside `1..=`[`crate::oracle::cases::MAX_CASES`], storage above the
/// limits, unmapped name, type mismatch, no colour output),
/// [`CheckError::Compile`] (with the file's line numbers; [`CheckError::VertexCompile`] for
/// the vertex shader), [`CheckError::Gl`].
pub fn check_and_diagnose<'s>(
    ctx: &GlContext,
    submission: impl Into<Submission<'s>>,
    model: ModelId,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Result<Diagnosed, CheckError> {
    check::check_cases(n)?;
    let Submission { fragment: source, vertex } = submission.into();
    if let Some(vertex) = vertex {
        let pair = check::pair::compile_pair(ctx, vertex, source, model, mapping)?;
        let checked = pair.check(n, seed)?;
        let found = check::pair::diagnose_pair(ctx, (vertex, source), pair.model(), mapping, &checked)?;
        let mut diagnosis = found.findings;
        if found.wrong_stage == Some(check::pair::Stage::Fragment) {
            if let Some(alone) = fragment_alone(ctx, source, model, mapping, n, seed)? {
                diagnosis = alone;
            }
        }
        return Ok(Diagnosed { report: checked.report, diagnosis });
    }
    let shader = check::compile_shader(ctx, source, model, mapping)?;
    let check::Checked { groups, outputs, report } = shader.check(n, seed)?;
    let diagnosis = diagnose(ctx, &shader, source, &groups, &outputs, &report)?;
    Ok(Diagnosed { report, diagnosis })
}

/// The diagnosis of a pair's fragment shader checked alone against `model`, when the pair's
/// difference lies in it: the catalogue's mistakes are named on the fragment model, which
/// a pair check cannot do. `None` when the fragment shader is no shader of `model` on its
/// own (a Gouraud pair's, which only passes the colour on), or agrees alone, or nothing
/// narrower than the pair's finding comes out.
fn fragment_alone(
    ctx: &GlContext,
    source: &str,
    model: ModelId,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Result<Option<Vec<Finding>>, CheckError> {
    let Ok(shader) = check::compile_shader(ctx, source, model, mapping) else { return Ok(None) };
    let check::Checked { groups, outputs, report } = shader.check(n, seed)?;
    if report.agrees() {
        return Ok(None);
    }
    let found = diagnose(ctx, &shader, source, &groups, &outputs, &report)?;
    Ok(Some(found).filter(|f| !f.is_empty()))
}

impl Diagnosed {
    /// Whether the shader agrees with its model.
    pub fn agrees(&self) -> bool {
        self.report.agrees()
    }

    /// Plain words first (the diagnosis), then the check's report. The sentences, the
    /// mistakes' titles and explanations are in the command line's language
    /// ([`crate::i18n::output_lang`]; English without the `book` feature).
    pub fn format(&self) -> String {
        let mut s = format_diagnosis(Subject::Model(self.report.model.name()), self.agrees(), &self.diagnosis);
        s.push('\n');
        s += &self.report.format();
        s
    }

    /// The JSON object of `check-shader --format json` (see the book's exercises appendix).
    pub fn to_json(&self) -> serde_json::Value {
        let r = &self.report;
        serde_json::json!({
            "verdict": if self.agrees() { "agrees" } else { "disagrees" },
            "model": r.model.name(),
            "stats": {
                "cases": r.cases,
                "defined": r.defined,
                "failing": r.failing,
                "bound": r.bound,
                "max_abs": finite_or_null(r.vs_f64.max_abs),
                "mean_abs": finite_or_null(r.vs_f64.mean_abs),
                "max_ulps": finite_or_null(r.vs_f64.max_ulps),
            },
            "counterexamples": r.counterexamples,
            "notes": r.notes,
            "diagnosis": self.diagnosis.iter().map(finding_json).collect::<Vec<_>>(),
        })
    }
}

/// Whom a verdict names: a model (a shader check), or an exercise's reference solution
/// (the model's shader with the exercise's change made).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Subject<'a> {
    /// The model, by name.
    Model(&'a str),
    /// The reference solution of the exercise, by id.
    Solution(&'a str),
}

impl<'a> Subject<'a> {
    /// The four verdict sentences: agrees, disagrees, disagrees with the isolation's
    /// sentence, disagrees with likely mistakes (msgids; `{}` the name, then the sentence).
    fn sentences(self) -> (&'a str, [&'static str; 4]) {
        match self {
            Subject::Model(name) => (name, [AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY]),
            Subject::Solution(id) => (id, super::texts::SOLUTION_SENTENCES),
        }
    }
}

/// The diagnosis in plain words, as every shader check prints it before its report: the
/// verdict sentence naming `subject`, then each finding with its explanation, the book's
/// page and hints (the likeliest finding's first hint; all three of each with `--hints`).
/// A finding outside the catalogue carries its own explanation-free title and its own
/// hints ([`Finding::hints`]).
#[must_use]
pub fn format_diagnosis(subject: Subject<'_>, agrees: bool, diagnosis: &[Finding]) -> String {
    let (name, [agrees_s, disagrees_s, isolated_s, likely_s]) = subject.sentences();
    let mut s = String::new();
    if agrees {
        let _ = writeln!(s, "{}", tr_fill(agrees_s, &[name]));
        return s;
    }
    match diagnosis {
        [] => {
            let _ = writeln!(s, "{}", tr_fill(disagrees_s, &[name]));
        }
        [f] if f.id == "isolated" => {
            let _ = writeln!(s, "{}", tr_fill(isolated_s, &[name, &f.title]));
            let _ = writeln!(s, "  {}", f.evidence);
            for line in super::hints::numbered(&f.hints, super::hints::showing_all(), "  ", tr) {
                let _ = writeln!(s, "{line}");
            }
        }
        findings => {
            let _ = writeln!(s, "{}", tr_fill(likely_s, &[name]));
            let all = super::hints::showing_all();
            for (k, f) in findings.iter().enumerate() {
                let why = match &f.second {
                    Some(b) => format!("{}; {}", tr(mistake_why(&f.id)), tr(mistake_why(&b.id))),
                    None if mistake_why(&f.id).is_empty() => String::new(),
                    None => tr(mistake_why(&f.id)),
                };
                if why.is_empty() {
                    let _ = writeln!(s, "  - {} [{}]", f.shown_title(tr), f.label());
                } else {
                    let _ = writeln!(s, "  - {} [{}]{} {why}", f.shown_title(tr), f.label(), colon());
                }
                let _ = writeln!(s, "    {}", f.evidence);
                if !f.link.is_empty() {
                    let _ = writeln!(s, "    {}", tr_fill(SEE_THE_BOOK, &[&f.link]));
                }
                // the likeliest mistake's first hint; every hint of each with --hints
                if all || k == 0 {
                    let lines = if f.hints.is_empty() {
                        super::hints::hint_lines(&f.id, all, "    ", tr)
                    } else {
                        super::hints::numbered(&f.hints, all, "    ", tr)
                    };
                    for line in lines {
                        let _ = writeln!(s, "{line}");
                    }
                }
            }
        }
    }
    s
}

fn finite_or_null(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::Value::Null
    }
}

/// One finding as `{id, site, title, evidence, link, hints, second}` (`site`: `null` or a
/// [`super::sites::Site::name`]; `hints`: the isolation step's three, or a catalogue
/// mistake's three from [`super::hints::hints`], in English as the rest of the JSON).
pub fn finding_json(f: &Finding) -> serde_json::Value {
    let hints: Vec<&str> = match super::hints::hints(&f.id) {
        Some(catalogue) if f.hints.is_empty() => catalogue.to_vec(),
        _ => f.hints.iter().map(String::as_str).collect(),
    };
    serde_json::json!({
        "id": f.id, "site": f.site.map(|s| s.name()), "title": f.title, "evidence": f.evidence, "link": f.link,
        "hints": hints, "second": f.second.as_deref().map(finding_json),
    })
}

fn mistake_why(id: &str) -> &'static str {
    Mistake::by_id(id).map_or("", |m| m.why)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn agreement(defined: usize, mismatches: usize) -> Agreement {
        Agreement { defined, mismatches, ..Agreement::default() }
    }

    #[test]
    fn a_single_mistake_that_leaves_more_than_one_case_in_ten_thousand_is_not_the_whole_story() {
        // measured: ambient-not-attenuated@point alone left 91 of 98 504 cases of a shader
        // that also had blinn-for-phong@spot
        assert!(!explains_all(&agreement(98_504, 91)));
        // a few in 10^5 on a discontinuity still count as explained
        assert!(explains_all(&agreement(98_504, 9)));
        assert!(explains_all(&agreement(2_000, 0)));
        assert!(!explains_all(&agreement(2_000, 1)));
    }

    #[test]
    fn a_pair_replaces_a_single_mistake_only_when_it_explains_clearly_more() {
        let single = agreement(98_504, 91);
        assert!(pair_explains_more(Some(&single), Some(&agreement(98_504, 0))));
        assert!(pair_explains_more(Some(&single), Some(&agreement(98_504, 45))));
        assert!(!pair_explains_more(Some(&single), Some(&agreement(98_504, 46))));
        assert!(!pair_explains_more(Some(&single), None));
        assert!(pair_explains_more(None, Some(&agreement(2_000, 1))));
        assert!(!pair_explains_more(None, None));
    }

    /// The tie-break by the learner's text: +1 for a step whose replacement the learner
    /// wrote, −1 for one whose original line the learner kept, whatever the spacing and
    /// comments; a replacement the base already contains says nothing.
    #[test]
    fn the_text_score_prefers_the_edit_the_learner_wrote() {
        let reflect = super::super::mistakes::Mistake::by_id("reflect-sign").unwrap();
        let view = super::super::mistakes::Mistake::by_id("view-dir-reversed").unwrap();
        let base =
            squashed("vec3 viewDir = normalize(viewPos - FragPos);\nvec3 reflectDir = reflect(-lightDir, norm);");
        let learner = squashed(
            "vec3 viewDir = normalize( viewPos - FragPos ); // reflect(-lightDir, norm)\nvec3 r = reflect(lightDir,norm);",
        );
        assert_eq!(text_score(reflect.steps_for(ModelId::BasicLighting).unwrap().iter().copied(), &base, &learner), 1);
        assert_eq!(text_score(view.steps_for(ModelId::BasicLighting).unwrap().iter().copied(), &base, &learner), -1);
        // a step whose replacement is already in the base is skipped
        let steps: &[&[(&str, &str)]] = &[&[("viewDir", "FragPos")]];
        assert_eq!(text_score(steps.iter().copied(), &base, &learner), 0);
        assert_eq!(text_score(reflect.steps_for(ModelId::BasicLighting).unwrap().iter().copied(), &base, ""), 0);
        // the learner's own names around the edit: its changed part still shows it
        let spot = super::super::mistakes::Mistake::by_id("spot-direction-reversed").unwrap();
        let base = squashed("float theta = dot(lightDir, normalize(-light.direction));");
        let learner = squashed("float theta = dot(L, normalize(light.direction));");
        assert_eq!(text_score(spot.steps_for(ModelId::Spot).unwrap().iter().copied(), &base, &learner), 1);
        let learner = squashed("float theta = dot(L, normalize(-light.direction));");
        assert_eq!(text_score(spot.steps_for(ModelId::Spot).unwrap().iter().copied(), &base, &learner), -1);
    }

    #[test]
    fn the_changed_part_reaches_the_nearest_delimiters() {
        let part = |a: &str, b: &str| changed_part(&squashed(a), &squashed(b));
        assert_eq!(
            part(
                "theta = dot(lightDir, normalize(-light.direction));",
                "theta = dot(lightDir, normalize(light.direction));"
            ),
            "normalize(light.direction))"
        );
        assert_eq!(part("reflect(-lightDir, norm)", "reflect(lightDir, norm)"), "reflect(lightDir");
        assert_eq!(
            part("viewDir = normalize(viewPos - FragPos)", "viewDir = normalize(FragPos - viewPos)"),
            "normalize(FragPos-viewPos)"
        );
        assert_eq!(part("abc", "abc"), "abc");
    }

    fn finding(id: &str, hints: Vec<String>) -> Finding {
        Finding {
            id: id.into(),
            title: String::new(),
            evidence: String::new(),
            link: String::new(),
            hints,
            site: None,
            second: None,
        }
    }

    /// A catalogue mistake's JSON carries its three hints (the finding keeps them by id), and
    /// the isolation step's JSON its own.
    #[test]
    fn a_findings_json_carries_its_hints() {
        let catalogue = super::super::hints::hints("light-dir-reversed").expect("a catalogue mistake with hints");
        let v = finding_json(&finding("light-dir-reversed", Vec::new()));
        assert_eq!(v["hints"], serde_json::json!(catalogue.to_vec()));
        let own = vec!["where".to_string(), "idea".to_string(), "fix".to_string()];
        let v = finding_json(&finding("isolated", own.clone()));
        assert_eq!(v["hints"], serde_json::json!(own));
    }
}
