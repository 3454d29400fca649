//! The packed layouts of the GL models: one description per model, read by the harnesses'
//! callers, the oracle's reports, `check-shader`, the Rust answers and (as JSON) the book.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | input | one `vec4` per case, read by the batch with `texelFetch` (`v[k]` in a harness) |
//! | component | `x`, `y`, `z`, `w` of an input (offset 0 to 3) |
//! | quantity | a named value of the tutorial (`lightPos`, `light.cutOff`, `model`) at an input and a component offset |
//! | group quantity | a uniform shared by a group of cases (the multiple-lights scene) |
//!
//! Each [`Layout`] is the single source of:
//! - the input labels of the oracle's reports ([`Layout::input_labels`]);
//! - the input count ([`Layout::n_inputs`]);
//! - the positions the Rust answers read ([`Layout::get`], a `const fn`: a misspelt name is a
//!   compile error, and a [`Row`] reads the resolved place);
//! - the names `check-shader` maps a user's declarations to;
//! - the multiple-lights scene's uniforms ([`scene_uniforms`] of the core's
//!   [`Scene::learnopengl_default`]);
//! - the JSON export ([`export_json`]).
//!
//! # The JSON export
//! `lightlab oracle --layouts` prints [`export_json`]: one object, byte-identical on every
//! run, keys in this order:
//! ```text
//! {
//!   "schema": 1,
//!   "models": [                           // every case model, in chapter order, then normal_matrix
//!     {
//!       "model": "basic_lighting",        // the name --model takes
//!       "source": "LearnOpenGL, ...",     // the chapter
//!       "tutorial_shader": true,          // false: check-shader only (normal_matrix)
//!       "n_inputs": 6,                    // vec4 inputs per case
//!       "n_outputs": 2,                   // vec4 outputs per case of the tutorial harness
//!       "inputs": ["FragPos.xyz, ambientStrength", ...],   // label of each input, "-" = unused component
//!       "outputs": ["result.rgb, 1", ...],                 // meaning of each output
//!       "quantities": [
//!         {
//!           "name": "FragPos",            // the tutorial's name
//!           "type": "vec3",               // float | vec2 | vec3 | texel | mat4 (texel: a sampled colour)
//!           "storage": "case",            // case | group (a uniform per group) | unused (loaded as zero)
//!           "input": 0,                   // null unless storage is case
//!           "offset": 0,                  // first component, null unless storage is case
//!           "components": 3,              // float 1, vec3 3, texel 3 or 4, mat4 16 (4 inputs)
//!           "label": "FragPos.xyz",       // the report's words for it
//!           "default": null,              // the chapter's value, [x, y, z], or null (random)
//!           "range": [-5.0, 5.0]          // every sampled component lies in it; null for group and unused
//!         }, ...
//!       ],
//!       "uniforms": [                     // the chapter's group uniforms (multiple_lights), else []
//!         {"name": "dirLight.direction", "type": "vec3", "value": [-0.2, -1.0, -0.3]}, ...
//!       ]
//!     }, ...
//!   ]
//! }
//! ```
//! Numbers are `f32` values written in Rust's shortest round-trip form.

use glam::{DVec3, Mat4, Vec3};

use super::batch::Uniform;
use super::model_id::ModelId;
use crate::scene::Scene;

mod json;
mod tables;

pub use json::export_json;
pub use tables::*;

/// What a model quantity is, for `check-shader`'s generated loads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum QType {
    /// `float`.
    Float,
    /// `vec2` (texture coordinates; not compared, always zero).
    Vec2,
    /// `vec3`.
    Vec3,
    /// A sampled texel, read by `texture(...)`: the input's `vec4`.
    Texel,
    /// `mat4`, four consecutive inputs as columns.
    Mat4,
}

impl QType {
    /// The name in the JSON export and in messages (`texel` is a sampled colour).
    pub fn name(self) -> &'static str {
        match self {
            QType::Float => "float",
            QType::Vec2 => "vec2",
            QType::Vec3 => "vec3",
            QType::Texel => "texel",
            QType::Mat4 => "mat4",
        }
    }
}

/// Where a model quantity lives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Slot {
    /// Per case: input `input`, starting at component `offset`.
    Case {
        /// Input index.
        input: usize,
        /// First component (0 = x).
        offset: usize,
    },
    /// Shared by a group of cases: a uniform of that name (multiple lights' scene).
    Group,
    /// Not an input of the model (texture coordinates): loaded as zero.
    Unused,
}

/// How the reports label a quantity's components.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Label {
    /// The name alone (floats).
    Plain,
    /// `name.xyz` (positions, directions, normals).
    Xyz,
    /// `name.rgb` (colours).
    Rgb,
    /// Words of their own (`diffuse map texel rgb`, `specular exponent`).
    Text(&'static str),
}

/// A named input of a model, as the tutorials name it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Quantity {
    /// The tutorial's name (`FragPos`, `light.position`, `pointLights[0].constant`, ...).
    pub name: &'static str,
    /// Its type.
    pub ty: QType,
    /// Where it is stored.
    pub slot: Slot,
    /// Components it occupies: float 1, vec2 2, vec3 3, texel 3 (rgb) or 4 (rgba), mat4 16.
    pub components: usize,
    /// The chapter's value, used by `check-shader` when the user's shader does not declare
    /// the quantity (it then hard-codes it, as the tutorials do). `None`: random.
    pub default: Option<[f32; 3]>,
    /// Every component of every generated case lies in `[lo, hi]` (checked by a test);
    /// `None` for group and unused quantities.
    pub range: Option<(f32, f32)>,
    /// How the reports label it.
    pub label: Label,
}

impl Quantity {
    /// A per-case quantity at `input`, component `offset`, labelled by its type
    /// (`name.xyz` for a vec3, the name for a float, `name column k` for a mat4).
    pub const fn new(name: &'static str, ty: QType, input: usize, offset: usize, range: (f32, f32)) -> Quantity {
        let (components, label) = match ty {
            QType::Float => (1, Label::Plain),
            QType::Vec2 => (2, Label::Plain),
            QType::Vec3 => (3, Label::Xyz),
            QType::Texel => (3, Label::Plain),
            QType::Mat4 => (16, Label::Plain),
        };
        Quantity { name, ty, slot: Slot::Case { input, offset }, components, default: None, range: Some(range), label }
    }

    /// Labelled `name.rgb`.
    pub const fn rgb(self) -> Quantity {
        Quantity { label: Label::Rgb, ..self }
    }

    /// Labelled with `text`.
    pub const fn text(self, text: &'static str) -> Quantity {
        Quantity { label: Label::Text(text), ..self }
    }

    /// With the chapter's value `value` (all three components).
    pub const fn chapter(self, value: f32) -> Quantity {
        Quantity { default: Some([value; 3]), ..self }
    }

    /// A texel that also carries alpha (4 components).
    pub const fn rgba(self) -> Quantity {
        Quantity { components: 4, ..self }
    }

    /// A model quantity that is not an input (texture coordinates), loaded as zero.
    pub const fn unused(name: &'static str) -> Quantity {
        Quantity {
            name,
            ty: QType::Vec2,
            slot: Slot::Unused,
            components: 2,
            default: None,
            range: None,
            label: Label::Plain,
        }
    }

    /// A plain uniform of type `ty` shared by a group of cases (the pair check's `view` and
    /// `projection`).
    pub const fn uniform(name: &'static str, ty: QType) -> Quantity {
        let components = match ty {
            QType::Float => 1,
            QType::Vec2 => 2,
            QType::Vec3 | QType::Texel => 3,
            QType::Mat4 => 16,
        };
        Quantity { name, ty, slot: Slot::Group, components, default: None, range: None, label: Label::Plain }
    }

    /// A struct or array of uniforms shared by a group of cases (`dirLight`, `pointLights`).
    pub const fn group(name: &'static str) -> Quantity {
        Quantity {
            name,
            ty: QType::Vec3,
            slot: Slot::Group,
            components: 3,
            default: None,
            range: None,
            label: Label::Plain,
        }
    }

    /// The report's words for the components in input `k` (`FragPos.xyz`, `model column 2`).
    pub fn label_in(&self, k: usize) -> String {
        match (self.label, self.ty, self.slot) {
            (_, QType::Mat4, Slot::Case { input, .. }) => format!("{} column {}", self.name, k - input),
            (Label::Plain, ..) => self.name.to_string(),
            (Label::Xyz, ..) => format!("{}.xyz", self.name),
            (Label::Rgb, ..) => format!("{}.rgb", self.name),
            (Label::Text(t), ..) => t.to_string(),
        }
    }

    /// The inputs it occupies (a mat4 takes four), empty unless per case.
    pub fn inputs(&self) -> std::ops::Range<usize> {
        match self.slot {
            Slot::Case { input, .. } if self.ty == QType::Mat4 => input..input + 4,
            Slot::Case { input, .. } => input..input + 1,
            _ => 0..0,
        }
    }
}

/// What a [`Layout`] describes: the cases of one model, or the triangles of a vertex +
/// fragment pair ([`VERTEX_PAIR`], no model of its own).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LayoutId {
    /// The cases of a model ([`ModelId::layout`] is its layout).
    Model(ModelId),
    /// The triangles of `check-shader --vertex` (`vertex_pair`).
    VertexPair,
}

impl LayoutId {
    /// The name reports and the JSON export print: the model's name, or `vertex_pair`.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            LayoutId::Model(m) => m.name(),
            LayoutId::VertexPair => "vertex_pair",
        }
    }
}

impl std::fmt::Display for LayoutId {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.pad(self.name())
    }
}

/// The packed layout of one model.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    /// What it describes: a model (`basic_lighting`, ..., `blinn_phong`) or the vertex pair.
    pub id: LayoutId,
    /// The chapter it follows.
    pub source: &'static str,
    /// Named inputs, in the order the reports list them.
    pub quantities: &'static [Quantity],
    /// Meaning of each `vec4` output of the tutorial harness.
    pub outputs: &'static [&'static str],
}

const fn same(a: &str, b: &str) -> bool {
    let (a, b) = (a.as_bytes(), b.as_bytes());
    if a.len() != b.len() {
        return false;
    }
    let mut i = 0;
    while i < a.len() {
        if a[i] != b[i] {
            return false;
        }
        i += 1;
    }
    true
}

impl Layout {
    /// Number of `vec4` inputs per case: one past the last input a quantity occupies.
    pub const fn n_inputs(&self) -> usize {
        let mut n = 0;
        let mut i = 0;
        while i < self.quantities.len() {
            let q = &self.quantities[i];
            if let Slot::Case { input, .. } = q.slot {
                let end = input + if matches!(q.ty, QType::Mat4) { 4 } else { 1 };
                if end > n {
                    n = end;
                }
            }
            i += 1;
        }
        n
    }

    /// Number of `vec4` outputs of the tutorial harness.
    pub const fn n_outputs(&self) -> usize {
        self.outputs.len()
    }

    /// The quantity called `name`; `None` if the model has none.
    pub fn find(&self, name: &str) -> Option<&'static Quantity> {
        self.quantities.iter().find(|q| q.name == name)
    }

    /// The quantity called `name`, for compile-time resolution
    /// (`const LIGHT_POS: Quantity = BASIC_LIGHTING.get("lightPos")`).
    ///
    /// Panics (a compile error in a `const`) if the model has no such quantity.
    pub const fn get(&self, name: &str) -> Quantity {
        let mut i = 0;
        while i < self.quantities.len() {
            if same(self.quantities[i].name, name) {
                return self.quantities[i];
            }
            i += 1;
        }
        panic!("the layout has no quantity of that name")
    }

    /// The label of each input: the quantities in it by component, `-` for an unused
    /// component (`FragPos.xyz, ambientStrength`, `viewPos.xyz, -`, `model column 0`).
    pub fn input_labels(&self) -> Vec<String> {
        (0..self.n_inputs())
            .map(|k| {
                let mut in_k: Vec<&Quantity> = self.quantities.iter().filter(|q| q.inputs().contains(&k)).collect();
                in_k.sort_by_key(|q| match q.slot {
                    Slot::Case { offset, .. } => offset,
                    _ => 0,
                });
                if let [q] = in_k[..] {
                    if q.ty == QType::Mat4 || q.components == 4 {
                        return q.label_in(k);
                    }
                }
                let mut parts = Vec::new();
                let mut next = 0;
                for q in in_k {
                    parts.push(q.label_in(k));
                    next = match q.slot {
                        Slot::Case { offset, .. } => offset + q.components,
                        _ => next,
                    };
                }
                if next < 4 {
                    parts.push("-".to_string());
                }
                parts.join(", ")
            })
            .collect()
    }

    /// GLSL macros reading each per-case quantity from the harness's input array `v`:
    /// `#define IN_<name> <expression>`, the name with every character other than a
    /// letter, digit or `_` replaced by `_` (`IN_light_position` is `v[5].xyz`,
    /// `IN_light_cutOff` is `v[5].w`, `IN_model` is `mat4(v[6], v[7], v[8], v[9])`, a texel
    /// is its `.rgb`, or the whole `vec4` when it carries alpha).
    pub fn glsl_defines(&self) -> String {
        let mut s = String::new();
        for q in self.quantities {
            let Slot::Case { input: k, offset } = q.slot else { continue };
            let expr = match (q.ty, q.components) {
                (QType::Mat4, _) => format!("mat4(v[{k}], v[{}], v[{}], v[{}])", k + 1, k + 2, k + 3),
                (QType::Texel, 4) => format!("v[{k}]"),
                (QType::Float, _) => format!("v[{k}].{}", ["x", "y", "z", "w"][offset]),
                (QType::Vec2, _) => format!("v[{k}].xy"),
                _ => format!("v[{k}].xyz"),
            };
            let name: String =
                q.name.chars().map(|c| if c.is_ascii_alphanumeric() || c == '_' { c } else { '_' }).collect();
            s += &format!("#define IN_{name} {expr}\n");
        }
        s
    }

    /// Whether the model has group quantities (uniforms shared by a group of cases).
    pub fn has_groups(&self) -> bool {
        self.quantities.iter().any(|q| q.slot == Slot::Group)
    }

    /// The uniforms every batch of the model starts with: the chapter's scene
    /// ([`Scene::learnopengl_default`]) for a model with group quantities, else none.
    pub fn chapter_uniforms(&self) -> Vec<(String, Uniform)> {
        if self.has_groups() {
            scene_uniforms(&Scene::learnopengl_default())
        } else {
            Vec::new()
        }
    }
}

/// One case's packed inputs, read through the quantities of its layout.
#[derive(Debug, Clone, Copy)]
pub struct Row<'a>(pub &'a [[f32; 4]]);

impl Row<'_> {
    fn at(&self, q: Quantity) -> (usize, usize) {
        match q.slot {
            Slot::Case { input, offset } => (input, offset),
            _ => panic!("{} is not a per-case quantity", q.name),
        }
    }

    /// A float quantity.
    pub fn float(&self, q: Quantity) -> f32 {
        let (k, o) = self.at(q);
        self.0[k][o]
    }

    /// A vec3 (or the rgb of a texel).
    pub fn vec3(&self, q: Quantity) -> Vec3 {
        let (k, o) = self.at(q);
        Vec3::new(self.0[k][o], self.0[k][o + 1], self.0[k][o + 2])
    }

    /// A vec3 widened exactly to `f64`.
    pub fn dvec3(&self, q: Quantity) -> DVec3 {
        self.vec3(q).as_dvec3()
    }

    /// A mat4 from four consecutive inputs (columns).
    pub fn mat4(&self, q: Quantity) -> Mat4 {
        let (k, _) = self.at(q);
        Mat4::from_cols_array_2d(&[self.0[k], self.0[k + 1], self.0[k + 2], self.0[k + 3]])
    }
}

/// One case's packed inputs being written through the quantities of its layout; components
/// no quantity occupies stay 0.
#[derive(Debug, Clone, PartialEq)]
pub struct Packed(Vec<[f32; 4]>);

impl Packed {
    /// All-zero inputs for `layout`.
    pub fn new(layout: &Layout) -> Packed {
        Packed(vec![[0.0; 4]; layout.n_inputs()])
    }

    fn put(mut self, q: Quantity, values: &[f32]) -> Packed {
        let Slot::Case { input, offset } = q.slot else { panic!("{} is not a per-case quantity", q.name) };
        for (i, &x) in values.iter().enumerate() {
            self.0[input + (offset + i) / 4][(offset + i) % 4] = x;
        }
        self
    }

    /// Writes a float quantity.
    pub fn float(self, q: Quantity, x: f32) -> Packed {
        self.put(q, &[x])
    }

    /// Writes a vec3 (or the rgb of a texel).
    pub fn vec3(self, q: Quantity, v: Vec3) -> Packed {
        self.put(q, &v.to_array())
    }

    /// Writes an rgba texel.
    pub fn rgba(self, q: Quantity, v: [f32; 4]) -> Packed {
        self.put(q, &v)
    }

    /// Writes a mat4 (four inputs, column by column).
    pub fn mat4(self, q: Quantity, m: Mat4) -> Packed {
        self.put(q, &m.to_cols_array())
    }

    /// The packed inputs.
    pub fn into_row(self) -> Vec<[f32; 4]> {
        self.0
    }
}

/// The uniforms that give the multiple-lights shader `scene` (names as in the chapter's shader).
pub fn scene_uniforms(scene: &Scene) -> Vec<(String, Uniform)> {
    let v = |x: Vec3| Uniform::Vec3(x.to_array());
    let mut u = Vec::new();
    if let Some(d) = &scene.dir_light {
        u.push(("dirLight.direction".to_string(), v(d.direction)));
        u.push(("dirLight.ambient".to_string(), v(d.props.ambient)));
        u.push(("dirLight.diffuse".to_string(), v(d.props.diffuse)));
        u.push(("dirLight.specular".to_string(), v(d.props.specular)));
    }
    for (i, l) in scene.point_lights.iter().enumerate() {
        let f = |field: &str| format!("pointLights[{i}].{field}");
        u.push((f("position"), v(l.position)));
        u.push((f("constant"), Uniform::Float(l.attenuation.constant)));
        u.push((f("linear"), Uniform::Float(l.attenuation.linear)));
        u.push((f("quadratic"), Uniform::Float(l.attenuation.quadratic)));
        u.push((f("ambient"), v(l.props.ambient)));
        u.push((f("diffuse"), v(l.props.diffuse)));
        u.push((f("specular"), v(l.props.specular)));
    }
    if let Some(s) = &scene.spot_light {
        u.push(("spotLight.position".to_string(), v(s.position)));
        u.push(("spotLight.direction".to_string(), v(s.direction)));
        u.push(("spotLight.cutOff".to_string(), Uniform::Float(s.cut_off)));
        u.push(("spotLight.outerCutOff".to_string(), Uniform::Float(s.outer_cut_off)));
        u.push(("spotLight.constant".to_string(), Uniform::Float(s.attenuation.constant)));
        u.push(("spotLight.linear".to_string(), Uniform::Float(s.attenuation.linear)));
        u.push(("spotLight.quadratic".to_string(), Uniform::Float(s.attenuation.quadratic)));
        u.push(("spotLight.ambient".to_string(), v(s.props.ambient)));
        u.push(("spotLight.diffuse".to_string(), v(s.props.diffuse)));
        u.push(("spotLight.specular".to_string(), v(s.props.specular)));
    }
    u
}
