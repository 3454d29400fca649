//! The multi-light shading kernel: the Multiple lights fragment shader, 16
//! fragments at a time, structure of arrays, written for autovectorization.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `LANES` | fragments per call (16: one AVX-512 register of `f32`, two AVX2 ones) |
//! | `norm`, `view_dir` | unit normal and direction to the eye, per lane |
//! | `acc_ambient`, `acc_diffuse`, `acc_specular` | per-channel sums over lights of `factor · light.term`, factor = attenuation · intensity (· diff or spec) |
//! | result | `acc_ambient ⊙ ka + acc_diffuse ⊙ kd + acc_specular ⊙ ks` |
//!
//! The sum is [`Scene::shade`]'s, regrouped by distributivity (each light's
//! `ambient ⊙ ka · factor` is accumulated as `(factor · ambient)` first and
//! multiplied by the material once), so results differ from the scalar path
//! by rounding only, and by results below 2^-126 flushed to 0 (as llvmpipe
//! does; subnormal arithmetic is very slow on x86). `pow(x, s)` is square-and-multiply for a whole
//! shininess (1 to 1024: the tutorials' 32 and 64), otherwise `exp2(s · log2 x)`
//! with polynomial `log2`/`exp2` (relative error below 2e-6 where the result is
//! visible at shininess ≤ 32), as llvmpipe computes every `pow`. Degenerate input follows the scalar path: zero vectors
//! normalize to zero, a fragment at a light gets ambient only.
//!
//! Every loop runs over the 16 lanes with no branches, so LLVM vectorizes it;
//! the kernel is written once, generic over an instruction-set marker
//! (`raster/simd.rs`), and compiled three times (AVX-512, AVX2+FMA, baseline; the first two fuse
//! multiply-adds, one rounding instead of two); the best the CPU supports is
//! chosen once, at construction.
//!
//! Every step is `#[inline(always)]` in release builds, so that each compiled variant (lobe,
//! light colours, exponent, window: `Variants`) is one function built for its instruction
//! set; debug builds call them instead, because
//! there the inlined variants made one stack frame deeper than a 2 MiB thread stack.
//!
//! Source: LearnOpenGL, Multiple lights (`CalcDirLight`, `CalcPointLight`,
//! `CalcSpotLight`); Blinn 1977 for the half-vector variant.

#![allow(clippy::needless_range_loop)] // lane-indexed loops are the structure-of-arrays form LLVM vectorizes

use glam::Vec3;

use super::rasterize::FragmentBatch;
/// The instruction set in use (the speed study records it).
#[cfg(feature = "book")]
pub(crate) use super::simd::detect_isa;
#[cfg(target_arch = "x86_64")]
use super::simd::{Avx2, Avx512};
use super::simd::{Baseline, Isa, Level, Simd};
use super::wide::{dot, madd, normalize_or_zero, point_minus, W, W3};
use crate::material::Material;
use crate::scene::Scene;

/// Fragments per kernel call and one value per lane, defined with the instruction sets
/// (`raster/simd.rs`, the lowest layer), re-exported here as the kernel's interface.
pub use super::simd::{Lanes, LANES};

/// The specular lobe the kernel evaluates: the core's [`crate::phong::Specular`].
pub use crate::phong::Specular;

/// Per-lane material reflectances (the shininess is the kernel's, one for all lanes).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LaneMaterial {
    /// Ambient reflectance, per channel then lane.
    pub ambient: [Lanes; 3],
    /// Diffuse reflectance.
    pub diffuse: [Lanes; 3],
    /// Specular reflectance.
    pub specular: [Lanes; 3],
}

impl LaneMaterial {
    /// The same material in every lane.
    pub fn uniform(material: &Material) -> LaneMaterial {
        let splat = |v: Vec3| [[v.x; LANES], [v.y; LANES], [v.z; LANES]];
        LaneMaterial {
            ambient: splat(material.ambient),
            diffuse: splat(material.diffuse),
            specular: splat(material.specular),
        }
    }

    /// Set lane `i` to `material`'s reflectances.
    pub fn set(&mut self, i: usize, material: &Material) {
        for c in 0..3 {
            self.ambient[c][i] = material.ambient[c];
            self.diffuse[c][i] = material.diffuse[c];
            self.specular[c][i] = material.specular[c];
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Props {
    ambient: Vec3,
    diffuse: Vec3,
    specular: Vec3,
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Falloff {
    position: Vec3,
    constant: f32,
    linear: f32,
    quadratic: f32,
    /// `1 / constant`, the attenuation at distance 0.
    at_zero: f32,
}

fn falloff(position: Vec3, a: &crate::casters::Attenuation) -> Falloff {
    Falloff { position, constant: a.constant, linear: a.linear, quadratic: a.quadratic, at_zero: 1.0 / a.constant }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum KernelLight {
    Dir { light_dir: Vec3, props: Props },
    Point { falloff: Falloff, props: Props },
    Spot { falloff: Falloff, axis_to_light: Vec3, edge: Edge, props: Props },
}

impl KernelLight {
    /// The light's ambient, diffuse and specular colours.
    fn props(&self) -> &Props {
        match self {
            KernelLight::Dir { props, .. } | KernelLight::Point { props, .. } | KernelLight::Spot { props, .. } => {
                props
            }
        }
    }

    /// The same, to change.
    fn props_mut(&mut self) -> &mut Props {
        match self {
            KernelLight::Dir { props, .. } | KernelLight::Point { props, .. } | KernelLight::Spot { props, .. } => {
                props
            }
        }
    }
}

/// The point lights and the spot of `lights`, in order, as cones (a point light's never cuts).
fn cones_of(lights: &[KernelLight]) -> Vec<Cone> {
    lights
        .iter()
        .filter_map(|l| match *l {
            KernelLight::Dir { .. } => None,
            KernelLight::Point { falloff, props } => {
                Some(Cone { falloff, axis_to_light: Vec3::ZERO, edge: Edge::None, props })
            }
            KernelLight::Spot { falloff, axis_to_light, edge, props } => {
                Some(Cone { falloff, axis_to_light, edge, props })
            }
        })
        .collect()
}

/// How a light's intensity falls at its cone's edge, with the cut-offs as the cosines the
/// shader compares `theta = L·(−direction)` with (LearnOpenGL stores `cos(12.5°)` in
/// `cutOff`, not the angle).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Edge {
    /// No cone: a point light, intensity 1 everywhere.
    None,
    /// `theta > cos_outer` is lit, the rest dark: equal or inverted cones (ε ≤ 0), where
    /// the shader's `(theta − outer)/ε` has no soft edge.
    Hard {
        /// `cos(outer angle)`.
        cos_outer: f32,
    },
    /// `clamp((theta − cos_outer) · inv_epsilon, 0, 1)`, ε = `cos_inner − cos_outer` > 0.
    Soft {
        /// `cos(outer angle)`.
        cos_outer: f32,
        /// `1/ε`.
        inv_epsilon: f32,
    },
}

impl Edge {
    /// The edge of a spot with cut-off cosines `cos_inner` and `cos_outer`.
    fn of_spot(cos_inner: f32, cos_outer: f32) -> Edge {
        if cos_inner > cos_outer {
            Edge::Soft { cos_outer, inv_epsilon: 1.0 / (cos_inner - cos_outer) }
        } else {
            Edge::Hard { cos_outer }
        }
    }
}

/// A point light or spot in the form the kernel evaluates: attenuated, times a cone intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Cone {
    falloff: Falloff,
    axis_to_light: Vec3,
    /// [`Edge::None`] for a point light, which skips the cone.
    edge: Edge,
    props: Props,
}

/// LearnOpenGL's attenuation times the range window `w(d, r)` of
/// [`crate::casters::range_window`] (Karis 2013; Filament), for every point light and
/// the spot, and optionally culling: a light is skipped for a batch of 16 fragments
/// when the batch's bounding box lies at least `range` from it, where the window, and so
/// the light, is exactly zero.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RangeWindow {
    /// The range `r`. NaN or `r ≤ 0` makes the window 0: every point light and the spot go dark.
    pub range: f32,
    /// Skip the lights that cannot reach a batch.
    pub cull: bool,
}

/// The kernel's value-based specialisations: shortcuts taken because of the values of the
/// lights and the material, not their form. Each gives the same image within rounding
/// (the kernel tests and the golden images hold with all of them on); `bench --general`
/// turns them off, `bench --specialisations` measures each alone.
///
/// | specialisation | when it applies | what it saves |
/// | --- | --- | --- |
/// | `grey_lights` | every light's ambient, diffuse and specular have equal channels | one sum per term instead of three |
/// | `whole_exponent` | the shininess is a whole number in 1..=1024 (32 and 64 unrolled at compile time) | `pow` by square-and-multiply instead of `exp2(y · log2 x)` |
/// | `phong_rewrite` | the Phong lobe | `R·V` as `L·R_V`, with the view direction reflected about the normal, `R_V = 2(N·V)N − V`, once per fragment, instead of `reflect(−L, N)·V` per light |
/// | `folded_material` | coloured lights on a material that is the same in every lane (no texture) | each light's colours multiplied by the material once, at setup, so each light adds to one sum per channel: three sums instead of nine, and no material at the end |
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Specialisations {
    /// Grey lights accumulate one channel.
    pub grey_lights: bool,
    /// A whole shininess is evaluated by square-and-multiply.
    pub whole_exponent: bool,
    /// Phong's `R·V` is `L·R_V`, `R_V = 2(N·V)N − V` once per fragment.
    pub phong_rewrite: bool,
    /// A uniform material is folded into coloured lights' colours ([`MultiLightKernel::with_material`]).
    pub folded_material: bool,
}

impl Specialisations {
    /// Every specialisation that applies (the default).
    pub const ALL: Specialisations =
        Specialisations { grey_lights: true, whole_exponent: true, phong_rewrite: true, folded_material: true };
    /// None: the general path, the shader's formulas for any values.
    pub const NONE: Specialisations =
        Specialisations { grey_lights: false, whole_exponent: false, phong_rewrite: false, folded_material: false };
    /// Each specialisation alone, named as `bench --specialisations` prints it.
    pub const EACH: [(&'static str, Specialisations); 4] = [
        ("grey-lights", Specialisations { grey_lights: true, ..Specialisations::NONE }),
        ("whole-exponent", Specialisations { whole_exponent: true, ..Specialisations::NONE }),
        ("phong-rewrite", Specialisations { phong_rewrite: true, ..Specialisations::NONE }),
        ("folded-material", Specialisations { folded_material: true, ..Specialisations::NONE }),
    ];
}

impl Default for Specialisations {
    fn default() -> Specialisations {
        Specialisations::ALL
    }
}

/// The specular lobe as the kernel's variants are compiled: Phong through the `R·V`
/// rewrite, Phong through `reflect`, Blinn-Phong.
const PHONG_REWRITE: u8 = 0;
const PHONG_REFLECT: u8 = 1;
const BLINN: u8 = 2;

/// How the kernel sums the lights' terms, as its variants are compiled: one channel per
/// term when every light is grey (the material multiplied at the end), three channels per
/// term, or one sum per channel of lights whose colours already hold the material
/// ([`Folded`]).
const SUMS_GREY: u8 = 0;
const SUMS_RGB: u8 = 1;
const SUMS_FOLDED: u8 = 2;

/// The kernel's lights with a uniform material folded in: each light's ambient, diffuse
/// and specular colours times the material's (`light.ambient ⊙ ka`, …), the products the
/// shader forms per fragment, formed once. The lights are otherwise the kernel's.
#[derive(Clone, Debug, PartialEq)]
struct Folded {
    /// The material in every lane: the kernel uses the folded lights only for a call given
    /// this very value ([`MultiLightKernel::material_lanes`]).
    lanes: LaneMaterial,
    lights: Vec<KernelLight>,
    cones: Vec<Cone>,
}

impl Folded {
    fn of(lights: &[KernelLight], m: &Material) -> Folded {
        let mut lights = lights.to_vec();
        for light in &mut lights {
            let p = light.props_mut();
            *p = Props {
                ambient: p.ambient * m.ambient,
                diffuse: p.diffuse * m.diffuse,
                specular: p.specular * m.specular,
            };
        }
        Folded { lanes: LaneMaterial::uniform(m), cones: cones_of(&lights), lights }
    }
}

/// A [`Scene`] compiled for 16-lane shading, with the eye position, shininess and lobe fixed.
#[derive(Clone, Debug, PartialEq)]
pub struct MultiLightKernel {
    lights: Vec<KernelLight>,
    /// Point lights and the spot, as cones (a point light's cone never cuts), shader order.
    cones: Vec<Cone>,
    view_pos: Vec3,
    /// Every light's colours are grey (equal channels) and the grey path is allowed: one
    /// accumulator per term, not three.
    grey: bool,
    /// Every light's colours are grey, whether or not the grey path is allowed.
    all_grey: bool,
    specialisations: Specialisations,
    shininess: f32,
    exponent: Exponent,
    specular: Specular,
    window: Option<RangeWindow>,
    /// The lights with a uniform material folded in ([`MultiLightKernel::with_material`]).
    folded: Option<Box<Folded>>,
    isa: Isa,
}

impl MultiLightKernel {
    /// Compile `scene` (dir light, point lights, spot, in the shader's order).
    ///
    /// `shininess` is the material exponent for every lane; `view_pos` the eye.
    pub fn new(scene: &Scene, view_pos: Vec3, shininess: f32, specular: Specular) -> MultiLightKernel {
        let props =
            |p: &crate::material::LightProps| Props { ambient: p.ambient, diffuse: p.diffuse, specular: p.specular };
        let mut lights = Vec::new();
        if let Some(d) = &scene.dir_light {
            lights.push(KernelLight::Dir { light_dir: d.light_dir(), props: props(&d.props) });
        }
        for p in &scene.point_lights {
            let a = p.attenuation;
            lights.push(KernelLight::Point { falloff: falloff(p.position, &a), props: props(&p.props) });
        }
        if let Some(s) = &scene.spot_light {
            let a = s.attenuation;
            lights.push(KernelLight::Spot {
                falloff: falloff(s.position, &a),
                axis_to_light: (-s.direction).normalize_or_zero(),
                edge: Edge::of_spot(s.cut_off, s.outer_cut_off),
                props: props(&s.props),
            });
        }
        let cones = cones_of(&lights);
        let grey = lights.iter().all(|l| {
            let p = l.props();
            [p.ambient, p.diffuse, p.specular].iter().all(|v| v.x == v.y && v.y == v.z)
        });
        MultiLightKernel {
            lights,
            cones,
            grey,
            all_grey: grey,
            specialisations: Specialisations::ALL,
            view_pos,
            shininess,
            exponent: Exponent::of(shininess),
            specular,
            window: None,
            folded: None,
            isa: Isa::detect(),
        }
    }

    /// The same kernel with the range window on every point light and the spot
    /// (`None`: LearnOpenGL's falloff, as [`MultiLightKernel::new`]).
    pub fn with_range_window(mut self, window: Option<RangeWindow>) -> MultiLightKernel {
        self.window = window;
        self
    }

    /// The same kernel, told `material`, the material of every lane of a surface without
    /// textures: with coloured lights and the `folded_material` specialisation, a call given
    /// [`MultiLightKernel::material_lanes`] (this kernel's own copy, recognised by its
    /// address, so the check costs nothing next to a batch) sums each light's colours
    /// already multiplied by it. A call with any other material takes the usual path.
    /// Either way the colours are the same within rounding.
    pub fn with_material(mut self, material: &Material) -> MultiLightKernel {
        self.folded = Some(Box::new(Folded::of(&self.lights, material)));
        self
    }

    /// The material of [`MultiLightKernel::with_material`] in every lane, to pass to
    /// [`MultiLightKernel::shade`] and [`MultiLightKernel::shade_batches`]; `None` for a
    /// kernel not told one.
    pub fn material_lanes(&self) -> Option<&LaneMaterial> {
        self.folded.as_ref().map(|f| &f.lanes)
    }

    /// Whether calls given [`MultiLightKernel::material_lanes`] sum folded lights: coloured
    /// lights (the grey path is cheaper) and the specialisation allowed.
    fn folds(&self) -> bool {
        !self.grey && self.specialisations.folded_material && self.folded.is_some()
    }

    /// Whether a call with the material `m` sums folded lights: [`MultiLightKernel::folds`]
    /// and `m` is the kernel's own copy (told by its address, not its 144 values).
    fn folds_for(&self, m: &LaneMaterial) -> bool {
        self.folds() && self.material_lanes().is_some_and(|own| std::ptr::eq(own, m))
    }

    /// The same kernel with only the given value-based [`Specialisations`] allowed
    /// ([`Specialisations::ALL`] is [`MultiLightKernel::new`]'s; [`Specialisations::NONE`] the
    /// general path of `bench --general`).
    pub fn with_specialisations(mut self, allowed: Specialisations) -> MultiLightKernel {
        self.specialisations = allowed;
        self.grey = self.all_grey && allowed.grey_lights;
        self.exponent =
            if allowed.whole_exponent { Exponent::of(self.shininess) } else { Exponent::General(self.shininess) };
        self
    }

    /// The value-based specialisations allowed.
    pub fn specialisations(&self) -> Specialisations {
        self.specialisations
    }

    /// The eye the kernel's `view_dir` points to (the shaders' `viewPos`).
    pub fn view_pos(&self) -> Vec3 {
        self.view_pos
    }

    /// The same kernel restricted to the portable baseline instruction set
    /// (for tests comparing instruction sets).
    pub fn baseline(mut self) -> MultiLightKernel {
        self.isa = Isa::BASELINE;
        self
    }

    /// The arithmetic of one fragment through [`MultiLightKernel::shade`], counted from
    /// the code in floating-point operations per lane: an FMA counts 2; an add,
    /// multiply, estimate (`rsqrt14`, `rcp14`), compare, mask `and`, select or max counts 1.
    ///
    /// | step | operations |
    /// | --- | --- |
    /// | normalize (dot 5, `rsqrt` + Newton 6, finite test 3, select 1, scale 3) | 18 |
    /// | per fragment: normalize `N` (18), `V = eye − p` (3 + 18), zero-normal mask (8), combine with the material (15, none when folded); for the Phong lobe through `L·R_V`, `R_V = 2(N·V)N − V` (12) | 62 (47) + 12 |
    /// | directional light: `N·L` 5, `max` 1, specular base 5 (Phong `L·R_V`; Phong through `reflect` 12; Blinn 26) | 11 (18, 32) + power + sums |
    /// | point light: `p` to light 3, `d²` 5, the test that every lane's `d²` is normal and finite 2, `rsqrt` 6, `d` 1, denominator `Kl·d + (Kq·d² + Kc)` 4, `rcp` 4, `N·p_L` 5 scaled by `1/d` 1, `max` 1; specular base `p_L·R_V` 5 scaled 1 (through `reflect`: `L` 3 and 12; Blinn: `L` 3 and 26) | 38 (47, 61) + power + sums |
    /// | spot light: a point light plus `θ` 5 scaled 1, and the soft edge 5 | 49 (58, 72) + power + sums |
    /// | sums: `factor · diff`, `factor · spec`, then three FMAs per channel (one channel when every light is grey); folded, one sum per channel of `factor · (ambient + diff · diffuse + spec · specular)`, three FMAs | 20 (8; folded 18) |
    /// | power: underflow select 2, then 5 multiplies (32), 6 (64), about 40 otherwise (`exp2(y log2 x)`) | 7, 8 or 42 |
    ///
    /// A batch with a lane whose `d²` is zero, subnormal, infinite or NaN first mends that
    /// light's odd lanes (the finite test 3, four selects for `p_L` and `1/d`, the two
    /// edge tests and selects 4): not counted, since no benchmark scene has such a lane.
    pub fn flops_per_fragment(&self) -> f64 {
        self.flops_per_fragment_evaluating(1.0)
    }

    /// [`MultiLightKernel::flops_per_fragment`] when only a `share` (0 to 1) of the point
    /// lights and spots is evaluated, the rest skipped by culling on the range window
    /// ([`RangeWindow::cull`]). Culling adds the batch's bounding box, 6 min/max folds of 15
    /// operations and 3 NaN tests over 16 lanes per coordinate set (about 7 a lane), and a
    /// box test of 12 operations per light per batch (0.75 a lane a light).
    pub fn flops_per_fragment_evaluating(&self, share: f64) -> f64 {
        // the specular base beyond the rewrite's, for a directional light and for a point
        // light or spot (which scales the rewrite's base by 1/d, 1, but builds L, 3, for the
        // others), and the rewrite's R_V per fragment
        let (lobe, cone_lobe, r_v) = match (self.specular, self.specialisations.phong_rewrite) {
            (Specular::Blinn, _) => (21.0, 23.0, 0.0),
            (Specular::Phong, true) => (0.0, 0.0, 12.0),
            // 2(N·L) 1, r = 2(N·L)·N − L 6, dot(r, V) 5: 12 against 5
            (Specular::Phong, false) => (7.0, 9.0, 0.0),
        };
        let power = match self.exponent {
            Exponent::Whole { n: 32, .. } => 7.0,
            Exponent::Whole { n: 64, .. } => 8.0,
            Exponent::Whole { n, .. } => 2.0 + 2.0 * (32 - n.leading_zeros()) as f64,
            Exponent::Zero => 2.0,
            Exponent::General(_) => 42.0,
        };
        let sums = if self.grey {
            8.0
        } else if self.folds() {
            18.0
        } else {
            20.0
        };
        // the material combined at the end: three products and six FMAs, none when folded
        let combine = if self.folds() { 0.0 } else { 15.0 };
        let dir = self.lights.iter().filter(|l| matches!(l, KernelLight::Dir { .. })).count() as f64;
        let spots = self.cones.iter().filter(|c| c.edge != Edge::None).count() as f64;
        let points = self.cones.len() as f64 - spots;
        // the window: d²/r² 1, its square 1, 1 − x⁴ 1, clamp 2, square 1, times the attenuation 1
        let window = if self.window.is_some() { 7.0 } else { 0.0 };
        let culled = self.window.is_some_and(|w| w.cull);
        let (share, cull) = if culled { (share, 7.0 + 0.75 * (points + spots)) } else { (1.0, 0.0) };
        47.0 + r_v
            + combine
            + cull
            + dir * (11.0 + lobe + power + sums)
            + share * points * (38.0 + window + cone_lobe + power + sums)
            + share * spots * (49.0 + window + cone_lobe + power + sums)
    }

    /// How many point lights and spots [`MultiLightKernel::shade`] evaluates for one batch
    /// at positions `pos`, and how many it has: all of them, unless the range window culls
    /// (then the same bounding-box test as the kernel's decides).
    pub fn cones_evaluated(&self, pos: &[Lanes; 3]) -> (usize, usize) {
        let total = self.cones.len();
        match self.window.filter(|w| w.cull) {
            Some(w) => {
                let bounds = Bounds::of(&[W(pos[0]), W(pos[1]), W(pos[2])]);
                (self.cones.iter().filter(|c| bounds.within(c.falloff.position, w.range)).count(), total)
            }
            None => (total, total),
        }
    }

    /// Shade 16 fragments: `pos` world positions, `normal` interpolated
    /// normals (any length; normalized here), `material` per lane. Writes
    /// unclamped linear RGB to `out`.
    pub fn shade(&self, pos: &[Lanes; 3], normal: &[Lanes; 3], material: &LaneMaterial, out: &mut [Lanes; 3]) {
        shade_per_isa(self.isa, self, &[(pos, normal)], material, std::slice::from_mut(out));
    }

    /// [`MultiLightKernel::shade`] of several batches of 16 fragments, `out[b]` from
    /// `batches[b]` (positions in varyings 0 to 2, normals in 3 to 5): the same values as
    /// one call per batch. The call and the choice of compiled variant are paid once per
    /// `BATCHES_PER_CALL` batches, and the CPU finds independent batches back to back
    /// (on the single-light quad, one light's chain, `x^32` by squaring, is long next to
    /// the rest of a batch's work).
    pub fn shade_batches(&self, batches: &[FragmentBatch], material: &LaneMaterial, out: &mut [[Lanes; 3]]) {
        for (batches, out) in batches.chunks(BATCHES_PER_CALL).zip(out.chunks_mut(BATCHES_PER_CALL)) {
            let inputs: [Input; BATCHES_PER_CALL] = std::array::from_fn(|b| {
                // the lanes past the chunk's batches repeat its last one and are not shaded
                let v = &batches[b.min(batches.len() - 1)].varyings;
                (v[..3].try_into().expect("3 position lanes"), v[3..6].try_into().expect("3 normal lanes"))
            });
            shade_per_isa(self.isa, self, &inputs[..batches.len()], material, out);
        }
    }
}

/// Batches per call of the per-instruction-set entry point in [`MultiLightKernel::shade_batches`].
const BATCHES_PER_CALL: usize = 4;

/// One batch's inputs: 16 positions and 16 normals, structure of arrays.
type Input<'a> = (&'a [Lanes; 3], &'a [Lanes; 3]);

/// Run [`shade_dispatch`] on the instruction set `isa`, with its marker.
fn shade_per_isa(isa: Isa, k: &MultiLightKernel, inputs: &[Input], m: &LaneMaterial, out: &mut [[Lanes; 3]]) {
    match isa.level() {
        // SAFETY: an `Isa` at this level comes only from `Isa::detect`, which found the features.
        #[cfg(target_arch = "x86_64")]
        Level::Avx512 => shade_dispatch(unsafe { Avx512::new_unchecked() }, k, inputs, m, out),
        // SAFETY: as above.
        #[cfg(target_arch = "x86_64")]
        Level::Avx2 => shade_dispatch(unsafe { Avx2::new_unchecked() }, k, inputs, m, out),
        Level::Baseline => shade_dispatch(Baseline, k, inputs, m, out),
    }
}

/// One compiled variant of the kernel per function: [`shade_each`] with its constants,
/// compiled for the marker's instruction set and never inlined into the dispatch.
///
/// Why each variant is its own function: with all 45 variants inlined into one entry point
/// per instruction set (`per_isa!`), three functions held 1.2 MB of machine code, and
/// LLVM spent 460 s of the release build optimising them on one core (one codegen unit).
/// One function per variant spreads them over the codegen units and keeps each small.
trait Variants: Simd {
    /// The variant, compiled with the target's default features (the baseline's); the
    /// x86 markers override it with their own features.
    #[inline(never)]
    fn each<const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool>(
        self,
        k: &MultiLightKernel,
        inputs: &[Input],
        m: &LaneMaterial,
        out: &mut [[Lanes; 3]],
    ) {
        shade_each::<Self, LOBE, SUMS, EXP, WINDOW>(self, k, inputs, m, out)
    }
}

impl Variants for Baseline {}

/// `impl Variants for $marker`, whose variants are compiled with `$features`.
#[cfg(target_arch = "x86_64")]
macro_rules! x86_variants {
    ($marker:ident, $features:literal) => {
        impl Variants for $marker {
            #[inline(always)]
            fn each<const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool>(
                self,
                k: &MultiLightKernel,
                inputs: &[Input],
                m: &LaneMaterial,
                out: &mut [[Lanes; 3]],
            ) {
                #[target_feature(enable = $features)]
                #[inline(never)]
                fn variant<const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool>(
                    s: $marker,
                    k: &MultiLightKernel,
                    inputs: &[Input],
                    m: &LaneMaterial,
                    out: &mut [[Lanes; 3]],
                ) {
                    shade_each::<$marker, LOBE, SUMS, EXP, WINDOW>(s, k, inputs, m, out)
                }
                // SAFETY: a marker value exists only once `Isa::detect` found its features.
                unsafe { variant::<LOBE, SUMS, EXP, WINDOW>(self, k, inputs, m, out) }
            }
        }
    };
}
#[cfg(target_arch = "x86_64")]
x86_variants!(Avx512, "avx512f,avx512vl,avx2,fma");
#[cfg(target_arch = "x86_64")]
x86_variants!(Avx2, "avx2,fma");

/// Pick the compiled variant: lobe (Phong through the `R·V` rewrite or `reflect`, Blinn), grey or coloured lights, the tutorials' shininess
/// 32 and 64 unrolled at compile time (any other exponent is evaluated at run time), and
/// the range window. The window is its own variant: a run-time branch on it in the light
/// loop made the tutorials' path about 15 % slower (different code generation).
#[inline(always)]
fn shade_dispatch<S: Variants>(s: S, k: &MultiLightKernel, inputs: &[Input], m: &LaneMaterial, out: &mut [[Lanes; 3]]) {
    macro_rules! by_exponent {
        ($lobe:tt, $sums:tt) => {
            match (k.exponent, k.window.is_some()) {
                (Exponent::Whole { n: 32, .. }, false) => s.each::<$lobe, $sums, 32, false>(k, inputs, m, out),
                (Exponent::Whole { n: 64, .. }, false) => s.each::<$lobe, $sums, 64, false>(k, inputs, m, out),
                (_, false) => s.each::<$lobe, $sums, 0, false>(k, inputs, m, out),
                (Exponent::Whole { n: 32, .. }, true) => s.each::<$lobe, $sums, 32, true>(k, inputs, m, out),
                (_, true) => s.each::<$lobe, $sums, 0, true>(k, inputs, m, out),
            }
        };
    }
    let sums = if k.grey {
        SUMS_GREY
    } else if k.folds_for(m) {
        SUMS_FOLDED
    } else {
        SUMS_RGB
    };
    match (k.specular, k.specialisations.phong_rewrite, sums) {
        (Specular::Phong, true, SUMS_GREY) => by_exponent!(PHONG_REWRITE, SUMS_GREY),
        (Specular::Phong, true, SUMS_FOLDED) => by_exponent!(PHONG_REWRITE, SUMS_FOLDED),
        (Specular::Phong, true, _) => by_exponent!(PHONG_REWRITE, SUMS_RGB),
        (Specular::Phong, false, SUMS_GREY) => by_exponent!(PHONG_REFLECT, SUMS_GREY),
        (Specular::Phong, false, SUMS_FOLDED) => by_exponent!(PHONG_REFLECT, SUMS_FOLDED),
        (Specular::Phong, false, _) => by_exponent!(PHONG_REFLECT, SUMS_RGB),
        (Specular::Blinn, _, SUMS_GREY) => by_exponent!(BLINN, SUMS_GREY),
        (Specular::Blinn, _, SUMS_FOLDED) => by_exponent!(BLINN, SUMS_FOLDED),
        (Specular::Blinn, _, _) => by_exponent!(BLINN, SUMS_RGB),
    }
}

/// [`shade_lanes`] of one compiled variant on the batches of `inputs`: two at a time,
/// side by side in 32 lanes, where the instruction set has the registers for it
/// ([`Simd::PAIRED_BATCHES`]) and the range window is off (its culling skips lights per
/// batch of 16); else, and for an odd last batch, one at a time. Every lane's arithmetic
/// is the same either way, so are the results.
#[cfg_attr(not(debug_assertions), inline(always))]
fn shade_each<S: Simd, const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool>(
    s: S,
    k: &MultiLightKernel,
    inputs: &[Input],
    m: &LaneMaterial,
    out: &mut [[Lanes; 3]],
) {
    let count = inputs.len().min(out.len());
    let mut b = 0;
    // a branch on constants: the other builds and variants compile no pair code
    if S::PAIRED_BATCHES && !WINDOW {
        while b + 2 <= count {
            shade_side_by_side::<S, LOBE, SUMS, EXP, WINDOW, { 2 * LANES }>(s, k, &inputs[b..b + 2], m, &mut out[b..]);
            b += 2;
        }
    }
    while b < count {
        shade_side_by_side::<S, LOBE, SUMS, EXP, WINDOW, LANES>(s, k, &inputs[b..b + 1], m, &mut out[b..]);
        b += 1;
    }
}

/// [`shade_lanes`] of the `N / 16` batches `inputs` side by side in `N` lanes, the material
/// `m` repeated for each, `out[b]` from `inputs[b]`.
///
/// Written with plain loops: a closure through `std::array::from_fn` stayed a call out of
/// the per-instruction-set entry, compiled without its instruction set (`fmaf` calls).
#[cfg_attr(not(debug_assertions), inline(always))]
fn shade_side_by_side<S: Simd, const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool, const N: usize>(
    s: S,
    k: &MultiLightKernel,
    inputs: &[Input],
    m: &LaneMaterial,
    out: &mut [[Lanes; 3]],
) {
    let (mut pos, mut normal) = ([W::<N>::ZERO; 3], [W::<N>::ZERO; 3]);
    for b in 0..N / LANES {
        let (p, n) = inputs[b];
        for c in 0..3 {
            pos[c].set_part(b, &p[c]);
            normal[c].set_part(b, &n[c]);
        }
    }
    let rgb = shade_lanes::<S, LOBE, SUMS, EXP, WINDOW, N>(s, k, pos, normal, m);
    for b in 0..N / LANES {
        out[b] = [rgb[0].part(b), rgb[1].part(b), rgb[2].part(b)];
    }
}

/// Per-lane sums over lights of `factor · light.term`, per channel (only channel 0 is
/// used when every light is grey: the others would repeat it).
struct Acc<const N: usize> {
    ambient: W3<N>,
    diffuse: W3<N>,
    specular: W3<N>,
}

/// What every light of one batch of fragments shares: the unit normal, the unit
/// direction to the eye (zero where the normal is zero, so that no light gives
/// specular there, as in the core), and for the Phong lobe the view direction
/// reflected about the normal, `R_V = 2(N·V)N − V`: `R·V = L·R_V` for every light.
struct Surfel<const N: usize> {
    n: W3<N>,
    v: W3<N>,
    r_v: W3<N>,
}

/// The shaded colour (unclamped linear RGB) of `N` fragments at `pos` with the normals
/// `normal`, the material's 16 lanes `m` repeated for each batch of 16.
#[cfg_attr(not(debug_assertions), inline(always))]
fn shade_lanes<S: Simd, const LOBE: u8, const SUMS: u8, const EXP: u32, const WINDOW: bool, const N: usize>(
    s: S,
    k: &MultiLightKernel,
    pos: W3<N>,
    normal: W3<N>,
    m: &LaneMaterial,
) -> W3<N> {
    let n = normalize_or_zero(s, &normal);
    let v = normalize_or_zero(s, &point_minus(k.view_pos, &pos));
    // A zero normal (normalize_or_zero of a degenerate one) would reflect -l onto
    // itself and light the fragment; the core gives no specular there.
    let zero = |x: f32| x == 0.0;
    let no_normal = n[0].test(zero).and(n[1].test(zero)).and(n[2].test(zero));
    let v = [no_normal.pick(W::ZERO, v[0]), no_normal.pick(W::ZERO, v[1]), no_normal.pick(W::ZERO, v[2])];
    // R_V only where the lobe reads it
    let r_v = if LOBE == PHONG_REWRITE {
        let twice_n_dot_v = dot::<S, N>(&n, &v) * W::splat(2.0);
        [
            madd::<S, N>(twice_n_dot_v, n[0], -v[0]),
            madd::<S, N>(twice_n_dot_v, n[1], -v[1]),
            madd::<S, N>(twice_n_dot_v, n[2], -v[2]),
        ]
    } else {
        [W::ZERO; 3]
    };
    let surfel = Surfel { n, v, r_v };
    let mut acc = Acc { ambient: [W::ZERO; 3], diffuse: [W::ZERO; 3], specular: [W::ZERO; 3] };
    let exponent = k.exponent;
    // the folded lights when this variant sums them (the dispatch checked they exist)
    let (lights, cones) = match (SUMS, &k.folded) {
        (SUMS_FOLDED, Some(f)) => (&f.lights[..], &f.cones[..]),
        _ => (&k.lights[..], &k.cones[..]),
    };
    for light in lights {
        if let KernelLight::Dir { light_dir, props } = *light {
            let l = [W::splat(light_dir.x), W::splat(light_dir.y), W::splat(light_dir.z)];
            let n_dot_l = dot::<S, N>(&surfel.n, &l);
            let spec = pow_lanes::<EXP, N>(specular_base::<S, LOBE, N>(s, &surfel, &l, n_dot_l), exponent);
            accumulate::<S, SUMS, N>(&mut acc, W::splat(1.0), n_dot_l.max0(), spec, &props);
        }
    }
    let window = if WINDOW { k.window } else { None };
    let bounds = window.filter(|w| w.cull).map(|_| Bounds::of(&pos));
    for cone in cones {
        if let (Some(w), Some(b)) = (window, &bounds) {
            if !b.within(cone.falloff.position, w.range) {
                continue;
            }
        }
        if cone.edge != Edge::None {
            cone_light::<S, LOBE, SUMS, EXP, true, N>(s, &mut acc, &pos, &surfel, cone, exponent, window);
        } else {
            cone_light::<S, LOBE, SUMS, EXP, false, N>(s, &mut acc, &pos, &surfel, cone, exponent, window);
        }
    }
    if SUMS == SUMS_FOLDED {
        return acc.ambient;
    }
    let mut rgb = [W::ZERO; 3];
    for c in 0..3 {
        let from = if SUMS == SUMS_GREY { 0 } else { c };
        let a = acc.ambient[from] * W::tile(&m.ambient[c]);
        let d = madd::<S, N>(acc.diffuse[from], W::tile(&m.diffuse[c]), a);
        rgb[c] = madd::<S, N>(acc.specular[from], W::tile(&m.specular[c]), d);
    }
    rgb
}

/// The bounding box of a batch's 16 positions (all lanes, the stale ones too, so it
/// can only be larger than the live fragments' box; the kernel pairs no batches when it
/// culls, so the lanes are one batch's).
struct Bounds {
    lo: Vec3,
    hi: Vec3,
    /// Some coordinate is NaN: the box says nothing.
    unknown: bool,
}

impl Bounds {
    fn of<const N: usize>(pos: &W3<N>) -> Bounds {
        let lo = |w: &W<N>| w.0.iter().copied().fold(f32::INFINITY, f32::min);
        let hi = |w: &W<N>| w.0.iter().copied().fold(f32::NEG_INFINITY, f32::max);
        let unknown = pos.iter().any(|w| w.0.iter().any(|x| x.is_nan()));
        let (lo, hi) =
            (Vec3::new(lo(&pos[0]), lo(&pos[1]), lo(&pos[2])), Vec3::new(hi(&pos[0]), hi(&pos[1]), hi(&pos[2])));
        Bounds { lo, hi, unknown }
    }

    /// Whether some point of the box is nearer than `range` to `p` (true when anything is
    /// NaN, so that a light is never skipped on a value it cannot judge).
    fn within(&self, p: Vec3, range: f32) -> bool {
        if self.unknown {
            return true;
        }
        let nearest = p.max(self.lo).min(self.hi);
        let d2 = (p - nearest).length_squared();
        let r2 = range * range;
        d2 < r2 || d2.is_nan() || r2.is_nan()
    }
}

/// One point light or spot: attenuation × cone intensity × (ambient + diffuse + specular);
/// a point light (`SPOT` false) skips the cone, whose intensity would be 1.
#[cfg_attr(not(debug_assertions), inline(always))]
#[allow(clippy::too_many_arguments)]
fn cone_light<S: Simd, const LOBE: u8, const SUMS: u8, const EXP: u32, const SPOT: bool, const N: usize>(
    s: S,
    acc: &mut Acc<N>,
    pos: &W3<N>,
    f: &Surfel<N>,
    g: &Cone,
    exponent: Exponent,
    k_window: Option<RangeWindow>,
) {
    let fo = g.falloff;
    let to_light = point_minus(fo.position, pos);
    let dist2 = dot::<S, N>(&to_light, &to_light);
    let inv_distance = dist2.rsqrt(s);
    let distance = dist2 * inv_distance;
    // Kc + Kl·d + Kq·d² with d² as computed, not d·d: Kc + Kq·d² does not wait for the rsqrt
    let denominator =
        madd::<S, N>(W::splat(fo.linear), distance, madd::<S, N>(W::splat(fo.quadratic), dist2, W::splat(fo.constant)));
    let att = denominator.rcp(s);
    // A normal, finite d² in every lane (the usual case) has a finite, positive 1/d and
    // neither of the attenuation's two ends: nothing to mend. Else the odd lanes are
    // mended here, and both cases share the code below (one copy per variant).
    let (to_light, inv_distance, att) = if dist2.all_normal(s) {
        (to_light, inv_distance, att)
    } else {
        irregular_lanes(to_light, dist2, inv_distance, att, fo.at_zero)
    };
    let att = match k_window {
        // clamp(1 − (d/r)⁴, 0, 1)², with (d/r)² = d² · (1/r²); NaN or r ≤ 0 gives 0
        Some(w) if w.range > 0.0 => {
            let inv_r2 = 1.0 / (w.range * w.range);
            let x2 = dist2.map(|d2| d2 * inv_r2);
            let t = x2.map(|x| 1.0 - x * x).clamp01();
            att * t * t
        }
        Some(_) => W::ZERO,
        None => att,
    };
    // Every dot product with L = to_light · (1/d) is linear in L: (x·to_light)·(1/d), so
    // the dot products run beside the rsqrt and only the scaling waits for it (a shorter
    // dependency chain per light, the loop's bound); the same value within rounding.
    let unit = |raw: W<N>| raw * inv_distance;
    let n_dot_l = unit(dot::<S, N>(&f.n, &to_light));
    let factor = if SPOT {
        let axis = g.axis_to_light;
        let theta = unit(dot::<S, N>(&to_light, &[W::splat(axis.x), W::splat(axis.y), W::splat(axis.z)]));
        att * spot_intensity(theta, g.edge)
    } else {
        att
    };
    let base = if LOBE == PHONG_REWRITE {
        // R·V = L·R_V = (1/d)·(to_light·R_V)
        unit(dot::<S, N>(&to_light, &f.r_v))
    } else {
        let l = [to_light[0] * inv_distance, to_light[1] * inv_distance, to_light[2] * inv_distance];
        specular_base::<S, LOBE, N>(s, f, &l, n_dot_l)
    };
    let spec = pow_lanes::<EXP, N>(base, exponent);
    accumulate::<S, SUMS, N>(acc, factor, n_dot_l.max0(), spec, &g.props);
}

/// The lanes of a light whose `d²` is not normal and finite, mended so that the shared
/// code gives each its documented result; the other lanes are returned bit for bit.
/// - Where `1/d` is not finite and positive (`d = 0`, `d = ∞`, NaN), `L = 0`, as glam's
///   `normalize_or_zero`: `to_light` and `1/d` become 0, so every dot product with `L`
///   is 0 (for a finite normal; a normal that is not finite gives NaN, as the fragment's
///   other lights do).
/// - The attenuation is `1/Kc` at the light (`d² = 0`) and 0 infinitely far (`d² = ∞`),
///   where `1/(Kc + Kl·d + Kq·d²)` would be NaN (`d = 0·∞` or `∞·0`).
#[cfg_attr(not(debug_assertions), inline(always))]
fn irregular_lanes<const N: usize>(
    to_light: W3<N>,
    dist2: W<N>,
    inv_distance: W<N>,
    att: W<N>,
    at_zero: f32,
) -> (W3<N>, W<N>, W<N>) {
    let finite = inv_distance.finite_positive();
    let to_light =
        [finite.pick(to_light[0], W::ZERO), finite.pick(to_light[1], W::ZERO), finite.pick(to_light[2], W::ZERO)];
    let att = dist2.test(|d| d == 0.0).pick(W::splat(at_zero), att);
    let att = dist2.test(|d| d == f32::INFINITY).pick(W::ZERO, att);
    (to_light, finite.pick(inv_distance, W::ZERO), att)
}

/// How `pow(base, shininess)` is evaluated for all lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Exponent {
    /// A whole exponent in 1..=1024: square-and-multiply (exact to a few ulps, no `log2`).
    Whole {
        /// The exponent.
        n: u32,
        /// Bases below this give `x^n < 2^-126`: they are flushed to 0 first, so no
        /// product is ever subnormal (subnormal arithmetic costs ~100 cycles per
        /// instruction on x86; llvmpipe flushes them too).
        underflow: f32,
    },
    /// `pow_or_zero(x, 0)`: 1 for `x > 0`, else 0.
    Zero,
    /// Any other exponent: `exp2(y · log2 x)`.
    General(f32),
}

impl Exponent {
    fn of(shininess: f32) -> Exponent {
        if shininess == 0.0 {
            Exponent::Zero
        } else if shininess.fract() == 0.0 && (1.0..=1024.0).contains(&shininess) {
            let n = shininess as u32;
            // 2^(-126/n), nudged up one part in 10^6 so that x^n at the threshold is still normal
            let underflow = (2f64.powf(-126.0 / n as f64) * (1.0 + 1e-6)) as f32;
            Exponent::Whole { n, underflow }
        } else {
            Exponent::General(shininess)
        }
    }
}

/// `x^N` by square-and-multiply, unrolled at compile time (`N ≥ 1`).
#[cfg_attr(not(debug_assertions), inline(always))]
fn pow_const<const N: u32>(x: f32) -> f32 {
    let (mut result, mut base, mut e) = (1.0, x, N);
    while e > 0 {
        if e & 1 == 1 {
            result *= base;
        }
        e >>= 1;
        if e > 0 {
            base *= base;
        }
    }
    result
}

/// `pow_or_zero(max(x, 0), y)` on every lane: a negative, zero or NaN base gives 0 in
/// each branch (the whole exponent's underflow flush, the zero exponent's `x > 0`,
/// `pow_or_zero`'s own test), so the shader's clamp needs no instruction of its own;
/// `EXP ≠ 0` is the exponent known at compile time.
#[cfg_attr(not(debug_assertions), inline(always))]
fn pow_lanes<const EXP: u32, const N: usize>(x: W<N>, exponent: Exponent) -> W<N> {
    let x = match exponent {
        Exponent::Whole { underflow, .. } => x.map(|v| if v >= underflow { v } else { 0.0 }),
        _ => x,
    };
    if EXP != 0 {
        return x.map(pow_const::<EXP>);
    }
    match exponent {
        Exponent::Whole { n, .. } => {
            let (mut result, mut base, mut e) = (W::splat(1.0), x, n);
            loop {
                if e & 1 == 1 {
                    result = result * base;
                }
                e >>= 1;
                if e == 0 {
                    break result;
                }
                base = base * base;
            }
        }
        Exponent::Zero => x.map(|v| if v > 0.0 { 1.0 } else { 0.0 }),
        Exponent::General(y) => x.map(|v| pow_or_zero(v, y)),
    }
}

/// Add one light's `factor · (ambient, diff · diffuse, spec · specular)` to the sums
/// (channel 0 only for [`SUMS_GREY`]; for [`SUMS_FOLDED`] all three terms to the one sum
/// per channel in `acc.ambient`).
#[cfg_attr(not(debug_assertions), inline(always))]
fn accumulate<S: Simd, const SUMS: u8, const N: usize>(
    acc: &mut Acc<N>,
    factor: W<N>,
    diff: W<N>,
    spec: W<N>,
    props: &Props,
) {
    if SUMS == SUMS_FOLDED {
        // the colours hold the material: every term goes to the channel's one sum,
        // factor · (ambient + diff · diffuse + spec · specular)
        for c in 0..3 {
            let d = madd::<S, N>(diff, W::splat(props.diffuse[c]), W::splat(props.ambient[c]));
            let terms = madd::<S, N>(spec, W::splat(props.specular[c]), d);
            acc.ambient[c] = madd::<S, N>(factor, terms, acc.ambient[c]);
        }
        return;
    }
    let (fd, fs) = (factor * diff, factor * spec);
    for c in 0..if SUMS == SUMS_GREY { 1 } else { 3 } {
        acc.ambient[c] = madd::<S, N>(factor, W::splat(props.ambient[c]), acc.ambient[c]);
        acc.diffuse[c] = madd::<S, N>(fd, W::splat(props.diffuse[c]), acc.diffuse[c]);
        acc.specular[c] = madd::<S, N>(fs, W::splat(props.specular[c]), acc.specular[c]);
    }
}

/// The cone's intensity at `theta` ([`Edge`]): `clamp((theta − outer) / ε, 0, 1)` as
/// `(theta − outer) · (1/ε)` for a soft edge, `theta > outer` for a hard one, 1 without a
/// cone.
#[cfg_attr(not(debug_assertions), inline(always))]
fn spot_intensity<const N: usize>(theta: W<N>, edge: Edge) -> W<N> {
    match edge {
        Edge::Soft { cos_outer, inv_epsilon } => theta.map(|t| (t - cos_outer) * inv_epsilon).clamp01(),
        Edge::Hard { cos_outer } => theta.map(|t| if t > cos_outer { 1.0 } else { 0.0 }),
        Edge::None => W::splat(1.0),
    }
}

/// The specular base `R·V` or `N·H` for the unit direction `l` to the light with
/// `N·L = n_dot_l`, unclamped: [`pow_lanes`] gives 0 for a base that is not positive,
/// as `pow(max(x, 0), shininess)` does, so the clamp is not a separate step.
///
/// Phong (`LOBE` [`PHONG_REWRITE`]): `R = reflect(−L, N) = 2 (N·L) N − L`, so
/// `R·V = 2 (N·L)(N·V) − L·V = L·(2(N·V)N − V) = L·R_V`, with `R_V` computed once per
/// fragment; [`PHONG_REFLECT`]
/// computes `R` as the shader does and then `R·V`. Blinn: `H = normalize(L + V)`. Where
/// the normal is zero, `V` was zeroed, and all give 0.
#[cfg_attr(not(debug_assertions), inline(always))]
fn specular_base<S: Simd, const LOBE: u8, const N: usize>(s: S, f: &Surfel<N>, l: &W3<N>, n_dot_l: W<N>) -> W<N> {
    match LOBE {
        BLINN => {
            let h = normalize_or_zero(s, &[l[0] + f.v[0], l[1] + f.v[1], l[2] + f.v[2]]);
            dot::<S, N>(&f.n, &h)
        }
        PHONG_REFLECT => {
            let twice = n_dot_l + n_dot_l;
            let r = [
                madd::<S, N>(twice, f.n[0], -l[0]),
                madd::<S, N>(twice, f.n[1], -l[1]),
                madd::<S, N>(twice, f.n[2], -l[2]),
            ];
            dot::<S, N>(&r, &f.v)
        }
        _ => dot::<S, N>(l, &f.r_v),
    }
}

/// `pow(x, y)` for `x ≥ 0` as `exp2(y · log2 x)`; 0 when `x = 0` or `x` is NaN
/// (the core's `pow_or_zero` on the shader's clamped inputs).
///
/// Relative error about `ln 2 · (6e-8 · y + 1.2e-7 · |y log2 x|)` for normal
/// `x` and `|y · log2 x| ≤ 126` (below 2e-6 wherever the result exceeds 1/255 at `y ≤ 32`);
/// results below 2^-126 flush to 0 (as llvmpipe's denormal flush).
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn pow_or_zero(x: f32, y: f32) -> f32 {
    let r = exp2(y * log2(x));
    if x > 0.0 {
        r
    } else {
        0.0
    }
}

/// `log2(x)` for normal positive `x`: exponent extraction, the mantissa moved
/// to [√½, √2), then `log2(1 + t) = t · P(t)` with a degree-8 polynomial
/// fitted on that interval (Chebyshev least squares; maximum absolute error
/// 6e-8 measured in `f32`). No division, so it vectorizes cheaply.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn log2(x: f32) -> f32 {
    let bits = x.to_bits();
    let mut e = ((bits >> 23) & 0xff) as i32 - 127;
    let mut m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    let big = m > std::f32::consts::SQRT_2;
    m = if big { m * 0.5 } else { m };
    e += big as i32;
    let t = m - 1.0;
    let p = LOG2_POLY[8];
    let p = p * t + LOG2_POLY[7];
    let p = p * t + LOG2_POLY[6];
    let p = p * t + LOG2_POLY[5];
    let p = p * t + LOG2_POLY[4];
    let p = p * t + LOG2_POLY[3];
    let p = p * t + LOG2_POLY[2];
    let p = p * t + LOG2_POLY[1];
    let p = p * t + LOG2_POLY[0];
    e as f32 + t * p
}

/// Coefficients of `P(t) ≈ log2(1 + t) / t` on [√½ − 1, √2 − 1], lowest degree first.
const LOG2_POLY: [f32; 9] = [
    std::f32::consts::LOG2_E, // the fitted constant term equals log2(e) to f32 precision
    -0.721_347_3,
    0.480_910_6,
    -0.360_704_84,
    0.287_918_33,
    -0.238_920_35,
    0.215_669_86,
    -0.207_421_03,
    0.126_148_46,
];

/// `2^y`, by splitting `y = k + f`, `|f| ≤ ½`, and the Taylor series of
/// `e^(f ln 2)` to degree 7 (truncation below 2e-9). `y < −126` gives 0,
/// `y > 127` is clamped to 127; NaN gives 0.
#[cfg_attr(not(debug_assertions), inline(always))]
pub fn exp2(y: f32) -> f32 {
    let yc = if y < 127.0 { y } else { 127.0 };
    let yc = if yc > -126.0 { yc } else { -126.0 };
    // round to nearest with the 1.5 · 2^23 trick: the low mantissa bits hold k
    const SHIFTER: f32 = 12_582_912.0;
    let t = yc + SHIFTER;
    let k = t.to_bits() as i32 - SHIFTER.to_bits() as i32;
    let f = yc - (t - SHIFTER);
    let z = f * std::f32::consts::LN_2;
    let p = 1.0
        + z * (1.0
            + z * (1.0 / 2.0
                + z * (1.0 / 6.0 + z * (1.0 / 24.0 + z * (1.0 / 120.0 + z * (1.0 / 720.0 + z * (1.0 / 5040.0)))))));
    let scale = f32::from_bits(((k + 127) as u32) << 23);
    if y >= -126.0 {
        p * scale
    } else {
        0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Five batches of fragments (two pairs and an odd one for the kernel) around the
    /// LearnOpenGL scene's lights, from a fixed linear congruential sequence; one lane has a
    /// zero normal.
    fn five_batches() -> Vec<FragmentBatch> {
        let mut state = 12345u32;
        let mut next = move || {
            state = state.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (state >> 8) as f32 / (1u32 << 24) as f32 * 4.0 - 2.0
        };
        let mut batches: Vec<FragmentBatch> = (0..5)
            .map(|_| {
                let varyings = std::array::from_fn(|k| std::array::from_fn(|_| if k < 6 { next() } else { 0.0 }));
                FragmentBatch::from_varyings(varyings, LANES)
            })
            .collect();
        for k in 3..6 {
            batches[2].varyings[k][7] = 0.0;
        }
        batches
    }

    #[test]
    fn batches_shaded_together_equal_each_shaded_alone_bit_for_bit() {
        let batches = five_batches();
        let lanes = LaneMaterial::uniform(&Material::coral());
        let grey = Scene::learnopengl_default();
        let mut coloured = grey.clone();
        coloured.point_lights[0].props.diffuse = Vec3::new(1.0, 0.5, 0.2);
        let eye = Vec3::new(0.5, 1.0, 3.0);
        for specular in [Specular::Phong, Specular::Blinn] {
            // 32 and 64 compiled as constants, 10 at run time, 10.5 through exp2(y log2 x)
            for shininess in [32.0, 64.0, 10.0, 10.5] {
                for kernel in [
                    MultiLightKernel::new(&grey, eye, shininess, specular),
                    MultiLightKernel::new(&coloured, eye, shininess, specular),
                    MultiLightKernel::new(&grey, eye, shininess, specular).with_specialisations(Specialisations::NONE),
                ] {
                    let mut together = vec![[[0.0; LANES]; 3]; batches.len()];
                    kernel.shade_batches(&batches, &lanes, &mut together);
                    for (batch, together) in batches.iter().zip(&together) {
                        let v = &batch.varyings;
                        let (pos, normal) = (v[..3].try_into().unwrap(), v[3..6].try_into().unwrap());
                        let mut alone = [[0.0; LANES]; 3];
                        kernel.shade(pos, normal, &lanes, &mut alone);
                        let bits = |rgb: &[Lanes; 3]| rgb.map(|c| c.map(f32::to_bits));
                        assert_eq!(bits(together), bits(&alone), "{specular:?} shininess {shininess}");
                    }
                }
            }
        }
    }

    #[test]
    fn a_spots_edge_is_soft_hard_or_none_by_its_cosines() {
        // LearnOpenGL's cones, 12.5° and 17.5°: ε = cos 12.5° − cos 17.5° > 0
        let (inner, outer) = (12.5f32.to_radians().cos(), 17.5f32.to_radians().cos());
        assert_eq!(Edge::of_spot(inner, outer), Edge::Soft { cos_outer: outer, inv_epsilon: 1.0 / (inner - outer) });
        // equal and inverted cones have no soft edge
        assert_eq!(Edge::of_spot(outer, outer), Edge::Hard { cos_outer: outer });
        assert_eq!(Edge::of_spot(outer, inner), Edge::Hard { cos_outer: inner });
        // at the middle of the ramp the soft edge gives one half; the hard edge 1 inside, 0 outside
        let mid = W::<LANES>::splat(0.5 * (inner + outer));
        let soft = spot_intensity(mid, Edge::of_spot(inner, outer)).0[0];
        // the cosines (about 0.96) round at 6e-8; over the 0.0225 ramp that is about 3e-6
        assert!((soft - 0.5).abs() < 1e-5, "{soft}");
        assert_eq!(spot_intensity(W::<LANES>::splat(inner), Edge::Hard { cos_outer: outer }).0[0], 1.0);
        assert_eq!(spot_intensity(W::<LANES>::splat(-1.0), Edge::Hard { cos_outer: outer }).0[0], 0.0);
        assert_eq!(spot_intensity(W::<LANES>::splat(-1.0), Edge::None).0[0], 1.0);
    }
}
