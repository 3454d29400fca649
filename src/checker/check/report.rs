//! The comparison of a shader's results with the `f64` reference, and the report.

use std::fmt::Write as _;

use super::mapping::Leaf;
use crate::checker::texts;
use crate::gl::layout::{QType, Quantity, Slot};
use crate::gl::model_id::ModelId;
use crate::oracle::cases::{CaseModel, Channels, Class, Group};
use crate::oracle::{ErrorAcc, ErrorSummary};

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
    /// At most 3 failing cases as printable blocks in the shader's own names (`lightPos`,
    /// `light.position`): the worst case with typical inputs first ([`typical`]), then the
    /// worst case of all, then the next worst ([`teaching_order`]).
    pub counterexamples: Vec<String>,
    /// Notes: quantities fixed to the chapter's value, inactive uniforms.
    pub notes: Vec<String>,
}

/// The report's lines (English msgids of `po/messages.pot`, in the command line's language
/// through [`crate::checker::diagnose`]'s lookup).
pub const REPORT_AGREES: &str = "verdict: AGREES with model {}";
/// See [`REPORT_AGREES`].
pub const REPORT_DISAGREES: &str = "verdict: DISAGREES with model {}";
/// See [`REPORT_AGREES`].
pub const REPORT_CASES: &str = "cases: {} run, {} defined, {} beyond the bound {}";
/// See [`REPORT_AGREES`].
pub const REPORT_ERROR: &str = "error vs the f64 reference: max {} ({} ulps), mean {} ({} ulps)";
/// See [`REPORT_AGREES`].
pub const REPORT_COUNTEREXAMPLE: &str = "counterexample {}:";

use crate::checker::texts::{localize_counterexample, number, tr_fill, NOTE};

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
                    &texts::measured(self.bound, 2)
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
                    &texts::measured(v.max_abs, 3),
                    &number(&texts::shown(v.max_ulps, 1, false)),
                    &texts::measured(v.mean_abs, 3),
                    &number(&texts::shown(v.mean_ulps, 2, false))
                ]
            )
        );
        for n in &self.notes {
            let _ = writeln!(s, "{}", tr_fill(NOTE, &[n]));
        }
        for (i, c) in self.counterexamples.iter().enumerate() {
            let c = localize_counterexample(c);
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
    let failing_cases: Vec<(usize, usize)> =
        worst.iter().take_while(|w| w.0 > model.bound).map(|&(_, g, i)| (g, i)).collect();
    let counterexamples = teaching_order(&failing_cases, |&(g, i)| typical(model, &groups[g].rows[i]))
        .into_iter()
        .take(3)
        .map(|(g, i)| {
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

/// The shininess a typical case has at least: the classic materials table's smallest,
/// rubber's 0.078125 × 128 = 10, rounded down (chapter 3); LearnOpenGL's scenes use 32.
pub const TYPICAL_SHININESS_MIN: f32 = 8.0;
/// The shininess a typical case has at most: the table's largest, chrome's 0.6 × 128 =
/// 76.8, rounded up to the next power of two.
pub const TYPICAL_SHININESS_MAX: f32 = 128.0;

/// Whether `row` is near the chapter's values, so that a counterexample on it teaches:
/// every shininess within [[`TYPICAL_SHININESS_MIN`], [`TYPICAL_SHININESS_MAX`]] (at 0 the
/// highlight covers everything and hides most mistakes), and the light in front of the
/// surface (N·L > 0 for the model's `Normal` and its light position or direction, when it
/// has them). A model without those quantities is typical on them.
#[must_use]
pub fn typical(model: &CaseModel, row: &[[f32; 4]]) -> bool {
    let find = |name: &str| model.quantities.iter().find(|q| q.name == name);
    let float = |q: &Quantity| match q.slot {
        Slot::Case { input, offset } => Some(row[input][offset]),
        _ => None,
    };
    let vec3 = |name: &str| match find(name)?.slot {
        Slot::Case { input, .. } => Some(glam::Vec3::new(row[input][0], row[input][1], row[input][2])),
        _ => None,
    };
    let shininess_typical = model
        .quantities
        .iter()
        .filter(|q| q.name.ends_with("shininess") && q.ty == QType::Float)
        .filter_map(float)
        .all(|s| (TYPICAL_SHININESS_MIN..=TYPICAL_SHININESS_MAX).contains(&s));
    let to_light = match (vec3("lightPos").or_else(|| vec3("light.position")), vec3("FragPos"), vec3("light.direction"))
    {
        (Some(light), Some(frag), _) => Some(light - frag),
        (None, _, Some(direction)) => Some(-direction),
        _ => None,
    };
    let in_front = match (vec3("Normal"), to_light) {
        (Some(n), Some(l)) => n.dot(l) > 0.0,
        _ => true,
    };
    shininess_typical && in_front
}

/// `failing` (distinct cases, worst first) in the order a learner should see them: the
/// worst case for which `is_typical` holds, then the worst case of all, then the rest, each
/// once. Linear in the number of cases (a shader that fails everywhere fails 10⁵ of them).
pub fn teaching_order<T: Copy + PartialEq>(failing: &[T], is_typical: impl Fn(&T) -> bool) -> Vec<T> {
    let first = failing.iter().find(|c| is_typical(c)).copied();
    let mut order: Vec<T> = Vec::with_capacity(failing.len());
    order.extend(first);
    order.extend(failing.iter().copied().filter(|c| first != Some(*c)));
    order
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_worst_typical_case_comes_first_then_the_raw_worst() {
        // cases 0..5 worst first; 2 and 4 typical
        let order = teaching_order(&[0, 1, 2, 3, 4], |c| *c == 2 || *c == 4);
        assert_eq!(order, vec![2, 0, 1, 3, 4]);
        // no typical case: the raw order
        assert_eq!(teaching_order(&[0, 1, 2], |_| false), vec![0, 1, 2]);
        // the worst is typical: the raw order
        assert_eq!(teaching_order(&[0, 1, 2], |c| *c == 0), vec![0, 1, 2]);
    }

    #[test]
    fn a_case_is_typical_with_chapter_shininess_and_the_light_in_front() {
        let model = ModelId::BasicLighting.case_model();
        let set = |row: &mut Vec<[f32; 4]>, name: &str, v: [f32; 3]| {
            let q = model.quantities.iter().find(|q| q.name == name).expect("a basic_lighting quantity");
            if let Slot::Case { input, offset } = q.slot {
                match q.ty {
                    QType::Float => row[input][offset] = v[0],
                    _ => row[input][..3].copy_from_slice(&v),
                }
            }
        };
        let mut row = vec![[0.0f32; 4]; model.n_inputs];
        set(&mut row, "FragPos", [0.0, 0.0, 0.0]);
        set(&mut row, "Normal", [0.0, 0.0, 1.0]);
        set(&mut row, "lightPos", [1.2, 1.0, 2.0]);
        set(&mut row, "shininess", [32.0; 3]);
        assert!(typical(model, &row));
        set(&mut row, "shininess", [0.0; 3]);
        assert!(!typical(model, &row), "shininess 0 is not typical");
        set(&mut row, "shininess", [32.0; 3]);
        set(&mut row, "lightPos", [1.2, 1.0, -2.0]);
        assert!(!typical(model, &row), "a light behind the surface is not typical");
    }
}
