//! Chapter 4, Lighting maps: diffuse, specular and emission textures.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `uv` | texture coordinates; (0, 0) is the first texel's corner, (1, 1) the last's |
//! | `texel` | one stored RGB value; texel `(i, j)` has its centre at `((i + ½)/w, (j + ½)/h)` |
//! | `diffuse_map` | per-texel diffuse (and ambient) reflectance |
//! | `specular_map` | per-texel specular reflectance |
//! | `emission_map` | light the surface emits, added unlit |
//!
//! Sampling follows OpenGL 3.3 §3.8.11: nearest picks `floor(u·w)`, bilinear
//! blends the four texels around `u·w − ½`. The container maps are generated
//! by code; no downloaded assets.

use glam::{Vec2, Vec3};

use crate::material::{LightProps, Material};
use crate::phong::Terms;

/// How coordinates outside [0, 1] are brought back in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wrap {
    /// `GL_REPEAT`: the fractional part.
    Repeat,
    /// `GL_CLAMP_TO_EDGE`: the nearest edge texel.
    ClampToEdge,
}

/// How a sample between texel centres is reconstructed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Filter {
    /// `GL_NEAREST`.
    Nearest,
    /// `GL_LINEAR`.
    Bilinear,
}

/// A sampler's state: the filter and the wrap mode, as `glTexParameteri` sets them
/// (`GL_TEXTURE_MIN_FILTER`/`GL_TEXTURE_MAG_FILTER` and `GL_TEXTURE_WRAP_S`/`_T`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sampler {
    /// Nearest or bilinear.
    pub filter: Filter,
    /// Repeat or clamp to edge (both axes).
    pub wrap: Wrap,
}

impl Sampler {
    /// `GL_LINEAR` with `GL_REPEAT`: the tutorials' container maps and the live figures'
    /// default.
    pub const LINEAR_REPEAT: Sampler = Sampler { filter: Filter::Bilinear, wrap: Wrap::Repeat };
    /// `GL_NEAREST` with `GL_REPEAT`: the lighting-maps figure's "nearest" option.
    pub const NEAREST_REPEAT: Sampler = Sampler { filter: Filter::Nearest, wrap: Wrap::Repeat };
}

/// Why a texture could not be made.
#[derive(Clone, Debug, PartialEq)]
pub struct TextureError(pub String);

impl std::fmt::Display for TextureError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for TextureError {}

/// The size check of every texture constructor (this one and the `f64` reference's):
/// both dimensions non-zero (else an error naming `size`) and `texel_count = width ×
/// height` (else an error naming `texels`).
pub(crate) fn check_texture_size(width: usize, height: usize, texel_count: usize) -> Result<(), TextureError> {
    if width == 0 || height == 0 {
        return Err(TextureError(format!("size: must be non-zero, got {width}x{height}")));
    }
    if texel_count != width * height {
        return Err(TextureError(format!(
            "texels: expected {} values for {width}x{height}, got {texel_count}",
            width * height
        )));
    }
    Ok(())
}

/// An RGB float texture, rows from `v = 0` upward (OpenGL's origin).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    width: usize,
    height: usize,
    texels: Vec<Vec3>,
}

impl Texture {
    /// A texture from `width × height` texels in row-major order.
    ///
    /// Errors: a zero dimension, or a texel count that is not `width × height`.
    pub fn new(width: usize, height: usize, texels: Vec<Vec3>) -> Result<Self, TextureError> {
        check_texture_size(width, height, texels.len())?;
        Ok(Texture { width, height, texels })
    }

    /// A texture computed texel by texel from `f(i, j)`.
    ///
    /// Errors: a zero dimension.
    pub fn from_fn(width: usize, height: usize, f: impl Fn(usize, usize) -> Vec3) -> Result<Self, TextureError> {
        let texels = (0..height).flat_map(|j| (0..width).map(move |i| (i, j))).map(|(i, j)| f(i, j)).collect();
        Texture::new(width, height, texels)
    }

    /// Width in texels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in texels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The texel at integer coordinates, wrapped.
    pub fn texel(&self, i: i64, j: i64, wrap: Wrap) -> Vec3 {
        let i = wrap_index(i, self.width, wrap);
        let j = wrap_index(j, self.height, wrap);
        self.texels[j * self.width + i]
    }

    /// Sample at `uv`.
    ///
    /// ```text
    /// nearest:  texel(floor(u·w), floor(v·h))
    /// bilinear: x = u·w − ½, y = v·h − ½, i = floor(x), fx = x − i (same for y)
    ///           mix(mix(t(i,j), t(i+1,j), fx), mix(t(i,j+1), t(i+1,j+1), fx), fy)
    /// ```
    ///
    /// Degenerate input: a NaN or infinite coordinate, or one whose product with
    /// the size overflows, is treated as 0.
    ///
    /// Source: OpenGL 3.3 §3.8.11; LearnOpenGL, Textures.
    // ANCHOR: sample
    pub fn sample(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> Vec3 {
        // Checked after scaling: a finite u near f32::MAX times the width overflows to ±∞.
        let finite = |c: f32| if c.is_finite() { c } else { 0.0 };
        let (x, y) = (finite(uv.x * self.width as f32), finite(uv.y * self.height as f32));
        match filter {
            Filter::Nearest => self.texel(x.floor() as i64, y.floor() as i64, wrap),
            Filter::Bilinear => {
                let (x, y) = (x - 0.5, y - 0.5);
                let (i, j) = (x.floor(), y.floor());
                let (fx, fy) = (x - i, y - j);
                // `as i64` saturates for huge coordinates; saturating_add keeps `+ 1` from overflowing.
                let (i, j) = (i as i64, j as i64);
                let (i1, j1) = (i.saturating_add(1), j.saturating_add(1));
                let bottom = self.texel(i, j, wrap).lerp(self.texel(i1, j, wrap), fx);
                let top = self.texel(i, j1, wrap).lerp(self.texel(i1, j1, wrap), fx);
                bottom.lerp(top, fy)
            }
        }
    }
    // ANCHOR_END: sample

    /// A texture with every texel mapped through `f` (for the chapter's exercises).
    pub fn map(&self, f: impl Fn(Vec3) -> Vec3) -> Texture {
        Texture { width: self.width, height: self.height, texels: self.texels.iter().map(|&t| f(t)).collect() }
    }
}

fn wrap_index(i: i64, n: usize, wrap: Wrap) -> usize {
    let n = n as i64;
    match wrap {
        Wrap::Repeat => i.rem_euclid(n) as usize,
        Wrap::ClampToEdge => i.clamp(0, n - 1) as usize,
    }
}

/// The three maps of the chapter's container, plus its shininess.
#[derive(Clone, Debug, PartialEq)]
pub struct LightingMaps {
    /// Diffuse (and ambient) reflectance map.
    pub diffuse: Texture,
    /// Specular reflectance map.
    pub specular: Texture,
    /// Optional emission map, added without lighting.
    pub emission: Option<Texture>,
    /// Specular exponent.
    pub shininess: f32,
}

impl LightingMaps {
    /// The material at `uv`: ambient = diffuse = the diffuse map's sample,
    /// specular = the specular map's sample.
    ///
    /// Source: LearnOpenGL, Lighting maps ("ambient equals diffuse").
    pub fn material_at(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> Material {
        let diffuse = self.diffuse.sample(uv, filter, wrap);
        Material {
            ambient: diffuse,
            diffuse,
            specular: self.specular.sample(uv, filter, wrap),
            shininess: self.shininess,
        }
    }

    /// The emission at `uv`, or black without an emission map.
    pub fn emission_at(&self, uv: Vec2, filter: Filter, wrap: Wrap) -> Vec3 {
        self.emission.as_ref().map_or(Vec3::ZERO, |e| e.sample(uv, filter, wrap))
    }

    /// The chapter's shader: material terms from the maps, plus emission.
    ///
    /// ```text
    /// ambient  = light.ambient  ⊙ diffuse_map(uv)
    /// diffuse  = light.diffuse  ⊙ diff · diffuse_map(uv)
    /// specular = light.specular ⊙ spec · specular_map(uv)
    /// color    = ambient + diffuse + specular + emission_map(uv)
    /// ```
    ///
    /// `n`, `light_dir`, `view_dir` unit length, pointing away from the surface.
    /// Returns the terms and the emission separately.
    ///
    /// Source: LearnOpenGL, Lighting maps.
    // ANCHOR: maps_shade
    pub fn shade(&self, light: &LightProps, uv: Vec2, n: Vec3, light_dir: Vec3, view_dir: Vec3) -> (Terms, Vec3) {
        let material = self.material_at(uv, Filter::Bilinear, Wrap::Repeat);
        let terms = crate::material::material_terms(&material, light, n, light_dir, view_dir);
        (terms, self.emission_at(uv, Filter::Bilinear, Wrap::Repeat))
    }
    // ANCHOR_END: maps_shade
}

/// The chapter's exercise "invert the specular map": `1 − specular`, so wood
/// shines and steel does not.
// ANCHOR: inverted
pub fn inverted(specular: &Texture) -> Texture {
    specular.map(|s| Vec3::ONE - s)
}
// ANCHOR_END: inverted

/// A deterministic hash of texel coordinates to [0, 1), for procedural maps.
fn hash01(i: usize, j: usize, seed: u32) -> f32 {
    let mut h = (i as u32).wrapping_mul(0x9E37_79B1) ^ (j as u32).wrapping_mul(0x85EB_CA77) ^ seed;
    h ^= h >> 15;
    h = h.wrapping_mul(0x2C1B_3C6D);
    h ^= h >> 12;
    h = h.wrapping_mul(0x297A_2D39);
    h ^= h >> 15;
    (h >> 8) as f32 / (1u32 << 24) as f32
}

/// Where a texel lies on the procedural container: in the steel frame or on wood.
fn on_steel_frame(i: usize, j: usize, size: usize) -> bool {
    let border = (size / 10).max(1);
    i < border || j < border || i >= size - border || j >= size - border
}

/// A procedural stand-in for the chapter's `container2.png`: wooden planks in
/// a steel frame, `size × size` texels.
///
/// Planks run along `u`, with a grain from a seeded hash (deterministic).
/// Errors: `size < 4`.
pub fn container_diffuse(size: usize) -> Result<Texture, TextureError> {
    container_map(
        size,
        |i, j| Vec3::splat(0.35 + 0.1 * hash01(i, j, 7)),
        |i, j| {
            let plank = j * 5 / size;
            let grain = 0.85 + 0.15 * hash01(i / 3, j, 11 + plank as u32);
            let seam = if (j * 5) % size < 5 { 0.6 } else { 1.0 };
            Vec3::new(0.55, 0.33, 0.12) * grain * seam
        },
    )
}

/// A procedural stand-in for `container2_specular.png`: the steel frame shines
/// (0.8 with a little noise), the wood barely (0.05).
///
/// Errors: `size < 4`.
pub fn container_specular(size: usize) -> Result<Texture, TextureError> {
    container_map(size, |i, j| Vec3::splat(0.7 + 0.2 * hash01(i, j, 3)), |_, _| Vec3::splat(0.05))
}

/// A procedural emission map for the chapter's exercise: green glyph strokes
/// on the wood, black on the frame (the frame does not glow).
///
/// Errors: `size < 4`.
pub fn container_emission(size: usize) -> Result<Texture, TextureError> {
    container_map(
        size,
        |_, _| Vec3::ZERO,
        |i, j| {
            let column_lit = hash01(i / 2, 0, 5) > 0.6;
            let stroke = hash01(i / 2, j / 3, 9) > 0.55;
            if column_lit && stroke {
                Vec3::new(0.1, 0.9, 0.3)
            } else {
                Vec3::ZERO
            }
        },
    )
}

/// A colored specular map for the chapter's exercise: the frame's highlight tinted.
///
/// Errors: `size < 4`.
pub fn container_colored_specular(size: usize, tint: Vec3) -> Result<Texture, TextureError> {
    Ok(container_specular(size)?.map(|s| s * tint))
}

/// A `size × size` container map: `frame(i, j)` on the steel frame
/// ([`on_steel_frame`]), `wood(i, j)` inside it. Errors: `size < 4`.
fn container_map(
    size: usize,
    frame: impl Fn(usize, usize) -> Vec3,
    wood: impl Fn(usize, usize) -> Vec3,
) -> Result<Texture, TextureError> {
    if size < 4 {
        return Err(TextureError(format!("size: must be at least 4 texels, got {size}")));
    }
    Texture::from_fn(size, size, |i, j| if on_steel_frame(i, j, size) { frame(i, j) } else { wood(i, j) })
}

/// The chapter's container: procedural diffuse and specular maps, shininess 32
/// (LearnOpenGL, Lighting maps, `material.shininess = 32.0`), with or without emission.
///
/// Errors: `size < 4`.
pub fn container(size: usize, with_emission: bool) -> Result<LightingMaps, TextureError> {
    Ok(LightingMaps {
        diffuse: container_diffuse(size)?,
        specular: container_specular(size)?,
        emission: if with_emission { Some(container_emission(size)?) } else { None },
        shininess: 32.0,
    })
}
