//! The comparison of a shader's results with the `f64` reference, and the report.

use std::fmt::Write as _;

use super::mapping::Leaf;
use crate::gl::cases::{CaseModel, Channels, Class, Group};
use crate::gl::layout::{QType, Quantity, Slot};
use crate::gl::model_id::ModelId;
use crate::gl::oracle::{ErrorAcc, ErrorSummary};

/// The result of a check.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// The model.
    pub model: ModelId,
    /// Cases run.
    pub cases: usize,
    /// Cases where the model is defined (the others are excluded from the verdict).
    pub defined: usize,
    /// The bound a correct shader stays within.
    pub bound: f64,
    /// The shader against the `f64` reference, defined cases.
    pub vs_f64: ErrorSummary,
    /// Cases beyond the bound.
    pub failing: usize,
    /// The worst cases (at most 3), the largest error first, as printable blocks in the
    /// shader's own names (`lightPos`, `light.position`).
    pub counterexamples: Vec<String>,
    /// Notes: quantities fixed to the chapter's value, inactive uniforms.
    pub notes: Vec<String>,
}

/// The report's lines (English msgids of `po/messages.pot`, in the command line's language
/// through [`crate::gl::diagnose`]'s lookup).
pub const REPORT_AGREES: &str = "verdict: AGREES with model {}";
/// See [`REPORT_AGREES`].
pub const REPORT_DISAGREES: &str = "verdict: DISAGREES with model {}";
/// See [`REPORT_AGREES`].
pub const REPORT_CASES: &str = "cases: {} run, {} defined, {} beyond the bound {}";
/// See [`REPORT_AGREES`].
pub const REPORT_ERROR: &str = "error vs the f64 reference: max {} ({} ulps), mean {} ({} ulps)";
/// See [`REPORT_AGREES`].
pub const REPORT_COUNTEREXAMPLE: &str = "counterexample {}:";

use crate::gl::diagnose::tr_fill;

impl CheckReport {
    /// Whether the shader agrees with the model on every defined case.
    pub fn agrees(&self) -> bool {
        self.failing == 0 && self.defined > 0
    }

    /// The report as text: verdict, statistics, notes, counterexamples.
    pub fn format(&self) -> String {
        let mut s = String::new();
        let model = self.model.name();
        let line = if self.agrees() { REPORT_AGREES } else { REPORT_DISAGREES };
        let _ = writeln!(s, "{}", tr_fill(line, &[model]));
        let _ = writeln!(
            s,
            "{}",
            tr_fill(
                REPORT_CASES,
                &[
                    &self.cases.to_string(),
                    &self.defined.to_string(),
                    &self.failing.to_string(),
                    &format!("{:.2e}", self.bound)
                ]
            )
        );
        let v = &self.vs_f64;
        let _ = writeln!(
            s,
            "{}",
            tr_fill(
                REPORT_ERROR,
                &[
                    &format!("{:.3e}", v.max_abs),
                    &format!("{:.1}", v.max_ulps),
                    &format!("{:.3e}", v.mean_abs),
                    &format!("{:.2}", v.mean_ulps)
                ]
            )
        );
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        for (i, c) in self.counterexamples.iter().enumerate() {
            let _ = writeln!(s, "\n{}\n{c}", tr_fill(REPORT_COUNTEREXAMPLE, &[&(i + 1).to_string()]));
        }
        s
    }
}

fn quantity_value(q: &Quantity, row: &[[f32; 4]]) -> String {
    match (q.slot, q.ty) {
        (Slot::Case { input, offset }, QType::Float) => format!("{:?}", row[input][offset]),
        (Slot::Case { input, .. }, QType::Vec3) => {
            format!("({:?}, {:?}, {:?})", row[input][0], row[input][1], row[input][2])
        }
        (Slot::Case { input, .. }, QType::Texel) => format!("texel {:?}", row[input]),
        (Slot::Case { input, .. }, QType::Mat4) => {
            format!("columns {:?} {:?} {:?} {:?}", row[input], row[input + 1], row[input + 2], row[input + 3])
        }
        _ => "-".into(),
    }
}

/// What the reference of a counterexample is, on its `expected` line.
pub const EXPECTED_F64: &str = "f64";

/// One case as a counterexample block: each input under the name the shader declares it
/// with (`leaf.user`: `lightPos`, `light.position`), then the quantities it does not
/// declare, then `expected (<expected>)` and `got (llvmpipe)`.
pub(super) fn describe_case(
    model: &CaseModel,
    leaves: &[Leaf],
    row: &[[f32; 4]],
    (want, expected): (&[f64], &str),
    got: &[f32],
    group: usize,
) -> String {
    let mut s = String::new();
    for leaf in leaves {
        if let Some(q) = &leaf.quantity {
            if q.slot != Slot::Unused {
                let _ = writeln!(s, "  {} = {}", leaf.user, quantity_value(q, row));
            }
        }
    }
    for q in model.quantities {
        let declared = leaves.iter().any(|l| l.quantity.is_some_and(|lq| lq.name == q.name));
        if !declared && matches!(q.slot, Slot::Case { .. }) {
            let _ = writeln!(s, "  (not declared) {} = {}", q.name, quantity_value(q, row));
        }
    }
    if model.layout.has_groups() {
        let _ = writeln!(s, "  scene: group {group} (0 = the chapter's lights)");
    }
    let _ = writeln!(s, "  expected ({expected}) = [{:.7}, {:.7}, {:.7}]", want[0], want[1], want[2]);
    let _ = write!(s, "  got (llvmpipe) = [{:.7}, {:.7}, {:.7}]", got[0], got[1], got[2]);
    s
}

/// Compares the shader's colour (`outputs[g][i]`) with the reference on every defined case.
pub(super) fn compare(
    model: &'static CaseModel,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
    leaves: &[Leaf],
    notes: Vec<String>,
) -> CheckReport {
    let mut acc = ErrorAcc::default();
    let mut failing = 0;
    let mut worst: Vec<(f64, usize, usize)> = Vec::new(); // (error, group, row)
    let mut index = 0;
    for (g, group) in groups.iter().enumerate() {
        let scene = group.scene.as_ref();
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, scene) != Class::Defined {
                continue;
            }
            let want: Channels<f64> = model.eval_f64(row, scene);
            let got: Vec<f64> = outputs[g][i][..3].iter().map(|&x| x as f64).collect();
            let abs = acc.add(index, &got, &want[..3]);
            index += 1;
            if abs > model.bound {
                failing += 1;
            }
            worst.push((abs, g, i));
        }
    }
    let stats = acc.finish();
    worst.sort_by(|a, b| b.0.total_cmp(&a.0));
    let counterexamples = worst
        .iter()
        .take(3)
        .filter(|w| w.0 > model.bound)
        .map(|&(_, g, i)| {
            let row = &groups[g].rows[i];
            let want = model.eval_f64(row, groups[g].scene.as_ref());
            describe_case(model, leaves, row, (&want, EXPECTED_F64), &outputs[g][i], g)
        })
        .collect();
    CheckReport {
        model: model.id,
        cases: groups.iter().map(|g| g.rows.len()).sum(),
        defined: stats.count,
        bound: model.bound,
        vs_f64: stats,
        failing,
        counterexamples,
        notes,
    }
}
