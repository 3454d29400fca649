//! Criterion benchmarks of the raster back end: the benchmark scenes (one frame each)
//! and one bench per kernel (single light, LearnOpenGL's multiple lights, the 256-light
//! floor on 16 fragments; Gouraud's lighting of every vertex of the sphere).
//!
//! Kept short by default (10 samples, 1 s each; no plots, which would need system fonts); `lightlab bench` is the
//! command whose output lines up with `llvmpipe_bench.py`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::{Vec2, Vec3};
use lightlab::material::Material;
use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::kernel::{LaneMaterial, MultiLightKernel, Specular, LANES};
use lightlab::raster::pipeline::{light_points, vertex_stage};
use lightlab::raster::presets::{bench_scene, floor_lights, BENCH_SCENES, BENCH_SIZE};
use lightlab::scene::Scene;

fn scenes(c: &mut Criterion) {
    let mut group = c.benchmark_group("scene");
    for name in BENCH_SCENES {
        let world = bench_scene(name).expect("benchmark scene");
        let mut fb = Framebuffer::new(BENCH_SIZE.0, BENCH_SIZE.1).expect("size");
        world.render(&mut fb);
        group.throughput(Throughput::Elements(fb.covered() as u64));
        group.bench_function(name, |b| b.iter(|| world.render(black_box(&mut fb))));
    }
    group.finish();
}

/// 16 fragments across the quad's middle row, facing the camera.
fn lanes() -> ([[f32; LANES]; 3], [[f32; LANES]; 3]) {
    let mut pos = [[0.0; LANES]; 3];
    let mut normal = [[0.0; LANES]; 3];
    for l in 0..LANES {
        let x = l as f32 / LANES as f32 - 0.5;
        pos[0][l] = x;
        pos[1][l] = 0.3 * x;
        normal[0][l] = x;
        normal[2][l] = 1.0;
    }
    (pos, normal)
}

/// One criterion bench per kernel: each benchmark scene's lights compiled as the
/// renderer compiles them, shading 16 fragments (Gouraud: every vertex of the sphere).
fn kernels(c: &mut Criterion) {
    let (pos, normal) = lanes();
    let mut group = c.benchmark_group("kernel");
    group.throughput(Throughput::Elements(LANES as u64));
    let eye = Vec3::new(0.0, 0.0, 3.0);
    let coral = Material::coral();
    let material = LaneMaterial::uniform(&coral);
    let mut out = [[0.0; LANES]; 3];
    for (name, scene) in [
        ("single-light", bench_scene("quad-single").expect("scene").lights),
        ("multi-light", Scene::learnopengl_default()),
        ("floor-lights256", floor_lights()),
    ] {
        let k = MultiLightKernel::new(&scene, eye, coral.shininess, Specular::Phong);
        group.bench_function(name, |b| b.iter(|| k.shade(black_box(&pos), black_box(&normal), &material, &mut out)));
    }
    group.finish();
    let world = bench_scene("sphere4096-gouraud").expect("scene");
    let Some(object) = world.objects.first() else { return };
    let (verts, _) = vertex_stage(&object.geometry, object.model, &world.camera);
    let points: Vec<(Vec3, Vec3, Vec2)> = verts.iter().map(|v| (v.world, v.normal, v.uv)).collect();
    let k = MultiLightKernel::new(&world.lights, world.camera.eye, object.surface.shininess(), Specular::Phong);
    let mut group = c.benchmark_group("kernel");
    group.throughput(Throughput::Elements(points.len() as u64));
    group.bench_function("gouraud-vertices", |b| b.iter(|| light_points(&k, &object.surface, black_box(&points))));
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().without_plots().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
    targets = scenes, kernels
}
criterion_main!(benches);
