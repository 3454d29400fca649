//! Chapter 2, Basic lighting, in `f64`: cosines through explicit angles.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `n` | unit surface normal |
//! | `light_dir` | unit vector toward the light |
//! | `view_dir` | unit vector toward the eye |
//! | `reflect_dir` | `reflect(−light_dir, n)`, by projection |
//! | `halfway` | `normalize(light_dir + view_dir)` |
//! | `α` | the angle between `view_dir` and `reflect_dir` (Phong) or `n` and `halfway` (Blinn) |
//!
//! Source: LearnOpenGL, Basic lighting; Blinn 1977.

use glam::{DMat4, DVec3};

pub use crate::phong::Specular;

use super::glsl::{normalize_or_zero, pow_or_zero, reflect};
use super::{cos_between_scaled, dvec3};

crate::phong::terms_struct!(
    /// The three terms of the Phong model at one fragment, in `f64`.
    DVec3,
    f64
);

impl Terms {
    /// Widen `f32` terms (for comparisons).
    pub fn from_f32(t: &crate::phong::Terms) -> Terms {
        Terms { ambient: dvec3(t.ambient), diffuse: dvec3(t.diffuse), specular: dvec3(t.specular) }
    }

    /// The largest absolute difference over the nine channels; NaN if any is NaN.
    pub fn max_abs_diff(&self, other: &Terms) -> f64 {
        let d = [self.ambient - other.ambient, self.diffuse - other.diffuse, self.specular - other.specular];
        d.iter().flat_map(|v| v.to_array()).map(f64::abs).fold(0.0, |m, x| {
            if x.is_nan() || m.is_nan() {
                f64::NAN
            } else {
                m.max(x)
            }
        })
    }
}

/// Ambient: `ambient_strength · light_color`. NaN propagates.
///
/// Source: LearnOpenGL, Basic lighting.
pub fn ambient(ambient_strength: f64, light_color: DVec3) -> DVec3 {
    light_color * ambient_strength
}

/// Lambert's diffuse factor through the angle of incidence θ.
///
/// ```text
/// θ = atan2(‖n × light_dir‖, n · light_dir)
/// diff = max(‖n‖ ‖light_dir‖ cos θ, 0)     (= max(cos θ, 0) for unit vectors)
/// ```
///
/// Unit `n` and `light_dir`, pointing away from the surface; the result is
/// then in [0, 1]. Degenerate input: a zero vector gives 0; NaN gives 0.
///
/// Source: LearnOpenGL, Basic lighting, diffuse.
pub fn diffuse_factor(n: DVec3, light_dir: DVec3) -> f64 {
    nan_to_zero(cos_between_scaled(n, light_dir).max(0.0))
}

/// Phong's specular factor through the angle α between `view_dir` and the mirror direction.
///
/// ```text
/// reflect_dir = −light_dir − 2 proj_n(−light_dir)
/// α = atan2(‖view_dir × reflect_dir‖, view_dir · reflect_dir)
/// spec = max(cos α, 0)^shininess     (scaled by the lengths for non-unit input)
/// ```
///
/// Unit `n`, `light_dir`, `view_dir`, pointing away from the surface. Not
/// gated by `n · light_dir` (as LearnOpenGL). Degenerate input: a zero base
/// with `shininess <= 0`, a zero vector (a zero normal has no mirror plane),
/// or NaN give 0.
///
/// Source: LearnOpenGL, Basic lighting, specular.
pub fn phong_specular_factor(n: DVec3, light_dir: DVec3, view_dir: DVec3, shininess: f64) -> f64 {
    if n.length() == 0.0 {
        return 0.0; // no mirror plane
    }
    let reflect_dir = reflect(-light_dir, n);
    let cos_alpha = nan_to_zero(cos_between_scaled(view_dir, reflect_dir).max(0.0));
    pow_or_zero(cos_alpha, shininess)
}

/// The halfway vector, or zero when `light_dir = −view_dir` (or NaN input).
///
/// ```text
/// halfway = (light_dir + view_dir) / ‖light_dir + view_dir‖
/// ```
///
/// Source: Blinn 1977.
pub fn halfway(light_dir: DVec3, view_dir: DVec3) -> DVec3 {
    let s = light_dir + view_dir;
    let len = s.length();
    if len > 0.0 && len.is_finite() {
        s / len
    } else {
        DVec3::ZERO
    }
}

/// Blinn-Phong's specular factor through the angle between `n` and `halfway`.
///
/// ```text
/// spec = max(cos(angle(n, halfway)), 0)^shininess
/// ```
///
/// Preconditions and degenerate results as [`phong_specular_factor`]; a zero
/// halfway vector gives 0.
///
/// Source: Blinn 1977; LearnOpenGL, Advanced lighting.
pub fn blinn_specular_factor(n: DVec3, light_dir: DVec3, view_dir: DVec3, shininess: f64) -> f64 {
    let h = halfway(light_dir, view_dir);
    pow_or_zero(nan_to_zero(cos_between_scaled(n, h).max(0.0)), shininess)
}

/// The specular factor of the chosen lobe ([`crate::phong::Specular`] is shared
/// with the `f32` path as a tag only).
pub fn specular_factor(specular: Specular, n: DVec3, light_dir: DVec3, view_dir: DVec3, shininess: f64) -> f64 {
    match specular {
        Specular::Phong => phong_specular_factor(n, light_dir, view_dir, shininess),
        Specular::Blinn => blinn_specular_factor(n, light_dir, view_dir, shininess),
    }
}

/// The angle in degrees at which `cos(α)^s` falls to one half: `acos(exp(−ln 2 / s))`.
///
/// `None` for `s <= 0` or non-finite `s`.
pub fn lobe_half_width_deg(shininess: f64) -> Option<f64> {
    if !(shininess > 0.0 && shininess.is_finite()) {
        return None;
    }
    Some((-(2f64.ln()) / shininess).exp().acos().to_degrees())
}

fn nan_to_zero(x: f64) -> f64 {
    if x.is_nan() {
        0.0
    } else {
        x
    }
}

/// The basic-lighting shader's parameters in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BasicLighting {
    /// Light position, world space.
    pub light_pos: DVec3,
    /// Eye position, world space.
    pub view_pos: DVec3,
    /// Light color.
    pub light_color: DVec3,
    /// Object color.
    pub object_color: DVec3,
    /// `ambientStrength`.
    pub ambient_strength: f64,
    /// `specularStrength`.
    pub specular_strength: f64,
    /// Specular exponent.
    pub shininess: f64,
}

impl BasicLighting {
    /// Widen the `f32` parameters exactly.
    pub fn from_f32(b: &crate::phong::BasicLighting) -> Self {
        BasicLighting {
            light_pos: dvec3(b.light_pos),
            view_pos: dvec3(b.view_pos),
            light_color: dvec3(b.light_color),
            object_color: dvec3(b.object_color),
            ambient_strength: b.ambient_strength as f64,
            specular_strength: b.specular_strength as f64,
            shininess: b.shininess as f64,
        }
    }

    /// The three terms at a fragment, multiplied by the object color.
    ///
    /// ```text
    /// norm = normalize(normal); light_dir = normalize(light_pos − frag_pos)
    /// view_dir = normalize(view_pos − frag_pos); lit = light_color ⊙ object_color
    /// ambient = ambient_strength · lit; diffuse = diff · lit
    /// specular = specular_strength · spec · lit
    /// ```
    ///
    /// Degenerate input: a zero normal, or a fragment at the light or eye,
    /// gives zero diffuse and specular.
    ///
    /// Source: LearnOpenGL, Basic lighting.
    pub fn terms(&self, frag_pos: DVec3, normal: DVec3) -> Terms {
        let norm = normalize_or_zero(normal);
        let light_dir = normalize_or_zero(self.light_pos - frag_pos);
        let view_dir = normalize_or_zero(self.view_pos - frag_pos);
        let lit = super::color::modulate(self.light_color, self.object_color);
        Terms {
            ambient: ambient(self.ambient_strength, lit),
            diffuse: lit * diffuse_factor(norm, light_dir),
            specular: lit * (self.specular_strength * phong_specular_factor(norm, light_dir, view_dir, self.shininess)),
        }
    }

    /// The same shader in view space: positions through `view`, the eye at
    /// the origin, the normal through `transpose(inverse(mat3(view)))`.
    ///
    /// For a rigid `view` this equals [`terms`](Self::terms) with `view_pos`
    /// the camera position. A singular `view` gives zero diffuse and specular.
    ///
    /// Source: opengl-tutorial 8 (camera space); LearnOpenGL, Basic lighting exercise.
    pub fn terms_in_view_space(&self, view: DMat4, frag_pos: DVec3, normal: DVec3) -> Terms {
        let normal_matrix = super::normals::normal_matrix_inverse_transpose(glam::DMat3::from_mat4(view));
        let n = normal_matrix.map_or(DVec3::ZERO, |m| m * normal);
        let in_view =
            BasicLighting { light_pos: view.transform_point3(self.light_pos), view_pos: DVec3::ZERO, ..*self };
        in_view.terms(view.transform_point3(frag_pos), n)
    }
}
