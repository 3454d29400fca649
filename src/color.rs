//! Chapter 1, Colors: the light's color modulates the object's color.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `light_color` | linear RGB of the light, each channel usually in [0, 1] |
//! | `object_color` | linear RGB fraction of each channel the surface reflects |
//! | `result` | `light_color ⊙ object_color`, the component-wise product |
//!
//! Colors are linear `f32` RGB, unclamped until output ([`to_rgb8`]).

use glam::Vec3;

/// LearnOpenGL's coral toy: `(1.0, 0.5, 0.31)`.
///
/// Source: LearnOpenGL, Colors.
pub const CORAL: Vec3 = Vec3::new(1.0, 0.5, 0.31);

/// The reflected color: the component-wise (Hadamard) product.
///
/// ```text
/// result = light_color ⊙ object_color = (Lr·Or, Lg·Og, Lb·Ob)
/// ```
///
/// No unit-length precondition. NaN in a channel stays in that channel only.
///
/// Source: LearnOpenGL, Colors.
// ANCHOR: modulate
pub fn modulate(light_color: Vec3, object_color: Vec3) -> Vec3 {
    light_color * object_color
}
// ANCHOR_END: modulate

/// Clamp a linear color to [0, 1] per channel and quantize to 8 bits.
///
/// ```text
/// q = round(clamp(c, 0, 1) · 255)
/// ```
///
/// This is what an `RGBA8` framebuffer stores (OpenGL 3.3 §2.1.6,
/// round-to-nearest conversion of normalized fixed point). NaN maps to 0.
// ANCHOR: to_rgb8
pub fn to_rgb8(c: Vec3) -> [u8; 3] {
    let q = |x: f32| (crate::glsl::saturate(x) * 255.0).round() as u8;
    [q(c.x), q(c.y), q(c.z)]
}
// ANCHOR_END: to_rgb8

/// The sRGB transfer function applied to one linear channel in [0, 1].
///
/// ```text
/// srgb(x) = 12.92 x                  for x <= 0.0031308
///         = 1.055 x^(1/2.4) - 0.055  otherwise
/// ```
///
/// Input is clamped to [0, 1] first; NaN gives 0. Figures use no gamma by
/// default, to match the tutorials' images; this is the optional sRGB output.
///
/// Source: IEC 61966-2-1.
pub fn linear_to_srgb(x: f32) -> f32 {
    let x = crate::glsl::saturate(x);
    if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    }
}
