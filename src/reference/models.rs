//! The opengl-tutorial 8 and ogldev 19 shading models in `f64`.
//!
//! LearnOpenGL's and Blinn-Phong's models are [`super::material`] and
//! [`super::phong`]. Sources: opengl-tutorial 8 "Basic shading"; ogldev 19
//! "Specular lighting".

use glam::DVec3;

use super::casters::inverse_square_falloff;
use super::glsl::{normalize_or_zero, pow_or_zero, reflect, saturate};
use super::phong::Terms;
use super::{cos_between_scaled, dvec3};

/// opengl-tutorial 8's inputs in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OpenGLTutorial {
    /// `LightPosition_worldspace`.
    pub light_pos: DVec3,
    /// `LightColor`.
    pub light_color: DVec3,
    /// `LightPower`.
    pub light_power: f64,
    /// `MaterialDiffuseColor`.
    pub diffuse: DVec3,
    /// `MaterialSpecularColor`.
    pub specular: DVec3,
    /// Ambient = factor × diffuse.
    pub ambient_factor: f64,
    /// Specular exponent.
    pub exponent: f64,
}

impl OpenGLTutorial {
    /// Widen the `f32` inputs exactly.
    pub fn from_f32(m: &crate::models::OpenGLTutorial) -> Self {
        OpenGLTutorial {
            light_pos: dvec3(m.light_pos),
            light_color: dvec3(m.light_color),
            light_power: m.light_power as f64,
            diffuse: dvec3(m.diffuse),
            specular: dvec3(m.specular),
            ambient_factor: m.ambient_factor as f64,
            exponent: m.exponent as f64,
        }
    }

    /// Shade a fragment.
    ///
    /// ```text
    /// cosTheta = clamp(cos(angle(n, l)), 0, 1);  cosAlpha = clamp(cos(angle(E, reflect(−l, n))), 0, 1)
    /// ambient = ambient_factor · diffuse
    /// diffuse = diffuse ⊙ LightColor · LightPower · cosTheta / d²
    /// specular = specular ⊙ LightColor · LightPower · cosAlpha^exponent / d²
    /// ```
    ///
    /// `d = 0` gives infinite diffuse and specular; a zero normal gives ambient only.
    pub fn terms(&self, frag_pos: DVec3, normal: DVec3, eye_pos: DVec3) -> Terms {
        let n = normalize_or_zero(normal);
        let to_light = self.light_pos - frag_pos;
        let l = normalize_or_zero(to_light);
        let e = normalize_or_zero(eye_pos - frag_pos);
        let cos_theta = saturate(cos_between_scaled(n, l));
        let cos_alpha = if n.length() == 0.0 { 0.0 } else { saturate(cos_between_scaled(e, reflect(-l, n))) };
        let falloff = inverse_square_falloff(self.light_power, to_light.length());
        let color = self.light_color * falloff;
        Terms {
            ambient: self.diffuse * self.ambient_factor,
            diffuse: self.diffuse * color * cos_theta,
            specular: self.specular * color * pow_or_zero(cos_alpha, self.exponent),
        }
    }
}

/// ogldev 19's inputs in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ogldev {
    /// Light color.
    pub color: DVec3,
    /// Ambient intensity.
    pub ambient_intensity: f64,
    /// Diffuse intensity.
    pub diffuse_intensity: f64,
    /// Direction *from* the light, used as given.
    pub direction: DVec3,
    /// Specular intensity.
    pub specular_intensity: f64,
    /// Specular power.
    pub specular_power: f64,
    /// Texture color multiplying the sum.
    pub texture_color: DVec3,
}

impl Ogldev {
    /// Widen the `f32` inputs exactly.
    pub fn from_f32(m: &crate::models::Ogldev) -> Self {
        Ogldev {
            color: dvec3(m.color),
            ambient_intensity: m.ambient_intensity as f64,
            diffuse_intensity: m.diffuse_intensity as f64,
            direction: dvec3(m.direction),
            specular_intensity: m.specular_intensity as f64,
            specular_power: m.specular_power as f64,
            texture_color: dvec3(m.texture_color),
        }
    }

    /// Shade a fragment, with both gates written as explicit conditions.
    ///
    /// ```text
    /// DiffuseFactor = n · (−Direction)                       (n = normalize(normal))
    /// DiffuseFactor > 0:
    ///     diffuse = Color · DiffuseIntensity · DiffuseFactor
    ///     c = cos(angle(VertexToEye, normalize(reflect(Direction, n))))
    ///     c > 0: specular = Color · SpecularIntensity · c^SpecularPower
    /// FragColor = texture ⊙ (ambient + diffuse + specular)
    /// ```
    ///
    /// The `f32` shader takes `pow` before its `> 0` test; where the base is
    /// negative GLSL leaves `pow` undefined and lightlab (like llvmpipe) gets
    /// no highlight. Here the test comes first, which gives the same result
    /// without meeting the undefined case. A zero normal gives ambient only.
    pub fn terms(&self, world_pos: DVec3, normal: DVec3, eye_world_pos: DVec3) -> Terms {
        let n = normalize_or_zero(normal);
        let diffuse_factor = cos_between_scaled(n, -self.direction);
        let mut terms = Terms { ambient: self.color * self.texture_color * self.ambient_intensity, ..Terms::default() };
        if diffuse_factor > 0.0 {
            terms.diffuse = self.color * self.texture_color * (self.diffuse_intensity * diffuse_factor);
            let vertex_to_eye = normalize_or_zero(eye_world_pos - world_pos);
            let light_reflect = normalize_or_zero(reflect(self.direction, n));
            let c = cos_between_scaled(vertex_to_eye, light_reflect);
            let specular_factor = if c > 0.0 { pow_or_zero(c, self.specular_power) } else { 0.0 };
            if specular_factor > 0.0 {
                terms.specular = self.color * self.texture_color * (self.specular_intensity * specular_factor);
            }
        }
        terms
    }
}
