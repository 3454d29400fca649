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
//! step group that declares what another uses, as Blinn-Phong's `halfwayDir`) is not tried
//! ([`LeftOut::optional`]). The page's checker gets the same parts (`src/live/exercises.rs`).

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

/// One way to leave the exercise's change out: the function file, and what its finding
/// says (the templates and their arguments, so the command line and the page fill them
/// each in the reader's language).
#[derive(Debug, Clone)]
pub struct LeftOut {
    /// [`MISSING_ID`] or [`PARTIAL_ID`].
    pub id: &'static str,
    /// The function file without the change (or without one step group of it).
    pub functions: String,
    /// The title's template ([`MISSING_TITLE`] or [`PARTIAL_TITLE`]) and its arguments:
    /// the exercise's title (a msgid), then for a part its number and the number of parts.
    pub title: (&'static str, Vec<String>),
    /// The three hints' templates; the first is filled with the exercise's title, the second
    /// with its statement, the third with [`LeftOut::edits`] (each [`EDIT`], joined by `; `).
    pub hints: &'static [&'static str; 3],
    /// The edits left out, as `(the solution's text, the chapter's text)`.
    pub edits: Vec<(&'static str, &'static str)>,
    /// The steps that turn the solution into [`LeftOut::functions`] (the left-out edits
    /// reversed), for the tie-break by the learner's text.
    pub reversed: Vec<Vec<(&'static str, &'static str)>>,
    /// Whether it may not compile (a step group left out that another needs): such a
    /// candidate is skipped rather than reported.
    pub optional: bool,
}

impl LeftOut {
    /// Its finding, in the language of `tr`, for `exercise`.
    pub fn finding(&self, exercise: &Exercise, tr: &dyn Fn(&str) -> String) -> Finding {
        let fill = |template: &str, args: &[&str]| crate::blanks::fill(&tr(template), args);
        let mut title_args: Vec<String> = vec![tr(&self.title.1[0])];
        title_args.extend(self.title.1[1..].iter().cloned());
        let title_refs: Vec<&str> = title_args.iter().map(String::as_str).collect();
        let edits: Vec<String> = self.edits.iter().map(|(to, from)| fill(EDIT, &[to.trim(), from.trim()])).collect();
        Finding {
            id: self.id.into(),
            title: fill(self.title.0, &title_refs),
            evidence: String::new(),
            link: String::new(),
            hints: vec![
                fill(self.hints[0], &[&tr(exercise.title)]),
                fill(self.hints[1], &[&tr(exercise.statement)]),
                fill(self.hints[2], &[&edits.join("; ")]),
            ],
            site: None,
            second: None,
        }
    }
}

/// The ways to leave a variant exercise's change out: the chapter's function file (the
/// change not made), then, for a change of two or more step groups, the solution without
/// each group in turn. Empty for other checks, or when the steps no longer apply.
pub fn parts(exercise: &Exercise) -> Vec<LeftOut> {
    let Check::Variant { model, steps, .. } = exercise.check else { return Vec::new() };
    let Some(base) = model.shader().map(|s| s.functions()) else { return Vec::new() };
    if apply_steps(steps, base).is_err() {
        return Vec::new();
    }
    let edits = |groups: &[&[Edit]]| -> Vec<(&'static str, &'static str)> {
        groups
            .iter()
            .filter_map(|step| step.iter().find(|(from, _)| base.contains(from)))
            .map(|&(f, t)| (t, f))
            .collect()
    };
    let reversed = |groups: &[&[Edit]]| -> Vec<Vec<(&'static str, &'static str)>> {
        groups.iter().map(|g| g.iter().map(|&(from, to)| (to, from)).collect()).collect()
    };
    let mut out = vec![LeftOut {
        id: MISSING_ID,
        functions: base.to_string(),
        title: (MISSING_TITLE, vec![exercise.title.to_string()]),
        hints: &MISSING_HINTS,
        edits: edits(steps),
        reversed: reversed(steps),
        optional: false,
    }];
    if steps.len() >= 2 {
        for k in 0..steps.len() {
            let others: Vec<&[Edit]> = steps.iter().enumerate().filter(|(j, _)| *j != k).map(|(_, s)| *s).collect();
            let Ok(functions) = apply_steps(&others, base) else { continue };
            out.push(LeftOut {
                id: PARTIAL_ID,
                functions,
                title: (PARTIAL_TITLE, vec![exercise.title.to_string(), (k + 1).to_string(), steps.len().to_string()]),
                hints: &PARTIAL_HINTS,
                edits: edits(&steps[k..=k]),
                reversed: reversed(&steps[k..=k]),
                optional: true,
            });
        }
    }
    out
}

/// The candidates of the diagnosis that leave `exercise`'s change out ([`parts`]), their
/// findings in the language of `tr`.
pub fn left_out(exercise: &Exercise, tr: &dyn Fn(&str) -> String) -> Vec<Candidate> {
    parts(exercise)
        .into_iter()
        .map(|p| Candidate { finding: p.finding(exercise, tr), functions: p.functions, edits: p.reversed })
        .collect()
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
