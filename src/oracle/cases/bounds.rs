//! The error bounds, derived from `f32` rounding (GLSL 3.30 §4.1.4 lets implementations
//! use IEEE single precision; llvmpipe does).
//!
//! Error budget of one lit channel, with `ε = 2^-24` and unit vectors from `normalize`:
//! - `normalize(p - q)` of exact `f32` inputs: the subtraction is correctly rounded
//!   (relative ε per component), the length and `inversesqrt` add a few ε: each component
//!   of a normalized vector is off by at most `N = 4ε` (llvmpipe's `inversesqrt` refines
//!   the hardware estimate with Newton steps; its error is in that budget).
//! - A cosine `dot(a, b)` of two such vectors: 3 products and 2 sums (3ε) plus the two
//!   normalizations (2N): `COS = 11ε`.
//! - The specular base `dot(viewDir, reflect(-lightDir, norm))`: `reflect` adds a dot and
//!   a scaled subtraction (`2·COS + 3ε` on each component of the reflected vector), then
//!   the dot with `viewDir`: `BASE = 32ε`.
//! - `pow(x, s)` with x in [0, 1]: the base error is carried through the exponent,
//!   `|d(x^s)| = s·x^(s-1)·|dx| <= s·BASE`; llvmpipe's own `exp2(s·log2 x)` adds a relative
//!   error `ln2·s·η` for an absolute `log2` error `η` (measured by the oracle's `pow` row,
//!   see [`LOG2_ABS`]).
//! - Products and sums of the terms: a few ε relative on values of order the coefficients.
//!
//! Each model's bound is then `Σ coefficient × term error`, with the coefficients' maxima
//! from the case ranges in the module docs; the individual derivations are next to each
//! constant.

/// `2^-24`, the unit roundoff of `f32`.
pub const EPS: f64 = 5.960_464_477_539_063e-8;
/// Error of a cosine of two normalized vectors (`11ε`, see the module docs).
pub const COS: f64 = 11.0 * EPS;
/// Error of Phong's specular base (`32ε`).
pub const BASE: f64 = 32.0 * EPS;
/// Absolute error allowed for llvmpipe's `log2` inside `pow(x, s) = exp2(s·log2 x)`:
/// `4ε`. Measured by [`crate::oracle::measure_pow`]: at most about `3ε` on
/// Mesa 22.3 / LLVM 15 (the `pow` row of the oracle report); `s·η` scales it into
/// `log2` of the result, so `pow`'s relative error is about `ln2·s·η`: 2.9e-5 was
/// measured at s = 256.
pub const LOG2_ABS: f64 = 4.0 * EPS;
/// Error of `spec = pow(base, s)` with `s <= s_max` and a result <= 1:
/// `s_max·BASE` (the base's error through the exponent) + `ln2·s_max·LOG2_ABS`
/// (llvmpipe's `exp2(s·log2 x)`) + `2ε` (rounding `s·log2 x`, whose `t·2^-t <= 0.53`
/// keeps it below `ε` in absolute terms, and `exp2`'s own rounding).
pub const fn spec(s_max: f64) -> f64 {
    s_max * BASE + std::f64::consts::LN_2 * s_max * LOG2_ABS + 2.0 * EPS
}
/// Error of Blinn-Phong's specular base `dot(norm, normalize(lightDir + viewDir))` when
/// `|lightDir + viewDir| >= 0.1` (closer to opposite directions the halfway vector is
/// ill-conditioned and the case is [`crate::oracle::cases::Class::NearOpposite`]): the sum is
/// off by `2N + 2ε = 10ε` per component (`√3·10ε` in length), which `normalize` divides by
/// the sum's length (`<= 173ε` in direction), plus `normalize`'s own `N`, the normal's `N`
/// and the dot's `3ε`: `BLINN_BASE = 184ε`.
pub const BLINN_BASE: f64 = 184.0 * EPS;
/// Smallest `|lightDir + viewDir|` a Blinn-Phong case keeps in the bound (see
/// [`BLINN_BASE`]).
pub const BLINN_MIN_HALFWAY: f64 = 0.1;
/// [`spec`] with the specular base's error `base`.
pub const fn spec_with_base(s_max: f64, base: f64) -> f64 {
    s_max * base + std::f64::consts::LN_2 * s_max * LOG2_ABS + 2.0 * EPS
}
/// Error of a sum of `terms` products of factors in [0, 1] with values up to `scale`:
/// `8ε` per term relative to the scale (the products, the sum and the final write).
pub const fn arith(terms: f64, scale: f64) -> f64 {
    8.0 * EPS * terms * scale
}

/// basic lighting: `(a + diff + sS·spec)·lc·oc`, a, sS, colors in [0, 1], s <= 256:
/// `COS` (diffuse) + `spec(256)` (specular) + arithmetic on a value <= 3.
pub const BASIC_LIGHTING: f64 = COS + spec(256.0) + arith(3.0, 3.0);
/// Blinn-Phong on the basic-lighting inputs: basic lighting with [`BLINN_BASE`] for the
/// specular base.
pub const BLINN_PHONG: f64 = COS + spec_with_base(256.0, BLINN_BASE) + arith(3.0, 3.0);
/// Gouraud: as basic lighting, plus the vertex transform. `model = T·R·S` with scales in
/// [0.25, 4]: the inverse-transpose has condition number <= 16, so the normal's direction
/// is off by `16·4ε` instead of `N`; the world position `model·aPos` (|aPos| <= √3,
/// |T| <= 2√3, so |world| <= 6√3 ≈ 10.4) is off by `4ε·10.4`, which the light and eye
/// directions (distance >= 1) carry as `4ε·10.4` absolute. Both enter every cosine:
/// `COS_G = COS + 64ε + 42ε`, and the specular base twice: `BASE_G = BASE + 2·106ε`.
pub const GOURAUD: f64 = (COS + 106.0 * EPS) + spec(256.0) + 256.0 * 212.0 * EPS + arith(3.0, 3.0);
/// A vertex + fragment pair (check-shader `--vertex`), per fragment or per vertex: as
/// [`GOURAUD`], with positions carried through a rigid `view` when the shaders light in
/// view space, and the lighting evaluated at a point inside the triangle. Magnitudes: the
/// fragment |model·aPos| <= 10.4, the eye |eye| <= 25 (the view's translation), the light
/// within 20 of the fragment (|light| <= 30.4); in view space the fragment is within 35.4
/// of the origin and the light within 55.4. Each is off by `4ε` of its magnitude, so the
/// light direction (distance >= 1) carries `4ε·(35.4 + 55.4) ≈ 363ε` and the eye direction
/// (distance >= 4.6) `4ε·35.4/4.6 ≈ 31ε`. The normal: `64ε` (the normal matrix, as Gouraud)
/// plus `4ε` (the view's rotation). Interpolating three `f32` values with weights summing
/// to 1 adds `3ε` relative to the largest; the interpolated normal's length stays above
/// 0.43·σ_min (vertex normals within 30° of each other), so its direction error stays
/// within `normalize`'s `N`. Hence `COS_P = COS + 431ε`, the specular base
/// `BASE + 2·431ε`, and `arith(3, 3)` once more for the per-vertex colours' interpolation.
pub const VERTEX_PAIR: f64 =
    (COS + 431.0 * EPS) + spec(256.0) + 256.0 * 862.0 * EPS + arith(3.0, 3.0) + arith(3.0, 3.0);
/// Materials: `La·Ka + Ld·diff·Kd + Ls·spec·Ks`, all colors in [0, 1]: like basic lighting.
pub const MATERIALS: f64 = COS + spec(256.0) + arith(3.0, 3.0);
/// Lighting maps: materials with `Ka = Kd` (the diffuse texel).
pub const LIGHTING_MAPS: f64 = MATERIALS;
/// Lighting maps with the emission map (exercise 4): lighting maps plus the emission texel
/// in [0, 1], added once: arithmetic on a value <= 4 with four terms.
pub const LIGHTING_MAPS_EMISSION: f64 = COS + spec(256.0) + arith(4.0, 4.0);
/// Directional: materials with `lightDir = normalize(-direction)`.
pub const DIRECTIONAL: f64 = MATERIALS;
/// Point: materials times the attenuation `1/(Kc + Kl·d + Kq·d²)` with `Kc >= 0.5`, so
/// attenuation <= 2, computed with a relative error of a few ε: `2·MATERIALS`.
pub const POINT: f64 = 2.0 * MATERIALS;
/// Spot (soft edge): point plus the intensity `clamp((θ - γ)/ε_s, 0, 1)` with the cone's
/// `ε_s = cos φ - cos γ >= cos 60° - cos 62° ≈ 0.0302` (inner angles in [5°, 60°], the outer
/// 2° to 15° wider): θ's error `COS` becomes `COS/0.0302 ≈ 33·COS` on the intensity,
/// which multiplies diffuse + specular (<= 2) times the attenuation (<= 2).
pub const SPOT: f64 = POINT + 4.0 * 33.2 * COS;
/// Multiple lights: one directional light, four point lights and a spot, summed; each
/// light's error as above with its own coefficients (<= 1 for the directional, <= 2 for
/// the attenuated ones): `MATERIALS + 4·POINT + SPOT` plus the five sums.
pub const MULTIPLE_LIGHTS: f64 = MATERIALS + 4.0 * POINT + SPOT + arith(5.0, 27.0);
/// opengl-tutorial 8: `Kd·0.1·... + (Kd·cosθ + Ks·cosα^s)·LC·P/d²` with `P <= 60`,
/// `d >= 1`, so `P/d² <= 60`; exponents <= 128; the division adds a few ε relative.
pub const OPENGL_TUTORIAL8: f64 = 60.0 * (COS + spec(128.0)) + arith(4.0, 121.0);
/// ogldev 19: `texel·(Color·(Ia + Id·DF + Is·SF))` with intensities in [0, 1], powers
/// <= 128. `LightReflect` is normalized once more (another `N` on each component).
pub const OGLDEV19: f64 = COS + spec(128.0) + 128.0 * 4.0 * EPS + arith(3.0, 3.0);
