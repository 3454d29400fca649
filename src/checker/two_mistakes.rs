//! Two mistakes at once: when no single mutant reproduces a learner's
//! output, pairs of mutants ([`super::sites::Mutant`]) composed in one function file.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | changed cases | the defined cases on which a run differs from the reference by more than `2·bound` (at the values' magnitude, [`super::outputs::differ`]) |
//! | candidate | a mutant whose changed cases are, but for [`CANDIDATE_SHARE`] of the defined cases, among the learner's |
//! | pair | two candidates of different mistakes whose edits compose in either order to the same text |
//!
//! # The bound
//! A mistake the learner made changes only cases the learner's output changes too (unless
//! the two mistakes cancel on a case, which the share allows for). So only candidates are
//! paired, and at most [`MAX_PAIRS`] pairs run: those whose two mutants already give the
//! learner's output on the most cases first, stopping at the first pair that matches. A pair whose edits
//! overlap (one edit destroys the text the other looks for, or the two orders give
//! different texts) is skipped, and so is a pair of the same mistake (everywhere and in one
//! site, or in two sites: the whole-file mutant of that mistake already covers it).

use super::check::CheckError;
use super::outputs::{compare_outputs, differ, run_functions, Agreement, MISMATCH_SHARE};
use super::sites::{self, Mutant};
use super::verdict::Finding;
use crate::oracle::cases::{CaseModel, Class, Group};

/// At most this many pairs are run, best scored first (each is one compile and one draw
/// per group: about 0.3 s on llvmpipe for `multiple_lights` on two cores under load).
/// Measured with the release build, `check-shader --model multiple_lights` on 10⁵ cases,
/// two cores loaded by other builds: 4 to 8 s for a shader with two mistakes, 8 s for one
/// with three (every pair runs, then the isolation step).
pub const MAX_PAIRS: usize = 60;

pub use super::verdict::TWO_MISTAKES;

/// Whether every case on which `run` differs from `reference` is one on which `learner`
/// differs too, but for [`CANDIDATE_SHARE`] of the defined cases.
fn changes_within(
    model: &CaseModel,
    groups: &[Group],
    run: &[Vec<[f32; 4]>],
    learner: &[Vec<[f32; 4]>],
    reference: &[Vec<[f32; 4]>],
) -> bool {
    let tolerance = 2.0 * model.bound;
    let differs = |a: &[f32; 4], b: &[f32; 4]| {
        (0..3).any(|c| {
            let (x, y) = (a[c], b[c]);
            if x.is_finite() && y.is_finite() {
                differ(f64::from(x), f64::from(y), tolerance)
            } else {
                x.is_finite() != y.is_finite()
            }
        })
    };
    let (mut outside, mut defined) = (0usize, 0usize);
    for (g, group) in groups.iter().enumerate() {
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, group.scene.as_ref()) != Class::Defined {
                continue;
            }
            defined += 1;
            if differs(&run[g][i], &reference[g][i]) && !differs(&learner[g][i], &reference[g][i]) {
                outside += 1;
            }
        }
    }
    outside as f64 <= CANDIDATE_SHARE * defined as f64
}

/// The share of defined cases a candidate may change that the learner's output does not:
/// 1 in 100, ten times [`MISMATCH_SHARE`], because the other mistake may cancel this one
/// on a case (measured: unclamped diffuse terms cancel the point lights' missing
/// attenuation on 3 of the 2948 defined cases of `multiple_lights`).
pub const CANDIDATE_SHARE: f64 = 10.0 * MISMATCH_SHARE;

/// `base` with `a` then `b` applied, if the two compose: both orders succeed and give the
/// same text.
fn compose(model: &CaseModel, base: &str, a: &Mutant, b: &Mutant) -> Option<String> {
    let ab = b.rewrite(model.id, &a.rewrite(model.id, base).ok()?).ok()?;
    let ba = a.rewrite(model.id, &b.rewrite(model.id, base).ok()?).ok()?;
    (ab == ba).then_some(ab)
}

/// Whether every case of `learner` has the same colour (a starter's black, a debugging
/// constant): two mistakes that happen to darken everything (the spot's light direction
/// reversed, which puts every fragment outside the cone, and no ambient) reproduce it, but
/// naming them would be a guess, so a constant output is left to the isolation step.
fn constant(learner: &[Vec<[f32; 4]>]) -> bool {
    let mut cases = learner.iter().flatten();
    let Some(first) = cases.next() else { return true };
    cases.all(|c| c[..3] == first[..3])
}

/// The pairs of mutants of `base` that reproduce `learner` (see the module docs), best
/// first: one finding each with its agreement with the learner, the first mistake's with the second in
/// [`Finding::second`]. Also returns how many pairs ran.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn matching_pairs(
    ctx: &crate::gl::context::GlContext,
    model: &CaseModel,
    base: &str,
    groups: &[Group],
    learner: &[Vec<[f32; 4]>],
) -> Result<(Vec<(Agreement, Finding)>, usize), CheckError> {
    if constant(learner) {
        return Ok((Vec::new(), 0));
    }
    let reference = run_functions(ctx, model, base, groups)?;
    let tolerance = 2.0 * model.bound;
    // each candidate with the number of cases on which it already gives the learner's output
    let mut candidates = Vec::new();
    for (mutant, text) in sites::mutants(model.id, base) {
        let out = run_functions(ctx, model, &text, groups)?;
        let visible = !compare_outputs(model, groups, &out, &reference, tolerance).matches();
        if visible && changes_within(model, groups, &out, learner, &reference) {
            let a = compare_outputs(model, groups, &out, learner, tolerance);
            candidates.push((mutant, a.defined - a.mismatches));
        }
    }
    // the pairs that compose, those whose two mistakes already give more of the learner's
    // output first (a mistake the learner made gives it wherever the other one does not act)
    let mut pairs = Vec::new();
    for (i, (a, sa)) in candidates.iter().enumerate() {
        for (b, sb) in &candidates[i + 1..] {
            if a.mistake.id != b.mistake.id {
                pairs.push((sa + sb, *a, *b));
            }
        }
    }
    pairs.sort_by_key(|p| std::cmp::Reverse(p.0));
    let mut found: Vec<(Agreement, Finding)> = Vec::new();
    let mut ran = 0;
    for (_, a, b) in &pairs {
        let Some(text) = compose(model, base, a, b) else { continue };
        if ran == MAX_PAIRS || !found.is_empty() {
            break;
        }
        ran += 1;
        let out = run_functions(ctx, model, &text, groups)?;
        let vs_learner = compare_outputs(model, groups, &out, learner, tolerance);
        if vs_learner.matches() {
            let evidence = super::texts::tr_fill(
                super::texts::EVIDENCE,
                &[
                    &(vs_learner.defined - vs_learner.mismatches).to_string(),
                    &vs_learner.defined.to_string(),
                    &super::texts::measured(vs_learner.max_diff, 1),
                    &compare_outputs(model, groups, &out, &reference, tolerance).mismatches.to_string(),
                ],
            );
            let second = Finding::of_mutant(b, evidence.clone());
            let mut first = Finding::of_mutant(a, evidence);
            first.title = crate::blanks::fill(TWO_MISTAKES, &[&first.title, &second.title]);
            first.second = Some(Box::new(second));
            found.push((vs_learner, first));
        }
    }
    found.sort_by(|a, b| a.0.mismatches.cmp(&b.0.mismatches).then(a.0.max_diff.total_cmp(&b.0.max_diff)));
    Ok((found, ran))
}

#[cfg(test)]
mod tests {
    use super::constant;

    #[test]
    fn a_constant_output_is_told_from_a_varying_one() {
        let black = vec![vec![[0.0, 0.0, 0.0, 1.0]; 4]; 2];
        assert!(constant(&black));
        let mut lit = black.clone();
        lit[1][3] = [0.0, 0.1, 0.0, 1.0];
        assert!(!constant(&lit));
        // alpha is not compared: the checks read rgb only
        lit[1][3] = [0.0, 0.0, 0.0, 0.5];
        assert!(constant(&lit));
    }
}
