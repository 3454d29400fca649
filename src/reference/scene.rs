//! Chapter 6, Multiple lights, in `f64`: the sum over a directional light,
//! point lights and a spot.
//!
//! Source: LearnOpenGL, Multiple lights. The light tag [`LightId`] is shared
//! with [`crate::scene`].

use crate::reference::casters::LocalLight as _;
use glam::DVec3;

use super::casters::{DirLight, PointLight, SpotLight};
use super::glsl::normalize_or_zero;
use super::material::Material;
use super::phong::{Specular, Terms};
pub use crate::scene::LightId;

/// A scene of lights in `f64`.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// Optional directional light.
    pub dir_light: Option<DirLight>,
    /// Point lights.
    pub point_lights: Vec<PointLight>,
    /// Optional spot light.
    pub spot_light: Option<SpotLight>,
}

/// Per-light terms at one fragment, in shader order.
#[derive(Clone, Debug, PartialEq)]
pub struct Shaded {
    /// `(light, terms)` for dir, points, spot.
    pub lights: Vec<(LightId, Terms)>,
}

impl Shaded {
    /// The unclamped sum, accumulated term by term.
    pub fn rgb(&self) -> DVec3 {
        let mut total = DVec3::ZERO;
        for (_, t) in &self.lights {
            total += t.ambient;
            total += t.diffuse;
            total += t.specular;
        }
        total
    }
}

impl Scene {
    /// Widen an `f32` scene exactly.
    pub fn from_f32(s: &crate::scene::Scene) -> Self {
        Scene {
            dir_light: s.dir_light.as_ref().map(DirLight::from_f32),
            point_lights: s.point_lights.iter().map(PointLight::from_f32).collect(),
            spot_light: s.spot_light.as_ref().map(SpotLight::from_f32),
        }
    }

    /// Shade a fragment.
    ///
    /// ```text
    /// norm = normalize(normal); view_dir = normalize(view_pos − frag_pos)
    /// result = CalcDirLight + Σ CalcPointLight + CalcSpotLight
    /// ```
    ///
    /// A zero normal or a fragment at the eye gives ambient-only terms.
    pub fn shade(&self, material: &Material, frag_pos: DVec3, normal: DVec3, view_pos: DVec3) -> Shaded {
        self.shade_with(Specular::Phong, material, frag_pos, normal, view_pos)
    }

    /// [`Self::shade`] with a choice of specular lobe for every light.
    pub fn shade_with(
        &self,
        specular: Specular,
        material: &Material,
        frag_pos: DVec3,
        normal: DVec3,
        view_pos: DVec3,
    ) -> Shaded {
        let norm = normalize_or_zero(normal);
        let view_dir = normalize_or_zero(view_pos - frag_pos);
        let mut lights = Vec::new();
        if let Some(d) = &self.dir_light {
            lights.push((LightId::Dir, d.terms_with(specular, material, norm, view_dir)));
        }
        for (i, p) in self.point_lights.iter().enumerate() {
            lights.push((LightId::Point(i), p.terms_with(specular, material, norm, frag_pos, view_dir)));
        }
        if let Some(s) = &self.spot_light {
            lights.push((LightId::Spot, s.terms_with(specular, material, norm, frag_pos, view_dir)));
        }
        Shaded { lights }
    }
}
