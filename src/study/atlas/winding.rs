//! Case 15: the LearnOpenGL cube's mixed winding under back-face culling.
//!
//! The chapter's `vertices[]` lists the cube as 12 triangles, three vertices each; six of
//! them (the back, right and top faces) are clockwise seen from outside. The tutorial draws
//! without culling, where winding does not matter. Turn `GL_CULL_FACE` on (the default of
//! most engines, and of lightlab's scene files) and those faces vanish when they face the
//! eye, while their clockwise triangles on the far side pass the test instead: the eye sees
//! the inside of the cube.
//!
//! Measured here by drawing the cube with lightlab's rasterizer from eyes around it, with
//! back-face culling and without, and counting the pixels that differ. The fix is
//! [`Mesh::learnopengl_cube`], the same vertices with each triangle wound counter-clockwise
//! against its face normal.

use glam::{Mat4, Vec3, Vec4};

use super::super::{Curve, Figure};
use crate::material::Material;
use crate::raster::camera::Camera;
use crate::raster::framebuffer::Framebuffer;
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::{Geometry, Object, World};
use crate::raster::rasterize::CullMode;
use crate::raster::shade::{ShadingMode, Surface};
use crate::scene::Scene;

/// Side of the square images the case is measured on, in pixels.
pub const CASE15_SIZE: u32 = 96;

/// Distance of the eye from the cube's centre (the tutorials' camera is 3 from it).
pub const CASE15_DISTANCE: f32 = 3.0;

/// The eye at `elevation_deg` above the xz-plane and `azimuth_deg` around +y, measured
/// from +z toward +x, [`CASE15_DISTANCE`] from the origin:
///
/// ```text
/// eye = d · (cos e · sin a, sin e, cos e · cos a)
/// ```
pub fn case15_eye(elevation_deg: f32, azimuth_deg: f32) -> Vec3 {
    let (e, a) = (elevation_deg.to_radians(), azimuth_deg.to_radians());
    CASE15_DISTANCE * Vec3::new(e.cos() * a.sin(), e.sin(), e.cos() * a.cos())
}

/// The cube `mesh` drawn from `eye` (looking at the origin, 45° field of view, the
/// default scene's lights, coral) with `cull`, as RGBA8 bytes; `None` when no camera can
/// look from `eye` (the eye on the y axis, where "up" is undefined, or not finite).
pub fn case15_image(mesh: &Mesh, eye: Vec3, cull: CullMode) -> Option<Vec<u8>> {
    let camera = Camera::new(eye, Vec3::ZERO, Vec3::Y, 45.0, 1.0, 0.1, 100.0).ok()?;
    let world = World {
        camera,
        lights: Scene::learnopengl_default(),
        objects: vec![Object {
            geometry: Geometry::Mesh(mesh.clone()),
            model: Mat4::IDENTITY,
            surface: Surface::Material(Material::coral()),
            cull,
        }],
        shading: ShadingMode::Phong,
        clear: Vec4::ZERO,
        depth_test: true,
        range_window: None,
        specialisations: crate::raster::kernel::Specialisations::ALL,
    };
    let mut fb = Framebuffer::new(CASE15_SIZE, CASE15_SIZE).ok()?;
    world.render(&mut fb);
    Some(fb.to_rgba8(false))
}

/// How many pixels of `mesh` drawn with back-face culling differ from the same mesh drawn
/// without culling, seen from `eye`, and how many pixels the unculled cube covers:
/// `(wrong, covered)`. Without culling the depth test alone picks the nearest face, which
/// is the image the tutorial means. `None` as [`case15_image`].
pub fn case15_wrong_pixels(mesh: &Mesh, eye: Vec3) -> Option<(usize, usize)> {
    let culled = case15_image(mesh, eye, CullMode::Back)?;
    let reference = case15_image(mesh, eye, CullMode::None)?;
    let wrong = culled.chunks_exact(4).zip(reference.chunks_exact(4)).filter(|(a, b)| a != b).count();
    let covered = reference.chunks_exact(4).filter(|p| p[3] > 0).count();
    Some((wrong, covered))
}

/// [`case15_wrong_pixels`] as a share of the covered pixels, in percent.
fn wrong_percent(mesh: &Mesh, elevation_deg: f32, azimuth_deg: f32) -> f32 {
    match case15_wrong_pixels(mesh, case15_eye(elevation_deg, azimuth_deg)) {
        Some((wrong, covered)) if covered > 0 => 100.0 * wrong as f32 / covered as f32,
        _ => f32::NAN,
    }
}

/// Elevation of the figure's orbit, degrees: high enough to see the top face.
const ORBIT_ELEVATION: f32 = 30.0;

/// Case 15's figure: the share of the cube's pixels drawn wrong under back-face culling as
/// the eye orbits it, 30° above the equator, for the tutorial's winding and the fixed one.
pub fn case15_figure() -> Figure {
    let azimuths = || (0..=36).map(|k| k as f32 * 10.0);
    let published = Mesh::learnopengl_cube_as_published();
    let fixed = Mesh::learnopengl_cube();
    Figure::new(
        "The tutorial's cube with back faces culled, eye 30° up",
        "eye azimuth around +y (°, 0 = the front face)",
        "pixels drawn wrong (% of the cube)",
        vec![
            Curve::from_fn("as published (mixed winding)", azimuths(), |a| {
                wrong_percent(&published, ORBIT_ELEVATION, a)
            }),
            Curve::from_fn("re-wound (Mesh::learnopengl_cube)", azimuths(), |a| {
                wrong_percent(&fixed, ORBIT_ELEVATION, a)
            }),
        ],
    )
}

pub(super) fn case15_measure() -> (String, String) {
    let worst =
        |mesh: &Mesh| (0..36).map(|k| wrong_percent(mesh, ORBIT_ELEVATION, k as f32 * 10.0)).fold(0.0f32, f32::max);
    (
        format!(
            "orbit 30° up: up to {:.0}% of the cube's pixels wrong (lost faces, the inside shows)",
            worst(&Mesh::learnopengl_cube_as_published())
        ),
        format!(
            "re-wound: {:.0}% of pixels differ from the unculled image at every azimuth",
            worst(&Mesh::learnopengl_cube())
        ),
    )
}
