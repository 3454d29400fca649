//! Chapter 5, Light casters, in `f64`.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `direction` | direction *from* the light (dir and spot lights) |
//! | `light_dir` | unit vector from the fragment toward the light |
//! | `d` | distance from the fragment to the light |
//! | `attenuation` | `1 / (Kc + Kl d + Kq d²)` |
//! | `theta` | cosine of the angle between `light_dir` and `−direction` |
//! | `cut_off`, `outer_cut_off` | cosines of the inner and outer half-angles |
//!
//! Source: LearnOpenGL, Light casters and Multiple lights.

use glam::DVec3;

use super::dvec3;
use super::glsl::normalize_or_zero;
use super::material::{material_terms, material_terms_with, LightProps, Material};
use super::phong::{Specular, Terms};

/// Attenuation coefficients in `f64` (unchecked: build them from a checked
/// [`crate::casters::Attenuation`] with [`Attenuation::from_f32`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Attenuation {
    /// `Kc`.
    pub constant: f64,
    /// `Kl`.
    pub linear: f64,
    /// `Kq`.
    pub quadratic: f64,
}

impl Attenuation {
    /// Widen checked `f32` coefficients exactly.
    pub fn from_f32(a: &crate::casters::Attenuation) -> Self {
        Attenuation { constant: a.constant as f64, linear: a.linear as f64, quadratic: a.quadratic as f64 }
    }

    /// `1 / (Kc + d (Kl + Kq d))` (Horner form).
    ///
    /// In (0, 1] and decreasing for `Kc ≥ 1`, `Kl, Kq ≥ 0`, `d ≥ 0`.
    /// Degenerate input: a zero denominator gives `+∞`; NaN propagates.
    ///
    /// Source: LearnOpenGL, Light casters, attenuation.
    pub fn at(&self, distance: f64) -> f64 {
        1.0 / (self.constant + distance * (self.linear + self.quadratic * distance))
    }

    /// The attenuation times the range window, `f64`: see [`range_window`].
    pub fn windowed_at(&self, distance: f64, range: f64) -> f64 {
        self.at(distance) * range_window(distance, range)
    }

    /// The distance where the attenuation equals `fraction`, by bisection.
    ///
    /// ```text
    /// find d ≥ 0 with at(d) = fraction:
    ///   hi = 1, 2, 4, … until at(hi) ≤ fraction;  then halve [0, hi] until it stops shrinking
    /// ```
    ///
    /// `at` is decreasing for `Kl, Kq ≥ 0`, so bisection converges to the root
    /// to the last `f64` bit, with no closed form (the `f32` code solves the
    /// quadratic in a cancellation-free form; the textbook root
    /// `(−Kl + sqrt(Kl² − 4 Kq c')) / (2 Kq)` would lose digits when
    /// `4 Kq |c'| ≪ Kl²`, so it is not used here either).
    ///
    /// `Some(0)` when the attenuation at 0 is already ≤ `fraction`; `None` for
    /// `fraction` outside (0, ∞), or when the light never falls that far
    /// (no `hi` below 1e300 works, e.g. `Kl = Kq = 0`).
    pub fn distance_for(&self, fraction: f64) -> Option<f64> {
        if !(fraction > 0.0 && fraction.is_finite()) {
            return None;
        }
        if self.at(0.0) <= fraction {
            return Some(0.0);
        }
        let mut hi = 1.0;
        while self.at(hi) > fraction {
            hi *= 2.0;
            if hi > 1e300 {
                return None;
            }
        }
        let mut lo = 0.0;
        loop {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                return Some(hi);
            }
            if self.at(mid) > fraction {
                lo = mid;
            } else {
                hi = mid;
            }
        }
    }
}

/// opengl-tutorial 8's `light_power / d²`; `d = 0` gives `+∞`.
///
/// Source: opengl-tutorial 8.
pub fn inverse_square_falloff(light_power: f64, distance: f64) -> f64 {
    light_power / distance.powi(2)
}

/// The soft spot intensity as a piecewise ramp.
///
/// ```text
/// theta ≥ cut_off        → 1
/// theta ≤ outer_cut_off  → 0
/// otherwise              → (theta − outer_cut_off) / (cut_off − outer_cut_off)
/// ```
///
/// Equals `clamp((theta − γ)/ε, 0, 1)` for `ε > 0`. Degenerate input:
/// `cut_off ≤ outer_cut_off` gives the hard edge `theta > outer_cut_off`;
/// NaN `theta` gives 0.
///
/// Source: LearnOpenGL, Light casters, soft edges.
pub fn spot_intensity(theta: f64, cut_off: f64, outer_cut_off: f64) -> f64 {
    if theta.is_nan() {
        0.0
    } else if cut_off <= outer_cut_off {
        hard_spot(theta, outer_cut_off)
    } else if theta >= cut_off {
        1.0
    } else if theta <= outer_cut_off {
        0.0
    } else {
        (theta - outer_cut_off) / (cut_off - outer_cut_off)
    }
}

/// `theta > cut_off ? 1 : 0`; NaN gives 0. Source: LearnOpenGL, Light casters.
pub fn hard_spot(theta: f64, cut_off: f64) -> f64 {
    if theta > cut_off {
        1.0
    } else {
        0.0
    }
}

/// A directional light in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirLight {
    /// Direction *from* the light.
    pub direction: DVec3,
    /// Term intensities.
    pub props: LightProps,
}

impl DirLight {
    /// Widen an `f32` light exactly.
    pub fn from_f32(l: &crate::casters::DirLight) -> Self {
        DirLight { direction: dvec3(l.direction), props: LightProps::from_f32(&l.props) }
    }

    /// `normalize(−direction)`, or zero for a zero or non-finite direction.
    pub fn light_dir(&self) -> DVec3 {
        normalize_or_zero(-self.direction)
    }

    /// The light's terms; unit `n` and `view_dir`. Source: `CalcDirLight`.
    pub fn terms(&self, material: &Material, n: DVec3, view_dir: DVec3) -> Terms {
        self.terms_with(Specular::Phong, material, n, view_dir)
    }

    /// [`Self::terms`] with a choice of specular lobe.
    pub fn terms_with(&self, specular: Specular, material: &Material, n: DVec3, view_dir: DVec3) -> Terms {
        material_terms_with(specular, material, &self.props, n, self.light_dir(), view_dir)
    }
}

/// A point light in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointLight {
    /// World position.
    pub position: DVec3,
    /// Distance falloff.
    pub attenuation: Attenuation,
    /// Term intensities.
    pub props: LightProps,
}

impl PointLight {
    /// Widen an `f32` light exactly.
    pub fn from_f32(l: &crate::casters::PointLight) -> Self {
        PointLight {
            position: dvec3(l.position),
            attenuation: Attenuation::from_f32(&l.attenuation),
            props: LightProps::from_f32(&l.props),
        }
    }
}

/// A light with a position (point and spot), in `f64`: its terms depend on where the
/// fragment is. `n` and `view_dir` must be unit length.
pub trait LocalLight {
    /// The light's terms at `frag_pos` with a choice of specular lobe.
    fn terms_with(&self, specular: Specular, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms;

    /// The light's terms with the chapters' Phong lobe.
    fn terms(&self, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms {
        self.terms_with(Specular::Phong, material, n, frag_pos, view_dir)
    }
}

impl LocalLight for PointLight {
    /// All three terms × `attenuation(d)`. A fragment at the light gives
    /// ambient only, × `1/Kc`. Source: `CalcPointLight`.
    fn terms_with(&self, specular: Specular, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms {
        let to_light = self.position - frag_pos;
        let light_dir = normalize_or_zero(to_light);
        material_terms_with(specular, material, &self.props, n, light_dir, view_dir)
            .scaled(self.attenuation.at(to_light.length()))
    }
}

/// A spot light in `f64`, cut-offs stored as cosines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotLight {
    /// World position.
    pub position: DVec3,
    /// Unit cone axis, *from* the light.
    pub direction: DVec3,
    /// `cos φ`, inner.
    pub cut_off: f64,
    /// `cos γ`, outer.
    pub outer_cut_off: f64,
    /// Distance falloff.
    pub attenuation: Attenuation,
    /// Term intensities.
    pub props: LightProps,
}

impl SpotLight {
    /// Widen a checked `f32` spot light exactly (its cosines as stored).
    pub fn from_f32(l: &crate::casters::SpotLight) -> Self {
        SpotLight {
            position: dvec3(l.position),
            direction: dvec3(l.direction),
            cut_off: l.cut_off as f64,
            outer_cut_off: l.outer_cut_off as f64,
            attenuation: Attenuation::from_f32(&l.attenuation),
            props: LightProps::from_f32(&l.props),
        }
    }

    /// `theta = cos(angle(light_dir, −direction))` through the explicit angle.
    pub fn theta(&self, light_dir: DVec3) -> f64 {
        super::cos_between_scaled(light_dir, normalize_or_zero(-self.direction))
    }

    fn parts(
        &self,
        specular: Specular,
        material: &Material,
        n: DVec3,
        frag_pos: DVec3,
        view_dir: DVec3,
    ) -> (Terms, f64, f64) {
        let to_light = self.position - frag_pos;
        let light_dir = normalize_or_zero(to_light);
        let intensity = spot_intensity(self.theta(light_dir), self.cut_off, self.outer_cut_off);
        (
            material_terms_with(specular, material, &self.props, n, light_dir, view_dir),
            self.attenuation.at(to_light.length()),
            intensity,
        )
    }

    /// Light casters' soft spot: ambient × attenuation; diffuse and specular × attenuation × intensity.
    pub fn terms_keep_ambient(&self, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms {
        let (t, att, intensity) = self.parts(Specular::Phong, material, n, frag_pos, view_dir);
        Terms {
            ambient: t.ambient * att,
            diffuse: t.diffuse * (att * intensity),
            specular: t.specular * (att * intensity),
        }
    }

    /// Light casters' first spot: full unattenuated terms when `theta > cut_off`, else ambient only.
    pub fn terms_hard_edge(&self, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms {
        let light_dir = normalize_or_zero(self.position - frag_pos);
        let t = material_terms(material, &self.props, n, light_dir, view_dir);
        if hard_spot(self.theta(light_dir), self.cut_off) > 0.0 {
            t
        } else {
            Terms { ambient: t.ambient, ..Terms::default() }
        }
    }
}

impl LocalLight for SpotLight {
    /// Multiple lights' `CalcSpotLight`: all three × attenuation × intensity.
    fn terms_with(&self, specular: Specular, material: &Material, n: DVec3, frag_pos: DVec3, view_dir: DVec3) -> Terms {
        let (t, att, intensity) = self.parts(specular, material, n, frag_pos, view_dir);
        t.scaled(att * intensity)
    }
}

/// The range window in `f64`, written from the definition `(max(0, 1 − (|d|/r)⁴))²` (an
/// independent form of [`crate::casters::range_window`]): 0 for `r ≤ 0` or NaN `r`.
pub fn range_window(distance: f64, range: f64) -> f64 {
    if range.is_nan() || range <= 0.0 {
        return 0.0;
    }
    let t = 1.0 - (distance.abs() / range).powi(4);
    if t > 0.0 {
        t.min(1.0).powi(2)
    } else {
        0.0
    }
}
