//! GLSL built-ins with GLSL semantics where they matter.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `i` | incident vector, pointing *toward* the surface |
//! | `n` | unit surface normal |
//! | `x`, `y` | base and exponent of `pow` |
//!
//! GLSL 3.30 §8.2–8.5 defines these functions. Where the specification leaves a
//! result undefined (`pow(x, y)` for `x < 0`, or `x == 0 && y <= 0`;
//! `normalize(0)`), lightlab returns NaN from the strict function, so that the
//! undefined case is visible instead of plausible, and offers a named fallback.

use glam::Vec3;

/// Mirror `i` about the plane with unit normal `n`.
///
/// ```text
/// reflect(i, n) = i - 2 (n · i) n
/// ```
///
/// - `n` must be unit length (GLSL's precondition too); `i` need not be.
/// - `i` points toward the surface, so `reflect(-light_dir, n)` is the
///   tutorials' `reflect_dir`.
/// - Degenerate input: a non-unit `n` gives a vector that is not a mirror
///   image (GLSL behaves the same); NaN propagates.
///
/// Source: GLSL 3.30 §8.5; ogldev 19 derives it as `R = I - 2N(N·I)`.
// ANCHOR: reflect
pub fn reflect(i: Vec3, n: Vec3) -> Vec3 {
    i - 2.0 * n.dot(i) * n
}
// ANCHOR_END: reflect

/// `clamp(x, 0, 1)` with GLSL's formula `min(max(x, 0), 1)`.
///
/// Degenerate input: NaN gives 0 here, because Rust's `f32::max` returns
/// the non-NaN operand; GLSL leaves `clamp(NaN)` undefined (llvmpipe's result
/// is reported by the OpenGL check).
///
/// Source: GLSL 3.30 §8.3.
// `f32::clamp` would keep NaN; the `max`/`min` form maps it to 0, as documented.
#[allow(clippy::manual_clamp)]
// ANCHOR: saturate
pub fn saturate(x: f32) -> f32 {
    x.max(0.0).min(1.0)
}
// ANCHOR_END: saturate

/// GLSL `pow(x, y) = x^y`, undefined where GLSL says so.
///
/// ```text
/// pow(x, y) = exp2(y · log2 x)      defined for x > 0, and for x = 0 with y > 0
/// ```
///
/// - Degenerate input: returns NaN for `x < 0` and for `x == 0 && y <= 0`,
///   where GLSL 3.30 §8.2 says the result is undefined. Use [`pow_or_zero`]
///   for the tutorials' usage, where the base is always clamped first.
///
/// Source: GLSL 3.30 §8.2; the failure atlas shows what CPUs and llvmpipe
/// return instead.
pub fn pow(x: f32, y: f32) -> f32 {
    try_pow(x, y).unwrap_or(f32::NAN)
}

/// [`pow`] returning `None` where GLSL leaves the result undefined.
///
/// Source: GLSL 3.30 §8.2.
// ANCHOR: try_pow
pub fn try_pow(x: f32, y: f32) -> Option<f32> {
    if x.is_nan() || y.is_nan() || x < 0.0 || (x == 0.0 && y <= 0.0) {
        None
    } else {
        Some(x.powf(y))
    }
}
// ANCHOR_END: try_pow

/// [`pow`] with the undefined cases mapped to 0.
///
/// This is the result a shader author means when writing
/// `pow(max(x, 0.0), s)` with `s > 0`. For `x == 0 && y <= 0` it returns 0, not
/// the `1` that C's `powf(0, 0)` gives: a highlight should not appear at a
/// grazing angle because shininess is 0.
///
/// Source: GLSL 3.30 §8.2; deviation documented in the failure atlas.
// ANCHOR: pow_or_zero
pub fn pow_or_zero(x: f32, y: f32) -> f32 {
    try_pow(x, y).unwrap_or(0.0)
}
// ANCHOR_END: pow_or_zero

/// Whether a homogeneous vector's `w` marks a direction (`w == 0`) rather than a
/// position (`w == 1`), tested with a tolerance instead of `==`.
///
/// LearnOpenGL, Light casters, writes `if (lightVector.w == 0.0)` and warns in a
/// comment that float comparison is fragile. A `w` that went through arithmetic
/// (for example `1e-8` after a matrix product) should still count as a
/// direction, so the test is `|w| <= tolerance`, with `tolerance` in units of
/// `w`. A NaN `w` is neither (returns `None`).
///
/// Source: LearnOpenGL, Light casters, directional light.
pub fn homogeneous_kind(w: f32, tolerance: f32) -> Option<HomogeneousKind> {
    if w.is_nan() {
        None
    } else if w.abs() <= tolerance {
        Some(HomogeneousKind::Direction)
    } else {
        Some(HomogeneousKind::Position)
    }
}

/// What a `vec4` light vector means, from its `w` component.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HomogeneousKind {
    /// `w == 0`: a direction (directional light).
    Direction,
    /// `w != 0`: a position, after division by `w` (point light).
    Position,
}
