//! Fragment stages and shading modes: flat, Gouraud, Phong and Blinn-Phong.
//!
//! | mode | lighting evaluated | interpolated |
//! | --- | --- | --- |
//! | `Flat` | once per triangle, face normal at the centroid | nothing (constant color) |
//! | `Gouraud` | per vertex | the color |
//! | `Phong` | per fragment, `reflect` lobe | position, normal (renormalized), uv |
//! | `BlinnPhong` | per fragment, half-vector lobe | position, normal (renormalized), uv |
//!
//! Every mode evaluates the same light sum ([`crate::scene::Scene`]) through
//! the 16-lane [`MultiLightKernel`]; the material is constant or sampled from
//! lighting maps at the interpolated uv (bilinear, repeat), with emission
//! added unlit.
//!
//! Sources: Gouraud 1971; Phong 1975; Blinn 1977; LearnOpenGL, Basic
//! lighting (Gouraud exercise) and Lighting maps.

use glam::{Vec2, Vec3};

use super::kernel::{LaneMaterial, Lanes, MultiLightKernel, Specular, LANES};
use super::rasterize::{FragmentBatch, FragmentShader};
use crate::maps::{Filter, LightingMaps, Wrap};
use crate::material::Material;

crate::named::named_enum! {
    /// Where lighting is evaluated.
    pub enum ShadingMode {
        /// Once per triangle.
        Flat => "flat",
        /// Per vertex, colors interpolated.
        Gouraud => "gouraud",
        /// Per fragment, Phong lobe.
        Phong => "phong",
        /// Per fragment, Blinn-Phong lobe.
        BlinnPhong => "blinn-phong",
    }
}

impl ShadingMode {
    /// The specular lobe this mode uses (flat and Gouraud use Phong's, as the tutorials do).
    pub fn specular(self) -> Specular {
        if self == ShadingMode::BlinnPhong {
            Specular::Blinn
        } else {
            Specular::Phong
        }
    }
}

/// A surface's reflectances: one material, or lighting maps sampled at uv.
#[derive(Clone, Debug, PartialEq)]
pub enum Surface {
    /// The same material everywhere.
    Material(Material),
    /// Diffuse, specular (and emission) maps, sampled bilinear with repeat.
    Maps(LightingMaps),
    /// No lighting: this color (the lamp cubes).
    Unlit(Vec3),
}

impl Surface {
    /// The shininess the kernel uses.
    pub fn shininess(&self) -> f32 {
        match self {
            Surface::Material(m) => m.shininess,
            Surface::Maps(m) => m.shininess,
            Surface::Unlit(_) => 1.0,
        }
    }

    /// The material at `uv` (maps are sampled; unlit gives black reflectances).
    pub fn material_at(&self, uv: Vec2) -> Material {
        match self {
            Surface::Material(m) => *m,
            Surface::Maps(m) => m.material_at(uv, Filter::Bilinear, Wrap::Repeat),
            Surface::Unlit(_) => {
                Material { ambient: Vec3::ZERO, diffuse: Vec3::ZERO, specular: Vec3::ZERO, shininess: 1.0 }
            }
        }
    }

    /// Emitted light at `uv` (unlit surfaces emit their color).
    pub fn emission_at(&self, uv: Vec2) -> Vec3 {
        match self {
            Surface::Maps(m) => m.emission_at(uv, Filter::Bilinear, Wrap::Repeat),
            Surface::Unlit(c) => *c,
            Surface::Material(_) => Vec3::ZERO,
        }
    }
}

/// Passes varyings 0..3 through as RGB (Gouraud and flat: the color was computed per vertex).
#[derive(Clone, Copy, Debug, Default)]
pub struct ColorShader;

impl FragmentShader for ColorShader {
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
        out.copy_from_slice(&batch.varyings[..3]);
    }

    fn passes_varyings_through(&self) -> bool {
        true
    }
}

/// Per-fragment lighting: varyings are world position (0..3), normal (3..6) and uv (6..8).
#[derive(Clone, Debug)]
pub struct LitShader {
    kernel: MultiLightKernel,
    surface: Surface,
    uniform: LaneMaterial,
}

impl LitShader {
    /// A fragment stage for `surface` under the compiled lights.
    pub fn new(kernel: MultiLightKernel, surface: Surface) -> LitShader {
        let uniform = LaneMaterial::uniform(&surface.material_at(Vec2::ZERO));
        LitShader { kernel, surface, uniform }
    }
}

impl FragmentShader for LitShader {
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
        let v = &batch.varyings;
        // borrowed in place, not copied (a copy of six lanes' arrays per batch showed in profiles)
        let (Some(pos), Some(normal)) = (v.first_chunk::<3>(), v[3..].first_chunk::<3>()) else {
            return;
        };
        match &self.surface {
            Surface::Material(_) => self.kernel.shade(pos, normal, &self.uniform, out),
            Surface::Unlit(c) => {
                *out = [[c.x; LANES], [c.y; LANES], [c.z; LANES]];
            }
            Surface::Maps(_) => {
                let mut material = self.uniform;
                let mut emission = [[0.0; LANES]; 3];
                for l in 0..batch.len {
                    let uv = Vec2::new(v[6][l], v[7][l]);
                    material.set(l, &self.surface.material_at(uv));
                    let e = self.surface.emission_at(uv);
                    for c in 0..3 {
                        emission[c][l] = e[c];
                    }
                }
                self.kernel.shade(pos, normal, &material, out);
                for c in 0..3 {
                    for l in 0..LANES {
                        out[c][l] += emission[c][l];
                    }
                }
            }
        }
    }
}
