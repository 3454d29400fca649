//! Meshes and textures the live figures draw, by name, and their encoding for the page.
//!
//! Arrays go to the page as base64 of little-endian `f32` (positions, normals, uvs,
//! texels) or `u32` (indices), so the browser gets the crate's exact bits. Each asset is
//! one classic script `generated/live/asset-<name>.js` that registers itself in
//! `window.LIGHTLAB_ASSETS` (classic scripts, not modules: pages opened from disk may not
//! load modules).

use glam::Vec3;

use super::LiveError;
use crate::maps::{LightingMaps, Texture, Wrap};
use crate::raster::mesh::Mesh;

/// The size of the container maps in the live figures (texels per side).
///
/// Smaller than the static renders' 128: the figures show a container face 40 to 100
/// pixels wide, and with 128 texels the maps are minified (no mipmaps, as the raster
/// samples them), where SwiftShader's texture coordinates, about 0.05 texel off, made
/// the hard-edged emission strokes differ from the raster by up to 41 steps. At 32
/// texels they are magnified and the same view stays within 11 (see [`super::TEXTURED`]).
pub const CONTAINER_SIZE: usize = 32;

/// Sphere tessellations (stacks, slices) offered by the Gouraud figure's slider.
pub const SPHERE_TESSELLATIONS: [(u32, u32); 5] = [(4, 8), (8, 16), (12, 24), (16, 32), (32, 64)];

/// The sphere the materials and normals figures draw.
pub const SMOOTH_SPHERE: (u32, u32) = (24, 48);

/// Every mesh name: `cube` (the LearnOpenGL cube) and `sphere-<stacks>x<slices>`.
pub fn mesh_names() -> Vec<String> {
    let mut names = vec!["cube".to_owned()];
    let mut spheres: Vec<(u32, u32)> = SPHERE_TESSELLATIONS.to_vec();
    if !spheres.contains(&SMOOTH_SPHERE) {
        spheres.push(SMOOTH_SPHERE);
    }
    names.extend(spheres.iter().map(|(a, b)| sphere_name(*a, *b)));
    names
}

/// `sphere-<stacks>x<slices>`.
pub fn sphere_name(stacks: u32, slices: u32) -> String {
    format!("sphere-{stacks}x{slices}")
}

/// The mesh called `name`, or an error naming it.
pub fn mesh(name: &str) -> Result<Mesh, LiveError> {
    if name == "cube" {
        return Ok(Mesh::learnopengl_cube());
    }
    let dims = name.strip_prefix("sphere-").and_then(|d| d.split_once('x'));
    match dims.and_then(|(a, b)| Some((a.parse::<u32>().ok()?, b.parse::<u32>().ok()?))) {
        Some((a, b)) => Ok(Mesh::uv_sphere(a, b)),
        None => Err(LiveError::UnknownAsset { kind: "mesh", name: name.to_owned() }),
    }
}

/// Every texture name.
pub const TEXTURE_NAMES: [&str; 3] = ["container-diffuse", "container-specular", "container-emission"];

/// The container's maps at [`CONTAINER_SIZE`], with emission.
pub fn container() -> Result<LightingMaps, LiveError> {
    crate::maps::container(CONTAINER_SIZE, true)
        .map_err(|e| LiveError::Asset { what: "the container maps", detail: e.to_string() })
}

/// The texture called `name`, or an error naming it.
pub fn texture(name: &str) -> Result<Texture, LiveError> {
    let maps = container()?;
    match name {
        "container-diffuse" => Ok(maps.diffuse),
        "container-specular" => Ok(maps.specular),
        "container-emission" => maps
            .emission
            .ok_or_else(|| LiveError::Asset { what: "the container emission map", detail: "missing".into() }),
        _ => Err(LiveError::UnknownAsset { kind: "texture", name: name.to_owned() }),
    }
}

/// Standard base64 (RFC 4648, with padding).
pub fn base64(bytes: &[u8]) -> String {
    const A: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [chunk[0], *chunk.get(1).unwrap_or(&0), *chunk.get(2).unwrap_or(&0)];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for k in 0..4 {
            if k <= chunk.len() {
                out.push(A[(n >> (18 - 6 * k) & 63) as usize] as char);
            } else {
                out.push('=');
            }
        }
    }
    out
}

fn f32s(values: impl IntoIterator<Item = f32>) -> String {
    base64(&values.into_iter().flat_map(f32::to_le_bytes).collect::<Vec<u8>>())
}

/// The JSON of a mesh: vertex count, base64 arrays.
pub fn mesh_json(m: &Mesh) -> serde_json::Value {
    serde_json::json!({
        "vertices": m.positions.len(),
        "indices": 3 * m.triangles.len(),
        "positions": f32s(m.positions.iter().flat_map(|p| p.to_array())),
        "normals": f32s(m.normals.iter().flat_map(|p| p.to_array())),
        "uvs": f32s(m.uvs.iter().flat_map(|p| p.to_array())),
        "triangles": base64(&m.triangles.iter().flatten().flat_map(|i| i.to_le_bytes()).collect::<Vec<u8>>()),
    })
}

/// The JSON of a texture: size and RGB `f32` texels, row 0 at `v = 0` (OpenGL's order).
pub fn texture_json(t: &Texture) -> serde_json::Value {
    let (w, h) = (t.width(), t.height());
    let texel = |i: usize, j: usize| t.texel(i as i64, j as i64, Wrap::Repeat);
    let rgb = (0..h).flat_map(|j| (0..w).map(move |i| (i, j))).flat_map(|(i, j)| texel(i, j).to_array());
    serde_json::json!({ "width": w, "height": h, "rgb": f32s(rgb) })
}

/// A constant texture of `size × size` texels (a map switched off).
pub fn constant_texture(c: Vec3) -> Result<Texture, LiveError> {
    Texture::from_fn(4, 4, |_, _| c).map_err(|e| LiveError::Asset { what: "a constant texture", detail: e.to_string() })
}

/// The script registering asset `name` (a mesh or a texture).
pub fn asset_script(name: &str) -> Result<Vec<u8>, LiveError> {
    let (kind, json) = if TEXTURE_NAMES.contains(&name) {
        ("textures", texture_json(&texture(name)?))
    } else {
        ("meshes", mesh_json(&mesh(name)?))
    };
    Ok(format!(
        "(window.LIGHTLAB_ASSETS = window.LIGHTLAB_ASSETS || {{meshes: {{}}, textures: {{}}}}).{kind}[{}] = {};\n",
        serde_json::Value::from(name),
        json
    )
    .into_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc4648_vectors() {
        for (i, o) in [("", ""), ("f", "Zg=="), ("fo", "Zm8="), ("foo", "Zm9v"), ("foobar", "Zm9vYmFy")] {
            assert_eq!(base64(i.as_bytes()), o);
        }
    }

    #[test]
    fn every_named_asset_exists() {
        for n in mesh_names() {
            mesh(&n).unwrap();
        }
        for n in TEXTURE_NAMES {
            texture(n).unwrap();
        }
        assert!(mesh("sphere-x").is_err() && texture("wood").is_err());
    }
}
