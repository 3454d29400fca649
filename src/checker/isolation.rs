//! The isolation step of the diagnosis (step 2 of [`super::diagnose`]): when no mistake of
//! the catalogue reproduces the learner's output, switch terms, lights and kinds of light
//! off one at a time, then split the failing cases by sign and region, and say where the
//! difference lives, with three hints that follow from it.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | switch | a term (ambient, diffuse, specular), a light, every light of a kind, or one term of every light, zeroed through the case inputs or the scene |
//! | located | a switch that, turned off in both shaders, removes every disagreement |
//! | split | the defined cases divided by a sign (N·L, R·V) or a region (inside the spot cone) |

use glam::DVec3;

use super::check::{CheckError, CompiledShader};
use super::verdict::{case_fails, expected_values, Finding};
use crate::gl::model_id::ModelId;
use crate::oracle::cases::{self, CaseModel, Class, Group, QType, Slot};

/// The isolation step's sentences, by key; `{}` marks each blank, filled in order by
/// [`fill`]. The in-page checker receives the same table and fills the same blanks.
pub const ISOLATION_TEXTS: [(&str, &str); 8] = [
    ("none", "the difference could not be narrowed to one term"),
    ("several_terms", "the difference stays when any one of these is off: {}"),
    ("one", "the difference is in {} only"),
    ("several", "the difference goes away when any of these is off: {}"),
    ("only_when", ", only when {}"),
    ("evidence", "{} of {} defined cases disagree"),
    ("evidence_off", "; with {} off: {} disagree"),
    ("evidence_always", "; every disagreeing case has {}"),
];

/// The sentence `key` of [`ISOLATION_TEXTS`] (empty for an unknown key).
fn template(key: &str) -> &'static str {
    ISOLATION_TEXTS.iter().find(|(k, _)| *k == key).map_or("", |(_, t)| t)
}

/// The sentence `key` of [`ISOLATION_TEXTS`] with its blanks filled by `args` in order.
pub fn fill(key: &str, args: &[&str]) -> String {
    let template = template(key);
    let mut out = String::new();
    let mut parts = template.split("{}");
    out += parts.next().unwrap_or("");
    for (part, arg) in parts.zip(args.iter().chain(std::iter::repeat(&""))) {
        out += arg;
        out += part;
    }
    out
}

/// The separators of the isolation step's lists (English msgids; the page marks the same
/// with `T(…)`).
pub const ISOLATION_SEPARATORS: [&str; 2] = [", ", " and "];

/// [`fill`] in the command line's language: the sentence and each of `args` (a switch's or
/// a condition's name, or a count) looked up in the PO files, as the page does with its
/// dictionary. [`fill`] stays English for what the page's self-test compares.
fn shown(key: &str, args: &[&str]) -> String {
    let template = template(key);
    let args: Vec<String> = args.iter().map(|a| super::texts::tr(a)).collect();
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    super::texts::tr_fill(template, &refs)
}

/// The three hints in the command line's language, each `{}` filled with `what` (already
/// in that language).
fn shown_hints(hints: &[&str; 3], what: &str) -> Vec<String> {
    hints.iter().map(|h| super::texts::tr_fill(h, &[what])).collect()
}

/// `names` translated and joined by the translated `sep` (one of [`ISOLATION_SEPARATORS`]).
fn joined(names: &[impl AsRef<str>], sep: &str) -> String {
    names.iter().map(|n| super::texts::tr(n.as_ref())).collect::<Vec<_>>().join(&super::texts::tr(sep))
}

/// One way to switch something off for the isolation step: its name in the sentence, what
/// is zeroed (case quantities, or lights and terms of the scene with the group uniforms
/// that carry them), and the three hints for a difference it removes.
#[derive(Debug, Clone, PartialEq)]
pub struct SwitchPlan {
    /// `the specular term`, `point light 2`, `the point lights`, `every light's diffuse term`.
    pub name: String,
    /// Case quantities set to zero (the switch applies only if the shader declares them all).
    pub quantities: Vec<&'static str>,
    /// Group uniforms set to zero (the page zeroes these).
    pub uniforms: Vec<String>,
    /// The scene's lights zeroed: 0 the directional light, 1..=n the point lights, n + 1
    /// the spotlight (the command line zeroes these in the scene).
    pub lights: Vec<usize>,
    /// The term zeroed in those lights (0 ambient, 1 diffuse, 2 specular), or every term.
    pub term: Option<usize>,
    /// Where to look, the idea, the fix: English msgids, `{}` filled with [`SwitchPlan::name`].
    pub hints: [&'static str; 3],
}

/// The light terms in the order of [`SwitchPlan::term`].
const TERMS: [&str; 3] = ["ambient", "diffuse", "specular"];

/// The three hints of a located term ([`super::hints::TERM_HINTS`]).
fn term_hints(term: &str) -> [&'static str; 3] {
    let hints = super::hints::TERM_HINTS.iter().find(|(t, _)| *t == term).map(|(_, h)| *h);
    hints.unwrap_or(super::hints::NOWHERE_HINTS)
}

/// The switches of `model` ([`isolate`] tries them in this order); `uniform_names` are
/// the group's uniforms (the multiple-lights scene's), for the light switches.
pub fn switch_plan(model: &CaseModel, uniform_names: &[&str]) -> Vec<SwitchPlan> {
    let n_points = uniform_names.iter().filter(|n| n.starts_with("pointLights[") && n.ends_with(".ambient")).count();
    plan(model, n_points)
}

/// The switches of `model` for a scene of `n_points` point lights, in order: each term the
/// model's inputs carry; then, for a scene, each light, the point lights together (when
/// there are two or more), and each term of every light.
fn plan(model: &CaseModel, n_points: usize) -> Vec<SwitchPlan> {
    let mut plan: Vec<SwitchPlan> = term_switches(model.id)
        .iter()
        .map(|s| SwitchPlan {
            name: term_name(s.name),
            quantities: s.quantities.to_vec(),
            uniforms: Vec::new(),
            lights: Vec::new(),
            term: None,
            hints: term_hints(s.name),
        })
        .collect();
    if !model.layout.has_groups() {
        return plan;
    }
    let light_prefix = |k: usize| match k {
        0 => "dirLight.".to_string(),
        k if k <= n_points => format!("pointLights[{}].", k - 1),
        _ => "spotLight.".to_string(),
    };
    let uniforms = |lights: &[usize], term: Option<usize>| -> Vec<String> {
        let terms: &[&str] = term.map_or(&TERMS[..], |t| std::slice::from_ref(&TERMS[t]));
        lights.iter().flat_map(|&k| terms.iter().map(move |t| format!("{}{t}", light_prefix(k)))).collect()
    };
    let lights_switch = |name: String, lights: Vec<usize>, term: Option<usize>, hints| SwitchPlan {
        name,
        quantities: Vec::new(),
        uniforms: uniforms(&lights, term),
        lights,
        term,
        hints,
    };
    let all: Vec<usize> = (0..n_points + 2).collect();
    for &k in &all {
        plan.push(lights_switch(light_name(k, n_points), vec![k], None, super::hints::LIGHT_HINTS));
    }
    if n_points >= 2 {
        plan.push(lights_switch("the point lights".into(), (1..=n_points).collect(), None, super::hints::KIND_HINTS));
    }
    for (t, term) in TERMS.iter().enumerate() {
        let [_, idea, fix] = term_hints(term);
        let hints = [super::hints::EVERY_LIGHT_TERM_WHERE, idea, fix];
        plan.push(lights_switch(format!("every light's {term} term"), all.clone(), Some(t), hints));
    }
    plan
}

/// A mistake outside the catalogue, for testing the isolation step (the command line's
/// and the page's): the specular term doubled, `ambient + diffuse + specular` becoming
/// `ambient + diffuse + 2.0 * specular` in a function file.
pub const ISOLATION_PROBE: (&str, &str) = ("ambient + diffuse + specular", "ambient + diffuse + 2.0 * specular");

/// What the isolation step says of [`ISOLATION_PROBE`] on `model` (the start of its
/// sentence): the one switch that removes a doubled specular term. `None` when the model
/// has no such switch.
pub fn probe_expectation(model: &CaseModel, uniform_names: &[&str]) -> Option<String> {
    let plan = switch_plan(model, uniform_names);
    let name =
        ["the specular term", "every light's specular term"].into_iter().find(|n| plan.iter().any(|s| s.name == *n))?;
    Some(fill("one", &[name]))
}

/// The labels of the case predicates of `model` (the signs and regions the isolation step splits failing cases by, in order) and, for
/// `row`, which hold.
pub fn case_flags(model: &CaseModel, row: &[[f32; 4]]) -> (Vec<&'static str>, Vec<bool>) {
    predicates(model, row).into_iter().map(|(label, _, holds)| (label, holds)).unzip()
}

/// A switch: a name and the model quantities zeroed to turn it off.
struct Switch {
    name: &'static str,
    quantities: &'static [&'static str],
}

const fn sw(name: &'static str, quantities: &'static [&'static str]) -> Switch {
    Switch { name, quantities }
}

/// The terms that can be switched off through a model's inputs.
fn term_switches(model: ModelId) -> &'static [Switch] {
    const LIGHT_TERMS: &[Switch] =
        &[sw("ambient", &["light.ambient"]), sw("diffuse", &["light.diffuse"]), sw("specular", &["light.specular"])];
    // The emission map's texel (Lighting maps, exercise 4): added unlit, so switching it off
    // removes a mistake in the emission alone, whatever light it was wrongly multiplied by.
    const EMISSION: &[Switch] = &[
        sw("ambient", &["light.ambient"]),
        sw("diffuse", &["light.diffuse"]),
        sw("specular", &["light.specular"]),
        sw("emission", &["material.emission"]),
    ];
    const BASIC: &[Switch] = &[sw("ambient", &["ambientStrength"]), sw("specular", &["specularStrength"])];
    const OT8: &[Switch] = &[sw("ambient", &["MaterialAmbientFactor"]), sw("specular", &["MaterialSpecularColor"])];
    const OGLDEV: &[Switch] = &[
        sw("ambient", &["gDirectionalLight.AmbientIntensity"]),
        sw("diffuse", &["gDirectionalLight.DiffuseIntensity"]),
        sw("specular", &["gMatSpecularIntensity"]),
    ];
    match model {
        ModelId::BasicLighting | ModelId::BlinnPhong => BASIC,
        ModelId::Materials | ModelId::LightingMaps | ModelId::Directional | ModelId::Point | ModelId::Spot => {
            LIGHT_TERMS
        }
        ModelId::LightingMapsEmission => EMISSION,
        ModelId::OpenGLTutorial8 => OT8,
        ModelId::Ogldev19 => OGLDEV,
        ModelId::MultipleLights | ModelId::Gouraud | ModelId::NormalMatrix => &[],
    }
}

/// The name of every term switch of every model (`the ambient term`, `the emission term`),
/// once each, in model order: msgids the command line shows, whether or not a page
/// exercise carries them.
#[must_use]
pub fn term_switch_names() -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for s in ModelId::ALL.iter().flat_map(|&m| term_switches(m)) {
        let name = term_name(s.name);
        if !names.contains(&name) {
            names.push(name);
        }
    }
    names
}

/// A term switch's name in the isolation sentence: `the specular term`.
fn term_name(term: &str) -> String {
    format!("the {term} term")
}

fn zero_rows(model: &CaseModel, groups: &[Group], quantities: &[&str]) -> Vec<Group> {
    let mut out = groups.to_vec();
    for name in quantities {
        let Some(q) = model.quantities.iter().find(|q| q.name == *name) else { continue };
        if let Slot::Case { input, offset } = q.slot {
            let width = if q.ty == QType::Float { 1 } else { 3 };
            for group in &mut out {
                for row in &mut group.rows {
                    row[input][offset..offset + width].fill(0.0);
                }
            }
        }
    }
    out
}

/// The multiple-lights scenes with `lights` zeroed: every term, or only `term`.
fn zero_scene(groups: &[Group], lights: &[usize], term: Option<usize>) -> Vec<Group> {
    use crate::material::LightProps;
    let zero = |p: &mut LightProps| match term {
        Some(0) => p.ambient = glam::Vec3::ZERO,
        Some(1) => p.diffuse = glam::Vec3::ZERO,
        Some(_) => p.specular = glam::Vec3::ZERO,
        None => *p = LightProps { ambient: glam::Vec3::ZERO, diffuse: glam::Vec3::ZERO, specular: glam::Vec3::ZERO },
    };
    let mut out = groups.to_vec();
    for group in &mut out {
        let Some(scene) = group.scene.as_mut() else { continue };
        let s = &mut scene.f32;
        let n_points = s.point_lights.len();
        for &k in lights {
            match k {
                0 => s.dir_light.iter_mut().for_each(|d| zero(&mut d.props)),
                k if k <= n_points => zero(&mut s.point_lights[k - 1].props),
                _ => s.spot_light.iter_mut().for_each(|d| zero(&mut d.props)),
            }
        }
        scene.f64 = crate::reference::scene::Scene::from_f32(&scene.f32);
        group.uniforms = cases::scene_uniforms(&scene.f32);
    }
    out
}

/// Light `k` of a scene with `n_points` point lights, by name.
fn light_name(k: usize, n_points: usize) -> String {
    match k {
        0 => "the directional light".into(),
        k if k <= n_points => format!("point light {}", k - 1),
        _ => "the spotlight".into(),
    }
}

fn quantity(model: &CaseModel, row: &[[f32; 4]], names: &[&str]) -> Option<DVec3> {
    let q = model.quantities.iter().find(|q| names.contains(&q.name))?;
    match q.slot {
        Slot::Case { input, offset } => {
            let v = row[input];
            Some(if q.ty == QType::Float {
                DVec3::splat(v[offset] as f64)
            } else {
                DVec3::new(v[0] as f64, v[1] as f64, v[2] as f64)
            })
        }
        _ => None,
    }
}

/// The signs and regions a failing case is sorted by: `(label when true, label when false, value)`.
fn predicates(model: &CaseModel, row: &[[f32; 4]]) -> Vec<(&'static str, &'static str, bool)> {
    let frag = quantity(model, row, &["FragPos", "WorldPos0", "Position_worldspace"]);
    let normal = quantity(model, row, &["Normal", "Normal0", "Normal_cameraspace"]).map(|n| n.normalize_or_zero());
    let from_position = || match (quantity(model, row, &["lightPos", "light.position"]), frag) {
        (Some(p), Some(f)) => Some((p - f).normalize_or_zero()),
        _ => None,
    };
    let light_dir = match model.id {
        ModelId::Directional | ModelId::Ogldev19 => {
            quantity(model, row, &["light.direction", "gDirectionalLight.Direction"]).map(|d| (-d).normalize_or_zero())
        }
        ModelId::OpenGLTutorial8 => {
            quantity(model, row, &["LightDirection_cameraspace"]).map(|d| d.normalize_or_zero())
        }
        ModelId::BasicLighting
        | ModelId::Gouraud
        | ModelId::Materials
        | ModelId::LightingMaps
        | ModelId::LightingMapsEmission
        | ModelId::Point
        | ModelId::Spot
        | ModelId::MultipleLights
        | ModelId::NormalMatrix
        | ModelId::BlinnPhong => from_position(),
    };
    let view_dir = match model.id {
        ModelId::OpenGLTutorial8 => quantity(model, row, &["EyeDirection_cameraspace"]).map(|d| d.normalize_or_zero()),
        ModelId::BasicLighting
        | ModelId::Gouraud
        | ModelId::Materials
        | ModelId::LightingMaps
        | ModelId::Directional
        | ModelId::Point
        | ModelId::Spot
        | ModelId::MultipleLights
        | ModelId::Ogldev19
        | ModelId::NormalMatrix
        | ModelId::BlinnPhong
        | ModelId::LightingMapsEmission => match (quantity(model, row, &["viewPos", "gEyeWorldPos"]), frag) {
            (Some(e), Some(f)) => Some((e - f).normalize_or_zero()),
            _ => None,
        },
    };
    let mut out = Vec::new();
    if let (Some(n), Some(l)) = (normal, light_dir) {
        out.push(("N·L < 0 (the light is behind the surface)", "N·L > 0", n.dot(l) < 0.0));
        if let Some(v) = view_dir {
            let r = -l - 2.0 * n.dot(-l) * n;
            out.push(("R·V < 0 (the eye is away from the mirror direction)", "R·V > 0", r.dot(v) < 0.0));
            out.push(("N·V < 0 (the eye is behind the surface)", "N·V > 0", n.dot(v) < 0.0));
        }
    }
    // The casters' own regions: the spot's cone, the distance to an attenuated light.
    let (cone, attenuated) = match model.id {
        ModelId::Spot => (true, true),
        ModelId::Point => (false, true),
        ModelId::BasicLighting
        | ModelId::Gouraud
        | ModelId::Materials
        | ModelId::LightingMaps
        | ModelId::Directional
        | ModelId::MultipleLights
        | ModelId::OpenGLTutorial8
        | ModelId::Ogldev19
        | ModelId::NormalMatrix
        | ModelId::BlinnPhong
        | ModelId::LightingMapsEmission => (false, false),
    };
    if cone {
        if let (Some(l), Some(axis)) = (light_dir, quantity(model, row, &["light.direction"])) {
            let theta = l.dot(-axis.normalize_or_zero());
            let (cut, outer) = (row[5][3] as f64, row[6][3] as f64);
            out.push(("the fragment is inside the inner cone", "outside the inner cone", theta > cut));
            out.push(("the fragment is in the soft edge", "not in the soft edge", theta <= cut && theta > outer));
            out.push(("the fragment is outside the outer cone", "inside the outer cone", theta <= outer));
        }
    }
    if let (Some(f), Some(p)) = (frag, quantity(model, row, &["light.position"])) {
        if attenuated {
            out.push(("the light is nearer than 1", "the light is farther than 1", (p - f).length() < 1.0));
        }
    }
    out
}

/// Defined cases beyond the bound ([`case_fails`]), as `(group, row)`, and
/// the number of defined cases.
fn failing_cases(
    target: &Target<'_>,
    model: &CaseModel,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
) -> Result<(usize, Vec<(usize, usize)>), CheckError> {
    let mut defined = 0;
    let mut failing = Vec::new();
    match target {
        Target::Model => {
            for (g, rows) in expected_values(model, groups).iter().enumerate() {
                for (i, want) in rows.iter().enumerate() {
                    let Some(want) = want else { continue };
                    defined += 1;
                    if case_fails(&outputs[g][i], want, model.bound) {
                        failing.push((g, i));
                    }
                }
            }
        }
        Target::Functions { ctx, functions } => {
            let want = super::outputs::run_functions(ctx, model, functions, groups)?;
            for (g, group) in groups.iter().enumerate() {
                for (i, row) in group.rows.iter().enumerate() {
                    if model.classify(row, group.scene.as_ref()) != Class::Defined {
                        continue;
                    }
                    defined += 1;
                    if super::outputs::case_differs(&outputs[g][i], &want[g][i], 2.0 * model.bound) {
                        failing.push((g, i));
                    }
                }
            }
        }
    }
    Ok((defined, failing))
}

/// What the isolation step compares the learner's output with.
#[derive(Clone, Copy)]
pub enum Target<'a> {
    /// The model's `f64` reference, within the model's bound ([`case_fails`]): a shader check.
    Model,
    /// A function file of the model run on llvmpipe (an exercise's reference solution),
    /// within `2·bound` at the values' magnitude, as the variant check's verdict
    /// ([`super::outputs::compare_outputs`]): the learner and the solution each stay within
    /// the bound of the exact value.
    Functions {
        /// The context the function file runs in.
        ctx: &'a crate::gl::context::GlContext,
        /// The function file.
        functions: &'a str,
    },
}

/// One switch of the isolation step with the cases it runs on.
pub struct Switched {
    /// Its name, as [`switch_plan`] gives it (`the specular term`, `point light 2`).
    pub name: String,
    /// The case quantities it zeroes (the switch applies only if the shader declares them all).
    pub quantities: Vec<&'static str>,
    /// The cases with the term or light switched off.
    pub groups: Vec<Group>,
}

/// Every switch of the isolation step with its switched cases, in the order [`isolate`]
/// tries them and [`switch_plan`] lists them.
pub fn switched_cases(model: &CaseModel, groups: &[Group]) -> Vec<Switched> {
    let n_points = groups.first().and_then(|g| g.scene.as_ref()).map_or(0, |s| s.f32.point_lights.len());
    plan(model, n_points)
        .into_iter()
        .map(|s| {
            let switched = if s.quantities.is_empty() {
                zero_scene(groups, &s.lights, s.term)
            } else {
                zero_rows(model, groups, &s.quantities)
            };
            Switched { name: s.name, quantities: s.quantities, groups: switched }
        })
        .collect()
}

/// Step 2 of the procedure: which term or light, and which inputs, disagree.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn isolate(
    shader: &CompiledShader<'_>,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
) -> Result<Finding, CheckError> {
    isolate_against(shader, &Target::Model, groups, outputs)
}

/// [`isolate`] against `target`: the model's `f64` reference or an exercise's reference
/// solution.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn isolate_against(
    shader: &CompiledShader<'_>,
    target: &Target<'_>,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
) -> Result<Finding, CheckError> {
    let model = shader.model();
    let (defined, failing) = failing_cases(target, model, groups, outputs)?;
    let mut evidence = shown("evidence", &[&failing.len().to_string(), &defined.to_string()]);
    let mut located: Vec<&SwitchPlan> = Vec::new();
    // the switches the shader could take: none located means the difference is in none
    // of them alone (a term with no switch, or several at once)
    let mut switchable: Vec<&str> = Vec::new();
    // switches the shader cannot take: it writes their quantities (a term's strength) as numbers
    let mut unswitched: Vec<&str> = Vec::new();
    let n_points = groups.first().and_then(|g| g.scene.as_ref()).map_or(0, |s| s.f32.point_lights.len());
    let switches = plan(model, n_points);
    for s in &switches {
        let switched = if !s.quantities.is_empty() {
            if !s.quantities.iter().all(|q| shader.declares(q)) {
                unswitched.push(&s.name);
                continue;
            }
            zero_rows(model, groups, &s.quantities)
        } else {
            zero_scene(groups, &s.lights, s.term)
        };
        let out = shader.run(&switched)?;
        let (_, still) = failing_cases(target, model, &switched, &out)?;
        evidence.push_str(&shown("evidence_off", &[s.name.as_str(), still.len().to_string().as_str()]));
        if still.is_empty() {
            located.push(s);
        }
        switchable.push(&s.name);
    }
    let names: Vec<&str> = located.iter().map(|s| s.name.as_str()).collect();
    let mut sentence = match names.as_slice() {
        [] if switchable.is_empty() => shown("none", &[]),
        [] => shown("several_terms", &[&joined(&switchable, ISOLATION_SEPARATORS[0])]),
        [one] => shown("one", &[one]),
        several => shown("several", &[&joined(several, ISOLATION_SEPARATORS[0])]),
    };
    // Splits: a predicate true for every failing case and false for some defined case.
    let mut always: Option<Vec<(&'static str, &'static str, bool)>> = None;
    let mut seen_true = std::collections::BTreeSet::new();
    let mut seen_false = std::collections::BTreeSet::new();
    for (g, group) in groups.iter().enumerate() {
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, group.scene.as_ref()) != Class::Defined {
                continue;
            }
            let preds = predicates(model, row);
            for p in &preds {
                if p.2 {
                    seen_true.insert(p.0);
                } else {
                    seen_false.insert(p.0);
                }
            }
            if failing.contains(&(g, i)) {
                always = Some(match always {
                    None => preds,
                    Some(prev) => prev.into_iter().zip(preds).map(|(a, b)| (a.0, a.1, a.2 && b.2)).collect(),
                });
            }
        }
    }
    let conditions: Vec<&str> = always
        .unwrap_or_default()
        .into_iter()
        .filter(|p| p.2 && seen_false.contains(p.0) && seen_true.contains(p.0))
        .map(|p| p.0)
        .collect();
    let conditions = joined(&conditions, ISOLATION_SEPARATORS[1]);
    if !conditions.is_empty() {
        sentence += &shown("only_when", &[&conditions]);
        evidence += &shown("evidence_always", &[&conditions]);
    }
    let hints = match located.first() {
        Some(s) => shown_hints(&s.hints, &super::texts::tr(&s.name)),
        None if !conditions.is_empty() => shown_hints(&super::hints::WHEN_HINTS, &conditions),
        None if !unswitched.is_empty() => {
            shown_hints(&super::hints::UNSWITCHED_HINTS, &joined(&unswitched, ISOLATION_SEPARATORS[1]))
        }
        None => shown_hints(&super::hints::NOWHERE_HINTS, ""),
    };
    Ok(Finding {
        id: "isolated".into(),
        title: sentence,
        evidence,
        link: String::new(),
        hints,
        site: None,
        second: None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The emission switch belongs to the one model with an emission map, zeroes its texel
    /// quantity (which the model's layout must hold), and carries the emission term's hints.
    #[test]
    fn only_the_emission_model_switches_the_emission_off() {
        for model in ModelId::ALL {
            let plan = plan(model.case_model(), 0);
            let emission: Vec<&SwitchPlan> = plan.iter().filter(|s| s.name == "the emission term").collect();
            if model != ModelId::LightingMapsEmission {
                assert!(emission.is_empty(), "{model:?}");
                continue;
            }
            let [s] = emission[..] else { panic!("one emission switch: {plan:?}") };
            assert_eq!(s.quantities, ["material.emission"]);
            assert!(model.case_model().quantities.iter().any(|q| q.name == "material.emission"));
            let hints = super::super::hints::TERM_HINTS.iter().find(|(t, _)| *t == "emission").unwrap().1;
            assert_eq!(s.hints, hints);
        }
        assert!(term_switch_names().contains(&"the emission term".to_string()));
        assert_eq!(term_switch_names().len(), 4, "{:?}", term_switch_names());
    }
}
