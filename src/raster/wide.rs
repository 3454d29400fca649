//! `W`, sixteen `f32` lanes as one value, and the few operations the kernel needs.
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

/// Sixteen lanes.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub(crate) struct W(pub Lanes);

/// A per-lane condition.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Mask(pub [bool; LANES]);

/// Three lanes' vectors, one `W` per coordinate.
pub(crate) type W3 = [W; 3];

impl W {
    /// Every lane zero.
    pub const ZERO: W = W([0.0; LANES]);

    /// `x` in every lane.
    #[inline(always)]
    pub fn splat(x: f32) -> W {
        W([x; LANES])
    }

    /// `f` of each lane.
    #[inline(always)]
    pub fn map(self, f: impl Fn(f32) -> f32) -> W {
        let mut r = [0.0; LANES];
        for i in 0..LANES {
            r[i] = f(self.0[i]);
        }
        W(r)
    }

    /// `f` of each pair of lanes.
    #[inline(always)]
    pub fn zip(self, o: W, f: impl Fn(f32, f32) -> f32) -> W {
        let mut r = [0.0; LANES];
        for i in 0..LANES {
            r[i] = f(self.0[i], o.0[i]);
        }
        W(r)
    }

    /// `p` of each lane.
    #[inline(always)]
    pub fn test(self, p: impl Fn(f32) -> bool) -> Mask {
        let mut r = [false; LANES];
        for i in 0..LANES {
            r[i] = p(self.0[i]);
        }
        Mask(r)
    }

    /// `max(x, 0)`, 0 for NaN (GLSL's `max(x, 0.0)` on the shader's dot products).
    #[inline(always)]
    pub fn max0(self) -> W {
        self.map(|x| if x > 0.0 { x } else { 0.0 })
    }

    /// `clamp(x, 0, 1)`, 0 for NaN.
    #[inline(always)]
    pub fn clamp01(self) -> W {
        self.map(|x| {
            let x = if x > 0.0 { x } else { 0.0 };
            if x < 1.0 {
                x
            } else {
                1.0
            }
        })
    }

    /// `1/√x` through the marker's estimate.
    #[inline(always)]
    pub fn rsqrt<S: Simd>(self, s: S) -> W {
        let mut r = [0.0; LANES];
        s.rsqrt(&self.0, &mut r);
        W(r)
    }

    /// `1/x` through the marker's estimate.
    #[inline(always)]
    pub fn rcp<S: Simd>(self, s: S) -> W {
        let mut r = [0.0; LANES];
        s.rcp(&self.0, &mut r);
        W(r)
    }
}

impl Mask {
    /// Per lane `if self { a } else { b }`.
    #[inline(always)]
    pub fn pick(self, a: W, b: W) -> W {
        let mut r = [0.0; LANES];
        for i in 0..LANES {
            r[i] = if self.0[i] { a.0[i] } else { b.0[i] };
        }
        W(r)
    }

    /// Per lane `self && o`.
    #[inline(always)]
    pub fn and(self, o: Mask) -> Mask {
        let mut r = [false; LANES];
        for i in 0..LANES {
            r[i] = self.0[i] & o.0[i];
        }
        Mask(r)
    }
}

impl Add for W {
    type Output = W;
    #[inline(always)]
    fn add(self, o: W) -> W {
        self.zip(o, |a, b| a + b)
    }
}

impl Sub for W {
    type Output = W;
    #[inline(always)]
    fn sub(self, o: W) -> W {
        self.zip(o, |a, b| a - b)
    }
}

impl Mul for W {
    type Output = W;
    #[inline(always)]
    fn mul(self, o: W) -> W {
        self.zip(o, |a, b| a * b)
    }
}

impl Neg for W {
    type Output = W;
    #[inline(always)]
    fn neg(self) -> W {
        self.map(|a| -a)
    }
}

/// `a · b + c`, fused (one rounding) in the FMA builds, else two roundings.
#[inline(always)]
pub(crate) fn madd<S: Simd>(a: W, b: W, c: W) -> W {
    let mut r = [0.0; LANES];
    for i in 0..LANES {
        r[i] = if S::FMA { a.0[i].mul_add(b.0[i], c.0[i]) } else { a.0[i] * b.0[i] + c.0[i] };
    }
    W(r)
}

/// `a · b` for 3-vectors, in glam's order `(ax bx + ay by) + az bz` (fused in the FMA builds).
#[inline(always)]
pub(crate) fn dot<S: Simd>(a: &W3, b: &W3) -> W {
    madd::<S>(a[2], b[2], madd::<S>(a[1], b[1], a[0] * b[0]))
}

/// glam's `normalize_or_zero`: `v · (1/|v|)` when that reciprocal is finite and
/// positive, else 0; `1/|v|` through the marker's estimate.
#[inline(always)]
pub(crate) fn normalize_or_zero<S: Simd>(s: S, v: &W3) -> W3 {
    let r = dot::<S>(v, v).rsqrt(s);
    let r = r.test(|x| x > 0.0 && x <= f32::MAX).pick(r, W::ZERO);
    [v[0] * r, v[1] * r, v[2] * r]
}

/// `p − v`, the point `p` in every lane.
#[inline(always)]
pub(crate) fn point_minus(p: glam::Vec3, v: &W3) -> W3 {
    [W::splat(p.x) - v[0], W::splat(p.y) - v[1], W::splat(p.z) - v[2]]
}
