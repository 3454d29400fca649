//! "The exercise's change is not made": the findings of a variant exercise (the model's
//! shader with the exercise's edits, [`super::Check::Variant`]) when the learner's shader
//! is the chapter's, or makes only part of the change.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | change | the exercise's edit steps, applied to the model's function file |
//! | step group | one entry of the steps: one edit, with its alternatives |
//! | left out | the reference solution without the change (the chapter's shader), or, for a change of several step groups, without one of them |
//!
//! Each left-out shader is a candidate of the diagnosis ([`crate::checker::diagnose::Candidate`]),
//! tried beside the catalogue's mistakes. Its title and hints are written once for every
//! exercise, from the exercise's title and statement and the edits themselves, so a new
//! variant exercise needs no text of its own. A left-out shader that does not compile (a
//! step group that declares what another uses, as Blinn-Phong's `halfwayDir`) is not tried.

use super::{Check, Exercise};
use crate::checker::diagnose::Candidate;
use crate::checker::mistakes::{apply_steps, Edit};
use crate::checker::verdict::Finding;

/// The id of the finding "your shader is the chapter's shader".
pub const MISSING_ID: &str = "exercise-change-missing";
/// The id of the finding "one step group of the change is not made".
pub const PARTIAL_ID: &str = "exercise-change-partial";

/// The title of [`MISSING_ID`] (an msgid; `{}`: the exercise's title, in the reader's language).
pub const MISSING_TITLE: &str = "the exercise's change is not made: your shader gives the chapter's output, not “{}”";
/// The title of [`PARTIAL_ID`] (`{}`: the exercise's title, the edit's number, the number of edits).
pub const PARTIAL_TITLE: &str = "part of the exercise's change is not made: “{}” without its edit {} of {}";
/// The three hints of [`MISSING_ID`]: where to look (`{}`: the exercise's title), the idea
/// (`{}`: its statement), the fix (`{}`: the edits, [`EDIT`] joined by `; `).
pub const MISSING_HINTS: [&str; 3] = [
    "Your output is the one of the chapter's shader: look for the line that the exercise “{}” asks you to change.",
    "Read the exercise again: {}",
    "The reference solution writes {}.",
];
/// The three hints of [`PARTIAL_ID`], as [`MISSING_HINTS`].
pub const PARTIAL_HINTS: [&str; 3] = [
    "Your shader makes part of the change that the exercise “{}” asks for: one line is still as the chapter writes it.",
    "Read the exercise again: {}",
    "The reference solution writes {}.",
];
/// One edit in a hint (`{}`: the reference solution's text, then the chapter's).
pub const EDIT: &str = "`{}` where the chapter writes `{}`";

/// Every msgid of this module, for the translation template.
pub const TEXTS: [&str; 9] = [
    MISSING_TITLE,
    PARTIAL_TITLE,
    MISSING_HINTS[0],
    MISSING_HINTS[1],
    MISSING_HINTS[2],
    PARTIAL_HINTS[0],
    PARTIAL_HINTS[1],
    PARTIAL_HINTS[2],
    EDIT,
];

/// The edits of `steps` that apply to `functions`, as a hint shows them (in the reader's
/// language through `tr`).
fn edits_text(steps: &[&[Edit]], functions: &str, tr: &dyn Fn(&str) -> String) -> String {
    steps
        .iter()
        .filter_map(|step| step.iter().find(|(from, _)| functions.contains(from)))
        .map(|(from, to)| crate::blanks::fill(&tr(EDIT), &[to.trim(), from.trim()]))
        .collect::<Vec<_>>()
        .join("; ")
}

/// The candidates of a variant exercise that leave its change out: the chapter's function
/// file (the change not made), then, for a change of two or more step groups, the
/// solution without each group in turn. Empty for other checks, or when the steps no
/// longer apply. Titles and hints are in the reader's language through `tr`.
pub fn left_out(exercise: &Exercise, tr: &dyn Fn(&str) -> String) -> Vec<Candidate> {
    let Check::Variant { model, steps, .. } = exercise.check else { return Vec::new() };
    let Some(base) = model.shader().map(|s| s.functions()) else { return Vec::new() };
    if apply_steps(steps, base).is_err() {
        return Vec::new();
    }
    let title = tr(exercise.title);
    let statement = tr(exercise.statement);
    let reversed = |groups: &[&[Edit]]| -> Vec<Vec<(&'static str, &'static str)>> {
        groups.iter().map(|g| g.iter().map(|&(from, to)| (to, from)).collect()).collect()
    };
    let finding = |id: &str, title: String, hints: &[&str; 3], edits: String| Finding {
        id: id.into(),
        title,
        evidence: String::new(),
        link: String::new(),
        hints: vec![
            crate::blanks::fill(&tr(hints[0]), &[&tr(exercise.title)]),
            crate::blanks::fill(&tr(hints[1]), &[&statement]),
            crate::blanks::fill(&tr(hints[2]), &[&edits]),
        ],
        site: None,
        second: None,
    };
    let mut out = vec![Candidate {
        functions: base.to_string(),
        finding: finding(
            MISSING_ID,
            crate::blanks::fill(&tr(MISSING_TITLE), &[&title]),
            &MISSING_HINTS,
            edits_text(steps, base, tr),
        ),
        edits: reversed(steps),
    }];
    if steps.len() >= 2 {
        for k in 0..steps.len() {
            let others: Vec<&[Edit]> = steps.iter().enumerate().filter(|(j, _)| *j != k).map(|(_, s)| *s).collect();
            let Ok(functions) = apply_steps(&others, base) else { continue };
            let shown = [(k + 1).to_string(), steps.len().to_string()];
            out.push(Candidate {
                functions,
                finding: finding(
                    PARTIAL_ID,
                    crate::blanks::fill(&tr(PARTIAL_TITLE), &[&title, &shown[0], &shown[1]]),
                    &PARTIAL_HINTS,
                    edits_text(&steps[k..=k], base, tr),
                ),
                edits: reversed(&steps[k..=k]),
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn english(s: &str) -> String {
        s.to_owned()
    }

    /// Every variant exercise gets the chapter's shader as a candidate, named from its own
    /// title, with the edit in its third hint; a change of several step groups gets one
    /// candidate more per group.
    #[test]
    fn every_variant_exercise_has_its_change_left_out() {
        let mut seen = 0;
        for e in super::super::EXERCISES {
            let Check::Variant { model, steps, .. } = e.check else {
                assert!(left_out(e, &english).is_empty(), "{}", e.id);
                continue;
            };
            seen += 1;
            let candidates = left_out(e, &english);
            let expected = if steps.len() >= 2 { 1 + steps.len() } else { 1 };
            assert_eq!(candidates.len(), expected, "{}", e.id);
            let chapter = model.shader().unwrap().functions();
            assert_eq!(candidates[0].functions, chapter, "{}", e.id);
            assert_eq!(candidates[0].finding.id, MISSING_ID);
            assert!(candidates[0].finding.title.contains(e.title), "{}", candidates[0].finding.title);
            assert_eq!(candidates[0].finding.hints.len(), 3);
            let first_edit = steps[0].iter().find(|(from, _)| chapter.contains(from)).unwrap();
            assert!(candidates[0].finding.hints[2].contains(first_edit.1.trim()), "{:?}", candidates[0].finding.hints);
            for c in &candidates[1..] {
                assert_eq!(c.finding.id, PARTIAL_ID);
                assert_ne!(c.functions, chapter);
                assert_ne!(Some(c.functions.clone()), e.functions(), "{}", e.id);
            }
        }
        assert!(seen >= 2, "{seen} variant exercises");
    }
}
