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
    /// The worst cases (at most 3), as printable blocks.
    pub counterexamples: Vec<String>,
    /// Notes: quantities fixed to the chapter's value, inactive uniforms.
    pub notes: Vec<String>,
}

impl CheckReport {
    /// Whether the shader agrees with the model on every defined case.
    pub fn agrees(&self) -> bool {
        self.failing == 0 && self.defined > 0
    }

    /// The report as text: verdict, statistics, notes, counterexamples.
    pub fn format(&self) -> String {
        let mut s = String::new();
        let verdict = if self.agrees() { "AGREES" } else { "DISAGREES" };
        let _ = writeln!(s, "verdict: {verdict} with model {}", self.model);
        let _ = writeln!(
            s,
            "cases: {} run, {} defined, {} beyond the bound {:.2e}",
            self.cases, self.defined, self.failing, self.bound
        );
        let v = &self.vs_f64;
        let _ = writeln!(
            s,
            "error vs the f64 reference: max {:.3e} ({:.1} ulps), mean {:.3e} ({:.2} ulps)",
            v.max_abs, v.max_ulps, v.mean_abs, v.mean_ulps
        );
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        for (i, c) in self.counterexamples.iter().enumerate() {
            let _ = writeln!(s, "\ncounterexample {}:\n{c}", i + 1);
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

fn describe_case(
    model: &CaseModel,
    leaves: &[Leaf],
    row: &[[f32; 4]],
    want: &[f64],
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
    let _ = writeln!(s, "  expected (f64) = [{:.7}, {:.7}, {:.7}]", want[0], want[1], want[2]);
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
            describe_case(model, leaves, row, &want, &outputs[g][i], g)
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
