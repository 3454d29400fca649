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
//! lighting maps at the interpolated uv (with the surface's [`Sampler`]: GL_LINEAR
//! or GL_NEAREST, GL_REPEAT or GL_CLAMP_TO_EDGE), with emission added unlit.
//! A [`Surface::Tutorial`] is the exception: one of the other tutorials' whole
//! single-light shaders ([`TutorialModel`]), evaluated point by point with the same
//! interpolated position and normal, in place of the kernel and the world's lights.
//!
//! Sources: Gouraud 1971; Phong 1975; Blinn 1977; LearnOpenGL, Basic
//! lighting (Gouraud exercise) and Lighting maps; opengl-tutorial 8; ogldev 19.

use glam::{Vec2, Vec3};

use super::kernel::{LaneMaterial, Lanes, MultiLightKernel, Specular, LANES};
use super::rasterize::{FragmentBatch, FragmentShader};
use crate::maps::{LightingMaps, Sampler};
use crate::material::Material;
use crate::models::{Ogldev, OpenGLTutorial};

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
    /// Diffuse, specular (and emission) maps, sampled as the [`Sampler`] says (the
    /// tutorials' `GL_LINEAR` with `GL_REPEAT` is [`Sampler::LINEAR_REPEAT`]).
    Maps(LightingMaps, Sampler),
    /// No lighting: this color (the lamp cubes).
    Unlit(Vec3),
    /// Shaded by one of the other tutorials' shaders, which carries its own light and
    /// reflectances; the world's lights are not used.
    Tutorial(TutorialModel),
}

/// The single-light shader of opengl-tutorial 8 or ogldev 19 ([`crate::models`]), as a
/// raster surface: each point is shaded by the model's own `terms`, in world space, with
/// the eye at the camera (both tutorials' shaders take the eye as an input; the view is
/// rigid, so opengl-tutorial's camera space gives the same vectors up to rounding).
///
/// ```text
/// color(p, n) = ambient + diffuse + specular  of  model.terms(p, n, eye)
/// ```
///
/// `n` is the interpolated normal, not renormalized: both models normalize it (a zero
/// normal gives ambient only). Sources: opengl-tutorial 8, "Basic shading"; ogldev 19,
/// "Specular lighting".
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TutorialModel {
    /// opengl-tutorial 8: one point light, `LightPower / d²`, `clamp(E·R, 0, 1)^5`.
    OpenGLTutorial(OpenGLTutorial),
    /// ogldev 19: one directional light, specular only where `n·l > 0`.
    Ogldev(Ogldev),
}

impl TutorialModel {
    /// The color at world position `frag_pos` with normal `normal` seen from `eye`
    /// (see [`TutorialModel`]); unclamped, as the shaders return it.
    pub fn shade(&self, frag_pos: Vec3, normal: Vec3, eye: Vec3) -> Vec3 {
        match self {
            TutorialModel::OpenGLTutorial(m) => m.terms(frag_pos, normal, eye).sum(),
            TutorialModel::Ogldev(m) => m.terms(frag_pos, normal, eye).sum(),
        }
    }

    /// The model's specular exponent (opengl-tutorial's 5, ogldev's `gSpecularPower`).
    pub fn exponent(&self) -> f32 {
        match self {
            TutorialModel::OpenGLTutorial(m) => m.exponent,
            TutorialModel::Ogldev(m) => m.specular_power,
        }
    }
}

impl Surface {
    /// The shininess the kernel uses (a tutorial model's own exponent).
    pub fn shininess(&self) -> f32 {
        match self {
            Surface::Material(m) => m.shininess,
            Surface::Maps(m, _) => m.shininess,
            Surface::Unlit(_) => 1.0,
            Surface::Tutorial(t) => t.exponent(),
        }
    }

    /// The material at `uv` the kernel uses (maps are sampled; unlit and tutorial
    /// surfaces give black reflectances: the kernel does not light them).
    pub fn material_at(&self, uv: Vec2) -> Material {
        match self {
            Surface::Material(m) => *m,
            Surface::Maps(m, s) => m.material_at(uv, s.filter, s.wrap),
            Surface::Unlit(_) | Surface::Tutorial(_) => {
                Material { ambient: Vec3::ZERO, diffuse: Vec3::ZERO, specular: Vec3::ZERO, shininess: 1.0 }
            }
        }
    }

    /// Emitted light at `uv` (unlit surfaces emit their color).
    pub fn emission_at(&self, uv: Vec2) -> Vec3 {
        match self {
            Surface::Maps(m, s) => m.emission_at(uv, s.filter, s.wrap),
            Surface::Unlit(c) => *c,
            Surface::Material(_) | Surface::Tutorial(_) => Vec3::ZERO,
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
        LitShader { kernel: with_surface_material(kernel, &surface), surface, uniform }
    }

    /// The material of a surface without textures, as the kernel is given it: the kernel's
    /// own copy when it was told one, which lets it use the folded lights.
    fn plain_material(&self) -> &LaneMaterial {
        self.kernel.material_lanes().unwrap_or(&self.uniform)
    }
}

/// `kernel` told the material of `surface` when it is the same at every point (a plain
/// material, no texture), so that coloured lights can be summed with it folded in
/// ([`MultiLightKernel::with_material`]); otherwise `kernel` as it is.
pub fn with_surface_material(kernel: MultiLightKernel, surface: &Surface) -> MultiLightKernel {
    match surface {
        Surface::Material(_) => kernel.with_material(&surface.material_at(Vec2::ZERO)),
        _ => kernel,
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
            Surface::Material(_) => self.kernel.shade(pos, normal, self.plain_material(), out),
            Surface::Unlit(c) => {
                *out = [[c.x; LANES], [c.y; LANES], [c.z; LANES]];
            }
            Surface::Tutorial(model) => {
                let eye = self.kernel.view_pos();
                for l in 0..batch.len {
                    let p = Vec3::new(pos[0][l], pos[1][l], pos[2][l]);
                    let n = Vec3::new(normal[0][l], normal[1][l], normal[2][l]);
                    let c = model.shade(p, n, eye);
                    for (channel, value) in out.iter_mut().zip(c.to_array()) {
                        channel[l] = value;
                    }
                }
            }
            Surface::Maps(..) => {
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

    /// The kernel's [`MultiLightKernel::shade_batches`] for a uniform material (one
    /// dispatch per call); [`FragmentShader::shade`] on each batch otherwise.
    fn shade_batches(&self, batches: &[FragmentBatch], out: &mut [[Lanes; 3]]) {
        match &self.surface {
            Surface::Material(_) => self.kernel.shade_batches(batches, self.plain_material(), out),
            _ => {
                for (batch, out) in batches.iter().zip(out) {
                    self.shade(batch, out);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::maps::{Filter, Texture, Wrap};

    /// A 4 × 2 map whose texel (i, j) holds (i, j, 0) / 8, so a sample names its texel.
    fn numbered_maps() -> LightingMaps {
        let t = Texture::from_fn(4, 2, |i, j| Vec3::new(i as f32, j as f32, 0.0) / 8.0).unwrap();
        LightingMaps { diffuse: t.clone(), specular: t.clone(), emission: Some(t), shininess: 32.0 }
    }

    /// The texel `(i, j)` of [`numbered_maps`].
    fn texel(i: f32, j: f32) -> Vec3 {
        Vec3::new(i, j, 0.0) / 8.0
    }

    #[test]
    fn nearest_maps_pick_the_texel_floor_uv_times_size_by_hand() {
        let nearest = Surface::Maps(numbered_maps(), Sampler::NEAREST_REPEAT);
        // (uv, texel by hand: i = floor(4u) mod 4, j = floor(2v) mod 2)
        let cases = [
            (Vec2::new(0.1, 0.1), texel(0.0, 0.0)),
            (Vec2::new(0.3, 0.7), texel(1.0, 1.0)),
            // on a texel boundary: u·w = 2 exactly belongs to texel 2, v·h = 1 to row 1
            (Vec2::new(0.5, 0.5), texel(2.0, 1.0)),
            // just below the boundary: still texel 1, row 0
            (Vec2::new(0.5 - 1e-6, 0.5 - 1e-6), texel(1.0, 0.0)),
            // GL_REPEAT: u = 1 is texel 0 again; u = −0.1 is floor(−0.4) = −1 → texel 3
            (Vec2::new(1.0, 0.2), texel(0.0, 0.0)),
            (Vec2::new(-0.1, -0.1), texel(3.0, 1.0)),
        ];
        for (uv, want) in cases {
            let m = nearest.material_at(uv);
            assert_eq!((m.diffuse, m.specular, nearest.emission_at(uv)), (want, want, want), "uv {uv}");
        }
        // the same surface with clamp to edge: u = −0.1 clamps to texel 0, u = 1 to texel 3
        let clamped = Surface::Maps(numbered_maps(), Sampler { filter: Filter::Nearest, wrap: Wrap::ClampToEdge });
        assert_eq!(clamped.material_at(Vec2::new(-0.1, 0.1)).diffuse, texel(0.0, 0.0));
        assert_eq!(clamped.material_at(Vec2::new(1.0, 0.9)).diffuse, texel(3.0, 1.0));
    }

    /// A tutorial surface is lit by its own model at the kernel's eye, whatever the world's
    /// lights: each point's color is the model's `terms(p, n, eye).sum()`, bit for bit.
    #[test]
    fn a_tutorial_surface_is_shaded_by_its_own_model_not_the_worlds_lights() {
        use crate::models::{ogldev_comparable, OpenGLTutorial};
        use crate::raster::pipeline::light_points;
        use crate::scene::Scene;
        let light_pos = Vec3::new(1.2, 1.0, 2.0);
        let eye = Vec3::new(-1.2, -0.8, 3.2);
        let points: Vec<(Vec3, Vec3, Vec2)> = (0..40)
            .map(|k| {
                let t = k as f32 * 0.37;
                (Vec3::new(t.sin() * 0.5, t.cos() * 0.5, 0.5), Vec3::new(t.cos(), t.sin(), 1.0 + t), Vec2::ZERO)
            })
            .collect();
        let models = [
            TutorialModel::OpenGLTutorial(OpenGLTutorial::with_defaults(light_pos, crate::color::CORAL)),
            TutorialModel::Ogldev(ogldev_comparable(light_pos)),
        ];
        for model in models {
            let surface = Surface::Tutorial(model);
            let want: Vec<Vec3> = points.iter().map(|&(p, n, _)| model.shade(p, n, eye)).collect();
            for lights in
                [Scene::learnopengl_default(), Scene { point_lights: Vec::new(), ..Scene::learnopengl_default() }]
            {
                let kernel = MultiLightKernel::new(&lights, eye, surface.shininess(), Specular::Phong);
                assert_eq!(light_points(&kernel, &surface, &points), want, "{model:?}");
            }
            // and the sum is not the kernel's black material: the model lights the points
            assert!(want.iter().any(|c| c.max_element() > 0.5), "{model:?}: {want:?}");
        }
    }

    #[test]
    fn linear_maps_still_blend_between_texel_centres() {
        // u·w − ½ = 1.5 lies halfway between texels 1 and 2; v·h − ½ = 0 is row 0's centre
        let linear = Surface::Maps(numbered_maps(), Sampler::LINEAR_REPEAT);
        let got = linear.material_at(Vec2::new(0.5, 0.25)).diffuse;
        assert!((got - texel(1.5, 0.0)).abs().max_element() < 1e-6, "{got}");
        let nearest = Surface::Maps(numbered_maps(), Sampler::NEAREST_REPEAT);
        assert_eq!(nearest.material_at(Vec2::new(0.5, 0.25)).diffuse, texel(2.0, 0.0));
    }
}
