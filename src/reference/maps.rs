//! Chapter 4, Lighting maps, in `f64`: texture sampling on `f64` texels.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `(i, j)` | texel column and row; centre at `((i + ½)/w, (j + ½)/h)` |
//! | `x, y` | `u·w − ½`, `v·h − ½`: coordinates in texel-centre units |
//! | `fx, fy` | fractional parts of `x`, `y`: the bilinear weights |
//!
//! Source: OpenGL 3.3 §3.8.11; LearnOpenGL, Lighting maps. The filter and
//! wrap tags and the error type are shared with [`crate::maps`].

use glam::{DVec2, DVec3};

use super::material::{LightProps, Material};
use super::phong::Terms;
use crate::maps::{Filter, TextureError, Wrap};

/// An RGB `f64` texture, rows from `v = 0` upward.
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: usize,
    height: usize,
    texels: Vec<DVec3>,
}

impl Texture {
    /// A texture from `width × height` texels, row-major.
    ///
    /// Errors: a zero dimension (message names `size`), or a texel count that
    /// is not `width × height` (names `texels`).
    pub fn new(width: usize, height: usize, texels: Vec<DVec3>) -> Result<Self, TextureError> {
        crate::maps::check_texture_size(width, height, texels.len())?;
        Ok(Texture { width, height, texels })
    }

    /// Widen an `f32` texture exactly, texel by texel.
    pub fn from_f32(t: &crate::maps::Texture) -> Self {
        let (w, h) = (t.width(), t.height());
        let texels = (0..h)
            .flat_map(|j| (0..w).map(move |i| (i, j)))
            .map(|(i, j)| super::dvec3(t.texel(i as i64, j as i64, Wrap::ClampToEdge)))
            .collect();
        Texture { width: w, height: h, texels }
    }

    /// Width in texels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The texel at integer coordinates after wrapping.
    ///
    /// ```text
    /// Repeat:      i mod n (Euclidean, in [0, n))
    /// ClampToEdge: min(max(i, 0), n − 1)
    /// ```
    pub fn texel(&self, i: i64, j: i64, wrap: Wrap) -> DVec3 {
        let (i, j) = (wrap_coord(i, self.width, wrap), wrap_coord(j, self.height, wrap));
        self.texels[j * self.width + i]
    }

    /// Sample at `uv`.
    ///
    /// ```text
    /// nearest:  texel(⌊u·w⌋, ⌊v·h⌋)
    /// bilinear: Σ over the four neighbours of weights
    ///           (1−fx)(1−fy) t00 + fx(1−fy) t10 + (1−fx)fy t01 + fx fy t11
    /// ```
    ///
    /// The bilinear weights are non-negative and sum to 1, so each channel
    /// lies between the four texels' min and max. Degenerate input: a
    /// coordinate that is non-finite, or overflows when scaled by the size, counts as 0.
    pub fn sample(&self, uv: DVec2, filter: Filter, wrap: Wrap) -> DVec3 {
        let finite = |c: f64| if c.is_finite() { c } else { 0.0 };
        let x = finite(uv.x * self.width as f64);
        let y = finite(uv.y * self.height as f64);
        match filter {
            Filter::Nearest => self.texel(x.floor() as i64, y.floor() as i64, wrap),
            Filter::Bilinear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (i0, j0) = (x.floor(), y.floor());
                let (fx, fy) = (x - i0, y - j0);
                let (i, j) = (i0 as i64, j0 as i64);
                let (i1, j1) = (i.saturating_add(1), j.saturating_add(1));
                self.texel(i, j, wrap) * ((1.0 - fx) * (1.0 - fy))
                    + self.texel(i1, j, wrap) * (fx * (1.0 - fy))
                    + self.texel(i, j1, wrap) * ((1.0 - fx) * fy)
                    + self.texel(i1, j1, wrap) * (fx * fy)
            }
        }
    }
}

fn wrap_coord(i: i64, n: usize, wrap: Wrap) -> usize {
    let n = n as i64;
    match wrap {
        Wrap::Repeat => i.rem_euclid(n) as usize,
        Wrap::ClampToEdge => i.max(0).min(n - 1) as usize,
    }
}

/// The chapter's maps in `f64`.
#[derive(Clone, Debug, PartialEq)]
pub struct LightingMaps {
    /// Diffuse (and ambient) map.
    pub diffuse: Texture,
    /// Specular map.
    pub specular: Texture,
    /// Optional emission map.
    pub emission: Option<Texture>,
    /// Specular exponent.
    pub shininess: f64,
}

impl LightingMaps {
    /// Widen `f32` maps exactly.
    pub fn from_f32(m: &crate::maps::LightingMaps) -> Self {
        LightingMaps {
            diffuse: Texture::from_f32(&m.diffuse),
            specular: Texture::from_f32(&m.specular),
            emission: m.emission.as_ref().map(Texture::from_f32),
            shininess: m.shininess as f64,
        }
    }

    /// The chapter's shader at `uv` (bilinear, repeat): ambient and diffuse
    /// reflectance from the diffuse map, specular from the specular map, and
    /// the emission (zero without a map) returned separately.
    ///
    /// Unit `n`, `light_dir`, `view_dir`. Source: LearnOpenGL, Lighting maps.
    pub fn shade(&self, light: &LightProps, uv: DVec2, n: DVec3, light_dir: DVec3, view_dir: DVec3) -> (Terms, DVec3) {
        let d = self.diffuse.sample(uv, Filter::Bilinear, Wrap::Repeat);
        let material = Material {
            ambient: d,
            diffuse: d,
            specular: self.specular.sample(uv, Filter::Bilinear, Wrap::Repeat),
            shininess: self.shininess,
        };
        let emission = self.emission.as_ref().map_or(DVec3::ZERO, |e| e.sample(uv, Filter::Bilinear, Wrap::Repeat));
        (super::material::material_terms(&material, light, n, light_dir, view_dir), emission)
    }
}
