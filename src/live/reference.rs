//! Reference images for `?selftest`: the CPU raster's render of a figure's state, with
//! the pixels to compare marked in the alpha channel.
//!
//! The PNG holds the panels side by side, each `width × height`, top row first. Alpha
//! is 255 where the page must match and 0 where it need not (its color is still there):
//!
//! - **silhouettes and creases**: a pixel is compared only when it and its eight
//!   neighbours see the same *surface piece* in an id render of the same world. A piece
//!   is one object's smooth part, or one flat face of it (a set of triangles whose three
//!   vertex normals are equal and the same), so the cube's edges count as creases.
//!   There, which triangle owns a pixel depends on sub-pixel rounding that the GPU and
//!   this raster do differently (both snap to 1/256 px, from differently rounded
//!   transforms), and the two sides of an edge shade differently.
//!
//! Everything else is compared; see [`super::Tolerance`] for the bound. With the PNG
//! comes the number of compared pixels that an object covers ([`Reference::covered`]):
//! the page's allowance of pixels above the bound is a share of those, not of the
//! background around them.

use std::collections::BTreeMap;

use glam::{IVec3, Vec3, Vec4};

use super::LiveError;
use crate::raster::framebuffer::Framebuffer;
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::{Geometry, Object, World};
use crate::raster::shade::{ShadingMode, Surface};

/// Split an object's mesh into pieces (see the module docs), each as its own object.
fn pieces(object: &Object) -> Vec<Object> {
    let Geometry::Mesh(mesh) = &object.geometry else {
        return vec![object.clone()];
    };
    let key = |v: Vec3| (v * 4096.0).round().as_ivec3();
    // key: the shared normal of a flat face, or None for the smooth part
    type FaceKey = Option<(i32, i32, i32)>;
    let mut groups: BTreeMap<FaceKey, Vec<[u32; 3]>> = BTreeMap::new();
    for t in &mesh.triangles {
        let n = t.map(|i| mesh.normals.get(i as usize).copied().map(key).unwrap_or(IVec3::ZERO));
        let flat = (n[0] == n[1] && n[1] == n[2]).then(|| (n[0].x, n[0].y, n[0].z));
        groups.entry(flat).or_default().push(*t);
    }
    groups
        .into_values()
        .map(|triangles| Object {
            geometry: Geometry::Mesh(Mesh { triangles, ..mesh.clone() }),
            model: object.model,
            surface: object.surface.clone(),
            cull: object.cull,
        })
        .collect()
}

/// The id of piece `k` as an unlit color (k + 1; 0 is the background).
fn id_color(k: usize) -> Vec3 {
    let k = k + 1;
    Vec3::new((k & 255) as f32, ((k >> 8) & 255) as f32, ((k >> 16) & 255) as f32) / 255.0
}

/// A framebuffer allocation error, as a [`LiveError`].
fn framebuffer(e: impl std::fmt::Display) -> LiveError {
    LiveError::Asset { what: "the reference framebuffer", detail: e.to_string() }
}

/// One world's render and where to look at it, each mask top row first.
pub struct Rendered {
    /// The render.
    pub fb: Framebuffer,
    /// `true` where the page must match (see the module docs).
    pub compare: Vec<bool>,
    /// `true` where some object covers the pixel (the id render is not background).
    pub covered: Vec<bool>,
}

/// Render one world, its comparison mask and its coverage.
pub fn render_with_mask(world: &World, width: u32, height: u32) -> Result<Rendered, LiveError> {
    let mut fb = Framebuffer::new(width, height).map_err(framebuffer)?;
    world.render(&mut fb);
    let mut ids = world.clone();
    ids.shading = ShadingMode::Phong;
    ids.clear = Vec4::ZERO;
    ids.objects = world.objects.iter().flat_map(pieces).collect();
    for (k, o) in ids.objects.iter_mut().enumerate() {
        o.surface = Surface::Unlit(id_color(k));
    }
    let mut id_fb = Framebuffer::new(width, height).map_err(framebuffer)?;
    ids.render(&mut id_fb);
    let id = id_fb.to_rgba8(false);
    let (w, h) = (width as i64, height as i64);
    let at = |x: i64, y: i64| {
        let k = 4 * (y * w + x) as usize;
        [id[k], id[k + 1], id[k + 2]]
    };
    let mut mask = vec![false; (w * h) as usize];
    for y in 0..h {
        for x in 0..w {
            let me = at(x, y);
            let same = (-1..=1).all(|dy| {
                (-1..=1).all(|dx| {
                    let (nx, ny) = (x + dx, y + dy);
                    !(0..w).contains(&nx) || !(0..h).contains(&ny) || at(nx, ny) == me
                })
            });
            mask[(y * w + x) as usize] = same;
        }
    }
    let covered = (0..(w * h) as usize).map(|k| id[4 * k..4 * k + 3] != [0, 0, 0]).collect();
    Ok(Rendered { fb, compare: mask, covered })
}

/// A reference image and the count the page's allowance is taken over.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The PNG: the panels side by side, alpha = the comparison mask.
    pub png: Vec<u8>,
    /// Compared pixels (alpha 255) that some object covers (not the clear color).
    pub covered: usize,
}

/// The reference of `worlds` (one panel each, side by side): the PNG with alpha = mask,
/// and the number of compared pixels the objects cover.
pub fn reference(worlds: &[World], width: u32, height: u32) -> Result<Reference, LiveError> {
    let total_w = width * worlds.len() as u32;
    let mut rgba = vec![0u8; (total_w * height * 4) as usize];
    let mut covered = 0;
    for (p, world) in worlds.iter().enumerate() {
        let Rendered { fb, compare: mask, covered: cover } = render_with_mask(world, width, height)?;
        let bytes = fb.to_rgba8(false);
        for y in 0..height {
            for x in 0..width {
                let src = (y * width + x) as usize;
                let dst = 4 * (y * total_w + p as u32 * width + x) as usize;
                rgba[dst..dst + 3].copy_from_slice(&bytes[4 * src..4 * src + 3]);
                rgba[dst + 3] = if mask[src] { 255 } else { 0 };
                covered += usize::from(mask[src] && cover[src]);
            }
        }
    }
    let img = image::RgbaImage::from_raw(total_w, height, rgba)
        .ok_or_else(|| LiveError::Png("the image size does not match its pixels".into()))?;
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png).map_err(|e| LiveError::Png(e.to_string()))?;
    Ok(Reference { png: out.into_inner(), covered })
}

/// A difference a reader sees at a glance, levels of 255 per channel: our choice, about 6 %
/// of full scale and eight times the 2-level steps of an 8-bit gradient a viewer can just tell.
#[cfg(test)]
pub(crate) const PLAIN_LEVELS: u8 = 16;

/// A plain difference covers at least 1 % of a panel (768 of 320 × 240 pixels, a 28 × 28
/// patch): our bar for "the reader sees it", not a measured threshold.
#[cfg(test)]
pub(crate) fn plain_share(size: (u32, u32)) -> usize {
    (size.0 * size.1 / 100) as usize
}

/// How many pixels of `a` and `b`, rendered at `width × height`, differ plainly:
///
/// ```text
/// d(p) = max_c |a_c(p) − b_c(p)|  (levels);   count = #{p : d(p) ≥ PLAIN_LEVELS}
/// ```
///
/// A figure that means to show a difference asks this of its two sides in a test.
#[cfg(test)]
pub(crate) fn plainly_different_pixels(a: &World, b: &World, width: u32, height: u32) -> Result<usize, LiveError> {
    let render = |w: &World| -> Result<Vec<u8>, LiveError> {
        let mut fb = Framebuffer::new(width, height).map_err(framebuffer)?;
        w.render(&mut fb);
        Ok(fb.to_rgba8(false))
    };
    let (pa, pb) = (render(a)?, render(b)?);
    let plain = |(x, y): (&[u8], &[u8])| (0..3).any(|c| x[c].abs_diff(y[c]) >= PLAIN_LEVELS);
    Ok(pa.chunks_exact(4).zip(pb.chunks_exact(4)).filter(|&p| plain(p)).count())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::camera::Camera;
    use crate::raster::rasterize::CullMode;
    use crate::scene::Scene;
    use glam::Mat4;

    #[test]
    fn mask_drops_silhouettes_and_cube_creases_only() {
        let cube = Object {
            geometry: Geometry::Mesh(Mesh::learnopengl_cube()),
            model: Mat4::from_rotation_y(0.6) * Mat4::from_rotation_x(0.4),
            surface: Surface::Unlit(Vec3::ONE),
            cull: CullMode::None,
        };
        assert_eq!(pieces(&cube).len(), 6);
        let world = World {
            camera: Camera::learnopengl(1.0),
            lights: Scene { dir_light: None, point_lights: vec![], spot_light: None, clear_color: Vec3::ZERO },
            objects: vec![cube],
            shading: ShadingMode::Phong,
            clear: Vec4::ZERO,
            depth_test: true,
            range_window: None,
            specialisations: crate::raster::kernel::Specialisations::ALL,
        };
        let Rendered { fb, compare: mask, covered: cover } = render_with_mask(&world, 64, 64).unwrap();
        let covered = fb.covered();
        assert_eq!(cover.iter().filter(|&&c| c).count(), covered, "the id render covers what the render covers");
        let compared_covered = fb.color.iter().zip(&mask).filter(|(c, &m)| c[3] > 0.0 && m).count();
        assert_eq!(reference(std::slice::from_ref(&world), 64, 64).unwrap().covered, compared_covered);
        // some covered pixels are compared, some (edges) are not; background far away is compared
        assert!(compared_covered > covered / 2 && compared_covered < covered, "{compared_covered} of {covered}");
        assert!(mask[0]);
    }
}
