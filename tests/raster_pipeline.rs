//! Rasterizer invariants: watertight coverage, perspective-correct varyings,
//! depth order, degenerate input, Gouraud = Phong at vertices.

use glam::{Mat4, Vec2, Vec3, Vec4};
use lightlab::material::Material;
use lightlab::raster::camera::Camera;
use lightlab::raster::clip::{ClipVertex, MAX_VARYINGS};
use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::kernel::{MultiLightKernel, Specular, LANES};
use lightlab::raster::mesh::Mesh;
use lightlab::raster::pipeline::{light_points, vertex_stage, Geometry};
use lightlab::raster::rasterize::{coverage, render, CullMode, DrawCall, FragmentBatch, FragmentShader};
use lightlab::raster::shade::{ColorShader, LitShader, Surface};
use lightlab::scene::Scene;
use proptest::prelude::*;

const W: u32 = 64;
const H: u32 = 48;

fn clip_vertices(mesh: &Mesh, model: Mat4, camera: &Camera) -> Vec<ClipVertex> {
    let (verts, _) = vertex_stage(&Geometry::Mesh(mesh.clone()), model, camera);
    verts
        .iter()
        .map(|v| {
            let mut varyings = [0.0; MAX_VARYINGS];
            varyings[..3].copy_from_slice(&v.world.to_array());
            ClipVertex { clip: v.clip, varyings }
        })
        .collect()
}

fn model_from(axis: (f32, f32, f32), angle: f32, scale: f32, offset: (f32, f32, f32)) -> Mat4 {
    let axis = Vec3::new(axis.0, axis.1, axis.2).try_normalize().unwrap_or(Vec3::Y);
    Mat4::from_translation(Vec3::new(offset.0, offset.1, offset.2))
        * Mat4::from_axis_angle(axis, angle)
        * Mat4::from_scale(Vec3::splat(scale))
}

fn counts(mesh: &Mesh, model: Mat4, cull: CullMode) -> Vec<u32> {
    let camera = Camera::learnopengl(W as f32 / H as f32);
    let vertices = clip_vertices(mesh, model, &camera);
    let draw = DrawCall {
        vertices: &vertices,
        triangles: &mesh.triangles,
        varying_count: 3,
        cull,
        depth_test: true,
        shader: &ColorShader,
    };
    coverage(W, H, &draw)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// A convex closed mesh drawn without culling covers every pixel 0 or 2
    /// times (front and back): a crack would leave a 1, a double hit on a
    /// shared edge a 3. With back faces culled, 0 or 1.
    #[test]
    fn closed_convex_meshes_are_watertight(
        axis in (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0),
        angle in 0.0f32..6.3,
        scale in 0.3f32..1.2,
        offset in (-0.6f32..0.6, -0.5f32..0.5, -1.5f32..0.5),
        which in 0usize..3,
    ) {
        let mesh = match which { 0 => Mesh::icosphere(2), 1 => Mesh::benchmark_cube(), _ => Mesh::uv_sphere(7, 13) };
        let model = model_from(axis, angle, scale, offset);
        let both = counts(&mesh, model, CullMode::None);
        let covered = both.iter().filter(|&&c| c > 0).count();
        prop_assert!(covered > 0);
        for (i, &c) in both.iter().enumerate() {
            prop_assert!(c == 0 || c == 2, "pixel {} covered {} times without culling", i, c);
        }
        let front = counts(&mesh, model, CullMode::Back);
        for (i, (&c, &b)) in front.iter().zip(&both).enumerate() {
            prop_assert!(c == b / 2, "pixel {}: {} front hits, {} hits in all", i, c, b);
        }
    }

    /// A tiled plane covers each pixel inside its projection exactly once and none outside.
    #[test]
    fn tiled_plane_covers_inside_pixels_exactly_once(
        axis in (-1.0f32..1.0, -1.0f32..1.0, -1.0f32..1.0),
        angle in 0.0f32..6.3,
        cells in 1u32..9,
        offset in (-0.5f32..0.5, -0.5f32..0.5, -1.0f32..0.5),
    ) {
        let mesh = Mesh::plane(cells);
        let model = model_from(axis, angle, 0.9, offset);
        let c = counts(&mesh, model, CullMode::None);
        let camera = Camera::learnopengl(W as f32 / H as f32);
        let vp = camera.view_projection() * model;
        let corner = |x: f32, z: f32| {
            let clip = vp * Vec4::new(x, 0.0, z, 1.0);
            let ndc = clip.truncate() / clip.w;
            Vec2::new((ndc.x + 1.0) * 0.5 * W as f32, (ndc.y + 1.0) * 0.5 * H as f32)
        };
        let quad = [corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0)];
        for row in 0..H {
            for i in 0..W {
                let p = Vec2::new(i as f32 + 0.5, (H - 1 - row) as f32 + 0.5);
                let k = c[(row * W + i) as usize];
                prop_assert!(k <= 1, "pixel ({}, {}) covered {} times", i, row, k);
                // 0.02 px margin: vertices are snapped to 1/256 px (≤ 0.002 px) plus f32 rounding
                match signed_inside(&quad, p) {
                    d if d > 0.02 => prop_assert!(k == 1, "crack at ({}, {})", i, row),
                    d if d < -0.02 => prop_assert!(k == 0, "pixel outside covered at ({}, {})", i, row),
                    _ => {}
                }
            }
        }
    }
}

/// Distance inside a convex quad (positive inside), either winding.
fn signed_inside(q: &[Vec2; 4], p: Vec2) -> f32 {
    let area: f32 = (0..4).map(|k| q[k].perp_dot(q[(k + 1) % 4])).sum();
    let s = area.signum();
    (0..4)
        .map(|k| {
            let (a, b) = (q[k], q[(k + 1) % 4]);
            s * (b - a).perp_dot(p - a) / (b - a).length().max(1e-12)
        })
        .fold(f32::INFINITY, f32::min)
}

#[test]
fn varyings_are_perspective_correct_on_a_tilted_plane() {
    let mesh = Mesh::plane(1);
    let model = Mat4::from_translation(Vec3::new(0.0, 0.0, -2.0))
        * Mat4::from_rotation_x(1.1)
        * Mat4::from_scale(Vec3::splat(3.0));
    let camera = Camera::learnopengl(W as f32 / H as f32);
    let vertices = clip_vertices(&mesh, model, &camera);
    let draw = DrawCall {
        vertices: &vertices,
        triangles: &mesh.triangles,
        varying_count: 3,
        cull: CullMode::None,
        depth_test: true,
        shader: &ColorShader,
    };
    let mut fb = Framebuffer::new(W, H).unwrap();
    render(&mut fb, Some(Vec4::ZERO), &[draw]);
    // the analytic value in f64: the eye ray through the pixel centre meets the plane
    let model64 = model.as_dmat4();
    let normal = model64.transform_vector3(glam::DVec3::Y).normalize();
    let point = model64.transform_point3(glam::DVec3::ZERO);
    let inv_vp = camera.view_projection().as_dmat4().inverse();
    let (mut checked, mut worst) = (0, 0.0f64);
    for row in 0..H {
        for i in 0..W {
            let px = fb.pixel(i, row).unwrap();
            if px[3] == 0.0 {
                continue;
            }
            let ndc = glam::DVec2::new(
                (i as f64 + 0.5) / W as f64 * 2.0 - 1.0,
                ((H - 1 - row) as f64 + 0.5) / H as f64 * 2.0 - 1.0,
            );
            let near = inv_vp.project_point3(ndc.extend(-1.0));
            let far = inv_vp.project_point3(ndc.extend(1.0));
            let dir = far - near;
            let t = normal.dot(point - near) / normal.dot(dir);
            let want = near + t * dir;
            let got = glam::DVec3::new(px[0] as f64, px[1] as f64, px[2] as f64);
            worst = worst.max((got - want).length());
            checked += 1;
        }
    }
    assert!(checked > 500, "only {checked} pixels covered");
    // 4e-4 world units: vertices are snapped to 1/256 px (moving the interpolation planes by up to
    // 1/512 px), and a pixel spans up to ~0.15 world units on this plane at 64x48, so ≤ 3e-4, plus
    // f32 rounding (~2e-5 relative); screen-linear (affine) interpolation would be off by ~0.1
    assert!(worst < 4e-4, "worst position error {worst} over {checked} pixels");
}

struct Flat(Vec3);
impl FragmentShader for Flat {
    fn shade(&self, _batch: &FragmentBatch, out: &mut [[f32; LANES]; 3]) {
        *out = [[self.0.x; LANES], [self.0.y; LANES], [self.0.z; LANES]];
    }
}

fn tri(z: f32, scale: f32) -> Vec<ClipVertex> {
    [(-1.0, -1.0), (1.0, -1.0), (0.0, 1.0)]
        .iter()
        .map(|&(x, y)| ClipVertex { clip: Vec4::new(x * scale, y * scale, z, 1.0), varyings: [0.0; MAX_VARYINGS] })
        .collect()
}

#[test]
fn depth_test_keeps_the_nearer_triangle_in_either_order() {
    let (near, far) = (tri(-0.5, 0.8), tri(0.5, 0.9));
    let tris = [[0u32, 1, 2]];
    let (red, green) = (Flat(Vec3::X), Flat(Vec3::Y));
    for near_first in [true, false] {
        let d_near = DrawCall {
            vertices: &near,
            triangles: &tris,
            varying_count: 0,
            cull: CullMode::None,
            depth_test: true,
            shader: &red,
        };
        let d_far = DrawCall {
            vertices: &far,
            triangles: &tris,
            varying_count: 0,
            cull: CullMode::None,
            depth_test: true,
            shader: &green,
        };
        let mut fb = Framebuffer::new(W, H).unwrap();
        if near_first {
            render(&mut fb, Some(Vec4::ZERO), &[d_near, d_far]);
        } else {
            render(&mut fb, Some(Vec4::ZERO), &[d_far, d_near]);
        }
        // the centre is inside both: red (near) must win
        let c = fb.pixel(W / 2, H / 2).unwrap();
        assert_eq!(c, [1.0, 0.0, 0.0, 1.0], "near_first={near_first}");
        // bottom middle, y_ndc ≈ −0.85: inside the far triangle (y ≥ −0.9), outside the near one (y ≥ −0.8)
        let edge = fb.pixel(W / 2, H - 4).unwrap();
        assert_eq!(edge, [0.0, 1.0, 0.0, 1.0], "near_first={near_first}");
    }
}

#[test]
fn degenerate_triangles_are_skipped_without_panic() {
    let v = |x: f32, y: f32, w: f32| ClipVertex { clip: Vec4::new(x, y, 0.0, w), varyings: [0.0; MAX_VARYINGS] };
    let vertices = vec![
        v(-0.5, -0.5, 1.0),
        v(0.5, -0.5, 1.0),
        v(0.0, 0.5, 1.0),
        v(0.0, 0.0, 1.0),
        v(f32::NAN, 0.0, 1.0),
        v(f32::INFINITY, 0.0, 1.0),
        v(0.2, 0.2, 0.0),
        v(1e30, -1e30, 1.0),
    ];
    let triangles =
        [[0, 0, 1], [0, 1, 1], [3, 3, 3], [0, 4, 1], [0, 1, 5], [0, 1, 6], [0, 1, 99], [0, 7, 2], [0, 3, 3]];
    let draw = DrawCall {
        vertices: &vertices,
        triangles: &triangles,
        varying_count: 3,
        cull: CullMode::None,
        depth_test: true,
        shader: &ColorShader,
    };
    let mut fb = Framebuffer::new(W, H).unwrap();
    let stats = render(&mut fb, Some(Vec4::ZERO), &[draw]);
    assert_eq!(stats.triangles, triangles.len());
    // drawn: the huge one (clipped to the guard band) and the one with a w = 0 corner (a point at
    // infinity, clipped to a finite polygon); the other 7 are skipped
    assert_eq!(stats.skipped, 7, "{stats:?}");
    assert!(fb.color.iter().all(|c| c.iter().all(|x| x.is_finite())));
}

#[test]
fn gouraud_equals_phong_at_the_vertices() {
    let scene = Scene::learnopengl_default();
    let material = Material::coral();
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let mesh = Mesh::uv_sphere(6, 10);
    let model = Mat4::from_rotation_y(0.4) * Mat4::from_scale(Vec3::splat(1.3));
    let (verts, _) = vertex_stage(&Geometry::Mesh(mesh), model, &Camera::learnopengl(4.0 / 3.0));
    let kernel = MultiLightKernel::new(&scene, eye, material.shininess, Specular::Phong);
    let surface = Surface::Material(material);
    let points: Vec<_> = verts.iter().map(|v| (v.world, v.normal, v.uv)).collect();
    let gouraud = light_points(&kernel, &surface, &points);
    let phong = LitShader::new(kernel, surface);
    for (chunk, colors) in points.chunks(LANES).zip(gouraud.chunks(LANES)) {
        let mut varyings = [[0.0; LANES]; MAX_VARYINGS];
        for (l, (p, n, uv)) in chunk.iter().enumerate() {
            for c in 0..3 {
                varyings[c][l] = p[c];
                varyings[3 + c][l] = n[c];
            }
            varyings[6][l] = uv.x;
            varyings[7][l] = uv.y;
        }
        let mut out = [[0.0; LANES]; 3];
        phong.shade(&FragmentBatch::from_varyings(varyings, chunk.len()), &mut out);
        for (l, g) in colors.iter().enumerate() {
            for c in 0..3 {
                // exactly equal: the same kernel on the same inputs
                assert_eq!(out[c][l], g[c], "vertex lane {l} channel {c}");
            }
        }
    }
}

#[test]
fn the_windowed_floor_culled_and_unculled_are_the_same_image_and_not_learnopengls() {
    use lightlab::raster::framebuffer::Framebuffer;
    use lightlab::raster::presets::{bench_scene, WINDOWED_SCENES};
    // a smaller frame than the benchmark's: the same scene, fewer fragments to shade in a test
    let draw = |name: &str| {
        let world = bench_scene(name).expect("scene");
        let mut fb = Framebuffer::new(200, 150).expect("size");
        world.render(&mut fb);
        fb.color
    };
    let plain = draw("floor-lights256");
    let [windowed, culled] = WINDOWED_SCENES.map(draw);
    assert!(windowed == culled, "culling beyond the range must change no pixel");
    let changed = plain.iter().zip(&windowed).filter(|(a, b)| a != b).count();
    assert!(changed > plain.len() / 10, "the window changes the look: {changed} pixels differ");
}

/// `quad-multi-ATM` and `sphere4096-multi-ATM` are their base scenes under the chapter's
/// atmosphere, in `llvmpipe_bench.py`'s order, and nothing else changes.
#[test]
fn the_coloured_light_scenes_are_their_base_scenes_under_an_atmosphere() {
    use lightlab::raster::presets::{all_bench_scenes, bench_scene, coloured_scene, coloured_scenes, BENCH_SCENES};
    use lightlab::scene::Atmosphere;
    let names = coloured_scenes();
    assert_eq!(names[..2], ["quad-multi-desert", "sphere4096-multi-desert"]);
    assert_eq!(names.len(), 2 * Atmosphere::ALL.len());
    assert_eq!(all_bench_scenes()[..BENCH_SCENES.len()], BENCH_SCENES.map(String::from));
    for name in &names {
        let (base, atmosphere) = coloured_scene(name).expect("a coloured scene");
        let (world, base_world) = (bench_scene(name).expect("scene"), bench_scene(base).expect("base"));
        assert_eq!(world.lights.point_lights, atmosphere.scene().point_lights, "{name}");
        assert_eq!(world.lights.spot_light, atmosphere.scene().spot_light, "{name}");
        assert_eq!(world.lights.dir_light, atmosphere.scene().dir_light, "{name}");
        assert_eq!(
            (world.objects, world.camera, world.shading),
            (base_world.objects, base_world.camera, base_world.shading)
        );
    }
    assert!(coloured_scene("quad-single-desert").is_none() && coloured_scene("quad-multi-").is_none());
}

/// The general path (`bench --general`: no value-based specialisation) draws the same image
/// within rounding as the specialised one, for grey and for coloured lights, and it is a
/// different path: the kernel's operation count says so.
#[test]
fn the_general_path_draws_the_specialised_image() {
    use lightlab::raster::framebuffer::Framebuffer;
    use lightlab::raster::kernel::Specialisations;
    use lightlab::raster::presets::bench_scene;
    for name in ["quad-multi", "quad-multi-desert", "sphere4096-multi"] {
        let world = bench_scene(name).expect("scene");
        let mut images = Vec::new();
        for allowed in [Specialisations::ALL, Specialisations::NONE] {
            let mut fb = Framebuffer::new(160, 120).expect("size");
            lightlab::raster::pipeline::World { specialisations: allowed, ..world.clone() }.render(&mut fb);
            images.push(fb.to_rgba8(false));
        }
        let worst = images[0].iter().zip(&images[1]).map(|(a, b)| a.abs_diff(*b)).max().unwrap_or(0);
        assert!(worst <= 1, "{name}: the general path differs by {worst} levels");
        let kernel = |allowed| {
            MultiLightKernel::new(&world.lights, world.camera.eye, 32.0, Specular::Phong).with_specialisations(allowed)
        };
        assert!(
            kernel(Specialisations::NONE).flops_per_fragment() > kernel(Specialisations::ALL).flops_per_fragment(),
            "{name}"
        );
        for (what, alone) in Specialisations::EACH {
            assert_eq!(kernel(alone).specialisations(), alone, "{what}");
        }
    }
}
