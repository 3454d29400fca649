//! `lightlab check-shader FRAG --vertex VERT`: a vertex + fragment pair, checked on
//! triangles.
//!
//! | step | what happens |
//! | --- | --- |
//! | compile | each file is compiled as it is (errors carry that file's line numbers), then the two are linked, so the driver checks that what the fragment shader reads, the vertex shader writes |
//! | map | the vertex shader's attributes and uniforms, and the fragment shader's uniforms, are matched to [`layout::VERTEX_PAIR`] by the tutorials' names (or the `--uniforms` TOML, for both files) |
//! | vertex stage | the vertex shader runs once per vertex of each triangle, as a batch (its `out` variables and `gl_Position` become the batch's outputs) |
//! | interpolate | each value the fragment shader reads is interpolated at the triangle's sample point with its barycentric weights `w` (`flat`: the last vertex's value, OpenGL's provoking vertex) |
//! | fragment stage | the fragment shader runs once per triangle on the interpolated values |
//! | compare | the colour against the `f64` reference interpolated the same way, within [`bounds::VERTEX_PAIR`] |
//!
//! The weights are the triangle's own (perspective-correct) barycentric coordinates, which
//! is what the rasterizer interpolates with for any projection; `gl_Position` therefore
//! does not move the sample, and it is checked on its own: when it is not
//! `projection·view·model·aPos` the report's notes say so.
//!
//! The reference, from the chapter's inputs (`world_k = model·aPos_k`,
//! `n_k = transpose(inverse(mat3(model)))·aNormal_k`, `L` Basic lighting's Phong sum):
//!
//! ```text
//! per fragment (basic_lighting):  L(Σ w_k·world_k, Σ w_k·n_k)
//! per vertex   (gouraud):         Σ w_k·L(world_k, n_k)
//! ```
//!
//! `view` is a random rigid transform per group of triangles, so a pair that lights in view
//! space (positions, normal and light moved by `view`, the eye at the origin) gives the same
//! colours as one that lights in world space, and agrees. `projection` is a perspective.
//!
//! Limits: at most seven values pass from the vertex to the fragment shader, each a
//! `float` or a vector (no arrays or structs); interface blocks match member by member.

use std::cell::RefCell;
use std::fmt::Write as _;

use glam::{DMat3, DVec3, Mat4, Vec4};

use super::glsl::{Parsed, Storage};
use super::mapping::{map_leaves, never_read_notes, Leaf, Mapping};
use super::{check_cases, check_storage, fixed_quantities, rewrite, usage, CheckError, CheckReport, Colour};
use crate::gl::batch::{self, log_excerpt, Batch, Uniform};
use crate::gl::context::{GlContext, GlError};
use crate::gl::layout::{self, Layout};
use crate::gl::model_id::ModelId;
use crate::oracle::cases::{self, bounds, strategies, Quantity, Slot};
use crate::oracle::ErrorAcc;

mod diagnose;

use crate::reference as r64;
pub use diagnose::{
    at_chapter_values, diagnose_pair, mutant_pair, pair_mistakes, reference_pair, verified_pairs, MutantPair,
    PairDiagnosis, Stage, ALL as MESSAGES,
};

/// The layout both shaders are mapped to.
const PAIR: &Layout = &layout::VERTEX_PAIR;

/// Groups of triangles, each with its own `view` and `projection` (one draw each).
pub const PAIR_GROUPS: usize = 8;

/// Most values passed from the vertex to the fragment shader (the vertex batch's outputs,
/// `gl_Position` being one more).
pub const MAX_VARYINGS: usize = batch::MAX_OUTPUTS - 1;

/// The case stream of the pair check (any number not used by [`cases::CASE_MODELS`]).
const STREAM: u64 = 2000;

/// Which reference a pair is compared with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairModel {
    /// Phong per fragment (`--model basic_lighting`): the vertex shader passes the position
    /// and the normal (through the normal matrix), the fragment shader lights.
    PerFragment,
    /// Phong per vertex (`--model gouraud`): the vertex shader lights, the fragment shader
    /// scales the interpolated colour.
    PerVertex,
}

impl PairModel {
    /// The pair reference of `--model` with `--vertex`. Errors: [`CheckError::Usage`]
    /// naming the two models a pair is checked against.
    pub fn for_model(model: ModelId) -> Result<PairModel, CheckError> {
        match model {
            ModelId::BasicLighting => Ok(PairModel::PerFragment),
            ModelId::Gouraud => Ok(PairModel::PerVertex),
            ModelId::Materials
            | ModelId::LightingMaps
            | ModelId::Directional
            | ModelId::Point
            | ModelId::Spot
            | ModelId::MultipleLights
            | ModelId::OpenGLTutorial8
            | ModelId::Ogldev19
            | ModelId::NormalMatrix
            | ModelId::BlinnPhong
            | ModelId::LightingMapsEmission => usage(format!(
                "with --vertex, --model is basic_lighting (Phong per fragment) or gouraud (Phong per vertex), \
                 not `{model}`"
            )),
        }
    }

    /// The model (`--model`) of this pair reference.
    #[must_use]
    pub fn model(self) -> ModelId {
        match self {
            PairModel::PerFragment => ModelId::BasicLighting,
            PairModel::PerVertex => ModelId::Gouraud,
        }
    }
}

/// One value the vertex shader writes and the fragment shader reads.
#[derive(Debug, Clone, PartialEq)]
struct Varying {
    /// The vertex shader's expression (`FragPos`, `vs_out.FragPos`).
    vertex: String,
    /// The fragment shader's expression (`FragPos`, `fs_in.FragPos`).
    fragment: String,
    /// Components: 1 (`float`) to 4 (`vec4`).
    components: usize,
    /// `flat`: the provoking (last) vertex's value, not interpolated.
    flat: bool,
}

/// An interface leaf of one shader: `(match key, expression, type, flat)`. The key is the
/// member or variable name, which is how GLSL matches the two stages.
type InterfaceLeaf = (String, String, String, bool);

/// The `storage` leaves of `parsed` (plain variables and block members).
fn interface(src: &str, parsed: &Parsed, storage: Storage) -> Vec<InterfaceLeaf> {
    let mut out = Vec::new();
    for d in parsed.decls.iter().filter(|d| d.storage == storage) {
        let flat = d.qualifiers.iter().any(|&(a, b)| &src[a..b] == "flat");
        match &d.block {
            None => out.push((d.name.clone(), d.name.clone(), d.ty.clone(), flat)),
            Some(block) => {
                for m in &block.members {
                    let expr = if d.name.is_empty() { m.name.clone() } else { format!("{}.{}", d.name, m.name) };
                    out.push((m.name.clone(), expr, m.ty.clone(), flat));
                }
            }
        }
    }
    out
}

fn components(ty: &str) -> Option<usize> {
    match ty {
        "float" => Some(1),
        "vec2" => Some(2),
        "vec3" => Some(3),
        "vec4" => Some(4),
        _ => None,
    }
}

/// The values passed between the stages: every fragment `in` leaf, matched by name to a
/// vertex `out` leaf. Errors: [`CheckError::Usage`] for an unmatched input, a type other
/// than `float`/`vec2`/`vec3`/`vec4`, or more than [`MAX_VARYINGS`].
fn varyings(vertex_out: &[InterfaceLeaf], fragment_in: &[InterfaceLeaf]) -> Result<Vec<Varying>, CheckError> {
    let mut out = Vec::new();
    for (key, expr, ty, flat) in fragment_in {
        let Some((_, vexpr, vty, vflat)) = vertex_out.iter().find(|v| &v.0 == key) else {
            return usage(format!("the fragment shader reads `{expr}`, which the vertex shader does not write"));
        };
        let Some(n) = components(ty).filter(|_| ty == vty) else {
            return usage(format!(
                "`{expr}` is a {ty} in the fragment shader and a {vty} in the vertex shader; the pair check passes \
                 float, vec2, vec3 and vec4 values"
            ));
        };
        out.push(Varying { vertex: vexpr.clone(), fragment: expr.clone(), components: n, flat: *flat || *vflat });
    }
    if out.len() > MAX_VARYINGS {
        return usage(format!(
            "the fragment shader reads {} values from the vertex shader; the pair check passes at most {MAX_VARYINGS}",
            out.len()
        ));
    }
    Ok(out)
}

/// `mapping` restricted to the names `parsed` declares (the two files share one mapping).
fn mapping_for(mapping: &Mapping, parsed: &Parsed) -> Mapping {
    let declared = |key: &str| {
        parsed.decls.iter().any(|d| {
            d.name == key
                || key.starts_with(&format!("{}.", d.name))
                || key.starts_with(&format!("{}[", d.name))
                || d.block.as_ref().is_some_and(|b| b.members.iter().any(|m| m.name == key))
        })
    };
    let mut m = mapping.clone();
    m.names.retain(|k, _| declared(k));
    m
}

/// Every `[names]` key must be declared by one of the two files.
fn check_mapping_names(mapping: &Mapping, vertex: &Mapping, fragment: &Mapping) -> Result<(), CheckError> {
    for key in mapping.names.keys().filter(|k| !mapping.optional_names.contains(*k)) {
        if !vertex.names.contains_key(key) && !fragment.names.contains_key(key) {
            return usage(format!("{}names.{key}: neither shader declares `{key}`", mapping.at("names", key)));
        }
    }
    Ok(())
}

/// `gl_Position` as a token (not part of a longer name) replaced by `lightlab_Position`,
/// which keeps the line numbers (the vertex shader runs as a fragment batch, where
/// `gl_Position` does not exist).
fn without_gl_position(src: &str) -> String {
    const FROM: &str = "gl_Position";
    let mut out = String::with_capacity(src.len());
    let mut rest = src;
    while let Some(i) = rest.find(FROM) {
        let before = rest[..i].chars().next_back();
        let after = rest[i + FROM.len()..].chars().next();
        let word = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
        out += &rest[..i];
        out += if word(before) || word(after) { FROM } else { "lightlab_Position" };
        rest = &rest[i + FROM.len()..];
    }
    out + rest
}

/// `expr` widened to a `vec4` (zeros after its components).
fn widened(expr: &str, components: usize) -> String {
    match components {
        1 => format!("vec4({expr}, 0.0, 0.0, 0.0)"),
        2 => format!("vec4({expr}, 0.0, 0.0)"),
        3 => format!("vec4({expr}, 0.0)"),
        _ => expr.to_string(),
    }
}

/// The vertex stage's `batch_main`: load, run the user's `main` with the loop counter at 0,
/// write each varying and then `gl_Position`, or the loop guard's mark in `gl_Position`'s
/// place when the cap stopped a loop ([`super::loops`]; [`CompiledPair::run`] marks the
/// vertex's triangles).
fn vertex_wrapper(leaves: &[Leaf], varyings: &[Varying]) -> String {
    let mut s = String::from(
        "\n#line 1 3\nvoid batch_main(in vec4 lightlab_v[LIGHTLAB_N_INPUTS], out vec4 lightlab_o[LIGHTLAB_N_OUTPUTS])\n{\n",
    );
    for line in leaves.iter().filter_map(rewrite::load) {
        s += &line;
    }
    s += &group_loads(leaves);
    s += "    lightlab_loops = 0;\n    lightlab_user_main();\n";
    for (k, v) in varyings.iter().enumerate() {
        let _ = writeln!(s, "    lightlab_o[{k}] = {};", widened(&v.vertex, v.components));
    }
    let _ = writeln!(
        s,
        "    lightlab_o[{}] = lightlab_loops > {cap} ? vec4({mark:.1}) : lightlab_Position;\n}}",
        varyings.len(),
        cap = super::loops::LOOP_CAP,
        mark = super::loops::LOOP_MARK
    );
    s
}

/// `colours` (one per triangle) with the loop guard's mark on every triangle one of whose
/// vertices carries it in `positions` (three per triangle): a triangle is not graded when
/// either of its shaders ran a loop to the cap.
fn mark_capped_vertices(colours: &mut [[f32; 4]], positions: &[[f32; 4]]) {
    for (t, colour) in colours.iter_mut().enumerate() {
        if positions.get(3 * t..3 * t + 3).is_some_and(|p| p.iter().any(super::loops::marked)) {
            *colour = [super::loops::LOOP_MARK; 4];
        }
    }
}

/// The fragment stage's loads of the varyings, from the inputs after the layout's.
fn varying_loads(varyings: &[Varying]) -> String {
    let mut s = String::new();
    for (k, v) in varyings.iter().enumerate() {
        let swizzle = ["", ".x", ".xy", ".xyz", ""][v.components];
        let _ = writeln!(s, "    {} = lightlab_v[{}]{swizzle};", v.fragment, PAIR.n_inputs() + k);
    }
    s
}

/// Compiles a shader's rewritten body into a batch; a failure is a lightlab defect.
fn batch_of<'a>(ctx: &'a GlContext, body: &str, n_inputs: usize, n_outputs: usize) -> Result<Batch<'a>, CheckError> {
    match Batch::new(ctx, body, n_inputs, n_outputs) {
        Ok(b) => Ok(b),
        Err(GlError::Compile { log, .. }) => Err(CheckError::Gl(GlError::Gl {
            call: "compiling the rewritten shader (a lightlab limitation; please report)".into(),
            detail: format!("{log}\n{body}"),
        })),
        Err(e) => Err(e.into()),
    }
}

/// The declarations of one shader that map to the layout: all become globals in the
/// rewrite (the per-case ones are loaded from the inputs, `view` and `projection` from
/// lightlab's own uniforms, [`GROUP_UNIFORMS`]), so one declaration may name both kinds
/// (`uniform mat4 model, view, projection;`).
fn mapped_decls(mapped: &[(usize, Vec<Leaf>)]) -> Vec<usize> {
    mapped.iter().filter(|(_, leaves)| !leaves.is_empty()).map(|(d, _)| *d).collect()
}

/// The uniforms that carry a group's `view` and `projection` (the user's declarations
/// become globals loaded from them).
const GROUP_UNIFORMS: &str = "uniform mat4 lightlab_view;\nuniform mat4 lightlab_projection;\n";

/// Loads of the leaves that map to a group uniform (`view`, `projection`).
fn group_loads(leaves: &[Leaf]) -> String {
    let mut s = String::new();
    for leaf in leaves.iter().filter(|l| l.quantity.is_none()) {
        let _ = writeln!(s, "    {} = lightlab_{};", leaf.user, leaf.model);
    }
    s
}

/// One `vec4` per triangle (or vertex) of each group: `values[group][i]`.
pub type PerGroup = Vec<Vec<[f32; 4]>>;

/// A vertex + fragment pair compiled for the check.
#[derive(Debug)]
pub struct CompiledPair<'a> {
    model: PairModel,
    vertex: Batch<'a>,
    fragment: Batch<'a>,
    vertex_leaves: Vec<Leaf>,
    fragment_leaves: Vec<Leaf>,
    varyings: Vec<Varying>,
    fixed: Vec<(&'static str, [f32; 3])>,
    notes: RefCell<Vec<String>>,
}

/// The triangles of a check, in groups sharing a camera (`view`, `projection`, and the
/// eye, which is every triangle's `viewPos`).
#[derive(Debug, Clone)]
pub struct PairGroup {
    /// `view`, `projection` and the eye ([`strategies::camera_strategy`]).
    pub camera: (Mat4, Mat4, glam::Vec3),
    /// The triangles.
    pub triangles: Vec<strategies::Triangle>,
}

/// What [`CompiledPair::check`] ran and found: the triangles, the fragment shader's colour
/// per triangle, and the verdict.
pub type PairChecked = super::Checked<PairGroup>;

/// Compiles a vertex + fragment pair for `model` (`basic_lighting` or `gouraud`; see
/// the module docs).
///
/// Errors: [`CheckError::VertexCompile`] / [`CheckError::Compile`] with the file's own line
/// numbers; [`CheckError::Usage`] for a model without a pair reference, a pair that does not link, an
/// unmapped name, a type mismatch, no colour output, storage above the limits, or values
/// the pair check cannot pass; [`CheckError::Gl`].
pub fn compile_pair<'a>(
    ctx: &'a GlContext,
    vertex: &str,
    fragment: &str,
    model: ModelId,
    mapping: &Mapping,
) -> Result<CompiledPair<'a>, CheckError> {
    let model = PairModel::for_model(model)?;
    super::pasted_characters(vertex, true)?;
    super::pasted_characters(fragment, false)?;
    let ((vtext, vparsed), (ftext, fparsed)) = (super::read(vertex), super::read(fragment));
    check_storage(vtext.as_deref().unwrap_or(vertex), &vparsed)?;
    check_storage(ftext.as_deref().unwrap_or(fragment), &fparsed)?;
    if let Err(e) = batch::compile_vertex(ctx, vertex) {
        return Err(match e {
            GlError::Compile { log, .. } => CheckError::VertexCompile { excerpt: log_excerpt(vertex, &log), log },
            other => CheckError::Gl(other),
        });
    }
    if let Err(e) = batch::compile_fragment(ctx, fragment) {
        return Err(match e {
            GlError::Compile { log, .. } => CheckError::Compile { excerpt: log_excerpt(fragment, &log), log },
            other => CheckError::Gl(other),
        });
    }
    match batch::link_pair(ctx, vertex, fragment) {
        Ok(()) => {}
        Err(GlError::Link { log }) => return usage(format!("the two shaders do not link:\n{}", log.trim_end())),
        Err(e) => return Err(e.into()),
    }
    let (vertex, mut fragment) = (super::preprocessed(vtext, true)?, super::preprocessed(ftext, false)?);
    let out = Colour::find(&fparsed, &mut fragment)?;
    let (vertex, fragment) = (vertex.as_str(), fragment.as_str());
    if vparsed.main.is_none() || fparsed.main.is_none() {
        return usage("each shader needs a `void main()`");
    }
    let varyings = varyings(&interface(vertex, &vparsed, Storage::Out), &interface(fragment, &fparsed, Storage::In))?;
    let (vmap, fmap) = (mapping_for(mapping, &vparsed), mapping_for(mapping, &fparsed));
    check_mapping_names(mapping, &vmap, &fmap)?;
    let vmapped = map_leaves(PAIR, &vparsed, &vmap, &[Storage::In, Storage::Uniform])?;
    let fmapped = map_leaves(PAIR, &fparsed, &fmap, &[Storage::Uniform])?;
    for leaf in vmapped.iter().chain(&fmapped).flat_map(|(_, l)| l).filter(|l| l.quantity.is_none()) {
        if !matches!(leaf.model.as_str(), "view" | "projection") {
            return usage(format!("`{}` maps to `{}`, which the pair check does not set", leaf.user, leaf.model));
        }
    }
    let (vdecls, fdecls) = (mapped_decls(&vmapped), mapped_decls(&fmapped));
    let vertex_leaves: Vec<Leaf> = vmapped.into_iter().flat_map(|(_, l)| l).collect();
    let fragment_leaves: Vec<Leaf> = fmapped.into_iter().flat_map(|(_, l)| l).collect();
    let both: Vec<Leaf> = vertex_leaves.iter().chain(&fragment_leaves).cloned().collect();
    let mut notes = Vec::new();
    // the eye is the camera's (`view`): an undeclared `viewPos` is not random
    let fixed = fixed_quantities(PAIR, &both, mapping, &["viewPos"], &mut notes)?;
    // a uniform one stage declares and the other reads is read (never_read_notes)
    notes.splice(0..0, never_read_notes(&both, &fixed));
    let vbody = format!(
        "{}{}{GROUP_UNIFORMS}vec4 lightlab_Position;\n#line 1 1\n{}\n{}",
        rewrite::extensions(vertex, &vparsed),
        rewrite::prelude(),
        without_gl_position(&rewrite::rewrite(vertex, &vparsed, &vdecls)),
        vertex_wrapper(&vertex_leaves, &varyings)
    );
    let fbody = format!(
        "{}{}{GROUP_UNIFORMS}{}#line 1 1\n{}\n{}",
        rewrite::extensions(fragment, &fparsed),
        rewrite::prelude(),
        out.declaration,
        rewrite::rewrite(fragment, &fparsed, &fdecls),
        rewrite::wrapper(&fragment_leaves, &(group_loads(&fragment_leaves) + &varying_loads(&varyings)), &out)
    );
    let vertex = batch_of(ctx, &vbody, PAIR.n_inputs(), varyings.len() + 1)?;
    let fragment = batch_of(ctx, &fbody, PAIR.n_inputs() + varyings.len(), 1)?;
    Ok(CompiledPair {
        model,
        vertex,
        fragment,
        vertex_leaves,
        fragment_leaves,
        varyings,
        fixed,
        notes: RefCell::new(notes),
    })
}

/// Writes `value` into every row at `q`'s place (a fixed quantity).
fn fix(rows: &mut [Vec<[f32; 4]>], q: &Quantity, value: [f32; 3]) {
    if let Slot::Case { input, offset } = q.slot {
        let width = if q.ty == cases::QType::Float { 1 } else { 3 };
        for row in rows {
            row[input][offset..offset + width].copy_from_slice(&value[..width]);
        }
    }
}

/// The inputs of a batch, `inputs[k][case]`, from rows.
fn columns<'r>(rows: impl Iterator<Item = &'r Vec<[f32; 4]>> + Clone, n_inputs: usize) -> Vec<Vec<[f32; 4]>> {
    (0..n_inputs).map(|k| rows.clone().map(|r| r[k]).collect()).collect()
}

/// `n` triangles from `seed` in [`PAIR_GROUPS`] groups, each triangle's `viewPos` set to
/// its group's eye and each `fixed` quantity to its value: the triangles
/// [`CompiledPair::check`] runs (`check-shader --vertex --cases n --seed seed`), which the
/// page's pair check runs too ([`crate::live::pair`]).
///
/// Errors: [`CheckError::Usage`] when `n` is outside `1..=`[`cases::MAX_CASES`].
pub fn generate_groups(n: usize, seed: u64, fixed: &[(&'static str, [f32; 3])]) -> Result<Vec<PairGroup>, CheckError> {
    check_cases(n)?;
    let triangles = cases::generate(&strategies::triangle_strategy(), n, cases::seed_bytes(seed, STREAM))?;
    let cameras = cases::generate(&strategies::camera_strategy(), PAIR_GROUPS, cases::seed_bytes(seed, STREAM + 1))?;
    let per_group = n.div_ceil(PAIR_GROUPS).max(1);
    let mut rest = triangles.into_iter();
    let mut groups = Vec::new();
    for camera in cameras {
        let mut triangles: Vec<_> = rest.by_ref().take(per_group).collect();
        if triangles.is_empty() {
            break;
        }
        for t in &mut triangles {
            fix(&mut t.rows, &PAIR.get("viewPos"), camera.2.to_array());
            for (name, value) in fixed {
                fix(&mut t.rows, &PAIR.get(name), *value);
            }
        }
        groups.push(PairGroup { camera, triangles });
    }
    Ok(groups)
}

impl CompiledPair<'_> {
    /// The model the pair is checked against.
    pub fn model(&self) -> PairModel {
        self.model
    }

    /// `n` triangles from `seed` in [`PAIR_GROUPS`] groups, with this pair's fixed
    /// quantities ([`generate_groups`]). Errors: [`CheckError::Usage`] when `n` is outside
    /// `1..=`[`cases::MAX_CASES`].
    pub fn generate(&self, n: usize, seed: u64) -> Result<Vec<PairGroup>, CheckError> {
        generate_groups(n, seed, &self.fixed)
    }

    /// Sets the group's `view` and `projection` on a stage that reads them.
    fn set_group_uniforms(&self, batch: &Batch<'_>, leaves: &[Leaf], group: &PairGroup) -> Result<(), CheckError> {
        let (view, projection, _) = group.camera;
        for leaf in leaves.iter().filter(|l| l.quantity.is_none()) {
            let value = if leaf.model == "view" { view } else { projection };
            match batch.set_uniform(&format!("lightlab_{}", leaf.model), Uniform::Mat4(value.to_cols_array())) {
                Ok(()) => {}
                // never read: its note is there already, or the other stage reads it
                Err(GlError::Input { .. }) if !leaf.read => {}
                Err(GlError::Input { .. }) => {
                    let note = crate::checker::texts::tr_fill(crate::checker::texts::NOTE_INACTIVE, &[&leaf.user]);
                    let mut notes = self.notes.borrow_mut();
                    if !notes.contains(&note) {
                        notes.push(note);
                    }
                }
                Err(e) => return Err(e.into()),
            }
        }
        Ok(())
    }

    /// Runs both stages on `groups`: the fragment shader's colour `outputs[group][triangle]`
    /// and the vertex shader's `gl_Position` per vertex, `positions[group][3·triangle + k]`.
    ///
    /// Errors: [`CheckError::DoesNotTerminate`] when a loop of either shader reached the
    /// loop guard's cap on some triangle; [`CheckError::Gl`] if a draw fails.
    pub fn run(&self, groups: &[PairGroup]) -> Result<(PerGroup, PerGroup), CheckError> {
        let mut colours = Vec::with_capacity(groups.len());
        let mut positions = Vec::with_capacity(groups.len());
        for group in groups {
            self.set_group_uniforms(&self.vertex, &self.vertex_leaves, group)?;
            self.set_group_uniforms(&self.fragment, &self.fragment_leaves, group)?;
            let vertex_rows = group.triangles.iter().flat_map(|t| t.rows.iter());
            let mut vertex_out = self.vertex.run(&columns(vertex_rows, PAIR.n_inputs()))?;
            let varying_columns: Vec<Vec<[f32; 4]>> = vertex_out[..self.varyings.len()]
                .iter()
                .zip(&self.varyings)
                .map(|(per_vertex, v)| {
                    group
                        .triangles
                        .iter()
                        .enumerate()
                        .map(|(t, tri)| interpolate(v, &per_vertex[3 * t..], tri))
                        .collect()
                })
                .collect();
            let mut inputs = columns(group.triangles.iter().map(|t| &t.rows[0]), PAIR.n_inputs());
            inputs.extend(varying_columns);
            let mut colour = self.fragment.run(&inputs)?;
            let position = vertex_out.swap_remove(self.varyings.len());
            mark_capped_vertices(&mut colour[0], &position);
            colours.push(colour.swap_remove(0));
            positions.push(position);
        }
        super::terminated(&colours)?;
        Ok((colours, positions))
    }

    /// The whole check: [`Self::generate`], [`Self::run`], and the comparison with the
    /// reference (see the module docs).
    ///
    /// Errors: as [`Self::generate`] and [`Self::run`].
    pub fn check(&self, n: usize, seed: u64) -> Result<PairChecked, CheckError> {
        let groups = self.generate(n, seed)?;
        let (outputs, positions) = self.run(&groups)?;
        let mut notes = self.notes.borrow().clone();
        if let Some(note) = position_note(&groups, &positions) {
            notes.push(note);
        }
        let report = compare(self.model, &groups, &outputs, &self.vertex_leaves, &self.fragment_leaves, notes);
        Ok(PairChecked { groups, outputs, report })
    }
}

/// A varying at the triangle's sample point, in `f32` as the rasterizer does:
/// `w0·a + w1·b + w2·c` per component (`flat`: the last vertex's value).
fn interpolate(v: &Varying, per_vertex: &[[f32; 4]], t: &strategies::Triangle) -> [f32; 4] {
    if v.flat {
        return per_vertex[2];
    }
    let [a, b, c] = [0, 1, 2].map(|k| Vec4::from_array(per_vertex[k]));
    (a * t.weights[0] + b * t.weights[1] + c * t.weights[2]).to_array()
}

/// The triangle's vertex `k`: world position `model·aPos` and normal (normal matrix ·
/// `aNormal`), in `f64`.
fn world_vertex(t: &strategies::Triangle, k: usize) -> (DVec3, DVec3) {
    let row = layout::Row(&t.rows[k]);
    let m = r64::dmat4(row.mat4(PAIR.get("model")));
    let world = m.transform_point3(row.dvec3(PAIR.get("aPos")));
    let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
    (world, nm.map_or(DVec3::ZERO, |nm| nm * row.dvec3(PAIR.get("aNormal"))))
}

/// The reference colour of a triangle (see the module docs).
pub fn reference(model: PairModel, t: &strategies::Triangle) -> DVec3 {
    let row = layout::Row(&t.rows[0]);
    let lighting = r64::phong::BasicLighting {
        light_pos: row.dvec3(PAIR.get("lightPos")),
        view_pos: row.dvec3(PAIR.get("viewPos")),
        light_color: row.dvec3(PAIR.get("lightColor")),
        object_color: row.dvec3(PAIR.get("objectColor")),
        ambient_strength: f64::from(row.float(PAIR.get("ambientStrength"))),
        specular_strength: f64::from(row.float(PAIR.get("specularStrength"))),
        shininess: f64::from(row.float(PAIR.get("shininess"))),
    };
    let w = t.weights.map(f64::from);
    let vertices = [0, 1, 2].map(|k| world_vertex(t, k));
    match model {
        PairModel::PerFragment => {
            let pos: DVec3 = (0..3).map(|k| vertices[k].0 * w[k]).sum();
            let normal: DVec3 = (0..3).map(|k| vertices[k].1 * w[k]).sum();
            lighting.terms(pos, normal).sum()
        }
        PairModel::PerVertex => (0..3).map(|k| lighting.terms(vertices[k].0, vertices[k].1).sum() * w[k]).sum(),
    }
}

/// A note when the vertex shader's `gl_Position` is not `projection·view·model·aPos`
/// (relative error above `1e-4`, far above `f32` rounding of two 4×4 products).
fn position_note(groups: &[PairGroup], positions: &[Vec<[f32; 4]>]) -> Option<String> {
    let (mut wrong, mut total) = (0usize, 0usize);
    for (group, got) in groups.iter().zip(positions) {
        let (view, projection, _) = group.camera;
        for (i, row) in group.triangles.iter().flat_map(|t| t.rows.iter()).enumerate() {
            let r = layout::Row(row);
            let want = projection * view * r.mat4(PAIR.get("model")) * r.vec3(PAIR.get("aPos")).extend(1.0);
            let got = Vec4::from_array(got[i]);
            total += 1;
            if (got - want).length() > 1e-4 * (1.0 + want.length()) {
                wrong += 1;
            }
        }
    }
    (wrong > 0).then(|| {
        format!(
            "gl_Position is not projection * view * model * vec4(aPos, 1.0) at {wrong} of {total} vertices \
             (the colours are checked at the triangle's own sample points, so this does not change the verdict; \
             on screen the triangle would be drawn elsewhere)"
        )
    })
}

fn describe(t: &strategies::Triangle, leaves: &[&Leaf], want: DVec3, got: &[f32; 4]) -> String {
    let mut s = String::new();
    for k in 0..3 {
        let r = layout::Row(&t.rows[k]);
        let (a, n) = (r.vec3(PAIR.get("aPos")), r.vec3(PAIR.get("aNormal")));
        let _ = writeln!(s, "  vertex {k}: aPos = {:?}, aNormal = {:?}", a.to_array(), n.to_array());
    }
    let _ = writeln!(s, "  weights = {:?}", t.weights);
    let row = layout::Row(&t.rows[0]);
    for name in ["model", "lightPos", "viewPos", "lightColor", "objectColor", "ambientStrength", "specularStrength"]
        .into_iter()
        .chain(["shininess"])
    {
        let q = PAIR.get(name);
        let declared = leaves.iter().any(|l| l.quantity.is_some_and(|lq| lq.name == name));
        let value = match q.ty {
            cases::QType::Float => format!("{:?}", row.float(q)),
            cases::QType::Mat4 => format!("columns {:?}", row.mat4(q).to_cols_array_2d()),
            _ => format!("{:?}", row.vec3(q).to_array()),
        };
        let _ = writeln!(s, "  {}{name} = {value}", if declared { "" } else { "(not declared) " });
    }
    let _ = writeln!(s, "  expected (f64) = [{:.7}, {:.7}, {:.7}]", want.x, want.y, want.z);
    let _ = write!(s, "  got (llvmpipe) = [{:.7}, {:.7}, {:.7}]", got[0], got[1], got[2]);
    s
}

/// Compares the fragment colours with the reference on every triangle (all are defined:
/// the triangles keep the light and eye away from the sample and the normal away from 0).
fn compare(
    model: PairModel,
    groups: &[PairGroup],
    outputs: &[Vec<[f32; 4]>],
    vertex_leaves: &[Leaf],
    fragment_leaves: &[Leaf],
    notes: Vec<String>,
) -> CheckReport {
    let bound = bounds::VERTEX_PAIR;
    let mut acc = ErrorAcc::default();
    let (mut failing, mut index) = (0, 0);
    let mut worst: Vec<(f64, usize, usize)> = Vec::new();
    for (g, group) in groups.iter().enumerate() {
        for (i, t) in group.triangles.iter().enumerate() {
            let want = reference(model, t).to_array();
            let got: Vec<f64> = outputs[g][i][..3].iter().map(|&x| f64::from(x)).collect();
            let abs = acc.add(index, &got, &want);
            index += 1;
            if abs > bound {
                failing += 1;
            }
            worst.push((abs, g, i));
        }
    }
    let stats = acc.finish();
    worst.sort_by(|a, b| b.0.total_cmp(&a.0));
    let leaves: Vec<&Leaf> = vertex_leaves.iter().chain(fragment_leaves).collect();
    let counterexamples = worst
        .iter()
        .take(3)
        .filter(|w| w.0 > bound)
        .map(|&(_, g, i)| {
            let t = &groups[g].triangles[i];
            describe(t, &leaves, reference(model, t), &outputs[g][i])
        })
        .collect();
    CheckReport {
        model: model.model(),
        cases: index,
        defined: stats.count,
        bound,
        vs_f64: stats,
        failing,
        counterexamples,
        notes,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_with_a_capped_vertex_is_marked() {
        let mark = [super::super::loops::LOOP_MARK; 4];
        let mut colours = [[0.5; 4], [0.25; 4]];
        let mut positions = [[1.0; 4]; 6];
        positions[4] = mark;
        mark_capped_vertices(&mut colours, &positions);
        assert_eq!(colours, [[0.5; 4], mark], "the second triangle's middle vertex ran to the cap");
        mark_capped_vertices(&mut colours, &positions[..2]);
        assert_eq!(colours[0], [0.5; 4], "a short position list marks nothing");
    }

    #[test]
    fn gl_position_is_replaced_only_as_a_whole_word() {
        let src = "gl_Position = p; my_gl_Position = q; gl_PositionX; gl_Position.x";
        assert_eq!(
            without_gl_position(src),
            "lightlab_Position = p; my_gl_Position = q; gl_PositionX; lightlab_Position.x"
        );
    }

    #[test]
    fn varyings_match_by_name_and_refuse_what_cannot_pass() {
        let leaf = |k: &str, e: &str, t: &str| (k.to_string(), e.to_string(), t.to_string(), false);
        let vs = [leaf("FragPos", "vs_out.FragPos", "vec3"), leaf("Normal", "Normal", "vec3")];
        let got = varyings(&vs, &[leaf("FragPos", "fs_in.FragPos", "vec3")]).unwrap();
        assert_eq!(got[0].vertex, "vs_out.FragPos");
        assert_eq!(got[0].fragment, "fs_in.FragPos");
        assert!(varyings(&vs, &[leaf("Color", "Color", "vec3")]).is_err());
        assert!(varyings(&vs, &[leaf("Normal", "Normal", "vec4")]).is_err());
        let many: Vec<InterfaceLeaf> = (0..8).map(|i| leaf(&format!("v{i}"), &format!("v{i}"), "float")).collect();
        assert!(varyings(&many, &many).is_err(), "more than {MAX_VARYINGS} values");
    }

    #[test]
    fn the_sample_is_interpolated_with_the_weights_and_flat_takes_the_last_vertex() {
        let t = strategies::Triangle { rows: [vec![], vec![], vec![]], weights: [0.5, 0.25, 0.25] };
        let smooth = Varying { vertex: String::new(), fragment: String::new(), components: 3, flat: false };
        let per_vertex = [[4.0, 0.0, 0.0, 0.0], [0.0, 8.0, 0.0, 0.0], [0.0, 0.0, 16.0, 0.0]];
        assert_eq!(interpolate(&smooth, &per_vertex, &t), [2.0, 2.0, 4.0, 0.0]);
        let flat = Varying { flat: true, ..smooth };
        assert_eq!(interpolate(&flat, &per_vertex, &t), per_vertex[2]);
    }
}
