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
//! Source: LearnOpenGL, Multiple lights (`CalcDirLight`, `CalcPointLight`,
//! `CalcSpotLight`); Blinn 1977 for the half-vector variant.

#![allow(clippy::needless_range_loop)] // lane-indexed loops are the structure-of-arrays form LLVM vectorizes

use glam::Vec3;

/// The instruction set in use (the speed study records it).
#[cfg(feature = "book")]
pub(crate) use super::simd::detect_isa;
use super::simd::{per_isa, Isa, Simd};
use crate::material::Material;
use crate::scene::Scene;

/// Fragments per kernel call.
pub const LANES: usize = 16;

/// One value per lane.
pub type Lanes = [f32; LANES];

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
    Spot { falloff: Falloff, axis_to_light: Vec3, outer_cut_off: f32, inv_epsilon: f32, props: Props },
}

/// A point light or spot in the form the kernel evaluates: attenuated, times a cone intensity.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Cone {
    falloff: Falloff,
    axis_to_light: Vec3,
    outer_cut_off: f32,
    /// `1/ε`, or 0 for a hard edge.
    inv_epsilon: f32,
    props: Props,
}

/// A [`Scene`] compiled for 16-lane shading, with the eye position, shininess and lobe fixed.
#[derive(Clone, Debug, PartialEq)]
pub struct MultiLightKernel {
    lights: Vec<KernelLight>,
    /// Point lights and the spot, as cones (a point light's cone never cuts), shader order.
    cones: Vec<Cone>,
    view_pos: Vec3,
    shininess: f32,
    exponent: Exponent,
    specular: Specular,
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
                outer_cut_off: s.outer_cut_off,
                // ε ≤ 0 (equal cones) is the hard edge: mark it with a zero reciprocal
                inv_epsilon: if s.cut_off > s.outer_cut_off { 1.0 / (s.cut_off - s.outer_cut_off) } else { 0.0 },
                props: props(&s.props),
            });
        }
        let cones = lights
            .iter()
            .filter_map(|l| match *l {
                KernelLight::Dir { .. } => None,
                // theta ≥ −1 > −2 = outer, so the intensity clamp((theta + 2) · 1) is always 1
                KernelLight::Point { falloff, props } => {
                    Some(Cone { falloff, axis_to_light: Vec3::ZERO, outer_cut_off: -2.0, inv_epsilon: 1.0, props })
                }
                KernelLight::Spot { falloff, axis_to_light, outer_cut_off, inv_epsilon, props } => {
                    Some(Cone { falloff, axis_to_light, outer_cut_off, inv_epsilon, props })
                }
            })
            .collect();
        MultiLightKernel {
            lights,
            cones,
            view_pos,
            shininess,
            exponent: Exponent::of(shininess),
            specular,
            isa: Isa::detect(),
        }
    }

    /// The same kernel restricted to the portable baseline instruction set
    /// (for tests comparing instruction sets).
    pub fn baseline(mut self) -> MultiLightKernel {
        self.isa = Isa::BASELINE;
        self
    }

    /// Shade 16 fragments: `pos` world positions, `normal` interpolated
    /// normals (any length; normalized here), `material` per lane. Writes
    /// unclamped linear RGB to `out`.
    pub fn shade(&self, pos: &[Lanes; 3], normal: &[Lanes; 3], material: &LaneMaterial, out: &mut [Lanes; 3]) {
        shade_per_isa(self.isa, self, pos, normal, material, out);
    }
}

per_isa! {
    fn shade_per_isa(
        k: &MultiLightKernel,
        p: &[Lanes; 3],
        n: &[Lanes; 3],
        m: &LaneMaterial,
        out: &mut [Lanes; 3],
    ) = shade_dispatch;
}

/// Pick the compiled variant: lobe, and the tutorials' shininess 32 and 64
/// unrolled at compile time (any other exponent is evaluated at run time).
#[inline(always)]
fn shade_dispatch<S: Simd>(
    s: S,
    k: &MultiLightKernel,
    p: &[Lanes; 3],
    n: &[Lanes; 3],
    m: &LaneMaterial,
    out: &mut [Lanes; 3],
) {
    let whole = match k.exponent {
        Exponent::Whole { n, .. } if n == 32 || n == 64 => n,
        _ => 0,
    };
    match (k.specular, whole) {
        (Specular::Phong, 32) => shade_lanes::<S, false, 32>(s, k, p, n, m, out),
        (Specular::Phong, 64) => shade_lanes::<S, false, 64>(s, k, p, n, m, out),
        (Specular::Phong, _) => shade_lanes::<S, false, 0>(s, k, p, n, m, out),
        (Specular::Blinn, 32) => shade_lanes::<S, true, 32>(s, k, p, n, m, out),
        (Specular::Blinn, 64) => shade_lanes::<S, true, 64>(s, k, p, n, m, out),
        (Specular::Blinn, _) => shade_lanes::<S, true, 0>(s, k, p, n, m, out),
    }
}

/// Per-lane accumulators of `factor · light.term`, per channel.
struct Acc {
    ambient: [Lanes; 3],
    diffuse: [Lanes; 3],
    specular: [Lanes; 3],
}

#[inline(always)]
fn shade_lanes<S: Simd, const BLINN: bool, const EXP: u32>(
    s: S,
    k: &MultiLightKernel,
    pos: &[Lanes; 3],
    normal: &[Lanes; 3],
    m: &LaneMaterial,
    out: &mut [Lanes; 3],
) {
    let mut norm = *normal;
    normalize_lanes(s, &mut norm);
    let mut view_dir = [[0.0; LANES]; 3];
    for c in 0..3 {
        for i in 0..LANES {
            view_dir[c][i] = k.view_pos[c] - pos[c][i];
        }
    }
    normalize_lanes(s, &mut view_dir);
    let mut acc = Acc { ambient: [[0.0; LANES]; 3], diffuse: [[0.0; LANES]; 3], specular: [[0.0; LANES]; 3] };
    let blinn = BLINN;
    let exponent = k.exponent;
    for light in &k.lights {
        if let KernelLight::Dir { light_dir, props } = *light {
            dir_light::<S, EXP>(&mut acc, &norm, &view_dir, light_dir, &props, exponent, blinn);
        }
    }
    for cone in &k.cones {
        cone_light::<S, EXP>(s, &mut acc, pos, &norm, &view_dir, cone, exponent, blinn);
    }
    for c in 0..3 {
        for i in 0..LANES {
            let a = acc.ambient[c][i] * m.ambient[c][i];
            let d = madd::<S>(acc.diffuse[c][i], m.diffuse[c][i], a);
            out[c][i] = madd::<S>(acc.specular[c][i], m.specular[c][i], d);
        }
    }
}

#[inline(always)]
fn dir_light<S: Simd, const EXP: u32>(
    acc: &mut Acc,
    n: &[Lanes; 3],
    v: &[Lanes; 3],
    l: Vec3,
    props: &Props,
    exponent: Exponent,
    blinn: bool,
) {
    let mut diff = [0.0; LANES];
    let mut spec = [0.0; LANES];
    for i in 0..LANES {
        let (nx, ny, nz) = (n[0][i], n[1][i], n[2][i]);
        let (vx, vy, vz) = (v[0][i], v[1][i], v[2][i]);
        diff[i] = max0(dot::<S>(nx, ny, nz, l.x, l.y, l.z));
        spec[i] = specular_base::<S>(nx, ny, nz, l.x, l.y, l.z, vx, vy, vz, blinn);
    }
    pow_lanes::<EXP>(&mut spec, exponent);
    for i in 0..LANES {
        accumulate::<S>(acc, i, 1.0, diff[i], spec[i], props);
    }
}

/// One point light or spot: attenuation × cone intensity × (ambient + diffuse + specular).
///
/// Each step runs over the 16 lanes into a small array (structure of arrays)
/// so every loop vectorizes; the square root and reciprocals go through
/// the marker's `rsqrt` and `rcp`.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn cone_light<S: Simd, const EXP: u32>(
    s: S,
    acc: &mut Acc,
    pos: &[Lanes; 3],
    n: &[Lanes; 3],
    v: &[Lanes; 3],
    g: &Cone,
    exponent: Exponent,
    blinn: bool,
) {
    // copies in registers: a select between a field and an array element would become a gather
    let f = g.falloff;
    let (at_zero, axis, outer_cut_off, inv_epsilon) = (f.at_zero, g.axis_to_light, g.outer_cut_off, g.inv_epsilon);
    let mut to_light = [[0.0; LANES]; 3];
    for c in 0..3 {
        for i in 0..LANES {
            to_light[c][i] = f.position[c] - pos[c][i];
        }
    }
    let mut dist2 = [0.0; LANES];
    for i in 0..LANES {
        let t = &to_light;
        dist2[i] = dot::<S>(t[0][i], t[1][i], t[2][i], t[0][i], t[1][i], t[2][i]);
    }
    let mut inv_distance = [0.0; LANES];
    s.rsqrt(&dist2, &mut inv_distance);
    let mut denominator = [0.0; LANES];
    for i in 0..LANES {
        let distance = dist2[i] * inv_distance[i];
        denominator[i] = madd::<S>(f.quadratic * distance, distance, madd::<S>(f.linear, distance, f.constant));
    }
    let mut attenuation = [0.0; LANES];
    s.rcp(&denominator, &mut attenuation);
    let mut factor = [0.0; LANES];
    let mut diff = [0.0; LANES];
    let mut spec = [0.0; LANES];
    for i in 0..LANES {
        let (tx, ty, tz) = (to_light[0][i], to_light[1][i], to_light[2][i]);
        let rcp = inv_distance[i];
        let ok = rcp > 0.0 && rcp <= f32::MAX;
        let s = if ok { rcp } else { 0.0 };
        // at the light (d = 0) the attenuation is 1/Kc; infinitely far it is 0
        let att = if dist2[i] == 0.0 { at_zero } else { attenuation[i] };
        let att = if dist2[i] == f32::INFINITY { 0.0 } else { att };
        let (lx, ly, lz) = (tx * s, ty * s, tz * s);
        let (nx, ny, nz) = (n[0][i], n[1][i], n[2][i]);
        diff[i] = max0(dot::<S>(nx, ny, nz, lx, ly, lz));
        spec[i] = specular_base::<S>(nx, ny, nz, lx, ly, lz, v[0][i], v[1][i], v[2][i], blinn);
        let theta = dot::<S>(lx, ly, lz, axis.x, axis.y, axis.z);
        factor[i] = att * spot_intensity(theta, outer_cut_off, inv_epsilon);
    }
    pow_lanes::<EXP>(&mut spec, exponent);
    for i in 0..LANES {
        accumulate::<S>(acc, i, factor[i], diff[i], spec[i], &g.props);
    }
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
#[inline(always)]
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

/// `pow_or_zero(x, y)` on 16 lanes of `x ≥ 0` (the shader's clamped dot
/// products); `EXP ≠ 0` is the exponent known at compile time.
#[inline(always)]
fn pow_lanes<const EXP: u32>(x: &mut Lanes, exponent: Exponent) {
    if let Exponent::Whole { underflow, .. } = exponent {
        for v in x.iter_mut() {
            *v = if *v >= underflow { *v } else { 0.0 };
        }
    }
    if EXP != 0 {
        for v in x.iter_mut() {
            *v = pow_const::<EXP>(*v);
        }
        return;
    }
    match exponent {
        Exponent::Whole { n, .. } => {
            let mut result = [1.0f32; LANES];
            let mut base = *x;
            let mut e = n;
            loop {
                if e & 1 == 1 {
                    for i in 0..LANES {
                        result[i] *= base[i];
                    }
                }
                e >>= 1;
                if e == 0 {
                    break;
                }
                for b in base.iter_mut() {
                    *b *= *b;
                }
            }
            *x = result;
        }
        Exponent::Zero => {
            for v in x.iter_mut() {
                *v = if *v > 0.0 { 1.0 } else { 0.0 };
            }
        }
        Exponent::General(y) => {
            for v in x.iter_mut() {
                *v = pow_or_zero(*v, y);
            }
        }
    }
}

#[inline(always)]
fn accumulate<S: Simd>(acc: &mut Acc, i: usize, factor: f32, diff: f32, spec: f32, props: &Props) {
    let (fd, fs) = (factor * diff, factor * spec);
    for c in 0..3 {
        acc.ambient[c][i] = madd::<S>(factor, props.ambient[c], acc.ambient[c][i]);
        acc.diffuse[c][i] = madd::<S>(fd, props.diffuse[c], acc.diffuse[c][i]);
        acc.specular[c][i] = madd::<S>(fs, props.specular[c], acc.specular[c][i]);
    }
}

/// `clamp((theta − outer) / ε, 0, 1)` as `(theta − outer) · (1/ε)`; `inv_epsilon = 0` marks ε ≤ 0: the hard edge `theta > outer`.
#[inline(always)]
fn spot_intensity(theta: f32, outer_cut_off: f32, inv_epsilon: f32) -> f32 {
    let soft = clamp01((theta - outer_cut_off) * inv_epsilon);
    let hard = if theta > outer_cut_off { 1.0 } else { 0.0 };
    if inv_epsilon > 0.0 {
        soft
    } else {
        hard
    }
}

#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn specular_base<S: Simd>(
    nx: f32,
    ny: f32,
    nz: f32,
    lx: f32,
    ly: f32,
    lz: f32,
    vx: f32,
    vy: f32,
    vz: f32,
    blinn: bool,
) -> f32 {
    let base = if blinn {
        let (hx, hy, hz) = normalize_or_zero::<S>(lx + vx, ly + vy, lz + vz);
        dot::<S>(nx, ny, nz, hx, hy, hz)
    } else {
        // reflect(-l, n) = -l - 2 (n · -l) n
        let d2 = 2.0 * dot::<S>(nx, ny, nz, -lx, -ly, -lz);
        let (rx, ry, rz) = (madd::<S>(-d2, nx, -lx), madd::<S>(-d2, ny, -ly), madd::<S>(-d2, nz, -lz));
        dot::<S>(vx, vy, vz, rx, ry, rz)
    };
    // A zero normal (normalize_or_zero of a degenerate one) would reflect -l onto
    // itself and light the fragment; the core gives no specular there.
    let has_normal = nx != 0.0 || ny != 0.0 || nz != 0.0;
    if has_normal {
        max0(base)
    } else {
        0.0
    }
}

/// Normalize 16 vectors in place, glam's `normalize_or_zero`: `v · (1/|v|)`
/// when that reciprocal is finite and positive, else 0.
#[inline(always)]
fn normalize_lanes<S: Simd>(s: S, v: &mut [Lanes; 3]) {
    let mut len2 = [0.0; LANES];
    for i in 0..LANES {
        len2[i] = dot::<S>(v[0][i], v[1][i], v[2][i], v[0][i], v[1][i], v[2][i]);
    }
    let mut rcp = [0.0; LANES];
    s.rsqrt(&len2, &mut rcp);
    for i in 0..LANES {
        let ok = rcp[i] > 0.0 && rcp[i] <= f32::MAX;
        let s = if ok { rcp[i] } else { 0.0 };
        for c in 0..3 {
            v[c][i] *= s;
        }
    }
}

/// `a · b + c`, fused (one rounding) when `F` (the FMA builds), else two roundings.
#[inline(always)]
fn madd<S: Simd>(a: f32, b: f32, c: f32) -> f32 {
    if S::FMA {
        a.mul_add(b, c)
    } else {
        a * b + c
    }
}

/// `a · b` for 3-vectors, in glam's order `(ax bx + ay by) + az bz` (fused when `F`).
#[inline(always)]
fn dot<S: Simd>(ax: f32, ay: f32, az: f32, bx: f32, by: f32, bz: f32) -> f32 {
    madd::<S>(az, bz, madd::<S>(ay, by, ax * bx))
}

#[inline(always)]
fn max0(x: f32) -> f32 {
    if x > 0.0 {
        x
    } else {
        0.0
    }
}

#[inline(always)]
fn clamp01(x: f32) -> f32 {
    let x = if x > 0.0 { x } else { 0.0 };
    if x < 1.0 {
        x
    } else {
        1.0
    }
}

/// glam's `normalize_or_zero`: `v · (1 / |v|)` when that reciprocal is finite and positive, else 0.
#[inline(always)]
fn normalize_or_zero<S: Simd>(x: f32, y: f32, z: f32) -> (f32, f32, f32) {
    let rcp = 1.0 / dot::<S>(x, y, z, x, y, z).sqrt();
    let ok = rcp > 0.0 && rcp <= f32::MAX;
    let s = if ok { rcp } else { 0.0 };
    (x * s, y * s, z * s)
}

/// `pow(x, y)` for `x ≥ 0` as `exp2(y · log2 x)`; 0 when `x = 0` or `x` is NaN
/// (the core's `pow_or_zero` on the shader's clamped inputs).
///
/// Relative error about `ln 2 · (6e-8 · y + 1.2e-7 · |y log2 x|)` for normal
/// `x` and `|y · log2 x| ≤ 126` (below 2e-6 wherever the result exceeds 1/255 at `y ≤ 32`);
/// results below 2^-126 flush to 0 (as llvmpipe's denormal flush).
#[inline(always)]
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
#[inline(always)]
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
#[inline(always)]
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
