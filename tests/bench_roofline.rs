//! The roofline's counts and formulas, and the committed benchmark CSVs the book draws from.
#![cfg(feature = "book")]

use glam::Vec3;
use lightlab::casters::{Attenuation, PointLight};
use lightlab::material::LightProps;
use lightlab::raster::kernel::{MultiLightKernel, Specular};
use lightlab::raster::presets::{bench_scene, BENCH_SCENES, BENCH_SIZE};
use lightlab::scene::Scene;
use lightlab::study::bench::roofline::{
    frame_cost, from_csv, to_csv, Bound, FrameCost, Peaks, RooflineRow, COLOR_BYTES,
};
use lightlab::study::bench::scaling::ScalingRow;

fn point(color: Vec3) -> PointLight {
    PointLight {
        position: Vec3::new(1.0, 2.0, 3.0),
        attenuation: Attenuation { constant: 1.0, linear: 0.09, quadratic: 0.032 },
        props: LightProps { ambient: 0.05 * color, diffuse: 0.8 * color, specular: color },
    }
}

fn kernel_flops(lights: usize, color: Vec3, specular: Specular, shininess: f32) -> f64 {
    let scene =
        Scene { dir_light: None, point_lights: vec![point(color); lights], spot_light: None, clear_color: Vec3::ZERO };
    MultiLightKernel::new(&scene, Vec3::Z, shininess, specular).flops_per_fragment()
}

#[test]
fn kernel_operations_grow_by_the_same_amount_per_light() {
    let grey = Vec3::ONE;
    let per_light = kernel_flops(1, grey, Specular::Phong, 32.0) - kernel_flops(0, grey, Specular::Phong, 32.0);
    assert!(per_light > 0.0);
    for n in [2, 7, 256] {
        let grown = kernel_flops(n, grey, Specular::Phong, 32.0) - kernel_flops(0, grey, Specular::Phong, 32.0);
        assert_eq!(grown, n as f64 * per_light, "{n} lights");
    }
}

#[test]
fn kernel_operations_follow_the_variant_that_runs() {
    let (grey, red) = (Vec3::ONE, Vec3::new(1.0, 0.2, 0.2));
    // coloured lights sum three channels, grey ones one
    assert!(kernel_flops(4, red, Specular::Phong, 32.0) > kernel_flops(4, grey, Specular::Phong, 32.0));
    // Blinn normalizes a half vector per light; Phong reuses N·L and N·V
    assert!(kernel_flops(4, grey, Specular::Blinn, 32.0) > kernel_flops(4, grey, Specular::Phong, 32.0));
    // a fractional exponent goes through exp2(y log2 x), dearer than square-and-multiply
    assert!(kernel_flops(4, grey, Specular::Phong, 31.5) > kernel_flops(4, grey, Specular::Phong, 64.0));
    assert!(kernel_flops(4, grey, Specular::Phong, 64.0) > kernel_flops(4, grey, Specular::Phong, 32.0));
}

#[test]
fn frame_cost_counts_the_clear_and_the_fragments() {
    let world = bench_scene("quad-single").expect("scene");
    let pixels = (BENCH_SIZE.0 * BENCH_SIZE.1) as usize;
    let none = frame_cost(&world, 0, pixels);
    // no fragment: the clear's colour stores only (no depth test on the quads)
    assert_eq!(none, FrameCost { flops: 0.0, bytes: COLOR_BYTES * pixels as f64 });
    let half = frame_cost(&world, pixels / 2, pixels);
    let all = frame_cost(&world, pixels, pixels);
    assert!((all.flops - 2.0 * half.flops).abs() <= 1e-9 * all.flops, "per-fragment work is linear");
    // the cube tests depth: its clear and its fragments move depth bytes too
    let cube = bench_scene("cube-multi").expect("scene");
    assert!(frame_cost(&cube, 0, pixels).bytes > none.bytes);
}

#[test]
fn the_bound_is_the_larger_time_and_the_csv_reads_back() {
    let peaks = Peaks { gflops: 100.0, store_gbs: 10.0, threads: 2 };
    // 1 GFLOP and 0.05 GB: 10 ms of arithmetic, 5 ms of stores; measured 20 ms
    let row = RooflineRow::new("x", 1000, 1000, 20.0, FrameCost { flops: 1e9, bytes: 5e7 }, &peaks);
    assert_eq!(row.bound(), Bound::Arithmetic);
    assert!((row.bound_ms() - 10.0).abs() < 1e-9);
    assert!((row.fraction() - 0.5).abs() < 1e-12);
    let memory = RooflineRow::new("y", 1000, 1000, 20.0, FrameCost { flops: 1e8, bytes: 1e8 }, &peaks);
    assert_eq!(memory.bound(), Bound::Memory);
    let text = to_csv(&[row.clone(), memory.clone()]).expect("csv");
    let back: Vec<RooflineRow> = from_csv(&text).expect("parse");
    assert_eq!(back, vec![row, memory]);
    // a malformed file is an error naming where, not a panic
    let bad = text.replace("20.0", "fast");
    let e = from_csv::<RooflineRow>(&bad).expect_err("not a number");
    assert!(e.to_string().contains("line"), "{e}");
}

#[test]
fn the_committed_csvs_hold_every_benchmark_scene() {
    let roofline: Vec<RooflineRow> =
        from_csv(include_str!("../book/data/bench/roofline.csv")).expect("roofline.csv parses");
    let scenes: Vec<&str> = roofline.iter().map(|r| r.scene.as_str()).collect();
    assert_eq!(scenes, BENCH_SCENES);
    let scaling: Vec<ScalingRow> =
        from_csv(include_str!("../book/data/bench/scaling.csv")).expect("scaling.csv parses");
    for axis in ["lights", "pixels", "threads"] {
        assert!(scaling.iter().any(|r| r.axis == axis), "{axis}");
    }
    for name in BENCH_SCENES {
        for threads in [1, 2] {
            assert!(
                scaling.iter().any(|r| r.axis == "threads" && r.scene == name && r.threads == threads),
                "{name} {threads}"
            );
        }
    }
}
