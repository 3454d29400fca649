//! The data of the in-page checker: one JSON document with the mistake catalogue, the
//! exercises, every model's case layout, bound, reference and mutant GLSL, and a fixed set
//! of cases with their defined flags.
//!
//! # Schema (version 1)
//! ```text
//! {
//!   "version": 1,
//!   "mistake_share": f,          // a mutant matches if it differs on at most this share of defined cases
//!   "isolation": {KEY: text},    // the isolation step's sentences, `{}` for each blank (isolation::ISOLATION_TEXTS)
//!   "layouts": {...},            // crate::gl::layout::export_json, embedded as it is
//!   "mistakes": [{id, title, why, link, models: [model], equivalent: [id], equivalence_reason}],
//!   "exercises": [{id, chapter, source, title, statement, kind: "shader"|"variant"|"numeric"|"choice",
//!                  model?, mapping?, starter, solution, functions?,       // functions: the GLSL the learner must match
//!                  tolerance?, choices?}],                                 // numeric and choice answers are not exported
//!   "models": {NAME: {
//!       "switches": [{name, quantities: [NAME], uniforms: [NAME]}],      // the isolation step's switches, in order
//!       "flag_labels": [text],                                            // the case predicates (N·L < 0, ...)
//!       "n_inputs": k, "bound": f, "match_tolerance": f,                  // 2·bound for learner-vs-mutant
//!       "quantities": [{name, type: "float"|"vec2"|"vec3"|"texel"|"mat4",
//!                       slot: {input, offset} | "group" | "unused", default?: [f, f, f]}],
//!       "functions": GLSL, "harness": GLSL, "outputs": [text],         // absent for a model without a function file
//!       "mutants": {ID: GLSL},                                             // the rewritten function file
//!       "cases": {"seed": u64, "groups": [{"uniforms": {NAME: number | [f, f, f]},
//!                                          "rows": [[[f, f, f, f] × n_inputs]], "defined": [bool],
//!                                          "flags": [[bool × flag_labels] per row]}]}}}
//! }
//! ```
//! Numbers are `f32` values written as the shortest decimal that reads back to the same
//! `f32` (`serde_json` on `f64` widened from `f32`). The document is the same on every run
//! for the same `n_cases` and `seed`.

use serde_json::{json, Map, Value};

use super::{Check, EXERCISES};
use crate::checker::complete;
use crate::checker::diagnose::{self, MISMATCH_SHARE};
use crate::checker::isolation;
use crate::checker::mistakes;
use crate::gl::batch::Uniform;
use crate::oracle::cases::{self, CaseModel, Class, Group, QType, Slot};

fn f(x: f32) -> Value {
    if x.is_finite() {
        json!(f64::from(x))
    } else {
        Value::Null
    }
}

fn uniform_json(u: &Uniform) -> Value {
    match u {
        Uniform::Int(i) => json!(i),
        Uniform::Float(x) => f(*x),
        Uniform::Vec3(v) => Value::Array(v.iter().map(|x| f(*x)).collect()),
        Uniform::Vec4(v) => Value::Array(v.iter().map(|x| f(*x)).collect()),
        Uniform::Mat4(m) => Value::Array(m.iter().map(|x| f(*x)).collect()),
    }
}

fn qtype(t: QType) -> &'static str {
    match t {
        QType::Float => "float",
        QType::Vec2 => "vec2",
        QType::Vec3 => "vec3",
        QType::Texel => "texel",
        QType::Mat4 => "mat4",
    }
}

/// The cases of `groups` as the schema's `groups` (uniforms, rows, defined flags, case flags).
pub fn groups_json(model: &CaseModel, groups: &[Group]) -> Vec<Value> {
    groups
        .iter()
        .map(|g| {
            let uniforms: Map<String, Value> = g.uniforms.iter().map(|(n, u)| (n.clone(), uniform_json(u))).collect();
            let rows: Vec<Value> = g
                .rows
                .iter()
                .map(|r| Value::Array(r.iter().map(|v| Value::Array(v.iter().map(|x| f(*x)).collect())).collect()))
                .collect();
            let defined: Vec<bool> =
                g.rows.iter().map(|r| model.classify(r, g.scene.as_ref()) == Class::Defined).collect();
            let flags: Vec<Vec<bool>> = g.rows.iter().map(|r| isolation::case_flags(model, r).1).collect();
            json!({ "uniforms": uniforms, "rows": rows, "defined": defined, "flags": flags })
        })
        .collect()
}

/// The `f64` reference's rgb on `groups` ([`diagnose::expected_values`]) as JSON: per group,
/// per case `[r, g, b]` (`f64`, shortest decimal that reads back the same), `null` where the
/// model is not defined.
pub fn expected_json(model: &CaseModel, groups: &[Group]) -> Value {
    let value = |want: &Option<[f64; 3]>| want.map_or(Value::Null, |w| json!(w));
    Value::Array(
        diagnose::expected_values(model, groups)
            .iter()
            .map(|rows| Value::Array(rows.iter().map(value).collect()))
            .collect(),
    )
}

fn model_json(model: &CaseModel, n_cases: usize, seed: u64) -> Option<Value> {
    // A model with a function file but no complete shader (blinn_phong) is not exported; one
    // without a function file would come without its GLSL and mutants.
    let shader = model.shader;
    if shader.is_some() && complete::reference(model.id).is_none() {
        return None;
    }
    // The page checks fragment shaders, as check-shader does (not the per-vertex gouraud).
    if crate::checker::check::model_for_check(model.id).is_err() {
        return None;
    }
    let quantities: Vec<Value> = model
        .quantities
        .iter()
        .map(|q| {
            let slot = match q.slot {
                Slot::Case { input, offset } => json!({ "input": input, "offset": offset }),
                Slot::Group => json!("group"),
                Slot::Unused => json!("unused"),
            };
            let mut o = json!({ "name": q.name, "type": qtype(q.ty), "slot": slot });
            if let Some(d) = q.default {
                o["default"] = Value::Array(d.iter().map(|x| f(*x)).collect());
            }
            o
        })
        .collect();
    let mut mutants = Map::new();
    for m in mistakes::for_model(model.id) {
        if let Ok(text) = m.mutate(model.id) {
            mutants.insert(m.id.into(), json!(text));
        }
    }
    let groups_data = cases::generate_cases(model, n_cases, seed, &[]).ok()?;
    let groups = groups_json(model, &groups_data);
    let uniform_names: Vec<&str> =
        groups_data.first().map_or(Vec::new(), |g| g.uniforms.iter().map(|(n, _)| n.as_str()).collect());
    let switches: Vec<Value> = isolation::switch_plan(model, &uniform_names)
        .into_iter()
        .map(|s| json!({ "name": s.name, "quantities": s.quantities, "uniforms": s.uniforms, "hints": s.hints }))
        .collect();
    let flag_labels =
        groups_data.first().and_then(|g| g.rows.first()).map_or(Vec::new(), |r| isolation::case_flags(model, r).0);
    let mut out = json!({
        "switches": switches,
        "flag_labels": flag_labels,
        "n_inputs": model.n_inputs,
        "bound": model.bound,
        "match_tolerance": 2.0 * model.bound,
        "quantities": quantities,
        "mutants": mutants,
        "cases": { "seed": seed, "groups": groups },
    });
    if let Some(shader) = shader {
        out["functions"] = json!(shader.functions());
        out["harness"] = json!(shader.harness());
        out["outputs"] = json!(shader.outputs());
    }
    Some(out)
}

/// The isolation step's sentences by key ([`isolation::ISOLATION_TEXTS`]), with the hints
/// for an isolation that located no switch: `hints_when` (`{}` the conditions),
/// `hints_unswitched` (`{}` the terms the shader cannot switch off) and `hints_nowhere`. A located switch carries its own `hints` in `switches`.
fn isolation_json() -> Value {
    let mut map: Map<String, Value> =
        isolation::ISOLATION_TEXTS.iter().map(|(k, t)| (k.to_string(), json!(t))).collect();
    map.insert("hints_when".into(), json!(crate::checker::hints::WHEN_HINTS));
    map.insert("hints_nowhere".into(), json!(crate::checker::hints::NOWHERE_HINTS));
    map.insert("hints_unswitched".into(), json!(crate::checker::hints::UNSWITCHED_HINTS));
    Value::Object(map)
}

fn exercise_json(e: &super::Exercise) -> Value {
    let mut o = json!({
        "id": e.id,
        "chapter": e.chapter,
        "source": e.source,
        "title": e.title,
        "statement": e.statement,
        "starter": e.starter(),
    });
    match e.check {
        Check::Shader { model, mapping } | Check::Variant { model, mapping, .. } => {
            let kind = if matches!(e.check, Check::Shader { .. }) { "shader" } else { "variant" };
            o["kind"] = json!(kind);
            o["model"] = json!(model.name());
            o["mapping"] = json!(mapping);
            o["solution"] = json!(e.solution());
            if let Some(functions) = e.functions() {
                o["functions"] = json!(functions);
            }
        }
        Check::Pair { model } => {
            o["kind"] = json!("pair");
            o["model"] = json!(model.model().name());
            o["solution"] = json!(e.solution());
            o["vertex_solution"] = json!(e.vertex_solution());
            o["vertex_starter"] = json!(e.vertex_starter());
        }
        Check::Numeric { tolerance, unit, .. } => {
            o["kind"] = json!("numeric");
            o["tolerance"] = json!(tolerance);
            o["unit"] = json!(unit);
        }
        Check::Choice { choices, .. } => {
            o["kind"] = json!("choice");
            o["choices"] = json!(choices);
        }
    }
    o
}

/// The in-page checker's document (see the module docs) with `n_cases` cases per model
/// from `seed`. The per-vertex `gouraud` is left out.
pub fn browser_json(n_cases: usize, seed: u64) -> Value {
    let mistakes: Vec<Value> = mistakes::fragment_mistakes()
        .into_iter()
        .map(|(m, models)| {
            let eq = m.equivalence();
            json!({
                "id": m.id,
                "title": m.title,
                "why": m.why,
                "hints": m.hints().map_or(&[][..], |h| &h[..]),
                "link": m.link,
                "models": models.iter().map(|m| m.name()).collect::<Vec<_>>(),
                "equivalent": eq.map_or(Vec::new(), |e| e.ids.iter().filter(|id| **id != m.id).copied().collect()),
                "equivalence_reason": eq.map_or("", |e| e.reason),
            })
        })
        .collect();
    let mut models = Map::new();
    for model in &cases::CASE_MODELS {
        if let Some(v) = model_json(model, n_cases, seed) {
            models.insert(model.name().into(), v);
        }
    }
    let layouts: Value = serde_json::from_str(&crate::gl::layout::export_json()).unwrap_or(Value::Null);
    json!({
        "version": 1,
        "mistake_share": MISMATCH_SHARE,
        "isolation": isolation_json(),
        "layouts": layouts,
        "mistakes": mistakes,
        "exercises": EXERCISES.iter().map(exercise_json).collect::<Vec<_>>(),
        "models": models,
    })
}
