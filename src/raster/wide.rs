//! `W`, sixteen `f32` lanes as one value (or 32: two batches side by side), and the few
//! operations the kernel needs.
//!
//! Each operation is one short loop over the lanes with no branch, so after
//! inlining every one becomes one vector instruction (AVX-512), two (AVX2) or four
//! (SSE2). The kernel written with them has the shape of the shader, and LLVM has
//! no long loop body to vectorize in pieces: written as loops over lanes that
//! mixed many steps and selects, the kernel compiled to partly 4- and 8-lane code,
//! a gather, and stack round trips that stalled store forwarding.

#![allow(clippy::needless_range_loop)] // lane-indexed loops are the form LLVM vectorizes

use std::ops::{Add, Mul, Neg, Sub};

use super::simd::{Lanes, Simd, LANES};

/// `N` lanes: [`LANES`] (one batch of fragments), or a multiple of it (batches side by
/// side, each lane computed exactly as alone: every operation is per lane).
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct W<const N: usize = LANES>(pub [f32; N]);

/// A per-lane condition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Mask<const N: usize = LANES>(pub [bool; N]);

/// Three lanes' vectors, one `W` per coordinate.
pub(crate) type W3<const N: usize = LANES> = [W<N>; 3];

impl<const N: usize> W<N> {
    /// Every lane zero.
    pub const ZERO: W<N> = W([0.0; N]);

    /// `x` in every lane.
    #[inline(always)]
    pub fn splat(x: f32) -> W<N> {
        W([x; N])
    }

    /// Set batch `b`'s 16 lanes, `16 b .. 16 b + 16`, to `lanes`.
    #[inline(always)]
    pub fn set_part(&mut self, b: usize, lanes: &Lanes) {
        self.0.as_chunks_mut::<LANES>().0[b] = *lanes;
    }

    /// Batch `b`'s 16 lanes, `16 b .. 16 b + 16`.
    #[inline(always)]
    pub fn part(&self, b: usize) -> Lanes {
        self.0.as_chunks::<LANES>().0[b]
    }

    /// `lanes` repeated in every batch of 16.
    #[inline(always)]
    pub fn tile(lanes: &Lanes) -> W<N> {
        let mut r = W([0.0; N]);
        for b in 0..N / LANES {
            r.set_part(b, lanes);
        }
        r
    }

    /// `f` of each lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f32) -> f32) -> W<N> {
        let mut r = [0.0; N];
        for i in 0..N {
            r[i] = f(self.0[i]);
        }
        W(r)
    }

    /// `f` of each pair of lanes.
    #[inline(always)]
    pub fn zip(self, o: W<N>, f: impl Fn(f32, f32) -> f32) -> W<N> {
        let mut r = [0.0; N];
        for i in 0..N {
            r[i] = f(self.0[i], o.0[i]);
        }
        W(r)
    }

    /// `p` of each lane.
    #[inline(always)]
    pub fn test(self, p: impl Fn(f32) -> bool) -> Mask<N> {
        let mut r = [false; N];
        for i in 0..N {
            r[i] = p(self.0[i]);
        }
        Mask(r)
    }

    /// `max(x, 0)`, 0 for NaN (GLSL's `max(x, 0.0)` on the shader's dot products).
    #[inline(always)]
    pub fn max0(self) -> W<N> {
        self.map(|x| if x > 0.0 { x } else { 0.0 })
    }

    /// `clamp(x, 0, 1)`, 0 for NaN.
    #[inline(always)]
    pub fn clamp01(self) -> W<N> {
        self.map(|x| {
            let x = if x > 0.0 { x } else { 0.0 };
            if x < 1.0 {
                x
            } else {
                1.0
            }
        })
    }

    /// `1/√x` through the marker's estimate, 16 lanes at a time.
    #[inline(always)]
    pub fn rsqrt<S: Simd>(self, s: S) -> W<N> {
        let mut r = [0.0; N];
        let (x, out) = (self.0.as_chunks::<LANES>().0, r.as_chunks_mut::<LANES>().0);
        for b in 0..N / LANES {
            s.rsqrt(&x[b], &mut out[b]);
        }
        W(r)
    }

    /// The lanes that are finite and positive: where a reciprocal `1/d` from
    /// [`W::rsqrt`] can scale a vector (else it is 0, as glam's `normalize_or_zero`).
    #[inline(always)]
    pub fn finite_positive(self) -> Mask<N> {
        self.test(|x| x > 0.0 && x <= f32::MAX)
    }

    /// Every lane normal, finite and positive ([`Simd::all_normal`]), 16 lanes at a time.
    #[inline(always)]
    pub fn all_normal<S: Simd>(self, s: S) -> bool {
        let x = self.0.as_chunks::<LANES>().0;
        let mut all = true;
        for b in 0..N / LANES {
            all &= s.all_normal(&x[b]);
        }
        all
    }

    /// `1/x` through the marker's estimate, 16 lanes at a time.
    #[inline(always)]
    pub fn rcp<S: Simd>(self, s: S) -> W<N> {
        let mut r = [0.0; N];
        let (x, out) = (self.0.as_chunks::<LANES>().0, r.as_chunks_mut::<LANES>().0);
        for b in 0..N / LANES {
            s.rcp(&x[b], &mut out[b]);
        }
        W(r)
    }
}

impl<const N: usize> Mask<N> {
    /// Per lane `if self { a } else { b }`.
    #[inline(always)]
    pub fn pick(self, a: W<N>, b: W<N>) -> W<N> {
        let mut r = [0.0; N];
        for i in 0..N {
            r[i] = if self.0[i] { a.0[i] } else { b.0[i] };
        }
        W(r)
    }

    /// Per lane `self && o`.
    #[inline(always)]
    pub fn and(self, o: Mask<N>) -> Mask<N> {
        let mut r = [false; N];
        for i in 0..N {
            r[i] = self.0[i] & o.0[i];
        }
        Mask(r)
    }
}

impl<const N: usize> Add for W<N> {
    type Output = W<N>;
    #[inline(always)]
    fn add(self, o: W<N>) -> W<N> {
        self.zip(o, |a, b| a + b)
    }
}

impl<const N: usize> Sub for W<N> {
    type Output = W<N>;
    #[inline(always)]
    fn sub(self, o: W<N>) -> W<N> {
        self.zip(o, |a, b| a - b)
    }
}

impl<const N: usize> Mul for W<N> {
    type Output = W<N>;
    #[inline(always)]
    fn mul(self, o: W<N>) -> W<N> {
        self.zip(o, |a, b| a * b)
    }
}

impl<const N: usize> Neg for W<N> {
    type Output = W<N>;
    #[inline(always)]
    fn neg(self) -> W<N> {
        self.map(|a| -a)
    }
}

/// `a · b + c`, fused (one rounding) in the FMA builds, else two roundings.
#[inline(always)]
pub(crate) fn madd<S: Simd, const N: usize>(a: W<N>, b: W<N>, c: W<N>) -> W<N> {
    let mut r = [0.0; N];
    for i in 0..N {
        r[i] = if S::FMA { a.0[i].mul_add(b.0[i], c.0[i]) } else { a.0[i] * b.0[i] + c.0[i] };
    }
    W(r)
}

/// `a · b` for 3-vectors, in glam's order `(ax bx + ay by) + az bz` (fused in the FMA builds).
#[inline(always)]
pub(crate) fn dot<S: Simd, const N: usize>(a: &W3<N>, b: &W3<N>) -> W<N> {
    madd::<S, N>(a[2], b[2], madd::<S, N>(a[1], b[1], a[0] * b[0]))
}

/// glam's `normalize_or_zero`: `v · (1/|v|)` when that reciprocal is finite and
/// positive, else 0; `1/|v|` through the marker's estimate.
#[inline(always)]
pub(crate) fn normalize_or_zero<S: Simd, const N: usize>(s: S, v: &W3<N>) -> W3<N> {
    let r = dot::<S, N>(v, v).rsqrt(s);
    let r = r.finite_positive().pick(r, W::ZERO);
    [v[0] * r, v[1] * r, v[2] * r]
}

/// `p − v`, the point `p` in every lane.
#[inline(always)]
pub(crate) fn point_minus<const N: usize>(p: glam::Vec3, v: &W3<N>) -> W3<N> {
    [W::splat(p.x) - v[0], W::splat(p.y) - v[1], W::splat(p.z) - v[2]]
}
