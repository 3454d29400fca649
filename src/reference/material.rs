//! Chapter 3, Materials, in `f64`.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `material.ambient/diffuse/specular` | reflectance per channel |
//! | `material.shininess` | Phong exponent |
//! | `light.ambient/diffuse/specular` | light intensity per term and channel |
//!
//! Source: LearnOpenGL, Materials.

use glam::DVec3;

use super::color::modulate;
use super::dvec3;
use super::phong::{diffuse_factor, specular_factor, Specular, Terms};

/// The surface's reflectances and exponent, in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Ambient reflectance.
    pub ambient: DVec3,
    /// Diffuse reflectance.
    pub diffuse: DVec3,
    /// Specular reflectance.
    pub specular: DVec3,
    /// Specular exponent.
    pub shininess: f64,
}

impl Material {
    /// Widen an `f32` material exactly.
    pub fn from_f32(m: &crate::material::Material) -> Self {
        Material {
            ambient: dvec3(m.ambient),
            diffuse: dvec3(m.diffuse),
            specular: dvec3(m.specular),
            shininess: m.shininess as f64,
        }
    }
}

/// A light's intensity per term, in `f64`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightProps {
    /// Ambient intensity.
    pub ambient: DVec3,
    /// Diffuse intensity.
    pub diffuse: DVec3,
    /// Specular intensity.
    pub specular: DVec3,
}

impl LightProps {
    /// Widen `f32` light properties exactly.
    pub fn from_f32(p: &crate::material::LightProps) -> Self {
        LightProps { ambient: dvec3(p.ambient), diffuse: dvec3(p.diffuse), specular: dvec3(p.specular) }
    }
}

/// The Materials chapter's three terms.
///
/// ```text
/// ambient  = light.ambient ⊙ material.ambient
/// diffuse  = light.diffuse ⊙ material.diffuse · diff
/// specular = light.specular ⊙ material.specular · spec
/// ```
///
/// Unit `n`, `light_dir`, `view_dir`, pointing away from the surface;
/// degenerate results as [`diffuse_factor`] and
/// [`phong_specular_factor`](super::phong::phong_specular_factor).
///
/// Source: LearnOpenGL, Materials.
pub fn material_terms(material: &Material, light: &LightProps, n: DVec3, light_dir: DVec3, view_dir: DVec3) -> Terms {
    material_terms_with(Specular::Phong, material, light, n, light_dir, view_dir)
}

/// [`material_terms`] with a choice of specular lobe.
pub fn material_terms_with(
    specular: Specular,
    material: &Material,
    light: &LightProps,
    n: DVec3,
    light_dir: DVec3,
    view_dir: DVec3,
) -> Terms {
    let diff = diffuse_factor(n, light_dir);
    let spec = specular_factor(specular, n, light_dir, view_dir, material.shininess);
    Terms {
        ambient: modulate(light.ambient, material.ambient),
        diffuse: modulate(light.diffuse, material.diffuse) * diff,
        specular: modulate(light.specular, material.specular) * spec,
    }
}
