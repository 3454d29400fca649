//! Naming the mistake in a vertex + fragment pair: the vertex-stage mistakes
//! ([`VERTEX_CATALOGUE`]) run as mutants of the model's reference pair on the learner's
//! triangles, then, if none matches, each half of the learner's pair beside the other half
//! of the reference.

use super::{
    compile_pair, reference, CheckError, GlContext, GlError, Mapping, PairChecked, PairGroup, PairModel, PerGroup,
};
use crate::gl::diagnose::{Finding, MISMATCH_SHARE};
use crate::gl::mistakes::{Mistake, MutateError, VERTEX_CATALOGUE};

/// The reference pair of a model: the verified LearnOpenGL-style vertex and fragment
/// shaders (`src/gl/shaders/examples/`), which agree with their model (tests).
pub fn reference_pair(model: PairModel) -> (&'static str, &'static str) {
    match model {
        PairModel::PerFragment => (
            include_str!("../../shaders/examples/basic_lighting.vert"),
            include_str!("../../shaders/examples/basic_lighting.frag"),
        ),
        PairModel::PerVertex => {
            (include_str!("../../shaders/examples/gouraud.vert"), include_str!("../../shaders/examples/gouraud.frag"))
        }
    }
}

/// The pair a learner with `mistake` would have written for `model`: the reference pair
/// with the mistake's steps applied to its vertex shader, or (a mistake with no steps) the
/// other model's reference pair.
///
/// Errors: [`MutateError`] when the mistake does not apply to the model or its steps no
/// longer match the reference.
pub fn mutant_pair(model: PairModel, mistake: &Mistake) -> Result<(String, String), MutateError> {
    if !mistake.applies_to(model.model()) {
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
    let (v, f) = reference_pair(model);
    Ok((mistake.rewrite(model.model(), v)?, f.into()))
}

/// How the colours of two pairs compare on the same triangles: `(mismatches, compared,
/// largest difference)`, a triangle mismatching when a channel differs by more than
/// `tolerance` (or one value is not finite and the other is).
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
                    off |= (x - y).abs() > tolerance;
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
/// 1. every [`VERTEX_CATALOGUE`] mistake of the model whose mutant pair gives the
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
) -> Result<Vec<Finding>, CheckError> {
    if checked.report.agrees() {
        return Ok(Vec::new());
    }
    let tolerance = 2.0 * checked.report.bound;
    let mut found = Vec::new();
    for mistake in VERTEX_CATALOGUE.iter().filter(|m| m.applies_to(model.model())) {
        let (v, f) = mutant_pair(model, mistake).map_err(|e| {
            CheckError::Gl(GlError::Gl {
                call: "rewriting the reference pair (a lightlab defect)".into(),
                detail: e.to_string(),
            })
        })?;
        let Some(mutant) = colours_of(ctx, &v, &f, model, &Mapping::default(), &checked.groups)? else { continue };
        let (bad, n, max) = compare_colours(&checked.outputs, &mutant, tolerance);
        if n > 0 && bad as f64 <= MISMATCH_SHARE * n as f64 {
            let evidence =
                format!("its mutant gives your colours on {} of {n} triangles (largest difference {max:.1e})", n - bad);
            found.push((bad, Finding::of_mistake(mistake, evidence)));
        }
    }
    found.sort_by_key(|(bad, _)| *bad);
    if !found.is_empty() {
        return Ok(found.into_iter().map(|(_, f)| f).collect());
    }
    let (rv, rf) = reference_pair(model);
    let halves = [
        (learner.0, rf, "your vertex shader with the reference fragment shader agrees: the difference is in your fragment shader (check it alone, without --vertex, for its diagnosis)"),
        (rv, learner.1, "your fragment shader with the reference vertex shader agrees: the difference is in your vertex shader"),
    ];
    for (v, f, sentence) in halves {
        if let Some(colours) = colours_of(ctx, v, f, model, mapping, &checked.groups)? {
            let (bad, n, _) =
                compare_colours(&colours, &reference_colours(model, &checked.groups), checked.report.bound);
            if bad == 0 && n > 0 {
                return Ok(vec![Finding {
                    id: "isolated".into(),
                    title: sentence.into(),
                    evidence: format!("{} of {} triangles disagree", checked.report.failing, checked.report.cases),
                    link: String::new(),
                    hints: Vec::new(),
                    site: None,
                    second: None,
                }]);
            }
        }
    }
    Ok(vec![Finding {
        id: "isolated".into(),
        title: "the difference could not be narrowed to one shader".into(),
        evidence: format!("{} of {} triangles disagree", checked.report.failing, checked.report.cases),
        link: String::new(),
        hints: Vec::new(),
        site: None,
        second: None,
    }])
}

/// The reference colours of every triangle, as `f32` (for comparing another pair's run).
fn reference_colours(model: PairModel, groups: &[PairGroup]) -> PerGroup {
    groups
        .iter()
        .map(|g| g.triangles.iter().map(|t| reference(model, t).as_vec3().extend(1.0).to_array()).collect())
        .collect()
}
