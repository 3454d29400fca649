//! The f64 ray caster, and Phong on a fine sphere converging to it.

use glam::{DMat4, DVec3, Mat4, Vec4};
use lightlab::material::Material;
use lightlab::raster::camera::Camera;
use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::kernel::Specular;
use lightlab::raster::mesh::Mesh;
use lightlab::raster::pipeline::{Geometry, Object, World};
use lightlab::raster::rasterize::CullMode;
use lightlab::raster::raycast::{RayObject, RayScene, Shape};
use lightlab::raster::shade::{ShadingMode, Surface};
use lightlab::scene::Scene;

#[test]
fn analytic_intersections_and_normals() {
    let sphere = Shape::Sphere { center: DVec3::new(0.0, 0.0, -5.0), radius: 2.0 };
    let (t, n) = sphere.intersect(DVec3::ZERO, DVec3::NEG_Z).unwrap();
    assert_eq!((t, n), (3.0, DVec3::Z));
    assert!(sphere.intersect(DVec3::ZERO, DVec3::X).is_none());
    // from inside: the far root, normal outward
    let (t, n) = sphere.intersect(DVec3::new(0.0, 0.0, -5.0), DVec3::X).unwrap();
    assert_eq!((t, n), (2.0, DVec3::X));
    let plane = Shape::Plane { point: DVec3::new(0.0, -1.0, 0.0), normal: DVec3::Y };
    let (t, n) = plane.intersect(DVec3::ZERO, DVec3::NEG_Y).unwrap();
    assert_eq!((t, n), (1.0, DVec3::Y));
    // two-sided: seen from below, the normal faces down
    let (_, n) = plane.intersect(DVec3::new(0.0, -3.0, 0.0), DVec3::Y).unwrap();
    assert_eq!(n, DVec3::NEG_Y);
    let cube = Shape::Box {
        model: DMat4::from_translation(DVec3::new(0.0, 0.0, -3.0)) * DMat4::from_scale(DVec3::splat(2.0)),
    };
    let (t, n) = cube.intersect(DVec3::ZERO, DVec3::NEG_Z).unwrap();
    assert_eq!((t, n), (2.0, DVec3::Z));
    let rotated = Shape::Box { model: DMat4::from_rotation_y(std::f64::consts::FRAC_PI_4) };
    let (t, n) = rotated.intersect(DVec3::new(5.0, 0.0, 0.0), DVec3::NEG_X).unwrap();
    // the box's edge at x = √2/2 faces the ray; the hit normal is a face normal at 45°
    assert!((t - (5.0 - 0.5 * std::f64::consts::SQRT_2)).abs() < 1e-12, "t = {t}");
    assert!((n.length() - 1.0).abs() < 1e-12 && (n.x - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-12, "n = {n}");
    // degenerate shapes are never hit, never a panic
    assert!(Shape::Sphere { center: DVec3::ZERO, radius: 0.0 }.intersect(DVec3::Z, DVec3::NEG_Z).is_none());
    assert!(Shape::Plane { point: DVec3::ZERO, normal: DVec3::ZERO }.intersect(DVec3::Z, DVec3::NEG_Z).is_none());
    assert!(Shape::Box { model: DMat4::ZERO }.intersect(DVec3::Z, DVec3::NEG_Z).is_none());
}

const W: u32 = 160;
const H: u32 = 120;

fn raster_sphere(stacks: u32) -> Framebuffer {
    let world = World {
        camera: Camera::learnopengl(W as f32 / H as f32),
        lights: Scene::learnopengl_default(),
        objects: vec![Object {
            geometry: Geometry::Mesh(Mesh::uv_sphere(stacks, 2 * stacks)),
            model: Mat4::IDENTITY,
            surface: Surface::Material(Material::coral()),
            cull: CullMode::Back,
        }],
        shading: ShadingMode::Phong,
        clear: Vec4::ZERO,
        depth_test: true,
        range_window: None,
        specialisations: lightlab::raster::kernel::Specialisations::ALL,
    };
    let mut fb = Framebuffer::new(W, H).unwrap();
    world.render(&mut fb);
    fb
}

/// Max and mean channel error over pixels whose 3×3 neighbourhood is covered in both images
/// (the silhouette itself differs by the tessellation's polygon outline).
fn interior_error(a: &Framebuffer, b: &Framebuffer) -> (f32, f32, usize) {
    let covered =
        |fb: &Framebuffer, x: i64, y: i64| x >= 0 && y >= 0 && fb.pixel(x as u32, y as u32).is_some_and(|p| p[3] > 0.0);
    let (mut worst, mut sum, mut n) = (0.0f32, 0.0f32, 0usize);
    for y in 0..H as i64 {
        for x in 0..W as i64 {
            let inside = (-1..=1).all(|dy| (-1..=1).all(|dx| covered(a, x + dx, y + dy) && covered(b, x + dx, y + dy)));
            if !inside {
                continue;
            }
            let (p, q) = (a.pixel(x as u32, y as u32).unwrap(), b.pixel(x as u32, y as u32).unwrap());
            let e = (0..3).map(|c| (p[c] - q[c]).abs()).fold(0.0, f32::max);
            worst = worst.max(e);
            sum += e;
            n += 1;
        }
    }
    (worst, sum / n.max(1) as f32, n)
}

#[test]
fn phong_on_a_fine_sphere_converges_to_the_ray_cast_sphere() {
    let truth = RayScene {
        camera: Camera::learnopengl(W as f32 / H as f32),
        lights: Scene::learnopengl_default(),
        objects: vec![RayObject {
            shape: Shape::Sphere { center: DVec3::ZERO, radius: 1.0 },
            material: Material::coral(),
        }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    }
    .render(W, H, 1)
    .unwrap()
    .to_framebuffer();
    let errors: Vec<(u32, (f32, f32, usize))> =
        [8u32, 32, 128].iter().map(|&s| (s, interior_error(&raster_sphere(s), &truth))).collect();
    for (s, (worst, mean, n)) in &errors {
        println!("uv sphere {s} stacks: max {worst:.5}, mean {mean:.6} over {n} interior pixels");
    }
    let (coarse, fine) = (errors[0].1, errors[2].1);
    assert!(fine.2 > 5000, "too few interior pixels: {}", fine.2);
    assert!(fine.1 < coarse.1 / 4.0, "mean error did not fall: {coarse:?} -> {fine:?}");
    // 1/255 (half an 8-bit step on either side): at 128 stacks the facets sit within
    // 1 - cos(π/256) ≈ 7.5e-5 of the sphere, so positions, normals and highlights agree far below one step
    assert!(fine.0 < 1.0 / 255.0, "max interior error {} at 128 stacks", fine.0);
}

/// The benchmark quads carry exact varyings (affine in the screen), so the only error left is the
/// shading's: every pixel must be within 1/255 of the f64 shader, the accuracy bar.
#[test]
fn benchmark_quads_are_within_one_step_of_the_f64_shader() {
    use lightlab::raster::presets::{basic_lighting_scene, bench_scene};
    use lightlab::raster::raycast::shade_f64;
    let (w, h) = (200u32, 150u32);
    for name in ["quad-single", "quad-multi"] {
        let world = bench_scene(name).unwrap();
        let (lights, material) = if name == "quad-single" {
            basic_lighting_scene(&lightlab::phong::BasicLighting::learnopengl())
        } else {
            (Scene::learnopengl_default(), Material::coral())
        };
        let mut fb = Framebuffer::new(w, h).unwrap();
        world.render(&mut fb);
        let mut worst = 0.0f64;
        for row in 0..h {
            for i in 0..w {
                let x = (i as f64 + 0.5) / w as f64 * 2.0 - 1.0;
                let y = ((h - 1 - row) as f64 + 0.5) / h as f64 * 2.0 - 1.0;
                let p = DVec3::new(x * 4.0 / 3.0, y, 0.0);
                let n = DVec3::new(x * 0.5, y * 0.5, 1.0).normalize();
                let want = shade_f64(&lights, &material, p, n, DVec3::new(0.0, 0.0, 3.0), Specular::Phong);
                let got = fb.pixel(i, row).unwrap();
                for c in 0..3 {
                    worst = worst.max((got[c] as f64 - want[c]).abs());
                }
            }
        }
        println!("{name}: worst |f32 raster − f64 shader| = {worst:.2e}");
        // 1/255: the bar; measured ~1e-6 (f32 rounding and the kernel's estimates)
        assert!(worst < 1.0 / 255.0, "{name}: {worst}");
        assert!(worst < 1e-4, "{name}: {worst} is far above f32 rounding");
    }
}
