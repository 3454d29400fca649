//! Naming the mistake: when a learner's shader disagrees with its model, which known
//! mistake gives the same output, or else which term, light and inputs disagree.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | learner | the checked shader's outputs on the cases |
//! | mutant | the model's function file with one [`crate::gl::mistakes`] entry applied, run on the same cases |
//! | match | learner and mutant within `2·bound` on every defined case but at most [`MISMATCH_SHARE`] of them |
//! | switch | a term (ambient, diffuse, specular) or a light zeroed through the case inputs |
//! | split | the defined cases divided by a sign (N·L, R·V) or a region (inside the spot cone) |
//!
//! # The procedure
//! 1. Every mutant of the model runs on the learner's cases (same rows, same uniforms). A
//!    mutant that agrees with the reference on these cases is invisible here and skipped
//!    (for example `shininess-ignored` when the shader hard-codes 32 and the check fixes
//!    the shininess to the chapter's 32). Every mutant that matches is reported, fewest
//!    mismatches first.
//! 2. If none matches, the learner's shader runs again with one term or light switched off
//!    (its inputs zeroed in the cases or the scene, only for quantities the shader
//!    declares); a switch that removes every disagreement locates it. The failing cases
//!    are then split by sign; a sign that holds for every failing case, but not for every
//!    case, is reported ("only when N·L < 0").
//!
//! The bound of a match is `2·bound`: the learner and the mutant each stay within the
//! model's bound of the exact mutant's value (the bound is a rounding bound; see
//! [`crate::gl::cases::bounds`]).

use std::fmt::Write as _;

use glam::DVec3;

use super::batch::{Batch, Outputs};
use super::cases::{self, CaseModel, Class, Group, QType, Slot};
use super::check::{self, CheckError, CheckReport, CompiledShader, Mapping};
use super::context::GlContext;
use super::mistakes::{self, Mistake};
use super::model_id::ModelId;
use super::texts::tr;
pub use super::texts::{tr_fill, AGREES, DISAGREES, DISAGREES_ISOLATED, DISAGREES_LIKELY, EVIDENCE, SEE_THE_BOOK};

/// The share of defined cases on which a matching mutant may still differ from the
/// learner: 1 in 1000. A mutant with a discontinuity (`spot-hard-edge`'s `θ > cutOff`, the
/// NaN boundary of `specular-no-clamp`) and a learner written differently may take
/// different sides of it when a case lies within rounding of it; such cases are far rarer
/// than 1 in 1000 (the case ranges put a few in 10^5 within 1e-5 of a branch), while a
/// different mistake differs on a large share.
pub const MISMATCH_SHARE: f64 = 1e-3;

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
}

/// How two outputs compare on the defined cases.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Agreement {
    /// Defined cases compared.
    pub defined: usize,
    /// Cases beyond the tolerance (a finite value against a non-finite one counts).
    pub mismatches: usize,
    /// The largest finite difference.
    pub max_diff: f64,
}

impl Agreement {
    /// Whether the two agree up to [`MISMATCH_SHARE`].
    pub fn matches(&self) -> bool {
        self.defined > 0 && self.mismatches as f64 <= MISMATCH_SHARE * self.defined as f64
    }
}

/// Compares two GL outputs on `groups`' defined cases, channel by channel (rgb), within
/// `tolerance`. Two non-finite values agree (both are undefined results of the same
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
                        bad |= d > tolerance;
                    }
                    (false, false) => {}
                    _ => bad = true,
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
/// on `groups`: `(mistake, outputs)`, catalogue order. Mistakes whose edits do not occur in
/// `base` are left out.
///
/// Errors: [`CheckError::Gl`] if a mutant does not compile (a catalogue bug) or a draw fails.
pub fn run_mutants(
    ctx: &GlContext,
    model: &CaseModel,
    base: &str,
    groups: &[Group],
) -> Result<Vec<(&'static Mistake, Outputs)>, CheckError> {
    let Some(shader) = model.shader else { return Ok(Vec::new()) };
    let mut out = Vec::new();
    for mistake in mistakes::for_model(model.id) {
        let Ok(functions) = mistake.rewrite(model.id, base) else { continue };
        let body = format!("{functions}\n{}", shader.harness());
        out.push((mistake, run_body(ctx, model, &body, groups)?));
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

/// Step 1 of the procedure: the catalogue mistakes whose mutants of `base` (the function
/// file the learner should match) match `learner`.
///
/// Errors: as [`run_mutants`].
pub fn matching_mistakes(
    ctx: &GlContext,
    model: &CaseModel,
    base: &str,
    groups: &[Group],
    learner: &[Vec<[f32; 4]>],
) -> Result<Vec<Finding>, CheckError> {
    if model.shader.is_none() {
        return Ok(Vec::new());
    }
    let reference = run_functions(ctx, model, base, groups)?;
    let tolerance = 2.0 * model.bound;
    let mut found: Vec<(Agreement, Finding)> = Vec::new();
    for (mistake, outputs) in run_mutants(ctx, model, base, groups)? {
        let vs_reference = compare_outputs(model, groups, &outputs, &reference, tolerance);
        if vs_reference.matches() {
            continue;
        }
        let vs_learner = compare_outputs(model, groups, &outputs, learner, tolerance);
        if vs_learner.matches() {
            let same = mistake.equivalence().map_or(String::new(), |e| {
                let others: Vec<&str> = e.ids.iter().copied().filter(|id| *id != mistake.id).collect();
                format!("; gives the same output as {} ({})", others.join(", "), e.reason)
            });
            let evidence = tr_fill(
                EVIDENCE,
                &[
                    &(vs_learner.defined - vs_learner.mismatches).to_string(),
                    &vs_learner.defined.to_string(),
                    &format!("{:.1e}", vs_learner.max_diff),
                    &vs_reference.mismatches.to_string(),
                ],
            ) + &same;
            found.push((
                vs_learner,
                Finding { id: mistake.id.into(), title: mistake.title.into(), evidence, link: mistake.link.into() },
            ));
        }
    }
    found.sort_by(|a, b| a.0.mismatches.cmp(&b.0.mismatches).then(a.0.max_diff.total_cmp(&b.0.max_diff)));
    Ok(found.into_iter().map(|(_, f)| f).collect())
}

// ---------------------------------------------------------------- isolation

/// The isolation step's sentences, by key; `{}` marks each blank, filled in order by
/// [`fill`]. The in-page checker receives the same table and fills the same blanks.
pub const ISOLATION_TEXTS: [(&str, &str); 8] = [
    ("none", "the difference could not be narrowed to one term"),
    ("several_terms", "the difference is in more than one term (switching off any one leaves it)"),
    ("one", "the difference is in {} only"),
    ("several", "the difference goes away when any of these is off: {}"),
    ("only_when", ", only when {}"),
    ("evidence", "{} of {} defined cases disagree"),
    ("evidence_off", "; with {} off: {} disagree"),
    ("evidence_always", "; every disagreeing case has {}"),
];

/// The sentence `key` of [`ISOLATION_TEXTS`] with its blanks filled by `args` in order.
pub fn fill(key: &str, args: &[&str]) -> String {
    let template = ISOLATION_TEXTS.iter().find(|(k, _)| *k == key).map_or("", |(_, t)| t);
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
    let template = ISOLATION_TEXTS.iter().find(|(k, _)| *k == key).map_or("", |(_, t)| t);
    let args: Vec<String> = args.iter().map(|a| super::texts::tr(a)).collect();
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    super::texts::tr_fill(template, &refs)
}

/// `names` translated and joined by the translated `sep` (one of [`ISOLATION_SEPARATORS`]).
fn joined(names: &[impl AsRef<str>], sep: &str) -> String {
    names.iter().map(|n| super::texts::tr(n.as_ref())).collect::<Vec<_>>().join(&super::texts::tr(sep))
}

/// One way to switch something off for the isolation step: its name in the sentence, the
/// case quantities zeroed, and the group uniforms zeroed (the multiple-lights scene).
#[derive(Debug, Clone, PartialEq)]
pub struct SwitchPlan {
    /// `the specular term`, `point light 2`, `every light's diffuse term`.
    pub name: String,
    /// Case quantities set to zero (the switch applies only if the shader declares them all).
    pub quantities: Vec<&'static str>,
    /// Group uniforms set to zero.
    pub uniforms: Vec<String>,
}

/// The switches of `model` ([`isolate`] tries them in this order); `uniform_names` are
/// the group's uniforms (the multiple-lights scene's), for the light switches.
pub fn switch_plan(model: &CaseModel, uniform_names: &[&str]) -> Vec<SwitchPlan> {
    let mut plan: Vec<SwitchPlan> = term_switches(model.id)
        .iter()
        .map(|s| SwitchPlan {
            name: format!("the {} term", s.name),
            quantities: s.quantities.to_vec(),
            uniforms: Vec::new(),
        })
        .collect();
    // The lights of a scene (the multiple-lights uniforms shared by a group of cases).
    if model.layout.has_groups() {
        let n_points =
            uniform_names.iter().filter(|n| n.starts_with("pointLights[") && n.ends_with(".ambient")).count();
        let terms = [".ambient", ".diffuse", ".specular"];
        let light_prefix = |k: usize| match k {
            0 => "dirLight.".to_string(),
            k if k <= n_points => format!("pointLights[{}].", k - 1),
            _ => "spotLight.".to_string(),
        };
        for k in 0..n_points + 2 {
            let prefix = light_prefix(k);
            let uniforms = terms.iter().map(|t| format!("{prefix}{}", &t[1..])).collect();
            plan.push(SwitchPlan { name: light_name(k), quantities: Vec::new(), uniforms });
        }
        for term in terms {
            let uniforms = (0..n_points + 2).map(|k| format!("{}{}", light_prefix(k), &term[1..])).collect();
            plan.push(SwitchPlan {
                name: format!("every light's {} term", &term[1..]),
                quantities: Vec::new(),
                uniforms,
            });
        }
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
        ModelId::OpenGLTutorial8 => OT8,
        ModelId::Ogldev19 => OGLDEV,
        ModelId::MultipleLights | ModelId::Gouraud | ModelId::NormalMatrix => &[],
    }
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

/// The multiple-lights scenes with one light (or one term of every light) zeroed.
fn zero_scene(groups: &[Group], light: Option<usize>, term: Option<usize>) -> Vec<Group> {
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
        for k in 0..n_points + 2 {
            if light.is_some_and(|l| l != k) {
                continue;
            }
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

fn light_name(k: usize) -> String {
    match k {
        0 => "the directional light".into(),
        5 => "the spotlight".into(),
        k => format!("point light {}", k - 1),
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
        | ModelId::BlinnPhong => match (quantity(model, row, &["viewPos", "gEyeWorldPos"]), frag) {
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
        | ModelId::BlinnPhong => (false, false),
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

/// The verdict's rule on one case: a shader's output `got` fails when some channel (rgb)
/// is more than `bound` from the `f64` reference's `want`, or is not a number (NaN, or an
/// infinity, whose difference is infinite). `lightlab check-shader`, `lightlab exercise
/// check` and the page (which reads `want` and `bound` from [`expected_values`] and the
/// exported model) all decide by this rule.
pub fn case_fails(got: &[f32; 4], want: &[f64; 3], bound: f64) -> bool {
    (0..3).any(|c| {
        let d = (f64::from(got[c]) - want[c]).abs();
        d.is_nan() || d > bound
    })
}

/// The `f64` reference's rgb on every case of `groups`, group by group, `None` where the
/// model is not defined (those cases are left out of the verdict).
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

/// Defined cases beyond the bound ([`case_fails`]), as `(group, row)`, and the number of
/// defined cases.
fn failing_cases(model: &CaseModel, groups: &[Group], outputs: &[Vec<[f32; 4]>]) -> (usize, Vec<(usize, usize)>) {
    let mut defined = 0;
    let mut failing = Vec::new();
    for (g, rows) in expected_values(model, groups).iter().enumerate() {
        for (i, want) in rows.iter().enumerate() {
            let Some(want) = want else { continue };
            defined += 1;
            if case_fails(&outputs[g][i], want, model.bound) {
                failing.push((g, i));
            }
        }
    }
    (defined, failing)
}

/// One switch of the isolation step with the cases it runs on.
pub struct Switched {
    /// Its name, as [`switch_plan`] gives it (`the specular term`, `point light 2`).
    pub name: String,
    /// The case quantities it zeroes (the switch applies only if the shader declares them all).
    pub quantities: &'static [&'static str],
    /// The cases with the term or light switched off.
    pub groups: Vec<Group>,
}

/// Every switch of the isolation step with its switched cases, in the order [`isolate`]
/// tries them and [`switch_plan`] lists them: the model's terms, then (multiple lights) each
/// light, then each term of every light.
pub fn switched_cases(model: &CaseModel, groups: &[Group]) -> Vec<Switched> {
    let mut out: Vec<Switched> = term_switches(model.id)
        .iter()
        .map(|s| Switched {
            name: format!("the {} term", s.name),
            quantities: s.quantities,
            groups: zero_rows(model, groups, s.quantities),
        })
        .collect();
    if model.layout.has_groups() {
        let n_lights = groups.first().and_then(|g| g.scene.as_ref()).map_or(0, |s| s.f32.point_lights.len() + 2);
        for k in 0..n_lights {
            out.push(Switched { name: light_name(k), quantities: &[], groups: zero_scene(groups, Some(k), None) });
        }
        for (t, term) in ["ambient", "diffuse", "specular"].iter().enumerate() {
            let name = format!("every light's {term} term");
            out.push(Switched { name, quantities: &[], groups: zero_scene(groups, None, Some(t)) });
        }
    }
    out
}

/// Step 2 of the procedure: which term or light, and which inputs, disagree.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn isolate(
    shader: &CompiledShader<'_>,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
) -> Result<Finding, CheckError> {
    let model = shader.model();
    let (defined, failing) = failing_cases(model, groups, outputs);
    let mut evidence = shown("evidence", &[&failing.len().to_string(), &defined.to_string()]);
    let mut located: Vec<String> = Vec::new();
    let mut switchable = Vec::new();
    let mut try_switch = |name: String, switched: Vec<Group>, evidence: &mut String| -> Result<(), CheckError> {
        let out = shader.run(&switched)?;
        let (_, still) = failing_cases(model, &switched, &out);
        evidence.push_str(&shown("evidence_off", &[name.as_str(), still.len().to_string().as_str()]));
        if still.is_empty() {
            located.push(name.clone());
        }
        switchable.push(name);
        Ok(())
    };
    for s in switched_cases(model, groups) {
        if s.quantities.iter().all(|q| shader.declares(q)) {
            try_switch(s.name, s.groups, &mut evidence)?;
        }
    }
    let mut sentence = match located.as_slice() {
        [] if switchable.is_empty() => shown("none", &[]),
        [] => shown("several_terms", &[]),
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
    if !conditions.is_empty() {
        let conditions = joined(&conditions, ISOLATION_SEPARATORS[1]);
        sentence += &shown("only_when", &[&conditions]);
        evidence += &shown("evidence_always", &[&conditions]);
    }
    Ok(Finding { id: "isolated".into(), title: sentence, evidence, link: String::new() })
}

/// The diagnosis of a shader that disagrees: the matching mistakes, best first; if none
/// matches, one `isolated` finding. Empty when the report agrees.
///
/// Errors: [`CheckError::Gl`] if a run fails.
pub fn diagnose(
    ctx: &GlContext,
    shader: &CompiledShader<'_>,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
    report: &CheckReport,
) -> Result<Vec<Finding>, CheckError> {
    if report.agrees() {
        return Ok(Vec::new());
    }
    let model = shader.model();
    let found = match model.shader {
        Some(s) => matching_mistakes(ctx, model, s.functions, groups, outputs)?,
        None => Vec::new(),
    };
    if !found.is_empty() {
        return Ok(found);
    }
    Ok(vec![isolate(shader, groups, outputs)?])
}

/// What a learner hands in: a complete fragment shader, and optionally the vertex shader
/// it pairs with (then both are checked together: [`check::pair`]). A `&str` is a fragment
/// shader alone.
#[derive(Debug, Clone, Copy)]
pub struct Submission<'s> {
    /// The fragment shader.
    pub fragment: &'s str,
    /// Its vertex shader, if handed in.
    pub vertex: Option<&'s str>,
}

impl<'s> From<&'s str> for Submission<'s> {
    fn from(fragment: &'s str) -> Self {
        Submission { fragment, vertex: None }
    }
}

impl<'s> From<&'s String> for Submission<'s> {
    fn from(fragment: &'s String) -> Self {
        Submission { fragment, vertex: None }
    }
}

/// A check with its diagnosis.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosed {
    /// The check's verdict and statistics.
    pub report: CheckReport,
    /// The diagnosis, best first; empty when the shader agrees.
    pub diagnosis: Vec<Finding>,
}

/// Checks `source` (a complete fragment shader) against `model` on `n` cases from
/// `seed` ([`check::CompiledShader::check`]), then runs [`diagnose`] on the same cases; a
/// submission with a vertex shader is checked as a pair on triangles
/// ([`check::pair::CompiledPair::check`], [`check::pair::diagnose_pair`]).
///
/// Compiles the user's file as it is on the driver, in the calling process (`lightlab
/// check-shader` runs this in a child process so a driver crash or a runaway shader cannot
/// take it down).
///
/// Errors: [`CheckError::Usage`] (`gouraud` without a vertex shader, a model with no pair
/// reference with one, `n` outside `1..=`[`super::cases::MAX_CASES`], storage above the
/// limits, unmapped name, type mismatch, no colour output),
/// [`CheckError::Compile`] (with the file's line numbers; [`CheckError::VertexCompile`] for
/// the vertex shader), [`CheckError::Gl`].
pub fn check_and_diagnose<'s>(
    ctx: &GlContext,
    submission: impl Into<Submission<'s>>,
    model: ModelId,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Result<Diagnosed, CheckError> {
    check::check_cases(n)?;
    let Submission { fragment: source, vertex } = submission.into();
    if let Some(vertex) = vertex {
        let pair = check::pair::compile_pair(ctx, vertex, source, model, mapping)?;
        let checked = pair.check(n, seed)?;
        let diagnosis = check::pair::diagnose_pair(ctx, (vertex, source), pair.model(), mapping, &checked)?;
        return Ok(Diagnosed { report: checked.report, diagnosis });
    }
    let shader = check::compile_shader(ctx, source, model, mapping)?;
    let check::Checked { groups, outputs, report } = shader.check(n, seed)?;
    let diagnosis = diagnose(ctx, &shader, &groups, &outputs, &report)?;
    Ok(Diagnosed { report, diagnosis })
}

impl Diagnosed {
    /// Whether the shader agrees with its model.
    pub fn agrees(&self) -> bool {
        self.report.agrees()
    }

    /// Plain words first (the diagnosis), then the check's report. The sentences, the
    /// mistakes' titles and explanations are in the command line's language
    /// ([`crate::i18n::output_lang`]; English without the `book` feature).
    pub fn format(&self) -> String {
        let model = self.report.model.name();
        let mut s = String::new();
        if self.agrees() {
            let _ = writeln!(s, "{}", tr_fill(AGREES, &[model]));
        } else {
            match self.diagnosis.as_slice() {
                [] => {
                    let _ = writeln!(s, "{}", tr_fill(DISAGREES, &[model]));
                }
                [f] if f.id == "isolated" => {
                    let _ = writeln!(s, "{}", tr_fill(DISAGREES_ISOLATED, &[model, &f.title]));
                    let _ = writeln!(s, "  {}", f.evidence);
                }
                findings => {
                    let _ = writeln!(s, "{}", tr_fill(DISAGREES_LIKELY, &[model]));
                    let all = super::hints::showing_all();
                    for (k, f) in findings.iter().enumerate() {
                        let _ = writeln!(s, "  - {} [{}]: {}", tr(&f.title), f.id, tr(mistake_why(&f.id)));
                        let _ = writeln!(s, "    {}", f.evidence);
                        if !f.link.is_empty() {
                            let _ = writeln!(s, "    {}", tr_fill(SEE_THE_BOOK, &[&f.link]));
                        }
                        // the likeliest mistake's first hint; every hint of each with --hints
                        if all || k == 0 {
                            for line in super::hints::hint_lines(&f.id, all, "    ", tr) {
                                let _ = writeln!(s, "{line}");
                            }
                        }
                    }
                }
            }
        }
        s.push('\n');
        s += &self.report.format();
        s
    }

    /// The JSON object of `check-shader --format json` (see the book's exercises appendix).
    pub fn to_json(&self) -> serde_json::Value {
        let r = &self.report;
        serde_json::json!({
            "verdict": if self.agrees() { "agrees" } else { "disagrees" },
            "model": r.model.name(),
            "stats": {
                "cases": r.cases,
                "defined": r.defined,
                "failing": r.failing,
                "bound": r.bound,
                "max_abs": finite_or_null(r.vs_f64.max_abs),
                "mean_abs": finite_or_null(r.vs_f64.mean_abs),
                "max_ulps": finite_or_null(r.vs_f64.max_ulps),
            },
            "counterexamples": r.counterexamples,
            "notes": r.notes,
            "diagnosis": self.diagnosis.iter().map(finding_json).collect::<Vec<_>>(),
        })
    }
}

fn finite_or_null(x: f64) -> serde_json::Value {
    if x.is_finite() {
        serde_json::json!(x)
    } else {
        serde_json::Value::Null
    }
}

/// One finding as `{id, title, evidence, link}`.
pub fn finding_json(f: &Finding) -> serde_json::Value {
    serde_json::json!({ "id": f.id, "title": f.title, "evidence": f.evidence, "link": f.link })
}

fn mistake_why(id: &str) -> &'static str {
    Mistake::by_id(id).map_or("", |m| m.why)
}
