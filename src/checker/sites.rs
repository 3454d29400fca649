//! Mistakes in one place: a catalogue mistake applied inside one function of the verified
//! shader only.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | site | the function a mistake lands in: in `multiple_lights`, `CalcDirLight` (the directional light), `CalcPointLight` (every point light) or `CalcSpotLight` (the spotlight) |
//! | mutant | a mistake with an optional site: the whole function file rewritten (no site), or one function's body only |
//!
//! A per-site mutant is generated from the verified text, as the whole-file mutants are
//! ([`crate::checker::mistakes`]): the site's function body is found by matching braces in the
//! text (comments blanked, [`crate::checker::check::glsl::blank_comments`]) and the mistake's
//! steps are applied to that body only ([`rewrite_at`]). The steps of a mistake are either
//! one change made in every function (all of them match in the site), or one edit per site
//! (each step matches in exactly one site, as `clamp-per-light`'s three `return`s): then the
//! site's own steps are applied. Only a mistake that matches in more than one site gets
//! per-site mutants (one per such site): a mistake that matches in one site only is its
//! whole-file mutant already.

use std::ops::Range;

use super::mistakes::{self, Equivalence, Mistake, MutateError, EQUIVALENT};
use crate::gl::model_id::ModelId;

/// The function a mistake lands in (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Site {
    /// `CalcDirLight`: the directional light.
    Directional,
    /// `CalcPointLight`: every point light (the function is called once per light).
    Point,
    /// `CalcSpotLight`: the spotlight.
    Spot,
}

impl Site {
    /// Every site, in the order the shader calls them.
    pub const ALL: [Site; 3] = [Site::Directional, Site::Point, Site::Spot];

    /// The site's name in ids and JSON (`directional`, `point`, `spot`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Site::Directional => "directional",
            Site::Point => "point",
            Site::Spot => "spot",
        }
    }

    /// The GLSL function that is the site (LearnOpenGL, Multiple lights).
    #[must_use]
    pub fn function(self) -> &'static str {
        match self {
            Site::Directional => "CalcDirLight",
            Site::Point => "CalcPointLight",
            Site::Spot => "CalcSpotLight",
        }
    }

    /// Where the mistake is, in words (an English msgid of `po/messages.pot`), appended to
    /// the mistake's title: "attenuation left out, in the point lights only".
    #[must_use]
    pub fn phrase(self) -> &'static str {
        match self {
            Site::Directional => "in the directional light only",
            Site::Point => "in the point lights only",
            Site::Spot => "in the spotlight only",
        }
    }

    /// The site named `name` ([`Site::name`]), if any.
    #[must_use]
    pub fn parse(name: &str) -> Option<Site> {
        Site::ALL.into_iter().find(|s| s.name() == name)
    }
}

/// The byte range of the body of function `name` in `text`, braces included: the first
/// occurrence of `name` followed by a parenthesised parameter list and `{` (a call is
/// followed by `;` or an operator instead). Comments are ignored. `None` when there is no
/// such definition or its braces do not balance.
#[must_use]
pub fn function_body(text: &str, name: &str) -> Option<Range<usize>> {
    let blank = super::check::glsl::blank_comments(text);
    let b = blank.as_bytes();
    let is_word = |c: u8| c.is_ascii_alphanumeric() || c == b'_';
    let mut from = 0;
    while let Some(k) = blank[from..].find(name) {
        let start = from + k;
        from = start + name.len();
        if (start > 0 && is_word(b[start - 1])) || b.get(from).copied().is_some_and(is_word) {
            continue;
        }
        let skip = |mut i: usize| {
            while b.get(i).is_some_and(u8::is_ascii_whitespace) {
                i += 1;
            }
            i
        };
        let open = skip(from);
        if b.get(open) != Some(&b'(') {
            continue;
        }
        let Some(close) = matching(b, open, b'(', b')') else { continue };
        let brace = skip(close + 1);
        if b.get(brace) == Some(&b'{') {
            return matching(b, brace, b'{', b'}').map(|end| brace..end + 1);
        }
    }
    None
}

/// The index of the bracket that closes the one at `open`.
fn matching(b: &[u8], open: usize, left: u8, right: u8) -> Option<usize> {
    let mut depth = 0usize;
    for (i, &c) in b.iter().enumerate().skip(open) {
        if c == left {
            depth += 1;
        } else if c == right {
            depth -= 1;
            if depth == 0 {
                return Some(i);
            }
        }
    }
    None
}

/// `text` with `steps` applied inside `site`'s function body only. Errors: the first
/// pattern that matches nothing in the body (or `""` if the function is not in `text`).
pub fn apply_steps_at(steps: &[&[mistakes::Edit]], text: &str, site: Site) -> Result<String, &'static str> {
    let body = function_body(text, site.function()).ok_or("")?;
    let rewritten = mistakes::apply_steps(steps, &text[body.clone()])?;
    Ok(format!("{}{rewritten}{}", &text[..body.start], &text[body.end..]))
}

/// Whether some alternative of `step` occurs in `site`'s function body in `text`.
fn step_matches_in(step: &[mistakes::Edit], text: &str, site: Site) -> bool {
    function_body(text, site.function())
        .is_some_and(|body| step.iter().any(|(from, _)| text[body.clone()].contains(from)))
}

/// `text` with a mistake's `steps` (its steps for the model, [`Mistake::steps_for`]) made in
/// `site` only (see the module docs): every step applied in the site's body when they all
/// match there; else, when each step matches in the body of exactly one site (one edit per
/// site), the steps that match in this one.
///
/// Errors: the first pattern that matches nothing in the body (or `""` when the function
/// is not in `text` or none of a per-site mistake's steps is this site's).
pub fn rewrite_at(steps: &[&[mistakes::Edit]], text: &str, site: Site) -> Result<String, &'static str> {
    let all = apply_steps_at(steps, text, site);
    if all.is_ok() {
        return all;
    }
    let one_site_each =
        steps.iter().all(|step| Site::ALL.iter().filter(|&&s| step_matches_in(step, text, s)).count() == 1);
    let own: Vec<&[mistakes::Edit]> = steps.iter().copied().filter(|step| step_matches_in(step, text, site)).collect();
    if one_site_each && !own.is_empty() {
        apply_steps_at(&own, text, site)
    } else {
        all
    }
}

/// One mutant: a catalogue mistake, everywhere or in one site.
#[derive(Debug, Clone, Copy)]
pub struct Mutant {
    /// The mistake.
    pub mistake: &'static Mistake,
    /// Where it is applied; `None`: wherever its steps match.
    pub site: Option<Site>,
}

impl Mutant {
    /// The mistake everywhere.
    #[must_use]
    pub fn whole(mistake: &'static Mistake) -> Mutant {
        Mutant { mistake, site: None }
    }

    /// `id` or `id@site`: a label for tests and tables (not an id of the catalogue).
    #[must_use]
    pub fn label(&self) -> String {
        match self.site {
            None => self.mistake.id.to_string(),
            Some(s) => format!("{}@{}", self.mistake.id, s.name()),
        }
    }

    /// The English title: the mistake's, then the site's phrase ("attenuation left out, in
    /// the point lights only").
    #[must_use]
    pub fn title(&self) -> String {
        match self.site {
            None => self.mistake.title.to_string(),
            Some(s) => format!("{}, {}", self.mistake.title, s.phrase()),
        }
    }

    /// The function file `base` of `model` with this mutant applied.
    ///
    /// Errors: [`MutateError::NoMatch`] naming the first step that matches nothing (in the
    /// site's body for a per-site mutant).
    pub fn rewrite(&self, model: ModelId, base: &str) -> Result<String, MutateError> {
        let Some(site) = self.site else { return self.mistake.rewrite(model, base) };
        let steps = self.mistake.steps_for(model).ok_or(MutateError::NotApplicable { id: self.mistake.id, model })?;
        rewrite_at(steps, base, site).map_err(|pattern| MutateError::NoMatch { id: self.mistake.id, model, pattern })
    }

    /// The equivalence group holding this mutant's label, if any ([`EQUIVALENT`]).
    #[must_use]
    pub fn equivalence(&self) -> Option<&'static Equivalence> {
        let label = self.label();
        EQUIVALENT.iter().find(|e| e.ids.contains(&label.as_str()))
    }
}

/// The sites of `base` (a function file of `model`) in which `mistake` can be made alone
/// ([`rewrite_at`]).
#[must_use]
pub fn matching_sites(mistake: &Mistake, model: ModelId, base: &str) -> Vec<Site> {
    let Some(steps) = mistake.steps_for(model) else { return Vec::new() };
    Site::ALL.into_iter().filter(|&s| rewrite_at(steps, base, s).is_ok()).collect()
}

/// Every mutant of `base` (a function file of `model`) with its rewritten text: each
/// mistake of the model whose steps match, everywhere, then, for a mistake that matches in
/// more than one site, in each such site alone. Catalogue order, sites in [`Site::ALL`]
/// order.
#[must_use]
pub fn mutants(model: ModelId, base: &str) -> Vec<(Mutant, String)> {
    let mut out = Vec::new();
    for mistake in mistakes::for_model(model) {
        let Ok(text) = mistake.rewrite(model, base) else { continue };
        out.push((Mutant::whole(mistake), text));
        let sites = matching_sites(mistake, model, base);
        if sites.len() > 1 {
            for site in sites {
                let m = Mutant { mistake, site: Some(site) };
                if let Ok(text) = m.rewrite(model, base) {
                    out.push((m, text));
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "float f(float x) { return x; } // g(1) { }\n\
                        vec3 g(vec3 a, /* { */ vec3 b)\n{ if (a.x > 0.0) { return a; } return f(b.x) * b; }\n\
                        void main() { g(vec3(1.0), vec3(2.0)); }";

    #[test]
    fn a_body_is_found_past_calls_comments_and_nested_braces() {
        let body = function_body(TEXT, "g").unwrap();
        assert_eq!(&TEXT[body], "{ if (a.x > 0.0) { return a; } return f(b.x) * b; }");
        let f = function_body(TEXT, "f").unwrap();
        assert_eq!(&TEXT[f], "{ return x; }");
        assert_eq!(function_body(TEXT, "h"), None);
        assert_eq!(function_body("vec3 g(vec3 a) { return a;", "g"), None, "unbalanced");
    }

    #[test]
    fn steps_apply_inside_the_site_only() {
        let text = "vec3 CalcDirLight() { x = 1.0; }\nvec3 CalcPointLight() { x = 1.0; }\n";
        let out = apply_steps_at(&[&[("x = 1.0", "x = 2.0")]], text, Site::Point).unwrap();
        assert_eq!(out, "vec3 CalcDirLight() { x = 1.0; }\nvec3 CalcPointLight() { x = 2.0; }\n");
        assert_eq!(apply_steps_at(&[&[("y", "z")]], text, Site::Point), Err("y"));
        assert_eq!(apply_steps_at(&[&[("x", "z")]], text, Site::Spot), Err(""));
    }

    #[test]
    fn attenuation_is_generated_in_the_point_and_spot_lights_of_multiple_lights() {
        let model = ModelId::MultipleLights;
        let base = model.shader().unwrap().functions();
        let all = mutants(model, base);
        let labels: Vec<String> = all.iter().map(|(m, _)| m.label()).collect();
        for want in ["attenuation-missing", "attenuation-missing@point", "attenuation-missing@spot"] {
            assert!(labels.iter().any(|l| l == want), "{want} not in {labels:?}");
        }
        assert!(!labels.iter().any(|l| l == "attenuation-missing@directional"), "{labels:?}");
        // spot-epsilon-swapped matches in CalcSpotLight only: no per-site mutant
        assert!(!labels.iter().any(|l| l.starts_with("spot-epsilon-swapped@")), "{labels:?}");
        for want in ["ambient-not-attenuated@point", "ambient-not-attenuated@spot"] {
            assert!(labels.iter().any(|l| l == want), "{want} not in {labels:?}");
        }
        // clamp-per-light has one step per site: each site gets its own
        for want in ["clamp-per-light@directional", "clamp-per-light@point", "clamp-per-light@spot"] {
            assert!(labels.iter().any(|l| l == want), "{want} not in {labels:?}");
        }
        let (_, clamped) = all.iter().find(|(m, _)| m.label() == "clamp-per-light@point").unwrap();
        assert_eq!(clamped.matches("clamp(").count(), base.matches("clamp(").count() + 1, "one return clamped");
        let (_, point) = all.iter().find(|(m, _)| m.label() == "attenuation-missing@point").unwrap();
        let spot = function_body(point, "CalcSpotLight").unwrap();
        assert!(point[spot].contains("attenuation = 1.0 / ("), "the spotlight keeps its attenuation");
        assert_eq!(point.lines().count(), base.lines().count());
        assert!(mutants(ModelId::BasicLighting, ModelId::BasicLighting.shader().unwrap().functions())
            .iter()
            .all(|(m, _)| m.site.is_none()));
    }
}
