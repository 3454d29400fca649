//! Chapter 1, Colors, in `f64`.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `light_color` | linear RGB of the light |
//! | `object_color` | linear RGB fraction the surface reflects |
//!
//! Source: LearnOpenGL, Colors.

use glam::DVec3;

/// The reflected color, channel by channel.
///
/// ```text
/// result = (Lr·Or, Lg·Og, Lb·Ob)
/// ```
///
/// No preconditions; NaN stays in its channel.
pub fn modulate(light_color: DVec3, object_color: DVec3) -> DVec3 {
    DVec3::new(light_color.x * object_color.x, light_color.y * object_color.y, light_color.z * object_color.z)
}

/// Clamp to [0, 1] and quantize to 8 bits with round-half-away-from-zero.
///
/// ```text
/// q = round(clamp(c, 0, 1) · 255)
/// ```
///
/// NaN maps to 0. Source: OpenGL 3.3 §2.1.6.
pub fn to_rgb8(c: DVec3) -> [u8; 3] {
    let q = |x: f64| (super::glsl::saturate(x) * 255.0).round() as u8;
    [q(c.x), q(c.y), q(c.z)]
}

/// The sRGB transfer function of one linear channel, input clamped to [0, 1].
///
/// ```text
/// srgb(x) = 12.92 x                      for x <= 0.0031308
///         = 1.055 exp(ln(x) / 2.4) − 0.055 otherwise
/// ```
///
/// NaN gives 0. Source: IEC 61966-2-1.
pub fn linear_to_srgb(x: f64) -> f64 {
    let x = super::glsl::saturate(x);
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * (x.ln() / 2.4).exp() - 0.055
    }
}
