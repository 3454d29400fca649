//! Naming the mistake in a vertex + fragment pair: the vertex-stage mistakes
//! ([`VERTEX_CATALOGUE`]) run as mutants of the model's reference pair on the learner's
//! triangles, then, if none matches, each half of the learner's pair beside the other half
//! of the reference.
//!
//! The verified pairs hard-code the chapter's strengths (ambient 0.1, specular 0.5,
//! shininess 32), while a learner may take them as uniforms, which the check fills with
//! random values. The diagnosis therefore runs on the check's triangles with every
//! quantity the chapter gives a value set to it ([`at_chapter_values`]), the learner's pair
//! included, so a mutant and the learner's pair read the same strengths whatever the
//! learner's style.

use super::{
    compile_pair, fix, reference, CheckError, GlContext, GlError, Mapping, PairChecked, PairGroup, PairModel, PerGroup,
    PAIR,
};
use crate::checker::diagnose::{Finding, MISMATCH_SHARE};
use crate::checker::mistakes::{Mistake, MutateError, CATALOGUE, VERTEX_CATALOGUE};
use crate::checker::outputs::differ;
use crate::checker::texts;
use crate::gl::ModelId;
use crate::oracle::cases::Slot;

/// The reference pair of a model: the verified LearnOpenGL-style vertex and fragment
/// shaders (`src/gl/shaders/examples/`), which agree with their model (tests).
pub fn reference_pair(model: PairModel) -> (&'static str, &'static str) {
    match model {
        PairModel::PerFragment => (
            include_str!("../../../gl/shaders/examples/basic_lighting.vert"),
            include_str!("../../../gl/shaders/examples/basic_lighting.frag"),
        ),
        PairModel::PerVertex => (
            include_str!("../../../gl/shaders/examples/gouraud.vert"),
            include_str!("../../../gl/shaders/examples/gouraud.frag"),
        ),
    }
}

/// Every verified pair of a model, the reference pair first: for `basic_lighting`, also
/// LearnOpenGL's view-space exercise (position, normal and light moved by `view * model`,
/// the eye at the origin), which agrees with the same model (tests).
pub fn verified_pairs(model: PairModel) -> Vec<(&'static str, &'static str)> {
    match model {
        PairModel::PerFragment => vec![
            reference_pair(model),
            (
                include_str!("../../../gl/shaders/examples/view_space.vert"),
                include_str!("../../../gl/shaders/examples/view_space.frag"),
            ),
        ],
        PairModel::PerVertex => vec![
            reference_pair(model),
            (
                include_str!("../../../gl/shaders/examples/gouraud_learnopengl.vert"),
                include_str!("../../../gl/shaders/examples/gouraud.frag"),
            ),
        ],
    }
}

/// Whether `mistake` is a lighting mistake made in a Gouraud vertex shader: a
/// [`CATALOGUE`] mistake of `basic_lighting` (Phong's terms), which per-vertex lighting
/// computes in the vertex shader. Its steps match the LearnOpenGL-named verified pair.
fn lit_in_vertex(model: PairModel, mistake: &Mistake) -> bool {
    model == PairModel::PerVertex
        && mistake.applies_to(ModelId::BasicLighting)
        && CATALOGUE.iter().any(|m| std::ptr::eq(m, mistake))
}

/// A mistake a pair can be diagnosed with, and the pair a learner making it would have
/// written ([`mutant_pair`]).
#[derive(Clone, Debug)]
pub struct MutantPair {
    /// The mistake.
    pub mistake: &'static Mistake,
    /// Its vertex shader (GLSL 3.30).
    pub vertex: String,
    /// Its fragment shader.
    pub fragment: String,
}

/// The mistakes a pair of `model` is diagnosed with, in catalogue order, each with its
/// mutant pair: the [`VERTEX_CATALOGUE`] mistakes of the model, then, for per-vertex
/// lighting, the lighting mistakes whose steps match one of its [`verified_pairs`]
/// (`lit_in_vertex`). The command line and the page's data ([`crate::live`]) both take
/// this list.
///
/// Errors: a vertex-stage mistake whose steps no longer match the reference (a lightlab
/// defect). A lighting mistake that matches none of the verified pairs is left out.
pub fn pair_mistakes(model: PairModel) -> Result<Vec<MutantPair>, MutateError> {
    let mut pairs = Vec::new();
    let with_pair =
        |mistake: &'static Mistake, (vertex, fragment): (String, String)| MutantPair { mistake, vertex, fragment };
    for mistake in VERTEX_CATALOGUE.iter().filter(|m| m.applies_to(model.model())) {
        pairs.push(with_pair(mistake, mutant_pair(model, mistake)?));
    }
    for mistake in CATALOGUE.iter().filter(|m| lit_in_vertex(model, m)) {
        if let Ok(pair) = mutant_pair(model, mistake) {
            pairs.push(with_pair(mistake, pair));
        }
    }
    Ok(pairs)
}

/// The pair a learner with `mistake` would have written for `model`: the first of the
/// model's [`verified_pairs`] whose vertex shader the mistake's steps match, with the
/// steps applied, or (a mistake with no steps) the other model's reference pair.
///
/// Errors: [`MutateError`] when the mistake does not apply to the model or its steps no
/// longer match the reference.
pub fn mutant_pair(model: PairModel, mistake: &Mistake) -> Result<(String, String), MutateError> {
    if !mistake.applies_to(model.model()) && !lit_in_vertex(model, mistake) {
        return Err(MutateError::NotApplicable { id: mistake.id, model: model.model() });
    }
    if mistake.steps.is_empty() {
        let other = match model {
            PairModel::PerFragment => PairModel::PerVertex,
            PairModel::PerVertex => PairModel::PerFragment,
        };
        let (v, f) = reference_pair(other);
        return Ok((v.into(), f.into()));
    }
    let mut first_error = None;
    for (v, f) in verified_pairs(model) {
        match mistake.rewrite(model.model(), v) {
            Ok(v) => return Ok((v, f.into())),
            Err(e) => {
                first_error.get_or_insert(e);
            }
        }
    }
    Err(first_error.unwrap_or(MutateError::NotApplicable { id: mistake.id, model: model.model() }))
}

/// `groups` with every quantity the chapter gives a value (the strengths) set to it,
/// except those the mapping's `[values]` fixes (see the module docs).
pub fn at_chapter_values(groups: &[PairGroup], mapping: &Mapping) -> Vec<PairGroup> {
    let mut out = groups.to_vec();
    for q in PAIR.quantities.iter().filter(|q| !mapping.values.contains_key(q.name)) {
        if let (Some(value), Slot::Case { .. }) = (q.default, q.slot) {
            for t in out.iter_mut().flat_map(|g| g.triangles.iter_mut()) {
                fix(&mut t.rows, q, value);
            }
        }
    }
    out
}

/// How the colours of two pairs compare on the same triangles: `(mismatches, compared,
/// largest difference)`, a triangle mismatching when a channel differs by more than
/// `tolerance` at the values' magnitude ([`differ`]), or one value is not finite and the
/// other is.
fn compare_colours(a: &[Vec<[f32; 4]>], b: &[Vec<[f32; 4]>], tolerance: f64) -> (usize, usize, f64) {
    let (mut bad, mut n, mut max) = (0, 0, 0.0f64);
    for (ga, gb) in a.iter().zip(b) {
        for (x, y) in ga.iter().zip(gb) {
            n += 1;
            let mut off = false;
            for c in 0..3 {
                let (x, y) = (f64::from(x[c]), f64::from(y[c]));
                if x.is_finite() && y.is_finite() {
                    max = max.max((x - y).abs());
                    off |= differ(x, y, tolerance);
                } else {
                    off |= x.is_finite() != y.is_finite();
                }
            }
            bad += usize::from(off);
        }
    }
    (bad, n, max)
}

/// Runs another pair on the same triangles; `None` when it does not compile or link with
/// these names (an isolation step that does not apply).
fn colours_of(
    ctx: &GlContext,
    vertex: &str,
    fragment: &str,
    model: PairModel,
    mapping: &Mapping,
    groups: &[PairGroup],
) -> Result<Option<PerGroup>, CheckError> {
    match compile_pair(ctx, vertex, fragment, model.model(), mapping) {
        Ok(pair) => Ok(Some(pair.run(groups)?.0)),
        Err(CheckError::Gl(e)) => Err(CheckError::Gl(e)),
        Err(_) => Ok(None),
    }
}

/// The diagnosis of a pair that disagrees (empty when it agrees):
/// 1. every mistake of [`pair_mistakes`] whose mutant pair gives the
///    learner's colours (within `2·bound` on all but [`MISMATCH_SHARE`] of the triangles),
///    fewest mismatches first;
/// 2. if none matches, each of the learner's shaders is paired with the other half of the
///    reference pair (when the names allow): the half that agrees there is right, and the
///    finding (`isolated`) says which shader the difference is in.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn diagnose_pair(
    ctx: &GlContext,
    learner: (&str, &str),
    model: PairModel,
    mapping: &Mapping,
    checked: &PairChecked,
) -> Result<PairDiagnosis, CheckError> {
    if checked.report.agrees() {
        return Ok(PairDiagnosis::named(Vec::new()));
    }
    let tolerance = 2.0 * checked.report.bound;
    let groups = at_chapter_values(&checked.groups, mapping);
    let Some(learner_colours) = colours_of(ctx, learner.0, learner.1, model, mapping, &groups)? else {
        return Ok(PairDiagnosis::named(vec![not_narrowed(checked, 0, false)]));
    };
    let mut found = Vec::new();
    let mut tried = 0;
    let mutants = pair_mistakes(model).map_err(|e| {
        CheckError::Gl(GlError::Gl {
            call: "rewriting the reference pair (a lightlab defect)".into(),
            detail: e.to_string(),
        })
    })?;
    for MutantPair { mistake, vertex, fragment } in &mutants {
        let Some(mutant) = colours_of(ctx, vertex, fragment, model, &Mapping::default(), &groups)? else { continue };
        tried += 1;
        let (bad, n, max) = compare_colours(&learner_colours, &mutant, tolerance);
        if n > 0 && bad as f64 <= MISMATCH_SHARE * n as f64 {
            let evidence =
                texts::tr_fill(PAIR_EVIDENCE, &[&(n - bad).to_string(), &n.to_string(), &texts::measured(max, 1)]);
            found.push((bad, Finding::of_mistake(mistake, evidence)));
        }
    }
    found.sort_by_key(|(bad, _)| *bad);
    if !found.is_empty() {
        return Ok(PairDiagnosis::named(found.into_iter().map(|(_, f)| f).collect()));
    }
    let (rv, rf) = reference_pair(model);
    let halves = [
        (learner.0, rf, Stage::Fragment, PAIR_IN_FRAGMENT, PAIR_HINT_FRAGMENT),
        (rv, learner.1, Stage::Vertex, PAIR_IN_VERTEX, PAIR_HINT_VERTEX),
    ];
    let mut halves_run = false;
    for (v, f, wrong, sentence, hint) in halves {
        if let Some(colours) = colours_of(ctx, v, f, model, mapping, &groups)? {
            halves_run = true;
            let (bad, n, _) = compare_colours(&colours, &reference_colours(model, &groups), checked.report.bound);
            if bad == 0 && n > 0 {
                let finding = Finding {
                    id: "isolated".into(),
                    title: texts::tr(sentence),
                    evidence: disagreeing_triangles(checked),
                    link: String::new(),
                    hints: vec![texts::tr(hint)],
                    site: None,
                    second: None,
                };
                return Ok(PairDiagnosis { findings: vec![finding], wrong_stage: Some(wrong) });
            }
        }
    }
    Ok(PairDiagnosis::named(vec![not_narrowed(checked, tried, halves_run)]))
}

/// A shader stage of a pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Stage {
    /// The vertex shader.
    Vertex,
    /// The fragment shader.
    Fragment,
}

/// What [`diagnose_pair`] found.
#[derive(Debug, Clone, PartialEq)]
pub struct PairDiagnosis {
    /// The findings (empty when the pair agrees).
    pub findings: Vec<Finding>,
    /// The learner's shader the difference is in, when the other one agreed beside the
    /// reference pair's other half (then `findings` is that one `isolated` finding). A
    /// wrong fragment shader can then be diagnosed on its own
    /// ([`crate::checker::diagnose::check_and_diagnose`]).
    pub wrong_stage: Option<Stage>,
}

impl PairDiagnosis {
    fn named(findings: Vec<Finding>) -> PairDiagnosis {
        PairDiagnosis { findings, wrong_stage: None }
    }
}

/// The evidence of a vertex-stage mistake (msgid): triangles it matches, triangles, the
/// largest difference.
pub const PAIR_EVIDENCE: &str = "its mutant gives your colours on {} of {} triangles (largest difference {})";
/// The finding when the learner's vertex shader agrees beside the reference fragment shader.
pub const PAIR_IN_FRAGMENT: &str =
    "your vertex shader with the reference fragment shader agrees: the difference is in \
                                    your fragment shader (check it alone, without --vertex, for its diagnosis)";
/// The hint of [`PAIR_IN_FRAGMENT`].
pub const PAIR_HINT_FRAGMENT: &str = "Your vertex shader is right: look in your fragment shader at what it does with \
                                      the values it receives, term by term, against the chapter's formulas.";
/// The hint of [`PAIR_IN_VERTEX`].
pub const PAIR_HINT_VERTEX: &str = "Your fragment shader is right: look in your vertex shader at what it computes and \
                                    passes on, term by term, against the chapter's formulas.";
/// The hint of [`PAIR_NOT_NARROWED`].
pub const PAIR_HINT_NEITHER: &str = "Make the two shaders fit first: what the vertex shader writes and the fragment \
                                     shader reads must have the chapter's names and meanings; then compare each term \
                                     with the chapter's formulas.";
/// The finding when the learner's fragment shader agrees beside the reference vertex shader.
pub const PAIR_IN_VERTEX: &str =
    "your fragment shader with the reference vertex shader agrees: the difference is in your vertex shader";
/// The end of [`PAIR_NOT_NARROWED`] when both halves ran and neither agreed.
pub const PAIR_IN_BOTH: &str =
    "neither of your shaders agrees beside the other half of the reference pair, so the difference is in both";
/// The end of [`PAIR_NOT_NARROWED`] when the halves could not run.
pub const PAIR_HALVES_NOT_RUN: &str =
    "your shaders could not be run beside the reference's other half (their names or the values they pass differ)";
/// Nothing named: how many vertex-stage mistakes were tried, then [`PAIR_IN_BOTH`] or
/// [`PAIR_HALVES_NOT_RUN`].
pub const PAIR_NOT_NARROWED: &str = "the difference could not be narrowed to one shader: none of the {} vertex-stage \
                                     mistakes of the catalogue gives your colours, and {}";
/// How many triangles disagree, of how many.
pub const PAIR_DISAGREEING: &str = "{} of {} triangles disagree";
/// Every msgid of this file, for the translation template.
pub const ALL: &[&str] = &[
    PAIR_EVIDENCE,
    PAIR_IN_FRAGMENT,
    PAIR_IN_VERTEX,
    PAIR_IN_BOTH,
    PAIR_HALVES_NOT_RUN,
    PAIR_NOT_NARROWED,
    PAIR_DISAGREEING,
    PAIR_HINT_FRAGMENT,
    PAIR_HINT_VERTEX,
    PAIR_HINT_NEITHER,
];

fn disagreeing_triangles(checked: &PairChecked) -> String {
    texts::tr_fill(PAIR_DISAGREEING, &[&checked.report.failing.to_string(), &checked.report.cases.to_string()])
}

/// The finding when nothing was named: what was tried (`tried` vertex-stage mutants, and
/// whether each half of the learner's pair ran beside the reference's other half).
fn not_narrowed(checked: &PairChecked, tried: usize, halves_run: bool) -> Finding {
    let halves = texts::tr(if halves_run { PAIR_IN_BOTH } else { PAIR_HALVES_NOT_RUN });
    Finding {
        id: "isolated".into(),
        title: texts::tr_fill(PAIR_NOT_NARROWED, &[&tried.to_string(), &halves]),
        evidence: disagreeing_triangles(checked),
        link: String::new(),
        hints: vec![texts::tr(PAIR_HINT_NEITHER)],
        site: None,
        second: None,
    }
}

/// The reference colours of every triangle, as `f32` (for comparing another pair's run).
fn reference_colours(model: PairModel, groups: &[PairGroup]) -> PerGroup {
    groups
        .iter()
        .map(|g| g.triangles.iter().map(|t| reference(model, t).as_vec3().extend(1.0).to_array()).collect())
        .collect()
}
