//! What a check decides, shared by the diagnosis ([`super::diagnose`]) and its isolation
//! step ([`super::isolation`]): the rule on one case against the `f64` reference, the
//! reference's values, and one entry of a diagnosis.

use crate::oracle::cases::{CaseModel, Class, Group};

/// The English sentence of a pair (an msgid): the two mistakes' titles.
pub const TWO_MISTAKES: &str = "two mistakes: {} and {}";

/// One entry of a diagnosis.
#[derive(Debug, Clone, PartialEq)]
pub struct Finding {
    /// The catalogue id, or `isolated` for the result of switching terms and splitting cases.
    pub id: String,
    /// The mistake's title, or the isolation's sentence.
    pub title: String,
    /// What was measured.
    pub evidence: String,
    /// Where the book explains it (relative to the book's root); empty if nowhere.
    pub link: String,
    /// The isolation step's three hints, in the command line's language; empty for a
    /// catalogue mistake, whose hints are [`super::hints::hints`] of its id.
    pub hints: Vec<String>,
    /// Where a catalogue mistake is, when it is in one function only ([`super::sites`]);
    /// `title` then ends with the site's phrase.
    pub site: Option<super::sites::Site>,
    /// The second mistake when two reproduce the output together
    /// ([`super::two_mistakes`]); `title` then names both ([`TWO_MISTAKES`]).
    pub second: Option<Box<Finding>>,
}

impl Finding {
    /// The finding of catalogue mistake `mistake`, with what was measured (its hints are
    /// the catalogue's, looked up by id).
    #[must_use]
    pub fn of_mistake(mistake: &super::mistakes::Mistake, evidence: String) -> Finding {
        Finding {
            id: mistake.id.into(),
            title: mistake.title.into(),
            evidence,
            link: mistake.link.into(),
            hints: Vec::new(),
            site: None,
            second: None,
        }
    }

    /// The finding of `mutant` (a mistake, everywhere or in one site): its English title
    /// ends with the site's phrase ([`super::sites::Mutant::title`]).
    #[must_use]
    pub fn of_mutant(mutant: &super::sites::Mutant, evidence: String) -> Finding {
        Finding { title: mutant.title(), site: mutant.site, ..Finding::of_mistake(mutant.mistake, evidence) }
    }

    /// The title in the command line's language: the mistake's title, then the site's
    /// phrase, each translated (`tr` looks a msgid up).
    #[must_use]
    pub fn shown_title(&self, tr: impl Fn(&str) -> String) -> String {
        self.shown_title_dyn(&tr)
    }

    fn shown_title_dyn(&self, tr: &dyn Fn(&str) -> String) -> String {
        let mistake = super::mistakes::Mistake::by_id(&self.id).map_or(self.title.as_str(), |m| m.title);
        let one = match self.site {
            Some(site) => format!("{}, {}", tr(mistake), tr(site.phrase())),
            None if self.second.is_some() => tr(mistake),
            None => tr(&self.title),
        };
        match &self.second {
            Some(b) => crate::blanks::fill(&tr(TWO_MISTAKES), &[&one, &b.shown_title_dyn(tr)]),
            None => one,
        }
    }

    /// `id`, `id@site`, or for two mistakes both joined by ` + ` (as the learner corpus's
    /// `expect:` lines write them).
    #[must_use]
    pub fn label(&self) -> String {
        let one = match self.site {
            Some(s) => format!("{}@{}", self.id, s.name()),
            None => self.id.clone(),
        };
        match &self.second {
            Some(b) => format!("{one} + {}", b.label()),
            None => one,
        }
    }
}

/// The verdict's rule on one case: a shader's output `got` fails when some channel (rgb)
/// is more than `bound` from the `f64` reference's `want`, or is not a number (NaN, or an
/// infinity, whose difference is infinite). `lightlab check-shader`, `lightlab exercise
/// check` and the page (which reads `want` and `bound` from [`expected_values`] and the
/// exported model) all decide by this rule.
#[must_use]
pub fn case_fails(got: &[f32; 4], want: &[f64; 3], bound: f64) -> bool {
    (0..3).any(|c| {
        let d = (f64::from(got[c]) - want[c]).abs();
        d.is_nan() || d > bound
    })
}

/// The `f64` reference's rgb on every case of `groups`, group by group, `None` where the
/// model is not defined (those cases are left out of the verdict).
#[must_use]
pub fn expected_values(model: &CaseModel, groups: &[Group]) -> Vec<Vec<Option<[f64; 3]>>> {
    groups
        .iter()
        .map(|group| {
            let scene = group.scene.as_ref();
            group
                .rows
                .iter()
                .map(|row| {
                    (model.classify(row, scene) == Class::Defined).then(|| {
                        let want = model.eval_f64(row, scene);
                        [want[0], want[1], want[2]]
                    })
                })
                .collect()
        })
        .collect()
}
