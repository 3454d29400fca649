//! GLSL built-ins in `f64`, written from their geometric meaning.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `i` | incident vector, pointing *toward* the surface |
//! | `n` | surface normal |
//! | `proj_n(i)` | `(i·n / n·n) n`, the component of `i` along `n` |
//!
//! Source: GLSL 3.30 §8.2–8.5.

use glam::DVec3;

/// `v / ‖v‖` (GLSL `normalize`), or zero for a zero or non-finite `v`, where
/// GLSL leaves the result undefined.
pub fn normalize_or_zero(v: DVec3) -> DVec3 {
    let len = v.length();
    if len > 0.0 && len.is_finite() {
        v / len
    } else {
        DVec3::ZERO
    }
}

/// The orthogonal projection of `v` onto the line spanned by `n`.
///
/// ```text
/// proj_n(v) = (v · n / n · n) n
/// ```
///
/// `n` need not be unit length. Degenerate input: a zero `n` gives the zero
/// vector (there is no line to project on); NaN propagates.
pub fn project_onto(v: DVec3, n: DVec3) -> DVec3 {
    let nn = n.dot(n);
    if nn == 0.0 {
        DVec3::ZERO
    } else {
        n * (v.dot(n) / nn)
    }
}

/// Mirror `i` about the plane with normal `n`, by explicit projection.
///
/// ```text
/// reflect(i, n) = i − 2 proj_n(i)
/// ```
///
/// - Equal to GLSL's `i − 2 (n·i) n` for unit `n`; for a non-unit `n` this
///   form is still a true mirror image (GLSL's is not), so use unit normals
///   when comparing with the `f32` path.
/// - `i` points toward the surface: `reflect(−light_dir, n)` is `reflect_dir`.
/// - Degenerate input: a zero `n` returns `i` unchanged; NaN propagates.
///
/// Source: GLSL 3.30 §8.5; ogldev 19.
pub fn reflect(i: DVec3, n: DVec3) -> DVec3 {
    i - 2.0 * project_onto(i, n)
}

/// `clamp(x, 0, 1)`, written as a case analysis.
///
/// Degenerate input: NaN gives 0, the `f32` path's documented choice.
pub fn saturate(x: f64) -> f64 {
    if x.is_nan() || x <= 0.0 {
        0.0
    } else if x >= 1.0 {
        1.0
    } else {
        x
    }
}

/// GLSL `pow(x, y)`, `None` where GLSL 3.30 §8.2 leaves it undefined
/// (`x < 0`, or `x == 0` with `y <= 0`, or a NaN operand).
///
/// ```text
/// pow(x, y) = exp(y · ln x)   for x > 0;   0 for x = 0, y > 0
/// ```
///
/// Written with `exp`/`ln` (natural base) rather than `powf`, as an
/// independent formulation; the relative error is a few `f64` ulps times
/// `|y ln x|`, far below the `f32` error it is compared with.
pub fn try_pow(x: f64, y: f64) -> Option<f64> {
    if x.is_nan() || y.is_nan() || x < 0.0 || (x == 0.0 && y <= 0.0) {
        None
    } else if x == 0.0 {
        Some(0.0)
    } else {
        Some((y * x.ln()).exp())
    }
}

/// [`try_pow`] with the undefined cases mapped to 0 (the tutorials clamp the
/// base first, so their `pow` never meets a negative base).
pub fn pow_or_zero(x: f64, y: f64) -> f64 {
    try_pow(x, y).unwrap_or(0.0)
}

/// [`try_pow`] with the undefined cases mapped to NaN, as the `f32`
/// [`crate::glsl::pow`] documents.
pub fn pow(x: f64, y: f64) -> f64 {
    try_pow(x, y).unwrap_or(f64::NAN)
}
