//! Live figures: WebGL2 figures in the book that run the verified GLSL, with the data
//! they need generated here, and the reference images their self-check compares with.
//!
//! # How a live figure is made
//!
//! A figure is a [`Spec`]: panels of draws (program, mesh, model matrix, textures), a
//! default parameter value `P`, a function from `P` to the **state** (every uniform the
//! draws read, and the `@`-named selections such as `@prog` or `@mesh`), a function
//! from `P` to the CPU raster's [`World`]s (one per panel), the controls, and two or
//! more extra parameter points for the self-check. From it the build writes
//! `generated/live/<id>.js` (one classic script with the figure's JSON) and
//! `generated/live/<id>.md` (the HTML markup a chapter includes; `.md` so that mdBook
//! includes it but does not copy it into the built book as a page of its own), and for every point a
//! reference PNG rendered by [`crate::raster`] (embedded as base64 in the JSON).
//!
//! Controls never compute: each option of a slider or select carries the **patch** of
//! state keys it changes, computed here by evaluating the state function with that
//! option applied (keys whose values differ between options). A toggle lists the keys it
//! zeroes (a light switched off); a color picker names the one key it sets; an orbit is
//! a grid of patches that dragging walks through, and a grid of sliders is one slider per
//! axis over such a grid (two parameters that move the same keys, such as a light's
//! azimuth and distance). The browser therefore never retypes a constant or a formula:
//! it sets uniforms and draws.
//!
//! The page side is `book/theme/live/lightlab-live.js` (plain JavaScript, classic
//! scripts only, so that a book opened from disk works: Chromium blocks `fetch` and
//! ES modules on `file://`). `?selftest` renders every figure at every point and writes
//! `{"figures":[{"id","pass","max_diff_255","mean_diff_255","pixels_over","pixels_over_cap",
//! "tolerance","mutant","points":[{"name","pass","pixels_over","allowed_over","covered",…}]}],"errors":[…]}`
//! into `<pre id="lightlab-selftest">`; `tests/browser.rs` reads it in headless Chromium.
//!
//! # Tolerance
//!
//! See [`Tolerance`]: the page's 8-bit pixel against the raster's 8-bit pixel, over the
//! pixels the reference's mask keeps ([`mod@reference`]), per figure and point
//! ([`UNTEXTURED`], [`TEXTURED`], [`NEAREST`]).
//!
//! # Speed
//!
//! `?fps=30` on each chapter (30 frames, each waited for with a one-pixel `readPixels`),
//! headless Chromium on SwiftShader, this 2-core machine shared with other builds (load
//! average 16): milliseconds per frame and frames per second.
//!
//! | figure | size | ms/frame | frames/s |
//! | --- | --- | --- | --- |
//! | colors | 320 × 240 | 1.5 | 655 |
//! | basic-move-light | 320 × 240 | 0.7 | 1376 |
//! | normal-matrix | 640 × 240 | 8.9 | 112 |
//! | basic-strengths | 320 × 240 | 1.1 | 943 |
//! | phong-blinn | 320 × 240 | 1.1 | 932 |
//! | world-view | 320 × 240 | 1.4 | 706 |
//! | gouraud-phong | 640 × 240 | 3.9 | 254 |
//! | materials | 320 × 240 | 4.1 | 243 |
//! | lighting-maps | 320 × 240 | 2.4 | 409 |
//! | attenuation | 320 × 240 | 12.2 | 82 |
//! | casters | 320 × 240 | 8.2 | 122 |
//! | spot-cone | 320 × 240 | 10.7 | 93 |
//! | flashlight | 320 × 240 | 10.8 | 93 |
//! | multiple-lights | 320 × 240 | 38.6 (39 to 118 over runs) | 26 (8.5 to 26) |
//! | conventions | 3 × 240 × 180 | 2.7 (load average 3 to 6) | 368 |
//!
//! The multiple-lights figure drew at 8 frames/s at 400 × 300 and is shown at 320 × 240;
//! sampling `/proc` during its run gave Chromium 0.3 to 0.5 of a core, so the work is
//! about 45 ms of CPU per frame at 320 × 240.

pub mod assets;
mod casters;
mod chapters;
mod conventions;
mod error;
pub mod exercises;
pub mod guard;
pub mod pair;
pub mod programs;
pub mod reference;
pub mod texts;

use std::collections::{BTreeMap, BTreeSet};

use glam::Mat4;
use serde_json::{json, Value};

use crate::figures::artifact::Artifact;
use crate::i18n::{tr, Lang};
use crate::raster::pipeline::World;
pub use error::LiveError;

/// The self-check's bound for one figure, in 8-bit steps on `|page − raster|` per
/// channel, over the pixels the reference's mask keeps ([`mod@reference`]).
///
/// A point passes when (1) no compared pixel is more than `cap` off, and (2) at most
/// `share` of the compared pixels an object covers ([`reference::Reference::covered`],
/// not the background, which a lit formula never touches) are more than `level` off.
///
/// Derivation of `level`. Both sides evaluate the same formula in `f32` on the same
/// inputs up to rounding: the GPU interpolates `FragPos`, `Normal` and uv with its own
/// rounding (perspective-correct barycentrics, about 2^-20 relative on SwiftShader and
/// desktop GPUs) and the raster with fixed-point edge functions; `pow` differs by a few
/// ulps (llvmpipe's `exp2(y·log2 x)`, see `crate::gl`). Through the lighting this stays
/// below 1e-4 of full scale except in a specular highlight, where an error δ in `cos α`
/// becomes `s·δ/cos α` relative: with `s = 128`, δ = 2^-20 gives 1.2e-4. The 8-bit
/// quantization of both images then turns any difference across a rounding boundary
/// into one step: untextured figures measured within 1 step everywhere in headless
/// Chromium (SwiftShader), and keep that [`UNTEXTURED`] level. Texture filtering adds
/// the largest term: GPUs compute bilinear weights with 8 fractional bits (the
/// Direct3D 10 minimum, which SwiftShader and ANGLE follow), so a sample can miss the
/// exact `mix` by `|Δtexel|/512` ≈ 0.5 step when neighbouring texels differ by a full
/// step of 1, times the light (up to 1.5 here): 1 step from rounding, plus 1 from
/// filtering, plus 1 for the highlight's amplification gives [`TEXTURED`]'s 3.
///
/// Why any pixel may exceed `level`, and the `cap`: see [`UNTEXTURED`], [`TEXTURED`] and
/// [`NEAREST`] (a point's own tolerance; the figure's data gives each point its own).
/// A wrong formula, a wrong constant or a swapped reference moves most pixels by far
/// more (the browser tests check that a swapped reference and a catalogue mutant fail).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// Most compared pixels are within this many steps.
    pub level: u8,
    /// No compared pixel is further off than this many steps.
    pub cap: u8,
    /// The share of the covered compared pixels allowed above `level` (up to `cap`).
    pub share: f64,
}

/// Figures that sample no texture: level 1, measured (every untextured figure, every
/// point: no pixel above 1 step in headless Chromium on SwiftShader). 0.1 % of the object's
/// pixels may reach the derived bound of 3 steps (1 from rounding, 1 from the highlight's
/// amplification, 1 from the quantization of both images), and none more.
pub const UNTEXTURED: Tolerance = Tolerance { level: 1, cap: 3, share: 0.001 };

/// Figures that sample the container's maps with `GL_LINEAR`: level 3 (derived, see
/// [`Tolerance`]). Measured in headless Chromium (SwiftShader), the emission map's hard
/// edges put 66 of the lighting-maps view's 4827 object pixels (1.4 %) above 3 steps, by
/// up to 11 (a texture coordinate off by about 0.05 texel where a stroke's edge goes from
/// black to 0.9 in one texel: 0.05 × 0.9 × 255 ≈ 11.5); the other textured views stay
/// within 5 steps on under 0.1 %. So 2 % of the object's pixels may be off by up to 12.
pub const TEXTURED: Tolerance = Tolerance { level: 3, cap: 12, share: 0.02 };

/// A point whose state samples the maps with `GL_NEAREST`: level 3 as [`TEXTURED`]. A
/// pixel whose texture coordinate lies within the two sides' rounding of a texel boundary
/// takes a neighbouring texel on one side, which can differ by anything the map holds
/// (measured: 35 of 4827 object pixels, 0.7 %, up to 232 steps, on the emission view), so
/// no cap below 255; 1 % of the object's pixels.
pub const NEAREST: Tolerance = Tolerance { level: 3, cap: 255, share: 0.01 };

/// The tolerance of a point of a figure whose draws sample textures (`textured`) or not,
/// with `GL_NEAREST` selected (`nearest`) or not.
pub fn tolerance_for(textured: bool, nearest: bool) -> Tolerance {
    match (textured, nearest) {
        (false, _) => UNTEXTURED,
        (true, false) => TEXTURED,
        (true, true) => NEAREST,
    }
}

/// A state value: numbers for a uniform (a float, a vector, a matrix in column order,
/// or a bool as 0/1), or a name for a selection (`@prog`, `@mesh`, `@filter`).
#[derive(Clone, Debug, PartialEq)]
pub enum Val {
    /// A uniform's components.
    Num(Vec<f32>),
    /// A selection.
    Sel(String),
}

impl Val {
    fn json(&self) -> Value {
        match self {
            Val::Num(v) => Value::Array(v.iter().map(|&x| f32_json(x)).collect()),
            Val::Sel(s) => json!(s),
        }
    }
}

/// `x` as the shortest JSON number the page reads back as exactly `x`.
///
/// JSON numbers are f64; `f64::from(x)` prints every bit of the f32 (`0.2f32` becomes
/// `0.20000000298023224`). The page hands the numbers to WebGL, which rounds each to f32
/// to nearest (`uniform*fv`, `Float32Array`), as Rust's `as f32` does. So `x`'s shortest
/// f32 decimal (`0.2`), read as f64, is used when that f64 rounds back to `x`, checked
/// here; otherwise the exact `f64::from(x)`. Non-finite values become `null`, as before.
fn f32_json(x: f32) -> Value {
    let short = x.to_string().parse::<f64>().ok().filter(|&d| d as f32 == x);
    json!(short.unwrap_or(f64::from(x)))
}

/// All uniforms and selections of a figure at one parameter point.
pub type State = BTreeMap<String, Val>;

/// Insert a uniform (any `f32` slice: a float, `Vec3::to_array()`, a matrix).
pub fn put(state: &mut State, key: &str, v: &[f32]) {
    state.insert(key.to_owned(), Val::Num(v.to_vec()));
}

/// Insert a selection.
pub fn select(state: &mut State, key: &str, v: &str) {
    state.insert(key.to_owned(), Val::Sel(v.to_owned()));
}

/// One draw call.
#[derive(Clone, Debug)]
pub struct Draw {
    /// Program name, or `@key` to read it from the state.
    pub program: String,
    /// Mesh name, or `@key`.
    pub mesh: String,
    /// The model matrix (uniform `model`).
    pub model: Mat4,
    /// Per-draw uniforms: the value names a state key (a lamp's color follows its light).
    pub uniforms: Vec<(String, String)>,
    /// Sampler uniform → texture name.
    pub textures: Vec<(String, String)>,
    /// Back-face culling on.
    pub cull: bool,
    /// Draw only when this state key is non-zero (`None`: always).
    pub when: Option<String>,
}

/// One viewport of a figure (panels sit side by side).
#[derive(Clone, Debug)]
pub struct Panel {
    /// Label under the panel.
    pub label: String,
    /// Draws, in order.
    pub draws: Vec<Draw>,
}

/// How a control is shown.
pub enum Kind {
    /// A slider over the options (optionally with a play button that steps through them).
    Range {
        /// Show a play button.
        play: bool,
    },
    /// Radio buttons.
    Select,
    /// A checkbox; off zeroes `zero` (the options are on, off).
    Toggle {
        /// State keys set to zero when off.
        zero: Vec<String>,
    },
    /// A color picker setting `key` (no options).
    Color {
        /// The state key.
        key: String,
    },
    /// Drag on the canvas (or arrow keys) to walk a `cols × rows` grid of options.
    Orbit {
        /// Columns (horizontal drag).
        cols: usize,
        /// Rows (vertical drag).
        rows: usize,
    },
    /// One slider per axis over a grid of options, for parameters that change the same
    /// state keys (each option is one position on every axis; see [`grid_option`]).
    Grid {
        /// The axes, the first one varying fastest in the options.
        axes: Vec<Axis>,
    },
}

/// One axis of a [`Kind::Grid`]: the slider's label and one label per position.
#[derive(Clone, Debug)]
pub struct Axis {
    /// The slider's label.
    pub label: String,
    /// One label per position, in slider order.
    pub ticks: Vec<String>,
}

/// The option of a grid with `axes` at `positions` (one per axis), the first axis
/// varying fastest:
///
/// ```text
/// option = Σ_a positions[a] · stride_a,   stride_0 = 1,   stride_{a+1} = stride_a · |ticks_a|
/// ```
///
/// `None` when a position is past its axis's end or the counts differ.
pub fn grid_option(axes: &[Axis], positions: &[usize]) -> Option<usize> {
    if axes.len() != positions.len() {
        return None;
    }
    let mut option = 0;
    let mut stride = 1;
    for (axis, &k) in axes.iter().zip(positions) {
        if k >= axis.ticks.len() {
            return None;
        }
        option += k * stride;
        stride *= axis.ticks.len();
    }
    Some(option)
}

/// How far apart two options are that differ by one position on each axis: the page walks
/// a slider with them (option = Σ position · stride, position = ⌊option / stride⌋ mod
/// ticks), so the numbering of [`grid_option`] is written once, here.
pub fn grid_strides(axes: &[Axis]) -> Vec<usize> {
    axes.iter()
        .scan(1, |stride, axis| {
            let here = *stride;
            *stride *= axis.ticks.len();
            Some(here)
        })
        .collect()
}

/// The positions on `axes` of grid option `option` (the inverse of [`grid_option`]);
/// `None` past the grid's last option.
pub fn grid_positions(axes: &[Axis], option: usize) -> Option<Vec<usize>> {
    let mut rest = option;
    let mut out = Vec::with_capacity(axes.len());
    for axis in axes {
        let n = axis.ticks.len();
        if n == 0 {
            return None;
        }
        out.push(rest % n);
        rest /= n;
    }
    (rest == 0).then_some(out)
}

/// Applies an option to the parameters.
pub type Apply<P> = Box<dyn Fn(&mut P) + Send + Sync>;

/// A control: a label, a kind and its options.
pub struct Control<P> {
    /// Visible label.
    pub label: String,
    /// How it is shown.
    pub kind: Kind,
    /// `(label, apply)` per option.
    pub options: Vec<(String, Apply<P>)>,
    /// Index of the default option.
    pub default: usize,
    /// One curve per option (points `(x, y)`), drawn under the figure; empty for none.
    pub curves: Vec<Vec<(f32, f32)>>,
}

impl<P> Control<P> {
    /// A control with no curves.
    pub fn new(label: &str, kind: Kind, options: Vec<(String, Apply<P>)>, default: usize) -> Control<P> {
        Control { label: label.to_owned(), kind, options, default, curves: Vec::new() }
    }

    /// A drop-down of `options`, the first one chosen at first.
    pub fn select(label: &str, options: Vec<(String, Apply<P>)>) -> Control<P> {
        Control::new(label, Kind::Select, options, 0)
    }

    /// A grid of sliders, one per axis ([`Kind::Grid`]): the option at positions `k` applies
    /// `set(p, k)`; `default` gives the starting position on each axis (an axis without
    /// one, or a position past its end, starts at 0). The options carry no labels of their
    /// own: each slider shows its axis's tick.
    pub fn grid(label: &str, axes: Vec<Axis>, default: &[usize], set: fn(&mut P, &[usize])) -> Control<P>
    where
        P: 'static,
    {
        let count: usize = axes.iter().map(|a| a.ticks.len()).product();
        let options = (0..count)
            .filter_map(|k| grid_positions(&axes, k))
            .map(|at| -> (String, Apply<P>) { (String::new(), Box::new(move |p: &mut P| set(p, &at))) })
            .collect();
        let start: Vec<usize> = axes
            .iter()
            .enumerate()
            .map(|(a, axis)| default.get(a).copied().filter(|&k| k < axis.ticks.len()).unwrap_or(0))
            .collect();
        let default = grid_option(&axes, &start).unwrap_or(0);
        Control::new(label, Kind::Grid { axes }, options, default)
    }
}

/// A figure, generic over its parameter type.
pub struct Spec<P> {
    /// Id: the HTML id and file stem.
    pub id: &'static str,
    /// The chapter file stem it belongs to (for example `02-basic-lighting`).
    pub chapter: &'static str,
    /// Caption.
    pub title: String,
    /// Panel size in pixels (the canvas is `panels × width` by `height`).
    pub size: (u32, u32),
    /// The panels.
    pub panels: Vec<Panel>,
    /// Default parameters.
    pub default: P,
    /// The state at `P`.
    pub state: fn(&P) -> State,
    /// The raster worlds at `P`, one per panel.
    pub worlds: fn(&P) -> Vec<World>,
    /// Controls.
    pub controls: Vec<Control<P>>,
    /// Extra self-check points (at least two).
    pub points: Vec<(String, P)>,
    /// The program whose fragment function the reader may edit.
    pub editor: Option<&'static str>,
    /// Curve axes `(x label, y label, x max)` when a control has curves.
    pub curve_axes: Option<(String, String, f32)>,
}

/// A figure ready to write: its id, chapter, and the two file bodies.
pub struct Built {
    /// Id.
    pub id: &'static str,
    /// Chapter stem.
    pub chapter: &'static str,
    /// The figure's JSON.
    pub json: Value,
    /// Asset names it needs.
    pub assets: BTreeSet<String>,
}

fn state_json(s: &State) -> Value {
    Value::Object(s.iter().map(|(k, v)| (k.clone(), v.json())).collect())
}

fn with<P: Clone>(p: &P, f: &Apply<P>) -> P {
    let mut q = p.clone();
    f(&mut q);
    q
}

/// Evaluate a spec into its JSON (patches, reference images, programs).
pub fn build<P: Clone>(spec: &Spec<P>) -> Result<Built, LiveError> {
    let id = spec.id;
    let err = |what: String| LiveError::Spec { id, what };
    let within = |e: LiveError| LiveError::InFigure { id, source: Box::new(e) };
    if spec.points.len() < 2 {
        return Err(err("needs at least two self-check points besides the default".into()));
    }
    // the page's starting state has every toggle on; a toggle whose default is off zeroes its keys
    let mut with_toggles_on = spec.default.clone();
    for c in &spec.controls {
        if let (Kind::Toggle { .. }, Some((_, on))) = (&c.kind, c.options.first()) {
            on(&mut with_toggles_on);
        }
    }
    let base = (spec.state)(&with_toggles_on);
    let mut controls = Vec::new();
    for c in &spec.controls {
        let states: Vec<State> = c.options.iter().map(|(_, f)| (spec.state)(&with(&spec.default, f))).collect();
        let keys: BTreeSet<&String> = states
            .iter()
            .flat_map(|s| s.iter())
            .filter(|(k, v)| states.iter().any(|s| s.get(*k) != Some(*v)) || base.get(*k) != Some(*v))
            .map(|(k, _)| k)
            .collect();
        let options: Vec<Value> = c
            .options
            .iter()
            .zip(&states)
            .map(|((label, _), s)| {
                let patch: State = keys.iter().filter_map(|k| Some(((*k).clone(), s.get(*k)?.clone()))).collect();
                json!({ "label": label, "patch": state_json(&patch) })
            })
            .collect();
        let mut v = json!({ "label": c.label, "options": options, "default": c.default });
        match &c.kind {
            Kind::Range { play } => {
                v["kind"] = json!("range");
                v["play"] = json!(play);
            }
            Kind::Select => v["kind"] = json!("select"),
            Kind::Toggle { zero } => {
                // off must be on with exactly `zero` zeroed, or the page and the raster disagree
                if states.len() != 2 {
                    return Err(err(format!("toggle '{}' needs options on, off", c.label)));
                }
                let mut expect = states[0].clone();
                for k in zero {
                    match expect.get_mut(k) {
                        Some(Val::Num(v)) => v.iter_mut().for_each(|x| *x = 0.0),
                        _ => return Err(err(format!("toggle '{}' zeroes unknown key {k}", c.label))),
                    }
                }
                if expect != states[1] {
                    return Err(err(format!("toggle '{}': off is not on with {zero:?} zeroed", c.label)));
                }
                v["kind"] = json!("toggle");
                v["zero"] = json!(zero);
                v["options"] = json!([]);
            }
            Kind::Color { key } => {
                if !matches!(base.get(key), Some(Val::Num(n)) if n.len() == 3) {
                    return Err(err(format!("color '{}' needs a vec3 key, {key} is not one", c.label)));
                }
                v["kind"] = json!("color");
                v["key"] = json!(key);
            }
            Kind::Orbit { cols, rows } => {
                if cols * rows != c.options.len() {
                    return Err(err(format!("orbit '{}': {cols} x {rows} != {} options", c.label, c.options.len())));
                }
                v["kind"] = json!("orbit");
                v["cols"] = json!(cols);
                v["rows"] = json!(rows);
            }
            Kind::Grid { axes } => {
                let count: usize = axes.iter().map(|a| a.ticks.len()).product();
                if axes.is_empty() || count != c.options.len() {
                    return Err(err(format!(
                        "grid '{}': its axes make {count} options, not {}",
                        c.label,
                        c.options.len()
                    )));
                }
                v["kind"] = json!("grid");
                v["strides"] = json!(grid_strides(axes));
                v["axes"] = json!(axes
                    .iter()
                    .map(|a| json!({ "label": a.label,
                                     "ticks": a.ticks.iter().map(|t| json!({ "label": t })).collect::<Vec<_>>() }))
                    .collect::<Vec<_>>());
            }
        }
        if !c.curves.is_empty() {
            v["curves"] = json!(c
                .curves
                .iter()
                .map(|pts| pts.iter().map(|(x, y)| [*x, *y]).collect::<Vec<_>>())
                .collect::<Vec<_>>());
        }
        controls.push(v);
    }

    let (w, h) = spec.size;
    let textured = spec.panels.iter().flat_map(|p| &p.draws).any(|d| !d.textures.is_empty());
    let mut points = Vec::new();
    let all_points = std::iter::once(("default".to_owned(), spec.default.clone())).chain(spec.points.iter().cloned());
    let mut states = Vec::new();
    for (name, p) in all_points {
        let worlds = (spec.worlds)(&p);
        if worlds.len() != spec.panels.len() {
            return Err(err(format!("{} worlds for {} panels", worlds.len(), spec.panels.len())));
        }
        let r = reference::reference(&worlds, w, h).map_err(within)?;
        let s = (spec.state)(&p);
        let nearest = s.get("@filter") == Some(&Val::Sel("nearest".into()));
        let tolerance = tolerance_json(tolerance_for(textured, nearest));
        points.push(json!({ "name": name, "state": state_json(&s), "png": assets::base64(&r.png),
                            "covered": r.covered, "tolerance": tolerance }));
        states.push(s);
    }

    // programs, meshes and textures the figure can reach
    let sels = |key: &str| -> BTreeSet<String> {
        let mut out = BTreeSet::new();
        let mut all_states: Vec<State> = states.clone();
        for c in &spec.controls {
            all_states.extend(c.options.iter().map(|(_, f)| (spec.state)(&with(&spec.default, f))));
        }
        for s in &all_states {
            if let Some(Val::Sel(v)) = s.get(key) {
                out.insert(v.clone());
            }
        }
        out
    };
    let mut program_names = BTreeSet::new();
    let mut asset_names = BTreeSet::new();
    for d in spec.panels.iter().flat_map(|p| &p.draws) {
        match d.program.strip_prefix('@') {
            Some(k) => program_names.extend(sels(&format!("@{k}"))),
            None => {
                program_names.insert(d.program.clone());
            }
        }
        match d.mesh.strip_prefix('@') {
            Some(k) => asset_names.extend(sels(&format!("@{k}"))),
            None => {
                asset_names.insert(d.mesh.clone());
            }
        }
        asset_names.extend(d.textures.iter().map(|(_, t)| t.clone()));
    }
    let all_programs = programs::programs().map_err(within)?;
    let mut progs = serde_json::Map::new();
    for name in &program_names {
        let p = all_programs.iter().find(|p| p.name == name).ok_or_else(|| err(format!("unknown program {name}")))?;
        progs.insert(
            name.clone(),
            json!({ "vertex": p.vertex, "fragment": p.fragment, "header": p.fragment_header, "main": p.fragment_main,
                    "model": p.model.map_or("", crate::gl::ModelId::name) }),
        );
    }
    let mut mutants = serde_json::Map::new();
    if let Some(e) = spec.editor {
        if !progs.get(e).is_some_and(|p| p["model"] != "") {
            return Err(err(format!("editor program {e} is not a drawn program with a function file")));
        }
        if let Some(model) = all_programs.iter().find(|p| p.name == e).and_then(|p| p.model) {
            mutants = editor_mutants(model).map_err(within)?;
        }
    }
    let panels: Vec<Value> = spec
        .panels
        .iter()
        .map(|p| {
            let draws: Vec<Value> = p
                .draws
                .iter()
                .map(|d| {
                    json!({ "program": d.program, "mesh": d.mesh, "model": d.model.to_cols_array(),
                            "uniforms": d.uniforms.iter().cloned().collect::<BTreeMap<_, _>>(),
                            "textures": d.textures.iter().cloned().collect::<BTreeMap<_, _>>(), "cull": d.cull,
                            "when": d.when })
                })
                .collect();
            json!({ "label": p.label, "draws": draws })
        })
        .collect();
    let json = json!({
        "id": id, "title": spec.title, "width": w, "height": h, "panels": panels,
        "state": state_json(&base), "controls": controls, "points": points, "programs": progs,
        "editor": spec.editor, "tolerance": tolerance_json(tolerance_for(textured, false)), "mutants": mutants,
        "guard": guard::guard_json(),
        "curve_axes": spec.curve_axes.as_ref().map(|(x, y, m)| json!({ "x": x, "y": y, "max": m })),
    });
    Ok(Built { id, chapter: spec.chapter, json, assets: asset_names })
}

/// The catalogue's mutants of `model`'s function file, by mistake id: the texts the
/// editor would hold if the reader made that mistake. `?selftest&figure-mutant=ID` puts
/// one into the figure (by id, never text from the URL), and its self-check must fail.
fn editor_mutants(model: crate::gl::ModelId) -> Result<serde_json::Map<String, Value>, LiveError> {
    let functions = programs::function_file(model)?;
    Ok(crate::checker::mistakes::for_model(model)
        .into_iter()
        .filter_map(|m| Some((m.id.to_owned(), json!(m.rewrite(model, functions).ok()?))))
        .collect())
}

/// A tolerance as the page reads it: `{"level", "cap", "share"}`.
fn tolerance_json(t: Tolerance) -> Value {
    json!({ "level": t.level, "cap": t.cap, "share": t.share })
}

/// The figures, in book order (the order of [`IDS`], checked), built.
pub fn all_built() -> Result<Vec<Built>, LiveError> {
    use casters::{attenuation, casters, flashlight, lighting_maps, multiple_lights, spot_cone};
    use chapters::{basic_move_light, basic_strengths, colors, gouraud_phong, materials_figure};
    use chapters::{normal_matrix_figure, phong_blinn, world_view};
    let built = vec![
        build(&colors())?,
        build(&basic_strengths())?,
        build(&basic_move_light())?,
        build(&phong_blinn())?,
        build(&world_view())?,
        build(&normal_matrix_figure())?,
        build(&gouraud_phong())?,
        build(&materials_figure())?,
        build(&lighting_maps())?,
        build(&casters())?,
        build(&attenuation())?,
        build(&spot_cone())?,
        build(&flashlight())?,
        build(&multiple_lights())?,
        build(&conventions::conventions())?,
    ];
    let ids: Vec<&str> = built.iter().map(|b| b.id).collect();
    if ids != IDS {
        return Err(LiveError::Ids { built: ids, listed: IDS });
    }
    Ok(built)
}

/// Escape text for an HTML attribute or element.
fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// The markup a chapter includes for figure `id`: the canvas, a slot for the controls,
/// and the scripts (assets first seen in this chapter, then the figure). No blank lines,
/// so Markdown keeps it as one HTML block.
fn figure_html(b: &Built, new_assets: &[String], lang: Lang) -> String {
    let title = html_escape(&tr(lang, b.json["title"].as_str().unwrap_or("")));
    let aria = html_escape(&crate::i18n::catalog::tr_fill(lang, "Live figure: {}", &[&title]));
    let caption = html_escape(&crate::i18n::catalog::tr_fill(lang, "Live: {}", &[&title]));
    let status = html_escape(&tr(lang, "(needs JavaScript and WebGL2; the static figure above shows the same scene)"));
    let w = b.json["width"].as_u64().unwrap_or(0) * b.json["panels"].as_array().map_or(1, |p| p.len() as u64);
    let h = b.json["height"].as_u64().unwrap_or(0);
    let mut s = format!(
        "<figure class=\"lightlab-figure\" id=\"live-{id}\" data-live=\"{id}\">\n\
         <canvas class=\"lightlab-live\" width=\"{w}\" height=\"{h}\" tabindex=\"0\" role=\"img\" aria-label=\"{aria}\"></canvas>\n\
         <div class=\"lightlab-controls\"></div>\n\
         <figcaption>{caption} <span class=\"lightlab-status\">{status}</span></figcaption>\n",
        id = b.id
    );
    if lang.is_translation() {
        s.push_str(TEXTS_SCRIPT);
    }
    for a in new_assets {
        s.push_str(&format!("<script src=\"generated/live/asset-{a}.js\"></script>\n"));
    }
    s.push_str(&format!("<script src=\"generated/live/{}.js\"></script>\n</figure>\n", b.id));
    s
}

/// The line a translated figure or exercise box adds for its words: the dictionary of the
/// page's language (the path becomes `generated/<code>/live/texts.js` in a translated
/// chapter, see [`crate::i18n::localize`]).
pub const TEXTS_SCRIPT: &str = "<script src=\"generated/live/texts.js\"></script>\n";

/// The figures, built once per process (the reference renders dominate).
fn built_once() -> Result<&'static [Built], LiveError> {
    static BUILT: std::sync::OnceLock<Result<Vec<Built>, LiveError>> = std::sync::OnceLock::new();
    BUILT.get_or_init(all_built).as_ref().map(Vec::as_slice).map_err(Clone::clone)
}

/// Each figure's markup, `live/<id>.md`, in `lang`: the canvas, the controls' slot and the
/// scripts (assets first seen in this chapter, then the figure).
pub fn fragments(lang: Lang) -> Result<BTreeMap<String, Vec<u8>>, LiveError> {
    let mut out = BTreeMap::new();
    let mut seen_in_chapter: BTreeMap<&str, BTreeSet<String>> = BTreeMap::new();
    for b in built_once()? {
        let seen = seen_in_chapter.entry(b.chapter).or_default();
        let new: Vec<String> = b.assets.iter().filter(|a| seen.insert((*a).clone())).cloned().collect();
        out.insert(format!("live/{}.md", b.id), figure_html(b, &new, lang).into_bytes());
    }
    Ok(out)
}

/// The page's words in `lang`, `live/texts.js` (see [`texts`]): the scripts' words and the
/// texts of every figure's and exercise's data.
pub fn texts_file(lang: Lang) -> Result<Vec<u8>, LiveError> {
    let exercises = exercises::page_data().map_err(LiveError::Exercises)?;
    let data = built_once()?.iter().map(|b| &b.json).chain(exercises.iter().map(|(_, v)| v));
    Ok(texts::texts_script(lang, &texts::page_words(data)))
}

/// Every language-neutral generated file of the live figures, by path under `generated/`:
/// per figure `live/<id>.js`, and one `live/asset-<name>.js` per mesh or texture. Built once
/// per process and shared by the artifacts.
pub fn files() -> Result<&'static BTreeMap<String, Vec<u8>>, LiveError> {
    static FILES: std::sync::OnceLock<Result<BTreeMap<String, Vec<u8>>, LiveError>> = std::sync::OnceLock::new();
    FILES.get_or_init(make_files).as_ref().map_err(Clone::clone)
}

fn make_files() -> Result<BTreeMap<String, Vec<u8>>, LiveError> {
    let mut out = BTreeMap::new();
    let mut all_assets = BTreeSet::new();
    for b in built_once()? {
        all_assets.extend(b.assets.iter().cloned());
        let js =
            format!("(window.LIGHTLAB_FIGURES = window.LIGHTLAB_FIGURES || {{}})[{}] = {};\n", json!(b.id), b.json);
        out.insert(format!("live/{}.js", b.id), js.into_bytes());
    }
    for a in all_assets {
        out.insert(format!("live/asset-{a}.js"), assets::asset_script(&a)?);
    }
    Ok(out)
}

/// The generated Markdown that chapters include beside their figures, by path under
/// `generated/`: paragraphs whose numbers come from a figure's constants
/// (`live/conventions-try.md`, `conventions::what_to_try`). English: the book's
/// translation step takes their sentences as it takes the chapters'.
pub const CHAPTER_TEXTS: [&str; 1] = ["live/conventions-try.md"];

/// The files of [`CHAPTER_TEXTS`], in its order.
pub fn chapter_texts() -> Result<Vec<Vec<u8>>, LiveError> {
    Ok(vec![conventions::what_to_try()?.into_bytes()])
}

/// The bytes of generated file `path` (see [`files`]).
pub fn file(path: &str) -> Result<Vec<u8>, LiveError> {
    files()?.get(path).cloned().ok_or_else(|| LiveError::NoFile(path.to_owned()))
}

macro_rules! live_artifacts {
    (figures: [$($id:literal),* $(,)?], assets: [$($asset:literal),* $(,)?]) => {
        /// The figure ids, in book order.
        pub const IDS: &[&str] = &[$($id),*];

        /// Every generated file of the live figures, as one book artifact: [`files`]
        /// computes them all at once, so one run writes them all.
        pub fn artifacts() -> Vec<Artifact> {
            let paths: Vec<String> = vec![
                $(concat!("live/", $id, ".js").to_owned(),)*
                $(concat!("live/asset-", $asset, ".js").to_owned(),)*
            ];
            let wanted = paths.clone();
            let mut all = vec![Artifact::many(paths, move || {
                let made = files()?;
                wanted
                    .iter()
                    .map(|p| made.get(p).cloned().ok_or_else(|| LiveError::NoFile(p.clone())))
                    .collect::<Result<Vec<_>, LiveError>>()
            })];
            let markup: Vec<String> = vec![$(concat!("live/", $id, ".md").to_owned(),)*];
            let wanted = markup.clone();
            all.extend(Artifact::localized(markup, move |lang| {
                let made = fragments(lang)?;
                wanted
                    .iter()
                    .map(|p| made.get(p).cloned().ok_or_else(|| LiveError::NoFile(p.clone())))
                    .collect::<Result<Vec<_>, LiveError>>()
            }));
            all.extend(Artifact::localized(vec!["live/texts.js".to_owned()], |lang| texts_file(lang).map(|t| vec![t])));
            all.push(Artifact::many(CHAPTER_TEXTS.iter().map(|p| (*p).to_owned()).collect(), chapter_texts));
            all
        }
    };
}

live_artifacts! {
    figures: [
        "colors", "basic-strengths", "basic-move-light", "phong-blinn", "world-view", "normal-matrix",
        "gouraud-phong", "materials", "lighting-maps", "casters", "attenuation", "spot-cone", "flashlight",
        "multiple-lights", "conventions",
    ],
    assets: [
        "cube", "sphere-4x8", "sphere-8x16", "sphere-12x24", "sphere-16x32", "sphere-32x64", "sphere-24x48",
        "container-diffuse", "container-specular", "container-emission",
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The strides the page walks a grid with number the options as [`grid_option`] does,
    /// and [`grid_positions`] inverts it, on every option of a 4 × 3 × 2 grid.
    #[test]
    fn grid_strides_positions_and_options_agree() {
        let axis = |n: usize| Axis { label: String::new(), ticks: vec![String::new(); n] };
        let axes = vec![axis(4), axis(3), axis(2)];
        let strides = grid_strides(&axes);
        assert_eq!(strides, [1, 4, 12]);
        for option in 0..24 {
            let at = grid_positions(&axes, option).unwrap();
            // the page's formulas, with the crate's strides
            let page: Vec<usize> = strides.iter().zip(&axes).map(|(s, a)| option / s % a.ticks.len()).collect();
            assert_eq!(at, page);
            assert_eq!(grid_option(&axes, &at), Some(option));
            assert_eq!(at.iter().zip(&strides).map(|(k, s)| k * s).sum::<usize>(), option);
        }
        assert_eq!(grid_positions(&axes, 24), None);
        assert_eq!(grid_option(&axes, &[4, 0, 0]), None);
        assert_eq!(grid_option(&axes, &[0, 0]), None);
    }

    /// Every f32 comes back from its JSON number exactly, in fewer characters than the exact
    /// f64 where the shortest decimal differs.
    #[test]
    fn state_numbers_are_short_and_round_trip_to_the_same_f32() {
        let mut samples = vec![0.2f32, 1.2, -0.522_783_16, 1.0 / 3.0, f32::MIN_POSITIVE, f32::MAX, -0.0, 7.612_999];
        samples.extend((0..2000).map(|k| (k as f32 * 0.731).sin() * 10f32.powi(k % 9 - 4)));
        for x in samples {
            let v = f32_json(x);
            let back = v.as_f64().unwrap() as f32;
            assert!(back == x && back.is_sign_negative() == x.is_sign_negative(), "{x}: {v}");
            assert!(v.to_string().len() <= json!(f64::from(x)).to_string().len(), "{x}: {v}");
        }
        assert_eq!(f32_json(0.2).to_string(), "0.2");
        assert_eq!(f32_json(f32::NAN), Value::Null);
    }

    #[test]
    fn artifact_list_matches_the_generated_files() {
        let listed: BTreeSet<String> = artifacts()
            .iter()
            .filter(|a| a.lang().is_none_or(|l| l == Lang::En))
            .flat_map(|a| a.paths())
            .filter(|p| p.as_str() != "live/texts.js")
            .cloned()
            .collect();
        let mut made: BTreeSet<String> = files().unwrap().keys().cloned().collect();
        made.extend(fragments(Lang::En).unwrap().into_keys());
        assert_eq!(chapter_texts().unwrap().len(), CHAPTER_TEXTS.len());
        made.extend(CHAPTER_TEXTS.iter().map(|p| (*p).to_owned()));
        assert_eq!(listed, made);
    }

    #[test]
    fn every_point_carries_its_tolerance_and_nearest_sampling_has_a_point() {
        let built = built_once().unwrap();
        let level_cap = |t: Tolerance| (Some(u64::from(t.level)), Some(u64::from(t.cap)));
        let mut nearest_points = 0;
        for b in built {
            let textured = b.id != "colors" && !b.assets.iter().all(|a| !a.starts_with("container-"));
            let panels = b.json["panels"].as_array().unwrap().len() as u64;
            let pixels = panels * b.json["width"].as_u64().unwrap() * b.json["height"].as_u64().unwrap();
            for p in b.json["points"].as_array().unwrap() {
                let nearest = p["state"]["@filter"] == "nearest";
                nearest_points += usize::from(nearest);
                let want = tolerance_for(textured, nearest);
                let got = (p["tolerance"]["level"].as_u64(), p["tolerance"]["cap"].as_u64());
                assert_eq!(got, level_cap(want), "{} {}", b.id, p["name"]);
                // the allowance is taken over the object's pixels: some, never the whole canvas
                let covered = p["covered"].as_u64().unwrap();
                assert!(covered > 0 && covered < pixels, "{} {}: {covered} of {pixels}", b.id, p["name"]);
            }
        }
        assert_eq!(nearest_points, 1, "the lighting-maps figure's GL_NEAREST option has one self-check point");
    }
}
