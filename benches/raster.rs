//! Criterion benchmarks of the raster back end: the five benchmark scenes of
//! `../shared/DESIGN.md` (one frame each) and the 16-lane multi-light kernel.
//!
//! Kept short by default (10 samples, 1 s each; no plots, which would need system fonts); `lightlab bench` is the
//! command whose output lines up with `llvmpipe_bench.py`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use glam::Vec3;
use lightlab::material::Material;
use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::kernel::{LaneMaterial, MultiLightKernel, Specular, LANES};
use lightlab::raster::presets::{bench_scene, BENCH_SCENES, BENCH_SIZE};
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

fn kernel(c: &mut Criterion) {
    let scene = Scene::learnopengl_default();
    let m = Material::coral();
    let k = MultiLightKernel::new(&scene, Vec3::new(0.0, 0.0, 3.0), m.shininess, Specular::Phong);
    let material = LaneMaterial::uniform(&m);
    let mut pos = [[0.0; LANES]; 3];
    let mut normal = [[0.0; LANES]; 3];
    for l in 0..LANES {
        let x = l as f32 / LANES as f32 - 0.5;
        pos[0][l] = x;
        pos[1][l] = 0.3 * x;
        normal[0][l] = x;
        normal[2][l] = 1.0;
    }
    let mut out = [[0.0; LANES]; 3];
    let mut group = c.benchmark_group("kernel");
    group.throughput(Throughput::Elements(LANES as u64));
    group.bench_function("multi-light-16", |b| {
        b.iter(|| k.shade(black_box(&pos), black_box(&normal), &material, &mut out))
    });
    group.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().without_plots().sample_size(10).warm_up_time(Duration::from_millis(300)).measurement_time(Duration::from_secs(1));
    targets = scenes, kernel
}
criterion_main!(benches);
