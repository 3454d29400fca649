//! The page's vertex + fragment pair check: the data `check-shader --vertex` decides by,
//! emitted for the page.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | pair model | `basic_lighting` (Phong per fragment) or `gouraud` (Phong per vertex) ([`PairModel`]) |
//! | triangle | three vertices (`aPos`, `aNormal`), the uniforms they share, and the barycentric weights of the sample the fragment shader runs at |
//! | group | triangles sharing a camera: `view` and `projection` are set once per group |
//! | expected | the `f64` reference's colour at the sample ([`pair::reference`]), `expected[group][triangle]` |
//!
//! The triangles are [`pair::generate_groups`]`(`[`N_PAIR_CASES`]`, `[`SEED`]`, fixed)`,
//! the ones `lightlab check-shader --vertex V F --model M --cases` [`N_PAIR_CASES`]
//! `--seed` [`SEED`] runs on the reference pair, `fixed` being the quantities the chapter
//! gives a value and the reference pair hard-codes (the strengths). The verdict's rule is
//! [`crate::checker::diagnose::case_fails`] against `expected` within `bound`
//! ([`crate::oracle::cases::bounds::VERTEX_PAIR`]); a mutant pair matches the reader's when
//! their colours are within `match_tolerance` on all but `mistake_share` of the triangles,
//! as [`pair::diagnose_pair`] decides. The page runs the reader's pair and the mutant
//! pairs itself; it computes no colour.

use serde_json::{json, Map, Value};

use super::exercises::SEED;
use super::programs::ES_HEADER;
use crate::checker::check::glsl::{self, Storage};
use crate::checker::check::pair::{self, PairGroup, PairModel};
use crate::checker::diagnose::MISMATCH_SHARE;
use crate::gl::layout::{self, Row};
use crate::oracle::cases::{bounds, QType, Slot};

/// Triangles per page check. 128 (16 per group) keeps the page data small; every
/// vertex-stage mutant differs from the reference on a large share of triangles
/// (`tests/gl_pair.rs` checks that each disagrees and is named on these triangles).
pub const N_PAIR_CASES: usize = 128;

/// The quantities that differ between the three vertices of a triangle (the vertex
/// attributes); every other quantity is shared by the triangle
/// ([`crate::oracle::cases::strategies::triangle_strategy`]).
pub const PER_VERTEX: [&str; 2] = ["aPos", "aNormal"];

/// The quantities the check fixes for a pair: each per-case quantity with a chapter value
/// that neither shader declares as a uniform or input (the shaders hard-code it), with
/// that value (`crate::checker::check`'s policy, without a mapping).
#[must_use]
pub fn fixed_for(vertex: &str, fragment: &str) -> Vec<(&'static str, [f32; 3])> {
    let declared = |name: &str| {
        [vertex, fragment].iter().any(|src| {
            glsl::parse(src).decls.iter().any(|d| matches!(d.storage, Storage::Uniform | Storage::In) && d.name == name)
        })
    };
    layout::VERTEX_PAIR
        .quantities
        .iter()
        .filter_map(|q| match (q.default, q.slot) {
            (Some(v), Slot::Case { .. }) if !declared(q.name) => Some((q.name, v)),
            _ => None,
        })
        .collect()
}

/// One quantity of a row as JSON: a number (`float`), 3 numbers (`vec3`) or 16 (`mat4`,
/// column-major, as `uniformMatrix4fv` takes it).
fn value_json(row: Row<'_>, name: &str) -> Value {
    let q = layout::VERTEX_PAIR.get(name);
    match q.ty {
        QType::Float => json!(f64::from(row.float(q))),
        QType::Mat4 => json!(row.mat4(q).to_cols_array().map(f64::from)),
        QType::Vec2 | QType::Vec3 | QType::Texel => json!(row.vec3(q).to_array().map(f64::from)),
    }
}

/// A group as JSON: `view`, `projection` (column-major) and its triangles, each with its
/// shared `uniforms`, its three `vertices` and its `weights`.
fn group_json(group: &PairGroup) -> Value {
    let (view, projection, _) = group.camera;
    let shared: Vec<&str> = layout::VERTEX_PAIR
        .quantities
        .iter()
        .filter(|q| matches!(q.slot, Slot::Case { .. }) && !PER_VERTEX.contains(&q.name))
        .map(|q| q.name)
        .collect();
    let triangles: Vec<Value> = group
        .triangles
        .iter()
        .map(|t| {
            let uniforms: Map<String, Value> =
                shared.iter().map(|&n| (n.to_string(), value_json(Row(&t.rows[0]), n))).collect();
            let vertices: Vec<Value> = t
                .rows
                .iter()
                .map(|r| {
                    let v: Map<String, Value> =
                        PER_VERTEX.iter().map(|&n| (n.to_string(), value_json(Row(r), n))).collect();
                    Value::Object(v)
                })
                .collect();
            json!({ "uniforms": uniforms, "vertices": vertices, "weights": t.weights.map(f64::from) })
        })
        .collect();
    json!({
        "view": view.to_cols_array().map(f64::from),
        "projection": projection.to_cols_array().map(f64::from),
        "triangles": triangles,
    })
}

/// The page's data for checking a pair against `model` (see the module docs): the rule,
/// the triangles with their expected colours, the reference pair and every
/// mutant pair of [`pair::pair_mistakes`] (GLSL 3.30 text; the page swaps the `#version` line for
/// `es_header`).
///
/// Errors: a message naming the model when the triangles or a mutant cannot be made (a
/// lightlab defect: the catalogue's patterns no longer match the verified pairs).
pub fn pair_json(model: PairModel) -> Result<Value, String> {
    let (rv, rf) = pair::reference_pair(model);
    let fixed = fixed_for(rv, rf);
    let groups =
        pair::generate_groups(N_PAIR_CASES, SEED, &fixed).map_err(|e| format!("pair {}: {e}", model.model()))?;
    let mut mutants = Vec::new();
    for pair::MutantPair { mistake, vertex, fragment } in
        pair::pair_mistakes(model).map_err(|e| format!("pair {}: {e}", model.model()))?
    {
        mutants.push(json!({
            "id": mistake.id, "title": mistake.title, "why": mistake.why, "link": mistake.link,
            "vertex": vertex, "fragment": fragment,
        }));
    }
    let bound = bounds::VERTEX_PAIR;
    Ok(json!({
        "model": model.model().name(),
        "verdict": { "rule": "f64", "bound": bound },
        "match_tolerance": 2.0 * bound,
        "mistake_share": MISMATCH_SHARE,
        "n_cases": N_PAIR_CASES,
        "seed": SEED,
        "fixed": fixed.iter().map(|(n, _)| *n).collect::<Vec<_>>(),
        "per_vertex": PER_VERTEX,
        "groups": groups.iter().map(group_json).collect::<Vec<_>>(),
        "expected": groups
            .iter()
            .map(|g| g.triangles.iter().map(|t| pair::reference(model, t).to_array()).collect::<Vec<_>>())
            .collect::<Vec<_>>(),
        "guard": super::guard::guard_json(),
        "loop_text": super::exercises::LOOP_TEXT,
        "reference": { "vertex": rv, "fragment": rf },
        "mutants": mutants,
        "es_header": ES_HEADER,
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_pairs_fix_the_strengths_they_hard_code() {
        for model in [PairModel::PerFragment, PairModel::PerVertex] {
            let (v, f) = pair::reference_pair(model);
            let names: Vec<&str> = fixed_for(v, f).iter().map(|(n, _)| *n).collect();
            assert_eq!(names, ["ambientStrength", "specularStrength", "shininess"], "{}", model.model());
        }
        let declared = "uniform float shininess;\nvoid main() {}";
        let names: Vec<&str> = fixed_for(declared, "void main() {}").iter().map(|(n, _)| *n).collect();
        assert_eq!(names, ["ambientStrength", "specularStrength"]);
    }

    #[test]
    fn only_the_attributes_differ_between_a_triangles_vertices() {
        let groups = pair::generate_groups(64, SEED, &[]).unwrap();
        for t in groups.iter().flat_map(|g| &g.triangles) {
            for q in layout::VERTEX_PAIR.quantities.iter().filter(|q| matches!(q.slot, Slot::Case { .. })) {
                let per_row: Vec<Value> = t.rows.iter().map(|r| value_json(Row(r), q.name)).collect();
                let same = per_row.iter().all(|v| *v == per_row[0]);
                assert_eq!(!same, PER_VERTEX.contains(&q.name), "{}: {per_row:?}", q.name);
            }
        }
    }

    #[test]
    fn the_data_names_every_vertex_mutant_of_the_model() {
        let v = pair_json(PairModel::PerFragment).unwrap();
        let ids: Vec<&str> = v["mutants"].as_array().unwrap().iter().map(|m| m["id"].as_str().unwrap()).collect();
        assert!(ids.contains(&"gouraud-for-phong") && ids.contains(&"normal-matrix-missing"), "{ids:?}");
        assert!(ids.contains(&"light-not-in-view-space"), "{ids:?}");
        let triangles: usize =
            v["groups"].as_array().unwrap().iter().map(|g| g["triangles"].as_array().unwrap().len()).sum();
        assert_eq!(triangles, N_PAIR_CASES);
    }
}
