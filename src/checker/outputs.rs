//! Running the model's function files and their mutants on a check's cases, and comparing
//! two runs: the pieces the diagnosis ([`super::diagnose`]) and the search for two mistakes
//! at once ([`super::two_mistakes`]) share, below both.

use super::check::CheckError;
use super::sites::{self, Mutant};
use crate::gl::batch::{Batch, Outputs};
use crate::gl::context::GlContext;
use crate::oracle::cases::{CaseModel, Class, Group};

/// The share of defined cases on which a matching mutant may still differ from the
/// learner: 1 in 1000. A mutant with a discontinuity (`spot-hard-edge`'s `θ > cutOff`, the
/// NaN boundary of `specular-no-clamp`) and a learner written differently may take
/// different sides of it when a case lies within rounding of it; such cases are far rarer
/// than 1 in 1000 (the case ranges put a few in 10^5 within 1e-5 of a branch), while a
/// different mistake differs on a large share.
pub const MISMATCH_SHARE: f64 = 1e-3;

/// Whether two finite channel values differ beyond `tolerance` taken at their magnitude:
///
/// ```text
/// |x − y| > tolerance · max(1, |x|, |y|)
/// ```
///
/// The models' bounds are rounding bounds for outputs of the order of one (a colour before
/// clamping, [`crate::oracle::cases::bounds`]). Rounding errors are relative, so for a larger
/// output the tolerance grows with it: a shader that leaves the normal long or drops a
/// clamp reaches 10³⁷ on some cases, where two writings of the same mistake differ by their
/// rounding alone (measured: a learner's `normal-not-normalized` on `multiple_lights`
/// differed from the mutant by 3·10²⁹ on 80 of 1964 cases, all above 10³⁶).
#[must_use]
pub fn differ(x: f64, y: f64, tolerance: f64) -> bool {
    (x - y).abs() > tolerance * x.abs().max(y.abs()).max(1.0)
}

/// Whether two outputs of one case differ (rgb): a channel beyond `tolerance` at the
/// values' magnitude ([`differ`]), or finite on one side only (two non-finite values
/// agree). [`compare_outputs`] counts the cases where this holds.
#[must_use]
pub fn case_differs(a: &[f32; 4], b: &[f32; 4], tolerance: f64) -> bool {
    (0..3).any(|c| {
        let (x, y) = (f64::from(a[c]), f64::from(b[c]));
        match (x.is_finite(), y.is_finite()) {
            (true, true) => differ(x, y, tolerance),
            (false, false) => false,
            _ => true,
        }
    })
}

/// How two outputs compare on the defined cases.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Agreement {
    /// Defined cases compared.
    pub defined: usize,
    /// Cases beyond the tolerance (a finite value against a non-finite one counts).
    pub mismatches: usize,
    /// The largest difference: infinite when a finite value meets a non-finite one (a NaN
    /// against a colour differs by more than any bound, as in the oracle's
    /// [`crate::oracle::ErrorSummary`]), so it never reads 0 beside failing cases.
    pub max_diff: f64,
}

impl Agreement {
    /// Whether the two agree up to [`MISMATCH_SHARE`].
    pub fn matches(&self) -> bool {
        self.defined > 0 && self.mismatches as f64 <= MISMATCH_SHARE * self.defined as f64
    }
}

/// Compares two GL outputs on `groups`' defined cases, channel by channel (rgb), within
/// `tolerance` at the values' magnitude ([`differ`]). Two non-finite values agree (both are undefined results of the same
/// operation); a finite against a non-finite one does not.
pub fn compare_outputs(
    model: &CaseModel,
    groups: &[Group],
    a: &[Vec<[f32; 4]>],
    b: &[Vec<[f32; 4]>],
    tolerance: f64,
) -> Agreement {
    let mut agreement = Agreement::default();
    for (g, group) in groups.iter().enumerate() {
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, group.scene.as_ref()) != Class::Defined {
                continue;
            }
            agreement.defined += 1;
            let mut bad = false;
            for c in 0..3 {
                let (x, y) = (a[g][i][c] as f64, b[g][i][c] as f64);
                match (x.is_finite(), y.is_finite()) {
                    (true, true) => {
                        let d = (x - y).abs();
                        agreement.max_diff = agreement.max_diff.max(d);
                        bad |= differ(x, y, tolerance);
                    }
                    (false, false) => {}
                    _ => {
                        agreement.max_diff = f64::INFINITY;
                        bad = true;
                    }
                }
            }
            agreement.mismatches += usize::from(bad);
        }
    }
    agreement
}

/// Runs a batch body of `model` (a function file and the model's harness) on `groups`:
/// output 0 of every case, group by group, with each group's uniforms set.
///
/// Errors: [`CheckError::Gl`] if the body does not compile or a draw fails.
pub fn run_body(
    ctx: &GlContext,
    model: &CaseModel,
    body: &str,
    groups: &[Group],
) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
    let n_outputs = model.shader.map_or(1, |s| s.outputs().len());
    let batch = Batch::new(ctx, body, model.n_inputs, n_outputs)?;
    run_batch(&batch, model, groups)
}

fn run_batch(batch: &Batch<'_>, model: &CaseModel, groups: &[Group]) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
    let mut out = Vec::with_capacity(groups.len());
    for group in groups {
        for (name, value) in &group.uniforms {
            batch.set_uniform(name, *value)?;
        }
        let mut o = batch.run(&group.columns(model.n_inputs))?;
        out.push(o.swap_remove(0));
    }
    Ok(out)
}

/// Every mutant of `base` (a function file of `model`: its own, or an exercise's variant)
/// on `groups`: `(mutant, outputs)`, catalogue order, each mistake everywhere and then in
/// each of its sites ([`sites::mutants`]). Mistakes whose edits do not occur in `base` are
/// left out.
///
/// Errors: [`CheckError::Gl`] if a mutant does not compile (a catalogue bug) or a draw fails.
pub fn run_mutants(
    ctx: &GlContext,
    model: &CaseModel,
    base: &str,
    groups: &[Group],
) -> Result<Vec<(Mutant, Outputs)>, CheckError> {
    let Some(shader) = model.shader else { return Ok(Vec::new()) };
    let mut out = Vec::new();
    for (mutant, functions) in sites::mutants(model.id, base) {
        let body = format!("{functions}\n{}", shader.harness());
        out.push((mutant, run_body(ctx, model, &body, groups)?));
    }
    Ok(out)
}

/// A function file of `model` (its harness appended) on `groups` (llvmpipe).
///
/// Errors: [`CheckError::Usage`] for a model without a function file; [`CheckError::Gl`].
pub fn run_functions(
    ctx: &GlContext,
    model: &CaseModel,
    functions: &str,
    groups: &[Group],
) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
    let shader = model.shader.ok_or_else(|| CheckError::Usage(format!("model {} has no function file", model.id)))?;
    run_body(ctx, model, &format!("{functions}\n{}", shader.harness()), groups)
}
