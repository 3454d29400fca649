//! SIMD in one place: which instruction set runs, the per-instruction-set
//! entry points, and the few vector helpers written with intrinsics.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | [`Isa`] | the instruction set chosen at run time: the best this CPU has, or a lower one named by `LIGHTLAB_ISA` |
//! | [`Simd`] | a compile-time marker of one instruction set: fused multiply-add or not, exact or estimated `1/√x` and `1/x` |
//! | [`Baseline`], [`Avx2`], [`Avx512`] | the markers |
//! | `per_isa!` | defines a function's per-instruction-set entry points and the `match` that picks one |
//! | [`LANES`], [`Lanes`] | the lane count (16) and one `f32` per lane, which the wide values and the kernel build on |
//!
//! The shading kernel and the rasterizer's band loop are written once,
//! generic over `S: Simd`, and instantiated inside functions compiled with
//! the instruction set enabled (`#[target_feature]`), so LLVM vectorizes the
//! whole body for it: the band loop through `per_isa!`, the kernel one
//! function per compiled variant (`raster/kernel.rs`, `Variants`). Three builds:
//!
//! | marker | features | `madd` | `1/√x`, `1/x` |
//! | --- | --- | --- | --- |
//! | [`Avx512`] | AVX-512F + VL, AVX2, FMA | fused | 14-bit estimate + one Newton step (within 2 ulps) |
//! | [`Avx2`] | AVX2, FMA | fused | 12-bit estimate + one Newton step (about 22 bits) |
//! | [`Baseline`] | the target's default (SSE2 on x86-64) | two roundings | exact division and square root |
//!
//! Safety by construction: [`Avx2`] and [`Avx512`] have private fields and
//! are made only by an `unsafe` constructor, which the dispatch calls after
//! [`Isa::detect`] found the features on this CPU; [`Isa`]'s level is private
//! too, so no other code can claim a level. Holding a marker value is the
//! proof that its intrinsics may run.
//!
//! The entry points take the job's arguments one by one (not packed in a
//! struct): a generic entry over a job struct measured about 15% slower on
//! the multi-light kernel, from different code generation.
//!
//! Sources: Intel Intrinsics Guide (`rsqrt14`, `rcp14`, `rsqrt`, `rcp`);
//! Newton–Raphson refinement as in Intel's optimization manual.

#![allow(clippy::needless_range_loop)] // lane-indexed loops are the structure-of-arrays form LLVM vectorizes

use super::clip::MAX_VARYINGS;

/// Fragments per kernel call: one AVX-512 register of `f32`, two AVX2 ones,
/// four SSE2 ones.
pub const LANES: usize = 16;

/// One value per lane.
pub type Lanes = [f32; LANES];

/// The instruction set the kernel and rasterizer run with.
///
/// Its `Debug` form is the level's name (`Avx512`, `Avx2`, `Baseline`), as
/// the speed study records it.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) struct Isa(Level);

/// An instruction-set level; only [`Isa::detect`] turns one into an [`Isa`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Level {
    #[cfg(target_arch = "x86_64")]
    Avx512,
    #[cfg(target_arch = "x86_64")]
    Avx2,
    Baseline,
}

impl std::fmt::Debug for Isa {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Debug::fmt(&self.0, f)
    }
}

impl Isa {
    /// The portable build: no intrinsics, exact divisions, separate multiply and add.
    pub(crate) const BASELINE: Isa = Isa(Level::Baseline);

    /// The level, for `per_isa!`'s `match`.
    pub(crate) fn level(self) -> Level {
        self.0
    }

    /// The best instruction set this CPU supports, or a lower one named by the
    /// environment variable `LIGHTLAB_ISA` (`avx2` or `baseline`; read once),
    /// so every build can be tested on one machine. An unknown value, or
    /// `avx2` on a CPU without it, gives the best.
    pub(crate) fn detect() -> Isa {
        static ISA: std::sync::OnceLock<Isa> = std::sync::OnceLock::new();
        *ISA.get_or_init(|| {
            let best = best_level();
            let level = match std::env::var("LIGHTLAB_ISA").as_deref() {
                Ok("baseline") => Level::Baseline,
                #[cfg(target_arch = "x86_64")]
                Ok("avx2") if best != Level::Baseline => Level::Avx2,
                _ => best,
            };
            Isa(level)
        })
    }
}

/// [`Isa::detect`], as a function (for the speed study).
#[cfg(feature = "book")]
pub(crate) fn detect_isa() -> Isa {
    Isa::detect()
}

fn best_level() -> Level {
    #[cfg(target_arch = "x86_64")]
    {
        if is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512vl") {
            return Level::Avx512;
        }
        if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
            return Level::Avx2;
        }
    }
    Level::Baseline
}

/// A compile-time instruction-set marker; a value of it proves the CPU has the set.
pub(crate) trait Simd: Copy {
    /// `madd` fuses (one rounding) in this build.
    const FMA: bool;

    /// The shading kernel evaluates two batches side by side, 32 lanes per step, so that
    /// each light's long dependency chains (`x^32` by squaring, the reciprocal square
    /// root) of one batch overlap the other's. Only where the registers hold both batches'
    /// values ([`Avx512`]: 32 registers of 16 lanes; AVX2's 16 registers of 8 lanes are
    /// already short for one batch).
    const PAIRED_BATCHES: bool = false;

    /// `out = 1 / sqrt(x)` per lane. 0 gives +∞ (or NaN after a Newton step),
    /// a negative or NaN input NaN: callers treat both as "not finite".
    fn rsqrt(self, x: &Lanes, out: &mut Lanes);

    /// `out = 1 / x` per lane (0 gives +∞ or NaN, as above).
    fn rcp(self, x: &Lanes, out: &mut Lanes);

    /// Every lane of `x` is a normal, finite, positive number: in
    /// `[f32::MIN_POSITIVE, f32::MAX]` (false for any zero, subnormal, infinite, negative or NaN lane).
    #[inline(always)]
    fn all_normal(self, x: &Lanes) -> bool {
        x.iter().fold(true, |all, &v| all & (f32::MIN_POSITIVE..=f32::MAX).contains(&v))
    }

    /// Perspective-correct varyings of 16 consecutive pixels `x0, x0 + 1, …` of a row:
    /// `v_k = (v0_k + vdx_k · x) / (w0 + wdx · x)` for `k < nv` (the planes of `v/w`
    /// and `1/w`), unfused and with an exact division in every build.
    ///
    /// Written with explicit vector instructions where LLVM, left to itself,
    /// vectorizes across the varyings (with scatters) instead of across the pixels.
    #[inline(always)]
    fn interpolate(self, x0: f32, planes: &RowPlanes, out: &mut [Lanes; MAX_VARYINGS]) {
        interpolate_portable(x0, planes, out)
    }

    /// 16 pixels `out[l] = [rgb[0][l], rgb[1][l], rgb[2][l], 1]` from the shader's
    /// structure of arrays: a transpose, so the same bits in every build.
    ///
    /// Left to itself, LLVM builds each pixel with three `vinsertps` from the spilled
    /// channels (about a tenth of quad-single's frame); [`Avx512`] transposes in registers.
    #[inline(always)]
    fn rgba_pixels(self, rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) {
        rgba_pixels_portable(rgb, out)
    }

    /// 16 RGBA8 pixels `out[l] = [q(rgb[0][l]), q(rgb[1][l]), q(rgb[2][l]), 255]`, `q` the
    /// framebuffer's [`quantize`](super::framebuffer::quantize): the same bytes in every build.
    ///
    /// LLVM does not vectorize the portable loop (the library's `round` and the saturating
    /// conversions stay one scalar conversion per channel, which made the RGBA8 target
    /// slower than the float one); [`Avx2`] and [`Avx512`] clamp, scale, round and pack in
    /// registers.
    #[inline(always)]
    fn rgba8_pixels(self, rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
        for (l, px) in out.iter_mut().enumerate() {
            *px = [0, 1, 2, 3].map(|k| if k < 3 { super::framebuffer::quantize(rgb[k][l]) } else { 255 });
        }
    }

    /// The depth test `LESS` with depth writes on the 16 pixels `depth` of a row at
    /// `x = x0 + l`, where the plane `z = z0 + zdx · x` (not fused) lies, for the lanes
    /// whose bit is set in `live`: bit `l` of the result says whether lane `l` is live
    /// and passed, and then `depth[l] = z`. The other lanes are left as they were.
    ///
    /// All 16 lanes are computed, branch-free. The per-lane loop with a branch was about
    /// 7 % of the band loop on the sweep's small triangles, whose spans are a few pixels;
    /// [`Avx512`] has the mask in a mask register and stores under it, where LLVM built
    /// the bit mask from the portable loop with a chain of shuffles.
    #[inline(always)]
    fn depth_less(self, depth: &mut Lanes, z0: f32, zdx: f32, x0: f32, live: u32) -> u32 {
        let mut pass = [false; LANES];
        for l in 0..LANES {
            let z = z0 + zdx * (x0 + l as f32);
            pass[l] = (live & (1 << l) != 0) & (z < depth[l]);
            depth[l] = if pass[l] { z } else { depth[l] };
        }
        let mut mask = 0;
        for l in 0..LANES {
            mask |= (pass[l] as u32) << l;
        }
        mask
    }

    /// [`Simd::rgba_pixels`] stored only to the pixels `l` whose bit `l` of `mask` is
    /// set; the others are left as they were.
    ///
    /// The portable form is a branch per pixel (a tenth of sphere4096-gouraud's band loop,
    /// on its partly covered chunks); [`Avx512`] stores the transposed registers with
    /// write masks.
    #[inline(always)]
    fn rgba_pixels_where(self, rgb: &[Lanes; 3], mask: u32, out: &mut [[f32; 4]; LANES]) {
        let mut block = [[0.0; 4]; LANES];
        self.rgba_pixels(rgb, &mut block);
        store_where(&block, mask, out);
    }

    /// [`Simd::rgba8_pixels`] stored only where `mask` has a bit, as [`Simd::rgba_pixels_where`].
    #[inline(always)]
    fn rgba8_pixels_where(self, rgb: &[Lanes; 3], mask: u32, out: &mut [[u8; 4]; LANES]) {
        let mut block = [[0; 4]; LANES];
        self.rgba8_pixels(rgb, &mut block);
        store_where(&block, mask, out);
    }

    /// The lanes `l` of `x` whose bit `l` of `mask` is set, in order, into the first
    /// `popcount(mask)` lanes of `out` (the later lanes of `out` hold unspecified values
    /// of `x`): a stream compaction.
    ///
    /// The portable form is a branch and a store per lane; [`Avx512`] has it as one
    /// instruction (`vcompressps`).
    #[inline(always)]
    fn compress(self, x: &Lanes, mask: u32, out: &mut Lanes) {
        compress_portable(x, mask, out)
    }

    /// [`Simd::compress`] of 32-bit integers.
    #[inline(always)]
    fn compress_u32(self, x: &[u32; LANES], mask: u32, out: &mut [u32; LANES]) {
        compress_portable(x, mask, out)
    }

    /// Which of the `8·BLOCKS` pixels `l = 0, 1, …` of a row are inside all three edges:
    /// bit `l` is set when
    ///
    /// ```text
    /// at[e] + a[e] · l ≥ 0   for e = 0, 1, 2
    /// ```
    ///
    /// (`at[e]` an edge function at the row's first pixel, `a[e]` its step per pixel).
    /// The callers' values are integers whose sums stay below 2^53, so every lane is exact
    /// and fused or not gives the same bits. `BLOCKS` is 2 (16 pixels) or 4 (32).
    ///
    /// Written with explicit vector compares into mask registers: LLVM, given the
    /// portable loop over an array of booleans, mixed 8-, 4- and 2-lane vectors with scalar
    /// compares and rebuilt the mask with a chain of shuffles.
    #[inline(always)]
    fn edge_mask<const BLOCKS: usize>(self, at: [f64; 3], a: [f64; 3]) -> u32 {
        edge_mask_portable::<BLOCKS>(at, a)
    }
}

/// [`Simd::edge_mask`], lane by lane.
#[inline(always)]
fn edge_mask_portable<const BLOCKS: usize>(at: [f64; 3], a: [f64; 3]) -> u32 {
    let mut mask = 0u32;
    for l in 0..8 * BLOCKS.min(4) {
        let inside = (0..3).all(|e| at[e] + a[e] * l as f64 >= 0.0);
        mask |= (inside as u32) << l;
    }
    mask
}

/// `out[l] = block[l]` where bit `l` of `mask` is set.
#[inline(always)]
fn store_where<T: Copy>(block: &[T; LANES], mask: u32, out: &mut [T; LANES]) {
    for (l, (px, &value)) in out.iter_mut().zip(block).enumerate() {
        if mask & (1 << l) != 0 {
            *px = value;
        }
    }
}

#[inline(always)]
fn compress_portable<T: Copy>(x: &[T; LANES], mask: u32, out: &mut [T; LANES]) {
    let mut to = 0;
    for l in 0..LANES {
        if mask & (1 << l) != 0 {
            out[to] = x[l];
            to += 1;
        }
    }
}

#[inline(always)]
fn rgba_pixels_portable(rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) {
    for (l, px) in out.iter_mut().enumerate() {
        *px = [rgb[0][l], rgb[1][l], rgb[2][l], 1.0];
    }
}

/// One pixel row's planes for [`Simd::interpolate`]: `1/w = w.0 + w.1 · x` and
/// `v_k/w = v0[k] + vdx[k] · x` for the first `nv` varyings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RowPlanes {
    /// `(1/w at x = 0, its change per pixel)`.
    pub w: (f32, f32),
    /// `v_k/w` at `x = 0`.
    pub v0: [f32; MAX_VARYINGS],
    /// The change of `v_k/w` per pixel.
    pub vdx: [f32; MAX_VARYINGS],
    /// How many varyings are live.
    pub nv: usize,
}

/// The portable build (any CPU).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Baseline;

/// AVX2 with FMA; made only by the dispatch, after detection.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx2(());

/// AVX-512 (F and VL) with AVX2 and FMA; made only by the dispatch, after detection.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx512(());

#[cfg(target_arch = "x86_64")]
impl Avx2 {
    /// The marker.
    ///
    /// # Safety
    /// The CPU running the program supports AVX2 and FMA.
    pub(crate) unsafe fn new_unchecked() -> Avx2 {
        Avx2(())
    }
}

#[cfg(target_arch = "x86_64")]
impl Avx512 {
    /// The marker.
    ///
    /// # Safety
    /// The CPU running the program supports AVX-512F, AVX-512VL, AVX2 and FMA.
    pub(crate) unsafe fn new_unchecked() -> Avx512 {
        Avx512(())
    }
}

impl Simd for Baseline {
    const FMA: bool = false;

    #[inline(always)]
    fn rsqrt(self, x: &Lanes, out: &mut Lanes) {
        for i in 0..LANES {
            out[i] = 1.0 / x[i].sqrt();
        }
    }

    #[inline(always)]
    fn rcp(self, x: &Lanes, out: &mut Lanes) {
        for i in 0..LANES {
            out[i] = 1.0 / x[i];
        }
    }
}

/// `impl Simd` for an x86 marker whose reciprocal square root and reciprocal are the
/// intrinsics wrappers `x86::$rsqrt` and `x86::$rcp`; `$extra` holds its other overrides.
/// Every call is sound because a marker value exists only after its features were
/// detected on this CPU (its `new_unchecked` is the only constructor, called by the dispatch
/// after detection).
macro_rules! x86_simd {
    ($marker:ty, $rsqrt:ident, $rcp:ident { $($extra:tt)* }) => {
        #[cfg(target_arch = "x86_64")]
        impl Simd for $marker {
            const FMA: bool = true;

            #[inline(always)]
            fn rsqrt(self, x: &Lanes, out: &mut Lanes) {
                // SAFETY: `self` exists only after its features were detected (see above).
                unsafe { x86::$rsqrt(x, out) }
            }

            #[inline(always)]
            fn rcp(self, x: &Lanes, out: &mut Lanes) {
                // SAFETY: as above.
                unsafe { x86::$rcp(x, out) }
            }

            $($extra)*
        }
    };
}

x86_simd!(Avx2, rsqrt_avx2, rcp_avx2 {
    #[inline(always)]
    fn all_normal(self, x: &Lanes) -> bool {
        // SAFETY: an `Avx2` value exists only after AVX2 and FMA were detected.
        unsafe { x86::all_normal_avx2(x) }
    }

    #[inline(always)]
    fn rgba8_pixels(self, rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
        // SAFETY: an `Avx2` value exists only after AVX2 and FMA were detected.
        unsafe { x86::rgba8_pixels_avx2(rgb, out) }
    }

    #[inline(always)]
    fn edge_mask<const BLOCKS: usize>(self, at: [f64; 3], a: [f64; 3]) -> u32 {
        // SAFETY: as above.
        unsafe { x86::edge_mask_avx2::<BLOCKS>(at, a) }
    }
});

x86_simd!(Avx512, rsqrt_avx512, rcp_avx512 {
    const PAIRED_BATCHES: bool = true;

    #[inline(always)]
    fn all_normal(self, x: &Lanes) -> bool {
        // SAFETY: an `Avx512` value exists only after AVX-512F/VL, AVX2 and FMA were detected.
        unsafe { x86::all_normal_avx512(x) }
    }

    #[inline(always)]
    fn interpolate(self, x0: f32, planes: &RowPlanes, out: &mut [Lanes; MAX_VARYINGS]) {
        // SAFETY: an `Avx512` value exists only after AVX-512F/VL, AVX2 and FMA were detected.
        unsafe { x86::interpolate_avx512(x0, planes, out) }
    }

    #[inline(always)]
    fn rgba_pixels(self, rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) {
        // SAFETY: as above.
        unsafe { x86::rgba_pixels_avx512(rgb, out) }
    }

    #[inline(always)]
    fn rgba8_pixels(self, rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
        // SAFETY: as above.
        unsafe { x86::rgba8_pixels_avx512(rgb, out) }
    }

    #[inline(always)]
    fn depth_less(self, depth: &mut Lanes, z0: f32, zdx: f32, x0: f32, live: u32) -> u32 {
        // SAFETY: as above.
        unsafe { x86::depth_less_avx512(depth, z0, zdx, x0, live) }
    }

    #[inline(always)]
    fn rgba_pixels_where(self, rgb: &[Lanes; 3], mask: u32, out: &mut [[f32; 4]; LANES]) {
        // SAFETY: as above.
        unsafe { x86::rgba_pixels_where_avx512(rgb, mask, out) }
    }

    #[inline(always)]
    fn rgba8_pixels_where(self, rgb: &[Lanes; 3], mask: u32, out: &mut [[u8; 4]; LANES]) {
        // SAFETY: as above.
        unsafe { x86::rgba8_pixels_where_avx512(rgb, mask, out) }
    }

    #[inline(always)]
    fn compress(self, x: &Lanes, mask: u32, out: &mut Lanes) {
        // SAFETY: as above.
        unsafe { x86::compress_avx512(x, mask, out) }
    }

    #[inline(always)]
    fn compress_u32(self, x: &[u32; LANES], mask: u32, out: &mut [u32; LANES]) {
        // SAFETY: as above.
        unsafe { x86::compress_u32_avx512(x, mask, out) }
    }

    #[inline(always)]
    fn edge_mask<const BLOCKS: usize>(self, at: [f64; 3], a: [f64; 3]) -> u32 {
        // SAFETY: as above.
        unsafe { x86::edge_mask_avx512::<BLOCKS>(at, a) }
    }
});

#[inline(always)]
fn interpolate_portable(x0: f32, planes: &RowPlanes, out: &mut [Lanes; MAX_VARYINGS]) {
    let ((w0, wdx), v0, vdx, nv) = (planes.w, &planes.v0, &planes.vdx, planes.nv);
    let mut rcp = [0.0f32; LANES];
    for (l, r) in rcp.iter_mut().enumerate() {
        *r = 1.0 / (w0 + wdx * (x0 + l as f32));
    }
    for k in 0..nv {
        for l in 0..LANES {
            out[k][l] = (v0[k] + vdx[k] * (x0 + l as f32)) * rcp[l];
        }
    }
}

/// `per_isa!(vis fn name(a: A, …) [-> R] = generic);` defines
/// `vis fn name(isa: Isa, a: A, …) [-> R]`, which runs `generic(marker, a, …)`
/// compiled for `isa`: one `#[target_feature]` entry point per instruction set,
/// each making its marker, and the `match` on [`Isa::level`] that picks one.
/// `generic` should be `#[inline(always)]`, so that its body is compiled
/// inside the entry point.
macro_rules! per_isa {
    ($vis:vis fn $name:ident($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)? = $generic:path;) => {
        $vis fn $name(isa: $crate::raster::simd::Isa, $($arg: $ty),*) $(-> $ret)? {
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
            fn avx512($($arg: $ty),*) $(-> $ret)? {
                // SAFETY: called only when `Isa::detect` found these features (the match below).
                let s = unsafe { $crate::raster::simd::Avx512::new_unchecked() };
                $generic(s, $($arg),*)
            }
            #[cfg(target_arch = "x86_64")]
            #[target_feature(enable = "avx2,fma")]
            fn avx2($($arg: $ty),*) $(-> $ret)? {
                // SAFETY: as above.
                let s = unsafe { $crate::raster::simd::Avx2::new_unchecked() };
                $generic(s, $($arg),*)
            }
            match isa.level() {
                // SAFETY: an `Isa` at this level comes only from `Isa::detect`, which found the features.
                #[cfg(target_arch = "x86_64")]
                $crate::raster::simd::Level::Avx512 => unsafe { avx512($($arg),*) },
                // SAFETY: as above.
                #[cfg(target_arch = "x86_64")]
                $crate::raster::simd::Level::Avx2 => unsafe { avx2($($arg),*) },
                $crate::raster::simd::Level::Baseline => $generic($crate::raster::simd::Baseline, $($arg),*),
            }
        }
    };
}
pub(crate) use per_isa;

/// The arithmetic peak probe of the roofline: `iterations` rounds of eight independent
/// multiply-add chains (`acc = acc · m + a`) of the widest vectors the CPU has; returns
/// the flops done (an FMA lane is 2) and a sum that keeps the work from being optimized
/// away. Written with intrinsics: LLVM, given loop-carried lane arrays, vectorized the
/// wrong dimension.
#[cfg(feature = "book")]
pub(crate) fn fma_probe(iterations: u64, seed: f32) -> (f64, f32) {
    #[cfg(target_arch = "x86_64")]
    match Isa::detect().level() {
        // SAFETY: the level was detected on this CPU.
        Level::Avx512 => {
            return (iterations as f64 * 8.0 * 16.0 * 2.0, unsafe { x86::fma_probe_avx512(iterations, seed) })
        }
        // SAFETY: as above.
        Level::Avx2 => return (iterations as f64 * 8.0 * 8.0 * 2.0, unsafe { x86::fma_probe_avx2(iterations, seed) }),
        Level::Baseline => {}
    }
    let mut acc = [[seed; 4]; 8];
    for _ in 0..iterations {
        for chain in acc.iter_mut() {
            for x in chain.iter_mut() {
                *x = *x * 0.999_99 + 1e-3;
            }
        }
    }
    (iterations as f64 * 8.0 * 4.0 * 2.0, acc.iter().flatten().sum())
}

/// The intrinsics (x86-64 only).
#[cfg(target_arch = "x86_64")]
mod x86 {
    use std::arch::x86_64::*;

    use super::{Lanes, RowPlanes, LANES, MAX_VARYINGS};

    /// Generates the probe for one vector width: eight named accumulators (kept in registers).
    macro_rules! fma_probe {
        ($name:ident, $features:literal, $set1:ident, $fmadd:ident, $add:ident, $store:ident, $n:literal) => {
            #[cfg(feature = "book")]
            #[target_feature(enable = $features)]
            pub(super) fn $name(iterations: u64, seed: f32) -> f32 {
                let (m, a) = ($set1(0.999_99), $set1(1e-3));
                let (mut a0, mut a1, mut a2, mut a3) =
                    ($set1(seed), $set1(seed + 1.0), $set1(seed + 2.0), $set1(seed + 3.0));
                let (mut a4, mut a5, mut a6, mut a7) =
                    ($set1(seed + 4.0), $set1(seed + 5.0), $set1(seed + 6.0), $set1(seed + 7.0));
                for _ in 0..iterations {
                    a0 = $fmadd(a0, m, a);
                    a1 = $fmadd(a1, m, a);
                    a2 = $fmadd(a2, m, a);
                    a3 = $fmadd(a3, m, a);
                    a4 = $fmadd(a4, m, a);
                    a5 = $fmadd(a5, m, a);
                    a6 = $fmadd(a6, m, a);
                    a7 = $fmadd(a7, m, a);
                }
                let sum = $add($add($add(a0, a1), $add(a2, a3)), $add($add(a4, a5), $add(a6, a7)));
                let mut out = [0.0f32; $n];
                // SAFETY: `out` holds one vector of f32.
                unsafe { $store(out.as_mut_ptr(), sum) };
                out.iter().sum()
            }
        };
    }
    fma_probe!(
        fma_probe_avx512,
        "avx512f,avx512vl,avx2,fma",
        _mm512_set1_ps,
        _mm512_fmadd_ps,
        _mm512_add_ps,
        _mm512_storeu_ps,
        16
    );
    fma_probe!(fma_probe_avx2, "avx2,fma", _mm256_set1_ps, _mm256_fmadd_ps, _mm256_add_ps, _mm256_storeu_ps, 8);

    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rsqrt_avx512(x: &Lanes, out: &mut Lanes) {
        // SAFETY: `x` and `out` hold 16 f32 each, the width of one unaligned load/store.
        let v = unsafe { _mm512_loadu_ps(x.as_ptr()) };
        let y = _mm512_rsqrt14_ps(v);
        // Newton: y · (1.5 − ½ v y²)
        let t = _mm512_fnmadd_ps(_mm512_mul_ps(_mm512_set1_ps(0.5), v), _mm512_mul_ps(y, y), _mm512_set1_ps(1.5));
        // SAFETY: as above.
        unsafe { _mm512_storeu_ps(out.as_mut_ptr(), _mm512_mul_ps(y, t)) };
    }

    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rcp_avx512(x: &Lanes, out: &mut Lanes) {
        // SAFETY: `x` and `out` hold 16 f32 each.
        let v = unsafe { _mm512_loadu_ps(x.as_ptr()) };
        let y = _mm512_rcp14_ps(v);
        // Newton: y · (2 − v y)
        let t = _mm512_fnmadd_ps(v, y, _mm512_set1_ps(2.0));
        // SAFETY: as above.
        unsafe { _mm512_storeu_ps(out.as_mut_ptr(), _mm512_mul_ps(y, t)) };
    }

    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn all_normal_avx512(x: &Lanes) -> bool {
        // SAFETY: `x` holds 16 f32, one unaligned load.
        let v = unsafe { _mm512_loadu_ps(x.as_ptr()) };
        let low = _mm512_cmp_ps_mask::<_CMP_GE_OQ>(v, _mm512_set1_ps(f32::MIN_POSITIVE));
        _mm512_mask_cmp_ps_mask::<_CMP_LE_OQ>(low, v, _mm512_set1_ps(f32::MAX)) == 0xffff
    }

    #[target_feature(enable = "avx2,fma")]
    #[inline]
    pub(super) fn all_normal_avx2(x: &Lanes) -> bool {
        let mut all = true;
        for h in 0..LANES / 8 {
            // SAFETY: lanes 8h..8h+8 are inside the 16-lane array.
            let v = unsafe { _mm256_loadu_ps(x.as_ptr().add(8 * h)) };
            let low = _mm256_cmp_ps::<_CMP_GE_OQ>(v, _mm256_set1_ps(f32::MIN_POSITIVE));
            let high = _mm256_cmp_ps::<_CMP_LE_OQ>(v, _mm256_set1_ps(f32::MAX));
            all &= _mm256_movemask_ps(_mm256_and_ps(low, high)) == 0xff;
        }
        all
    }

    /// `out = f(x)` on the two 8-lane halves of 16 lanes: loads half `h`, applies the
    /// expression `$f` to it (in the caller's `#[target_feature]` context, as a macro and
    /// not a closure) and stores the result.
    macro_rules! by_halves {
        ($x:expr, $out:expr, |$v:ident| $f:expr) => {
            for h in 0..LANES / 8 {
                // SAFETY: lanes 8h..8h+8 are inside the 16-lane arrays.
                let $v = unsafe { _mm256_loadu_ps($x.as_ptr().add(8 * h)) };
                let r = $f;
                // SAFETY: as above.
                unsafe { _mm256_storeu_ps($out.as_mut_ptr().add(8 * h), r) };
            }
        };
    }

    #[target_feature(enable = "avx2,fma")]
    #[inline]
    pub(super) fn rsqrt_avx2(x: &Lanes, out: &mut Lanes) {
        by_halves!(x, out, |v| {
            let y = _mm256_rsqrt_ps(v);
            // Newton: y · (1.5 − ½ v y²)
            _mm256_mul_ps(
                y,
                _mm256_fnmadd_ps(_mm256_mul_ps(_mm256_set1_ps(0.5), v), _mm256_mul_ps(y, y), _mm256_set1_ps(1.5)),
            )
        });
    }

    #[target_feature(enable = "avx2,fma")]
    #[inline]
    pub(super) fn rcp_avx2(x: &Lanes, out: &mut Lanes) {
        by_halves!(x, out, |v| {
            let y = _mm256_rcp_ps(v);
            // Newton: y · (2 − v y)
            _mm256_mul_ps(y, _mm256_fnmadd_ps(v, y, _mm256_set1_ps(2.0)))
        });
    }

    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn interpolate_avx512(x0: f32, planes: &RowPlanes, out: &mut [Lanes; MAX_VARYINGS]) {
        let ((w0, wdx), v0, vdx, nv) = (planes.w, &planes.v0, &planes.vdx, planes.nv);
        let iota = _mm512_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0);
        let x = _mm512_add_ps(_mm512_set1_ps(x0), iota);
        // the same operations as the portable path: w0 + wdx·x (not fused), then an exact division
        let w = _mm512_add_ps(_mm512_set1_ps(w0), _mm512_mul_ps(_mm512_set1_ps(wdx), x));
        let rcp = _mm512_div_ps(_mm512_set1_ps(1.0), w);
        for k in 0..nv.min(MAX_VARYINGS) {
            let v = _mm512_add_ps(_mm512_set1_ps(v0[k]), _mm512_mul_ps(_mm512_set1_ps(vdx[k]), x));
            // SAFETY: `out[k]` holds 16 f32.
            unsafe { _mm512_storeu_ps(out[k].as_mut_ptr(), _mm512_mul_ps(v, rcp)) };
        }
    }

    /// [`super::Simd::depth_less`]: the plane (a multiply, then an add), one compare into
    /// a mask register, and a store under it.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn depth_less_avx512(depth: &mut Lanes, z0: f32, zdx: f32, x0: f32, live: u32) -> u32 {
        let iota = _mm512_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0, 11.0, 12.0, 13.0, 14.0, 15.0);
        let x = _mm512_add_ps(_mm512_set1_ps(x0), iota);
        let z = _mm512_add_ps(_mm512_set1_ps(z0), _mm512_mul_ps(_mm512_set1_ps(zdx), x));
        // SAFETY: `depth` holds 16 f32.
        let old = unsafe { _mm512_loadu_ps(depth.as_ptr()) };
        let pass = _mm512_mask_cmp_ps_mask::<_CMP_LT_OQ>(live as __mmask16, z, old);
        // SAFETY: as above; lanes that did not pass are not written.
        unsafe { _mm512_mask_storeu_ps(depth.as_mut_ptr(), pass, z) };
        u32::from(pass)
    }

    /// The three channels of `rgb`, one register each. Three loads, not a closure over the
    /// channels (`each_ref().map(…)`): a closure is a function of its own, compiled without
    /// these target features and called.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    fn channels_avx512(rgb: &[Lanes; 3]) -> (__m512, __m512, __m512) {
        // SAFETY: each channel holds 16 f32, one unaligned load each.
        unsafe {
            (_mm512_loadu_ps(rgb[0].as_ptr()), _mm512_loadu_ps(rgb[1].as_ptr()), _mm512_loadu_ps(rgb[2].as_ptr()))
        }
    }

    /// [`super::Simd::rgba_pixels`] as a 4 × 4 transpose of 128-bit blocks: interleave
    /// r with g and b with 1 within each block, pair them into whole pixels (block `k` of
    /// `p_m` is pixel `4k + m`), then gather the blocks so register `o_q` holds pixels
    /// `4q … 4q + 3`. Shuffles only: the values are the inputs' bits.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    fn rgba_transpose_avx512(rgb: &[Lanes; 3]) -> [__m512; 4] {
        let (r, g, b) = channels_avx512(rgb);
        let a = _mm512_set1_ps(1.0);
        // block k: [r4k, g4k, r4k+1, g4k+1], [r4k+2, g4k+2, r4k+3, g4k+3], the same for b and 1
        let (rg_lo, rg_hi) = (_mm512_unpacklo_ps(r, g), _mm512_unpackhi_ps(r, g));
        let (ba_lo, ba_hi) = (_mm512_unpacklo_ps(b, a), _mm512_unpackhi_ps(b, a));
        // block k of p_m: pixel 4k + m
        let p0 = _mm512_shuffle_ps::<0x44>(rg_lo, ba_lo);
        let p1 = _mm512_shuffle_ps::<0xEE>(rg_lo, ba_lo);
        let p2 = _mm512_shuffle_ps::<0x44>(rg_hi, ba_hi);
        let p3 = _mm512_shuffle_ps::<0xEE>(rg_hi, ba_hi);
        // pixels (0, 4, 1, 5), (2, 6, 3, 7), (8, 12, 9, 13), (10, 14, 11, 15)
        let q0 = _mm512_shuffle_f32x4::<0b01_00_01_00>(p0, p1);
        let q1 = _mm512_shuffle_f32x4::<0b01_00_01_00>(p2, p3);
        let q2 = _mm512_shuffle_f32x4::<0b11_10_11_10>(p0, p1);
        let q3 = _mm512_shuffle_f32x4::<0b11_10_11_10>(p2, p3);
        [
            _mm512_shuffle_f32x4::<0b10_00_10_00>(q0, q1),
            _mm512_shuffle_f32x4::<0b11_01_11_01>(q0, q1),
            _mm512_shuffle_f32x4::<0b10_00_10_00>(q2, q3),
            _mm512_shuffle_f32x4::<0b11_01_11_01>(q2, q3),
        ]
    }

    /// [`super::Simd::rgba_pixels`]: [`rgba_transpose_avx512`], then four 64-byte stores.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rgba_pixels_avx512(rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) {
        for (q, v) in rgba_transpose_avx512(rgb).into_iter().enumerate() {
            // SAFETY: pixels 4q … 4q + 3 are 16 contiguous f32 inside `out`.
            unsafe { _mm512_storeu_ps(out[4 * q].as_mut_ptr(), v) };
        }
    }

    /// [`super::Simd::rgba_pixels_where`]: the transpose, then four stores under write
    /// masks. Register `q` holds pixels `4q … 4q + 3`, four lanes each, so its lane `i` is
    /// written when bit `⌊i/4⌋` of `mask >> 4q` is set (`vptestmd` against that bit per
    /// lane). A masked-off lane is neither read nor written.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rgba_pixels_where_avx512(rgb: &[Lanes; 3], mask: u32, out: &mut [[f32; 4]; LANES]) {
        let bits = _mm512_setr_epi32(1, 1, 1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 8, 8, 8, 8);
        for (q, v) in rgba_transpose_avx512(rgb).into_iter().enumerate() {
            let lanes = _mm512_test_epi32_mask(_mm512_set1_epi32((mask >> (4 * q)) as i32), bits);
            // SAFETY: pixels 4q … 4q + 3 are 16 contiguous f32 inside `out`.
            unsafe { _mm512_mask_storeu_ps(out[4 * q].as_mut_ptr(), lanes, v) };
        }
    }

    /// `quantize` of 16 lanes of one channel, shifted to its byte: `max(x, 0)` (`vmaxps`
    /// returns its second operand, 0, when `x` is NaN), `min(·, 1)`, `· 255` and `+ pred(½)`
    /// unfused, then a truncating conversion: `trunc(y + 0.49999997)` is `round(y)` for every
    /// `y = 255·c`, `c` an f32 in [0, 1] (checked over all of them).
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    fn quantize_avx512(x: __m512) -> __m512i {
        let c = _mm512_min_ps(_mm512_max_ps(x, _mm512_setzero_ps()), _mm512_set1_ps(1.0));
        let y = _mm512_add_ps(_mm512_mul_ps(c, _mm512_set1_ps(255.0)), _mm512_set1_ps(0.499_999_97));
        _mm512_cvttps_epi32(y)
    }

    /// 16 RGBA8 pixels: each channel quantized, shifted to its byte and or-ed with alpha
    /// 255, then one 64-byte store.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rgba8_pixels_avx512(rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
        let (r, g, b) = channels_avx512(rgb);
        let (r, g, b) = (quantize_avx512(r), quantize_avx512(g), quantize_avx512(b));
        let alpha = _mm512_set1_epi32(0xff00_0000u32 as i32);
        let words = _mm512_or_si512(
            _mm512_or_si512(r, _mm512_slli_epi32::<8>(g)),
            _mm512_or_si512(_mm512_slli_epi32::<16>(b), alpha),
        );
        // SAFETY: `out` is 64 contiguous bytes.
        unsafe { _mm512_storeu_si512(out.as_mut_ptr().cast(), words) };
    }

    /// [`super::Simd::rgba8_pixels_where`]: as [`rgba8_pixels_avx512`], then one store under
    /// the write mask `mask` (one pixel a lane).
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn rgba8_pixels_where_avx512(rgb: &[Lanes; 3], mask: u32, out: &mut [[u8; 4]; LANES]) {
        let mut block = [[0u8; 4]; LANES];
        rgba8_pixels_avx512(rgb, &mut block);
        // SAFETY: `block` and `out` are 64 contiguous bytes each.
        let words = unsafe { _mm512_loadu_si512(block.as_ptr().cast()) };
        // SAFETY: as above; masked-off lanes are not written.
        unsafe { _mm512_mask_storeu_epi32(out.as_mut_ptr().cast(), mask as __mmask16, words) };
    }

    /// [`super::Simd::compress`]: `vcompressps` into a register, then one full store (the
    /// lanes past the selected ones are zeros).
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn compress_avx512(x: &Lanes, mask: u32, out: &mut Lanes) {
        // SAFETY: `x` and `out` hold 16 f32 each.
        let v = unsafe { _mm512_loadu_ps(x.as_ptr()) };
        // SAFETY: as above.
        unsafe { _mm512_storeu_ps(out.as_mut_ptr(), _mm512_maskz_compress_ps(mask as __mmask16, v)) };
    }

    /// [`super::Simd::compress_u32`]: `vpcompressd`, as [`compress_avx512`].
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn compress_u32_avx512(x: &[u32; LANES], mask: u32, out: &mut [u32; LANES]) {
        // SAFETY: `x` and `out` hold 16 u32 each.
        let v = unsafe { _mm512_loadu_si512(x.as_ptr().cast()) };
        // SAFETY: as above.
        unsafe { _mm512_storeu_si512(out.as_mut_ptr().cast(), _mm512_maskz_compress_epi32(mask as __mmask16, v)) };
    }

    /// [`super::Simd::edge_mask`]: per block of 8 lanes, each edge's `at + a·l` (exact, so
    /// the fused multiply-add is the sum) compared `≥ 0` into a mask register under the
    /// previous edges' mask, then the blocks' 8-bit masks side by side.
    #[target_feature(enable = "avx512f,avx512vl,avx2,fma")]
    #[inline]
    pub(super) fn edge_mask_avx512<const BLOCKS: usize>(at: [f64; 3], a: [f64; 3]) -> u32 {
        let zero = _mm512_setzero_pd();
        let iota = _mm512_setr_pd(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
        let mut mask = 0u32;
        for block in 0..BLOCKS.min(4) {
            let l = _mm512_add_pd(iota, _mm512_set1_pd((8 * block) as f64));
            let mut inside: __mmask8 = 0xff;
            for e in 0..3 {
                let v = _mm512_fmadd_pd(_mm512_set1_pd(a[e]), l, _mm512_set1_pd(at[e]));
                inside = _mm512_mask_cmp_pd_mask::<_CMP_GE_OQ>(inside, v, zero);
            }
            mask |= u32::from(inside) << (8 * block);
        }
        mask
    }

    /// [`super::Simd::edge_mask`] in blocks of 4 lanes: the compares and-ed, then
    /// `vmovmskpd`.
    #[target_feature(enable = "avx2,fma")]
    #[inline]
    pub(super) fn edge_mask_avx2<const BLOCKS: usize>(at: [f64; 3], a: [f64; 3]) -> u32 {
        let zero = _mm256_setzero_pd();
        let iota = _mm256_setr_pd(0.0, 1.0, 2.0, 3.0);
        let mut mask = 0u32;
        for block in 0..2 * BLOCKS.min(4) {
            let l = _mm256_add_pd(iota, _mm256_set1_pd((4 * block) as f64));
            let mut inside = _mm256_castsi256_pd(_mm256_set1_epi64x(-1));
            for e in 0..3 {
                let v = _mm256_fmadd_pd(_mm256_set1_pd(a[e]), l, _mm256_set1_pd(at[e]));
                inside = _mm256_and_pd(inside, _mm256_cmp_pd::<_CMP_GE_OQ>(v, zero));
            }
            mask |= (_mm256_movemask_pd(inside) as u32) << (4 * block);
        }
        mask
    }

    /// [`quantize_avx512`] on 8 lanes (`vmaxps` returns its second operand for NaN too).
    #[target_feature(enable = "avx2,fma")]
    #[inline]
    fn quantize_avx2(x: __m256) -> __m256i {
        let c = _mm256_min_ps(_mm256_max_ps(x, _mm256_setzero_ps()), _mm256_set1_ps(1.0));
        let y = _mm256_add_ps(_mm256_mul_ps(c, _mm256_set1_ps(255.0)), _mm256_set1_ps(0.499_999_97));
        _mm256_cvttps_epi32(y)
    }

    /// [`rgba8_pixels_avx512`] in two halves of 8 pixels.
    #[target_feature(enable = "avx2,fma")]
    #[inline]
    pub(super) fn rgba8_pixels_avx2(rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
        let alpha = _mm256_set1_epi32(0xff00_0000u32 as i32);
        for half in 0..2 {
            // SAFETY: lanes 8·half … 8·half + 7 of each channel, one unaligned load each
            // (three loads, not a closure: see `channels_avx512`).
            let at = 8 * half;
            let (r, g, b) = unsafe {
                (
                    _mm256_loadu_ps(rgb[0][at..].as_ptr()),
                    _mm256_loadu_ps(rgb[1][at..].as_ptr()),
                    _mm256_loadu_ps(rgb[2][at..].as_ptr()),
                )
            };
            let (r, g, b) = (quantize_avx2(r), quantize_avx2(g), quantize_avx2(b));
            let words = _mm256_or_si256(
                _mm256_or_si256(r, _mm256_slli_epi32::<8>(g)),
                _mm256_or_si256(_mm256_slli_epi32::<16>(b), alpha),
            );
            // SAFETY: pixels 8·half … 8·half + 7 are 32 contiguous bytes inside `out`.
            unsafe { _mm256_storeu_si256(out[8 * half..].as_mut_ptr().cast(), words) };
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every build's pixels are the portable transpose's, bit for bit (NaN and −0 included).
    #[test]
    fn rgba_pixels_agree_in_every_build() {
        let mut rgb = [[0.0f32; LANES]; 3];
        for (c, channel) in rgb.iter_mut().enumerate() {
            for (l, v) in channel.iter_mut().enumerate() {
                *v = (c * LANES + l) as f32 * 0.37 - 5.0;
            }
        }
        (rgb[0][3], rgb[1][7], rgb[2][15]) = (f32::NAN, -0.0, f32::INFINITY);
        let mut expected = [[0.0; 4]; LANES];
        rgba_pixels_portable(&rgb, &mut expected);
        let bits = |px: &[[f32; 4]; LANES]| px.map(|p| p.map(f32::to_bits));
        per_isa! {
            fn pixels_per_isa(rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) = pixels_body;
        }
        #[inline(always)]
        fn pixels_body<S: Simd>(s: S, rgb: &[Lanes; 3], out: &mut [[f32; 4]; LANES]) {
            s.rgba_pixels(rgb, out)
        }
        let mut out = [[0.0; 4]; LANES];
        pixels_per_isa(Isa::detect(), &rgb, &mut out);
        assert_eq!(bits(&out), bits(&expected), "{:?}", Isa::detect());
        pixels_per_isa(Isa::BASELINE, &rgb, &mut out);
        assert_eq!(bits(&out), bits(&expected));
    }

    /// Each x86 build's [`Simd::all_normal`] is the portable test, lane by lane: an odd
    /// value (zero, −0, subnormal, ±∞, NaN, negative) in any lane among normal ones makes
    /// it false, and the extremes `f32::MIN_POSITIVE` and `f32::MAX` keep it true.
    #[test]
    fn all_normal_agrees_in_every_build() {
        let values = [
            0.0,
            -0.0,
            f32::MIN_POSITIVE,
            f32::MIN_POSITIVE / 2.0,
            f32::from_bits(1),
            f32::MAX,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -1.0,
            1e-30,
            3.5,
        ];
        for v in values {
            for lane in 0..LANES {
                let mut x = [1.0f32; LANES];
                x[lane] = v;
                let want = (f32::MIN_POSITIVE..=f32::MAX).contains(&v);
                assert_eq!(Baseline.all_normal(&x), want, "baseline, {v:e} in lane {lane}");
                #[cfg(target_arch = "x86_64")]
                {
                    if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
                        // SAFETY: the features were detected just above.
                        assert_eq!(unsafe { x86::all_normal_avx2(&x) }, want, "avx2, {v:e} in lane {lane}");
                    }
                    if is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512vl") {
                        // SAFETY: as above.
                        assert_eq!(unsafe { x86::all_normal_avx512(&x) }, want, "avx512, {v:e} in lane {lane}");
                    }
                }
            }
        }
    }

    /// The kernel's premise for skipping its selects ([`Simd::all_normal`]): on every
    /// normal, finite `x`, each build's `1/√x` is finite and positive, the extremes of
    /// the range included (there the Newton step squares an estimate near 2^63 or 2^-64).
    #[test]
    fn rsqrt_of_every_normal_number_is_finite_and_positive() {
        // every power of two from 2^-126 to 2^127, a value between each, and f32::MAX
        let mut xs: Vec<f32> = (-126..=127).flat_map(|e| [2f32.powi(e), 1.37 * 2f32.powi(e)]).collect();
        xs.retain(|x| x.is_finite());
        xs.push(f32::MAX);
        for chunk in xs.chunks(LANES) {
            let mut x = [1.0f32; LANES];
            x[..chunk.len()].copy_from_slice(chunk);
            let mut builds: Vec<(&str, Lanes)> = Vec::new();
            let mut out = [0.0; LANES];
            Baseline.rsqrt(&x, &mut out);
            builds.push(("baseline", out));
            #[cfg(target_arch = "x86_64")]
            {
                if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
                    // SAFETY: the features were detected just above.
                    unsafe { x86::rsqrt_avx2(&x, &mut out) };
                    builds.push(("avx2", out));
                }
                if is_x86_feature_detected!("avx512f")
                    && is_x86_feature_detected!("avx512vl")
                    && is_x86_feature_detected!("fma")
                {
                    // SAFETY: as above.
                    unsafe { x86::rsqrt_avx512(&x, &mut out) };
                    builds.push(("avx512", out));
                }
            }
            for (name, r) in builds {
                for l in 0..LANES {
                    assert!(r[l].is_finite() && r[l] > 0.0, "{name}: 1/sqrt({:e}) = {:e}", x[l], r[l]);
                }
            }
        }
    }

    proptest::proptest! {
        /// Both x86 builds of [`Simd::edge_mask`] give the portable loop's bits, for 16 and 32
        /// lanes, on integer edge functions up to the guard band's 2^50 and steps up to 2^33
        /// (the bounds `Tri::lane_edges` states), and on an edge that is exactly 0 at lane
        /// `zero_at`, where `≥` and `>` differ. Each build runs only where this CPU has it.
        #[test]
        fn edge_masks_agree_in_every_build(
            at in proptest::array::uniform3(-(1i64 << 50)..1 << 50),
            a in proptest::array::uniform3(-(1i64 << 33)..1 << 33),
            zero_at in 0i64..32,
            step in -4i64..5,
            edge in 0usize..3,
            on_zero in proptest::bool::ANY,
        ) {
            let (at, a) = if on_zero {
                // edge `edge` is a·(l − zero_at), 0 at lane zero_at; the others hold everywhere
                let a = [0, 1, 2].map(|e| if e == edge { step as f64 } else { 0.0 });
                let at = [0, 1, 2].map(|e| if e == edge { (-step * zero_at) as f64 } else { 1.0 });
                (at, a)
            } else {
                (at.map(|v| v as f64), a.map(|v| v as f64))
            };
            let (p16, p32) = (edge_mask_portable::<2>(at, a), edge_mask_portable::<4>(at, a));
            proptest::prop_assert_eq!(p16, p32 & 0xffff);
            #[cfg(target_arch = "x86_64")]
            {
                if is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma") {
                    // SAFETY: the features were detected just above.
                    let (m16, m32) = unsafe { (x86::edge_mask_avx2::<2>(at, a), x86::edge_mask_avx2::<4>(at, a)) };
                    proptest::prop_assert_eq!((m16, m32), (p16, p32), "avx2");
                }
                if is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512vl") && is_x86_feature_detected!("fma") {
                    // SAFETY: as above.
                    let (m16, m32) = unsafe { (x86::edge_mask_avx512::<2>(at, a), x86::edge_mask_avx512::<4>(at, a)) };
                    proptest::prop_assert_eq!((m16, m32), (p16, p32), "avx512");
                }
            }
        }
    }
}
