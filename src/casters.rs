//! Chapter 5, Light casters: directional, point (with attenuation), spot and flashlight.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `direction` | a directional or spot light's direction, pointing *from* the light |
//! | `light_dir` | unit vector from the fragment toward the light |
//! | `distance` | `length(light.position - frag_pos)` |
//! | `attenuation` | `1 / (Kc + Kl·d + Kq·d²)` |
//! | `theta` | `dot(light_dir, normalize(-light.direction))`, cosine of the angle off the spot axis |
//! | `cut_off`, `outer_cut_off` | cosines of the inner (φ) and outer (γ) cone half-angles |
//! | `epsilon` | `cut_off - outer_cut_off` (ε = φ − γ) |
//! | `intensity` | `clamp((theta - outer_cut_off) / epsilon, 0, 1)` |
//!
//! Angles enter the public API in degrees and are stored as cosines.
//! Source: LearnOpenGL, Light casters.

use glam::{Vec3, Vec4};

use crate::glsl::{homogeneous_kind, HomogeneousKind};
use crate::material::{material_terms as surface_terms, material_terms_with};
use crate::material::{LightProps, Material};
use crate::phong::{Specular, Terms};

/// A parameter that makes a light invalid, naming the field as the JSON and TOML
/// inputs spell it (e.g. `cut_off_deg`).
pub type ParamError = crate::error::FieldError;

/// The three coefficients of `1 / (Kc + Kl·d + Kq·d²)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    /// `Kc`, the constant term.
    pub constant: f32,
    /// `Kl`, the linear term.
    pub linear: f32,
    /// `Kq`, the quadratic term.
    pub quadratic: f32,
}

impl Attenuation {
    /// Checked constructor.
    ///
    /// Errors (naming `constant`, `linear` or `quadratic`): a negative or
    /// non-finite coefficient, or all three zero. `Kc < 1` is accepted (the
    /// chapter warns it makes the light brighter than the source near it; see
    /// the failure atlas).
    pub fn new(constant: f32, linear: f32, quadratic: f32) -> Result<Self, ParamError> {
        for (field, v) in [("constant", constant), ("linear", linear), ("quadratic", quadratic)] {
            if !v.is_finite() {
                return Err(ParamError::new(field, format!("must be finite, got {v}")));
            }
            if v < 0.0 {
                return Err(ParamError::new(field, format!("must be >= 0, got {v}")));
            }
        }
        if constant == 0.0 && linear == 0.0 && quadratic == 0.0 {
            return Err(ParamError::new("constant", "constant, linear and quadratic are all 0"));
        }
        Ok(Attenuation { constant, linear, quadratic })
    }

    /// The chapter's choice for a range of 50: (1, 0.09, 0.032).
    pub const LEARNOPENGL: Attenuation = Attenuation { constant: 1.0, linear: 0.09, quadratic: 0.032 };

    /// The attenuation factor at `distance`.
    ///
    /// ```text
    /// attenuation = 1 / (Kc + Kl·d + Kq·d²)
    /// ```
    ///
    /// For a valid `Attenuation` with `Kc ≥ 1` and `d ≥ 0` the result is in
    /// (0, 1] and decreasing in `d`. Degenerate input: `Kc = 0` at `d = 0`
    /// gives `+∞`; NaN `d` gives NaN.
    ///
    /// Source: LearnOpenGL, Light casters, attenuation.
    // ANCHOR: attenuation_at
    pub fn at(&self, distance: f32) -> f32 {
        1.0 / (self.constant + self.linear * distance + self.quadratic * distance * distance)
    }
    // ANCHOR_END: attenuation_at

    /// The distance at which the attenuation has fallen to `fraction`.
    ///
    /// Solves `Kq·d² + Kl·d + (Kc − 1/fraction) = 0` for its positive root, in
    /// the cancellation-free form
    ///
    /// ```text
    /// c' = Kc − 1/fraction   (≤ 0)
    /// d  = −2c' / (Kl + sqrt(Kl² − 4·Kq·c'))
    /// ```
    ///
    /// Returns `Some(0)` when the attenuation is already ≤ `fraction` at
    /// `d = 0`, and `None` when `fraction` is not in (0, ∞) or the light
    /// never falls that far (`Kl = Kq = 0`).
    // ANCHOR: distance_for
    pub fn distance_for(&self, fraction: f32) -> Option<f32> {
        if !(fraction > 0.0 && fraction.is_finite()) {
            return None;
        }
        let c = self.constant - 1.0 / fraction;
        if c >= 0.0 {
            return Some(0.0);
        }
        let denominator = self.linear + (self.linear * self.linear - 4.0 * self.quadratic * c).sqrt();
        (denominator > 0.0).then(|| -2.0 * c / denominator)
    }
    // ANCHOR_END: distance_for
}

/// The smooth window that takes a light's falloff to exactly zero at its `range`, as
/// Unreal Engine 4 and Filament do:
///
/// ```text
/// window(d, r) = clamp(1 − (d/r)⁴, 0, 1)²
/// ```
///
/// It is 1 at `d = 0`, stays above 0.99 up to `d ≈ 0.22·r`, falls smoothly, and is 0 for
/// every `d ≥ r` (with a zero slope there, so the lit area has no visible edge). Applied to a
/// falloff, it makes a light's contribution exactly zero beyond its range, so skipping the
/// light there (per fragment, or per screen tile as Forward+ does) changes nothing.
///
/// Degenerate input: `r ≤ 0` or NaN gives 0 (no range, no light); `d` is taken as `|d|`;
/// NaN `d` gives NaN.
///
/// Source: B. Karis, "Real Shading in Unreal Engine 4", SIGGRAPH 2013 course notes,
/// equation 9 (the window, there on `1/(d² + 1)`); Filament's documentation, "Punctual
/// lights" (the same window on the squared distance).
// ANCHOR: range_window
pub fn range_window(distance: f32, range: f32) -> f32 {
    if range.is_nan() || range <= 0.0 {
        return 0.0;
    }
    let x = distance.abs() / range;
    let x2 = x * x;
    let w = (1.0 - x2 * x2).clamp(0.0, 1.0);
    w * w
}
// ANCHOR_END: range_window

impl Attenuation {
    /// The attenuation at `distance` times [`range_window`]: the chapter's falloff near
    /// the light, exactly zero from `range` on.
    ///
    /// ```text
    /// attenuation_w(d) = window(d, r) / (Kc + Kl·d + Kq·d²)
    /// ```
    ///
    /// Degenerate input: as [`Attenuation::at`] and [`range_window`].
    pub fn windowed_at(&self, distance: f32, range: f32) -> f32 {
        range_window(distance, range) * self.at(distance)
    }
}

/// One row of the chapter's range table: coefficients that cover `range` units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RangeRow {
    /// The distance the light is meant to cover.
    pub range: f32,
    /// Its coefficients.
    pub attenuation: Attenuation,
}

const fn range_row(range: f32, constant: f32, linear: f32, quadratic: f32) -> RangeRow {
    RangeRow { range, attenuation: Attenuation { constant, linear, quadratic } }
}

/// The chapter's 12-row table of attenuation coefficients by range (7 … 3250).
///
/// Source: LearnOpenGL, Light casters, "Choosing the right values", crediting
/// the Ogre3D wiki.
pub const RANGE_TABLE: [RangeRow; 12] = [
    range_row(7.0, 1.0, 0.7, 1.8),
    range_row(13.0, 1.0, 0.35, 0.44),
    range_row(20.0, 1.0, 0.22, 0.20),
    range_row(32.0, 1.0, 0.14, 0.07),
    range_row(50.0, 1.0, 0.09, 0.032),
    range_row(65.0, 1.0, 0.07, 0.017),
    range_row(100.0, 1.0, 0.045, 0.0075),
    range_row(160.0, 1.0, 0.027, 0.0028),
    range_row(200.0, 1.0, 0.022, 0.0019),
    range_row(325.0, 1.0, 0.014, 0.0007),
    range_row(600.0, 1.0, 0.007, 0.0002),
    range_row(3250.0, 1.0, 0.0014, 0.000007),
];

/// opengl-tutorial 8's falloff: light power over squared distance.
///
/// ```text
/// falloff = light_power / d²
/// ```
///
/// Degenerate input: `d = 0` gives `+∞` (the atlas shows the blow-up);
/// negative power is not checked.
///
/// Source: opengl-tutorial 8, `LightPower / (distance*distance)`.
// ANCHOR: inverse_square_falloff
pub fn inverse_square_falloff(light_power: f32, distance: f32) -> f32 {
    light_power / (distance * distance)
}
// ANCHOR_END: inverse_square_falloff

/// A light infinitely far away, all rays parallel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirLight {
    /// Direction the light travels, *from* the light (LearnOpenGL's convention).
    pub direction: Vec3,
    /// Term intensities.
    pub props: LightProps,
}

impl DirLight {
    /// The vector toward the light: `normalize(-direction)`, or zero for a
    /// zero or non-finite direction (then only the ambient term remains).
    // ANCHOR: dir_light_dir
    pub fn light_dir(&self) -> Vec3 {
        (-self.direction).normalize_or_zero()
    }
    // ANCHOR_END: dir_light_dir

    /// The light's terms at a fragment.
    ///
    /// ```text
    /// light_dir = normalize(-direction)
    /// ambient = light.ambient ⊙ mat.ambient, diffuse = light.diffuse ⊙ diff·mat.diffuse,
    /// specular = light.specular ⊙ spec·mat.specular
    /// ```
    ///
    /// `n` and `view_dir` must be unit length. Source: LearnOpenGL, Multiple lights, `CalcDirLight`.
    // ANCHOR: dir_terms
    pub fn terms(&self, material: &Material, n: Vec3, view_dir: Vec3) -> Terms {
        self.terms_with(Specular::Phong, material, n, view_dir)
    }

    /// [`Self::terms`] with a choice of specular lobe.
    pub fn terms_with(&self, specular: Specular, material: &Material, n: Vec3, view_dir: Vec3) -> Terms {
        material_terms_with(specular, material, &self.props, n, self.light_dir(), view_dir)
    }
    // ANCHOR_END: dir_terms
}

/// A light at a position, fading with distance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// World position.
    pub position: Vec3,
    /// Distance falloff.
    pub attenuation: Attenuation,
    /// Term intensities.
    pub props: LightProps,
}

/// A light with a position (point and spot): its terms depend on where the fragment is.
///
/// `n` and `view_dir` must be unit length; `frag_pos` is in the light's space (world space
/// in the chapters).
pub trait LocalLight {
    /// The light's terms at `frag_pos` with a choice of specular lobe.
    fn terms_with(&self, specular: Specular, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms;

    /// The light's terms with the chapters' Phong lobe.
    fn terms(&self, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        self.terms_with(Specular::Phong, material, n, frag_pos, view_dir)
    }
}

impl LocalLight for PointLight {
    /// The light's terms at a fragment, all three multiplied by the attenuation.
    ///
    /// ```text
    /// light_dir = normalize(position - frag_pos); d = length(position - frag_pos)
    /// terms = attenuation(d) · (ambient, diffuse, specular)
    /// ```
    ///
    /// `n` and `view_dir` must be unit length. A fragment exactly at the
    /// light gives `light_dir = 0` (ambient only) and attenuation `1/Kc`.
    ///
    /// Source: LearnOpenGL, Multiple lights, `CalcPointLight`.
    // ANCHOR: point_terms
    fn terms_with(&self, specular: Specular, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        let to_light = self.position - frag_pos;
        let light_dir = to_light.normalize_or_zero();
        let attenuation = self.attenuation.at(to_light.length());
        material_terms_with(specular, material, &self.props, n, light_dir, view_dir).scaled(attenuation)
    }
    // ANCHOR_END: point_terms
}

/// A point light restricted to a cone, with a soft edge between two angles.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight {
    /// World position.
    pub position: Vec3,
    /// Unit axis of the cone, pointing *from* the light.
    pub direction: Vec3,
    /// `cos(φ)`, cosine of the inner half-angle.
    pub cut_off: f32,
    /// `cos(γ)`, cosine of the outer half-angle.
    pub outer_cut_off: f32,
    /// Distance falloff.
    pub attenuation: Attenuation,
    /// Term intensities.
    pub props: LightProps,
}

impl SpotLight {
    /// Checked constructor, angles in degrees.
    ///
    /// Errors, naming the field: `direction` zero or non-finite;
    /// `cut_off_deg` or `outer_cut_off_deg` outside [0, 90] or non-finite;
    /// `cut_off_deg` > `outer_cut_off_deg` (an inverted cone). Equal angles
    /// are accepted and give a hard edge (ε = 0, see [`spot_intensity`]).
    ///
    /// Source: LearnOpenGL, Light casters, spotlight.
    pub fn new(
        position: Vec3,
        direction: Vec3,
        cut_off_deg: f32,
        outer_cut_off_deg: f32,
        attenuation: Attenuation,
        props: LightProps,
    ) -> Result<Self, ParamError> {
        let direction = direction
            .try_normalize()
            .ok_or_else(|| ParamError::new("direction", "must be a non-zero finite vector"))?;
        for (field, v) in [("cut_off_deg", cut_off_deg), ("outer_cut_off_deg", outer_cut_off_deg)] {
            if !(0.0..=90.0).contains(&v) {
                return Err(ParamError::new(field, format!("must be in [0, 90] degrees, got {v}")));
            }
        }
        if cut_off_deg > outer_cut_off_deg {
            return Err(ParamError::new(
                "cut_off_deg",
                format!("inner cut-off {cut_off_deg} exceeds outer_cut_off_deg {outer_cut_off_deg}"),
            ));
        }
        Ok(SpotLight {
            position,
            direction,
            cut_off: cut_off_deg.to_radians().cos(),
            outer_cut_off: outer_cut_off_deg.to_radians().cos(),
            attenuation,
            props,
        })
    }

    /// The Multiple lights chapter's flashlight: a spot at the camera, pointing
    /// where it looks, cut-offs 12.5° and 15°, attenuation (1, 0.09, 0.032),
    /// ambient 0, diffuse 1, specular 1.
    ///
    /// Degenerate input: a zero `camera_front` gives `None`.
    // ANCHOR: flashlight
    pub fn flashlight(camera_pos: Vec3, camera_front: Vec3) -> Option<Self> {
        let props = LightProps { ambient: Vec3::ZERO, diffuse: Vec3::ONE, specular: Vec3::ONE };
        SpotLight::new(camera_pos, camera_front, 12.5, 15.0, Attenuation::LEARNOPENGL, props).ok()
    }
    // ANCHOR_END: flashlight

    /// `theta`: the cosine of the angle between the cone axis and the ray to the fragment.
    ///
    /// ```text
    /// theta = dot(light_dir, normalize(-direction))
    /// ```
    // ANCHOR: theta
    pub fn theta(&self, light_dir: Vec3) -> f32 {
        light_dir.dot((-self.direction).normalize_or_zero())
    }
    // ANCHOR_END: theta

    /// The Light casters chapter's soft spot: diffuse and specular × intensity,
    /// ambient not, then all three × attenuation ("so there is always a little light").
    ///
    /// Source: LearnOpenGL, Light casters, "Smooth/Soft edges".
    // ANCHOR: terms_keep_ambient
    pub fn terms_keep_ambient(&self, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        let (unlit, attenuation, intensity) = self.unscaled(Specular::Phong, material, n, frag_pos, view_dir);
        Terms {
            ambient: unlit.ambient * attenuation,
            diffuse: unlit.diffuse * (attenuation * intensity),
            specular: unlit.specular * (attenuation * intensity),
        }
    }
    // ANCHOR_END: terms_keep_ambient

    /// The Light casters chapter's first spot: full light inside the inner cone
    /// (`theta > cut_off`), ambient only outside; no soft edge, no attenuation.
    ///
    /// Source: LearnOpenGL, Light casters, spotlight ("else use ambient light").
    // ANCHOR: terms_hard_edge
    pub fn terms_hard_edge(&self, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        let light_dir = (self.position - frag_pos).normalize_or_zero();
        let lit = surface_terms(material, &self.props, n, light_dir, view_dir);
        if hard_spot(self.theta(light_dir), self.cut_off) > 0.0 {
            lit
        } else {
            Terms { ambient: lit.ambient, ..Terms::default() }
        }
    }
    // ANCHOR_END: terms_hard_edge

    fn unscaled(
        &self,
        specular: Specular,
        material: &Material,
        n: Vec3,
        frag_pos: Vec3,
        view_dir: Vec3,
    ) -> (Terms, f32, f32) {
        let to_light = self.position - frag_pos;
        let light_dir = to_light.normalize_or_zero();
        let intensity = spot_intensity(self.theta(light_dir), self.cut_off, self.outer_cut_off);
        let attenuation = self.attenuation.at(to_light.length());
        (material_terms_with(specular, material, &self.props, n, light_dir, view_dir), attenuation, intensity)
    }
}

impl LocalLight for SpotLight {
    /// The spot's terms at a fragment: all three × attenuation × intensity.
    ///
    /// `n` and `view_dir` must be unit length. Source: LearnOpenGL, Multiple
    /// lights, `CalcSpotLight` (which, unlike the Light casters chapter, also
    /// scales the ambient term by the intensity; see [`SpotLight::terms_keep_ambient`]).
    // ANCHOR: spot_terms
    fn terms_with(&self, specular: Specular, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        let (unlit, attenuation, intensity) = self.unscaled(specular, material, n, frag_pos, view_dir);
        unlit.scaled(attenuation * intensity)
    }
    // ANCHOR_END: spot_terms
}

/// The soft-edge spot intensity.
///
/// ```text
/// epsilon   = cut_off - outer_cut_off        (ε = φ − γ, cosines)
/// intensity = clamp((theta - outer_cut_off) / epsilon, 0, 1)
/// ```
///
/// Result in [0, 1]: 1 inside the inner cone, 0 outside the outer cone, and
/// non-decreasing in `theta`. Degenerate input: `ε ≤ 0` (equal or inverted
/// cones) gives the hard edge `theta > outer_cut_off ? 1 : 0` instead of the
/// division by zero, and NaN `theta` gives 0.
///
/// Source: LearnOpenGL, Light casters, "Smooth/Soft edges".
// ANCHOR: spot_intensity
pub fn spot_intensity(theta: f32, cut_off: f32, outer_cut_off: f32) -> f32 {
    let epsilon = cut_off - outer_cut_off;
    if epsilon > 0.0 {
        crate::glsl::saturate((theta - outer_cut_off) / epsilon)
    } else {
        hard_spot(theta, outer_cut_off)
    }
}
// ANCHOR_END: spot_intensity

/// The unsmoothed test `theta > cut_off ? 1 : 0`.
///
/// Source: LearnOpenGL, Light casters, spotlight. NaN gives 0.
// ANCHOR: hard_spot
pub fn hard_spot(theta: f32, cut_off: f32) -> f32 {
    if theta > cut_off {
        1.0
    } else {
        0.0
    }
}
// ANCHOR_END: hard_spot

/// The two kinds of light a `vec4` can describe, decided by `w`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightVector {
    /// `w ≈ 0`: a direction *from* the light.
    Direction(Vec3),
    /// `w ≠ 0`: a position (`xyz / w`).
    Position(Vec3),
}

/// Decide whether a `vec4` light vector is a direction or a position.
///
/// ```text
/// |w| <= tolerance  ->  Direction(xyz)
/// otherwise         ->  Position(xyz / w)
/// ```
///
/// LearnOpenGL tests `w == 0.0` and warns about float comparison; lightlab
/// takes an explicit tolerance. `None` for NaN `w`.
///
/// Source: LearnOpenGL, Light casters, directional light.
// ANCHOR: classify_light_vector
pub fn classify_light_vector(v: Vec4, tolerance: f32) -> Option<LightVector> {
    Some(match homogeneous_kind(v.w, tolerance)? {
        HomogeneousKind::Direction => LightVector::Direction(v.truncate()),
        HomogeneousKind::Position => LightVector::Position(v.truncate() / v.w),
    })
}
// ANCHOR_END: classify_light_vector
