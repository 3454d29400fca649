//! Chapter 2, Basic lighting: ambient, diffuse and specular (Phong and Blinn-Phong).
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `n` | unit surface normal |
//! | `light_dir` | unit vector from the surface point toward the light |
//! | `view_dir` | unit vector from the surface point toward the eye |
//! | `reflect_dir` | `reflect(-light_dir, n)`, the mirror direction |
//! | `halfway` | `normalize(light_dir + view_dir)` |
//! | `diff` | `max(n · light_dir, 0)` |
//! | `spec` | `pow(max(view_dir · reflect_dir, 0), shininess)` (Phong) |
//! | `shininess` | specular exponent `s` |
//!
//! All direction vectors point away from the surface (see the crate docs).

use glam::{Mat3, Mat4, Vec3};

use crate::glsl::{pow_or_zero, reflect};

/// Declares a `Terms` struct over a vector type and its scalar: the plumbing shared by
/// the `f32` shader path (here) and the `f64` reference ([`crate::reference::phong`]),
/// which compute the terms independently but hold and combine them alike.
macro_rules! terms_struct {
    ($(#[$meta:meta])* $vec:ty, $scalar:ty) => {
        $(#[$meta])*
        #[derive(Clone, Copy, Debug, Default, PartialEq)]
        pub struct Terms {
            /// Ambient term.
            pub ambient: $vec,
            /// Diffuse term.
            pub diffuse: $vec,
            /// Specular term.
            pub specular: $vec,
        }

        impl Terms {
            /// `ambient + diffuse + specular`, unclamped.
            pub fn sum(&self) -> $vec {
                self.ambient + self.diffuse + self.specular
            }

            /// Every term multiplied by the same factor (attenuation, spot intensity).
            pub fn scaled(&self, factor: $scalar) -> Terms {
                Terms { ambient: self.ambient * factor, diffuse: self.diffuse * factor, specular: self.specular * factor }
            }
        }
    };
}
pub(crate) use terms_struct;

terms_struct!(
    /// The three terms of the Phong reflection model at one fragment, before summing.
    Vec3,
    f32
);

impl std::ops::Add for Terms {
    type Output = Terms;
    fn add(self, o: Terms) -> Terms {
        Terms {
            ambient: self.ambient + o.ambient,
            diffuse: self.diffuse + o.diffuse,
            specular: self.specular + o.specular,
        }
    }
}

/// Ambient light: a constant fraction of the light color.
///
/// ```text
/// ambient = ambient_strength · light_color
/// ```
///
/// No preconditions; NaN propagates.
///
/// Source: LearnOpenGL, Basic lighting, `ambientStrength = 0.1`.
// ANCHOR: ambient
pub fn ambient(ambient_strength: f32, light_color: Vec3) -> Vec3 {
    ambient_strength * light_color
}
// ANCHOR_END: ambient

/// Lambert's diffuse factor.
///
/// ```text
/// diff = max(n · light_dir, 0)
/// ```
///
/// - `n` and `light_dir` must be unit length; both point away from the surface.
/// - Result in [0, 1] for unit inputs.
/// - Degenerate input: a NaN dot product gives 0 (Rust's `max` drops NaN),
///   so a zero-length normal that was normalized to NaN contributes no light.
///
/// Source: LearnOpenGL, Basic lighting, diffuse; opengl-tutorial 8 uses
/// `clamp(dot(n, l), 0, 1)`, equal for unit vectors.
// ANCHOR: diffuse_factor
pub fn diffuse_factor(n: Vec3, light_dir: Vec3) -> f32 {
    n.dot(light_dir).max(0.0)
}
// ANCHOR_END: diffuse_factor

/// Phong's specular factor.
///
/// ```text
/// reflect_dir = reflect(-light_dir, n)
/// spec = pow(max(view_dir · reflect_dir, 0), shininess)
/// ```
///
/// - `n`, `light_dir`, `view_dir` must be unit length, pointing away from the surface.
/// - Not gated by `n · light_dir` (LearnOpenGL's shader is not; see the failure atlas).
/// - Degenerate input: shininess ≤ 0 with a zero base gives 0 ([`pow_or_zero`]);
///   NaN vectors give 0; a zero normal gives 0 (there is no mirror plane:
///   `reflect(-light_dir, 0)` would be `-light_dir`, a highlight seen from
///   *behind* the surface).
///
/// Source: LearnOpenGL, Basic lighting, specular.
// ANCHOR: phong_specular_factor
pub fn phong_specular_factor(n: Vec3, light_dir: Vec3, view_dir: Vec3, shininess: f32) -> f32 {
    if n == Vec3::ZERO {
        return 0.0;
    }
    let reflect_dir = reflect(-light_dir, n);
    pow_or_zero(view_dir.dot(reflect_dir).max(0.0), shininess)
}
// ANCHOR_END: phong_specular_factor

/// Which specular lobe a light's terms use: LearnOpenGL's Phong or Blinn-Phong.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Specular {
    /// `pow(max(view_dir · reflect_dir, 0), s)`, [`phong_specular_factor`].
    #[default]
    Phong,
    /// `pow(max(n · halfway, 0), s)`, [`blinn_specular_factor`].
    Blinn,
}

impl Specular {
    /// The specular factor of this lobe; preconditions and degenerate results as
    /// [`phong_specular_factor`] and [`blinn_specular_factor`].
    pub fn factor(self, n: Vec3, light_dir: Vec3, view_dir: Vec3, shininess: f32) -> f32 {
        match self {
            Specular::Phong => phong_specular_factor(n, light_dir, view_dir, shininess),
            Specular::Blinn => blinn_specular_factor(n, light_dir, view_dir, shininess),
        }
    }
}

/// The halfway vector of Blinn-Phong.
///
/// ```text
/// halfway = normalize(light_dir + view_dir)
/// ```
///
/// Degenerate input: when `light_dir == -view_dir` the sum is zero and the
/// result is the zero vector (no highlight), not NaN.
///
/// Source: Blinn 1977, "Models of light reflection for computer synthesized pictures".
// ANCHOR: halfway
pub fn halfway(light_dir: Vec3, view_dir: Vec3) -> Vec3 {
    (light_dir + view_dir).normalize_or_zero()
}
// ANCHOR_END: halfway

/// Blinn-Phong's specular factor.
///
/// ```text
/// spec = pow(max(n · halfway, 0), shininess)
/// ```
///
/// Same preconditions and degenerate results as [`phong_specular_factor`].
///
/// Source: Blinn 1977; LearnOpenGL, Advanced lighting.
// ANCHOR: blinn_specular_factor
pub fn blinn_specular_factor(n: Vec3, light_dir: Vec3, view_dir: Vec3, shininess: f32) -> f32 {
    pow_or_zero(n.dot(halfway(light_dir, view_dir)).max(0.0), shininess)
}
// ANCHOR_END: blinn_specular_factor

/// The angle from the peak at which `cos(α)^s` falls to one half, in degrees.
///
/// ```text
/// half_width(s) = acos(2^(-1/s))
/// ```
///
/// Returns `None` for `s <= 0` or non-finite `s` (no lobe).
// ANCHOR: lobe_half_width_deg
pub fn lobe_half_width_deg(shininess: f32) -> Option<f32> {
    if !(shininess > 0.0 && shininess.is_finite()) {
        return None;
    }
    Some(0.5f32.powf(1.0 / shininess).acos().to_degrees())
}
// ANCHOR_END: lobe_half_width_deg

/// The rule of thumb for a Blinn-Phong exponent that gives the Phong lobe's width.
///
/// ```text
/// s_blinn ≈ 4 · s_phong
/// ```
///
/// In the plane of incidence the angle between `n` and `halfway` is half the
/// angle between `reflect_dir` and `view_dir`, and `cos(α/2)^(4s) ≈ cos(α)^s`
/// for small α (both are `exp(-s α²/2)` to second order).
///
/// Source: LearnOpenGL, Advanced lighting ("2 to 4 times").
// ANCHOR: blinn_exponent_rule_of_thumb
pub fn blinn_exponent_rule_of_thumb(phong_shininess: f32) -> f32 {
    4.0 * phong_shininess
}
// ANCHOR_END: blinn_exponent_rule_of_thumb

/// The Blinn-Phong exponent whose in-plane lobe has the same half-width as a Phong lobe.
///
/// ```text
/// α½ = acos(2^(-1/s))               Phong half-width
/// s_blinn = ln(1/2) / ln(cos(α½ / 2))
/// ```
///
/// Returns `None` for `s <= 0` or non-finite `s`.
// ANCHOR: blinn_exponent_matching_half_width
pub fn blinn_exponent_matching_half_width(phong_shininess: f32) -> Option<f32> {
    let half = lobe_half_width_deg(phong_shininess)?.to_radians();
    Some(0.5f32.ln() / (0.5 * half).cos().ln())
}
// ANCHOR_END: blinn_exponent_matching_half_width

/// The LearnOpenGL basic-lighting shader's parameters (one point light, one color).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BasicLighting {
    /// Light position, world space.
    pub light_pos: Vec3,
    /// Eye position, world space.
    pub view_pos: Vec3,
    /// Light color.
    pub light_color: Vec3,
    /// Object color.
    pub object_color: Vec3,
    /// `ambientStrength`.
    pub ambient_strength: f32,
    /// `specularStrength`.
    pub specular_strength: f32,
    /// Specular exponent.
    pub shininess: f32,
}

impl BasicLighting {
    /// The chapter's scene: light at (1.2, 1, 2), eye at (0, 0, 3), white light,
    /// coral object, ambient 0.1, specular strength 0.5, shininess 32.
    ///
    /// Source: LearnOpenGL, Basic lighting.
    pub fn learnopengl() -> Self {
        BasicLighting {
            light_pos: Vec3::new(1.2, 1.0, 2.0),
            view_pos: Vec3::new(0.0, 0.0, 3.0),
            light_color: Vec3::ONE,
            object_color: crate::color::CORAL,
            ambient_strength: 0.1,
            specular_strength: 0.5,
            shininess: 32.0,
        }
    }

    /// The three terms at a fragment, already multiplied by the object color.
    ///
    /// ```text
    /// norm = normalize(normal); light_dir = normalize(light_pos - frag_pos)
    /// view_dir = normalize(view_pos - frag_pos)
    /// ambient  = ambient_strength · light_color ⊙ object_color
    /// diffuse  = max(norm · light_dir, 0) · light_color ⊙ object_color
    /// specular = specular_strength · spec · light_color ⊙ object_color
    /// ```
    ///
    /// `normal` need not be unit length. Degenerate input: a zero normal, or a
    /// fragment at the light or eye position, gives zero diffuse and specular
    /// (the direction is normalized with `normalize_or_zero`).
    ///
    /// Source: LearnOpenGL, Basic lighting, final fragment shader.
    // ANCHOR: basic_terms
    pub fn terms(&self, frag_pos: Vec3, normal: Vec3) -> Terms {
        let norm = normal.normalize_or_zero();
        let light_dir = (self.light_pos - frag_pos).normalize_or_zero();
        let view_dir = (self.view_pos - frag_pos).normalize_or_zero();
        let lit = self.light_color * self.object_color;
        Terms {
            ambient: ambient(self.ambient_strength, lit),
            diffuse: diffuse_factor(norm, light_dir) * lit,
            specular: self.specular_strength * phong_specular_factor(norm, light_dir, view_dir, self.shininess) * lit,
        }
    }
    // ANCHOR_END: basic_terms

    /// The same shader evaluated in view space (camera at the origin).
    ///
    /// ```text
    /// frag_pos' = view · frag_pos;  light_pos' = view · light_pos;  view_pos' = 0
    /// normal'   = transpose(inverse(mat3(view))) · normal
    /// ```
    ///
    /// For any rigid `view` (rotation and translation) the result equals
    /// [`terms`](Self::terms) with `view_pos` set to the camera position;
    /// lightlab's property tests check this. A singular `view` gives zero
    /// diffuse and specular (normal matrix falls back to zero).
    ///
    /// Source: opengl-tutorial 8 works in camera space; LearnOpenGL, Basic
    /// lighting, exercise "do Phong shading in view space".
    // ANCHOR: terms_in_view_space
    pub fn terms_in_view_space(&self, view: Mat4, frag_pos: Vec3, normal: Vec3) -> Terms {
        let normal_matrix = crate::normals::normal_matrix_cofactor(Mat3::from_mat4(view));
        let in_view = BasicLighting { light_pos: view.transform_point3(self.light_pos), view_pos: Vec3::ZERO, ..*self };
        in_view.terms(view.transform_point3(frag_pos), normal_matrix * normal)
    }
    // ANCHOR_END: terms_in_view_space
}
