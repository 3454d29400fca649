//! The roofline's counts and formulas, and the committed benchmark CSVs the book draws from.
#![cfg(feature = "book")]

use glam::Vec3;
use lightlab::casters::{Attenuation, PointLight};
use lightlab::material::LightProps;
use lightlab::raster::kernel::{MultiLightKernel, Specular};
use lightlab::raster::presets::{all_bench_scenes, bench_scene, BENCH_SCENES, BENCH_SIZE};
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
    let (w, h) = BENCH_SIZE;
    let pixels = (w * h) as usize;
    let none = frame_cost(&world, 0, w, h);
    // no fragment: the clear's colour stores only (no depth test on the quads)
    assert_eq!(none, FrameCost { flops: 0.0, bytes: COLOR_BYTES * pixels as f64 });
    let half = frame_cost(&world, pixels / 2, w, h);
    let all = frame_cost(&world, pixels, w, h);
    assert!((all.flops - 2.0 * half.flops).abs() <= 1e-9 * all.flops, "per-fragment work is linear");
    // each pixel's colour is stored once, by the clear where no fragment covers it or by
    // its fragment: the same bytes at any coverage (exact: sums of whole multiples of 16)
    assert_eq!(half.bytes, none.bytes);
    assert_eq!(all.bytes, none.bytes);
    // the cube tests depth: its clear and its fragments move depth bytes too
    let cube = bench_scene("cube-multi").expect("scene");
    assert!(frame_cost(&cube, 0, w, h).bytes > none.bytes);
}

/// The windowed floors are counted as they run: the window's operations on every light,
/// and with culling only the lights evaluated. The expected share is computed here
/// independently of the kernel and the rasterizer: per pixel centre, the floor point the
/// camera sees and the lights within the range of it. Batches of 16 fragments cull on a
/// bounding box, which can only keep more lights than the pixels need, so the counted
/// share lies between the per-pixel share and a little above it.
#[test]
fn the_windowed_floors_count_the_window_and_only_the_lights_evaluated() {
    use lightlab::raster::presets::FLOOR_RANGE;
    let (w, h) = (200u32, 150u32);
    let world = |name: &str| lightlab::raster::presets::bench_scene_at(name, w as f32 / h as f32).expect("scene");
    let (plain, windowed, culled) =
        (world("floor-lights256"), world("floor-lights256-windowed"), world("floor-lights256-windowed-culled"));
    let mut fb = lightlab::raster::framebuffer::Framebuffer::new(w, h).expect("size");
    plain.render(&mut fb);
    let fragments = fb.covered();
    // the per-pixel share: cast each pixel centre's ray onto the floor y = -1
    let inverse = plain.camera.view_projection().inverse();
    let lights = &plain.lights.point_lights;
    let (mut within, mut seen) = (0usize, 0usize);
    for j in 0..h {
        for i in 0..w {
            let ndc = Vec3::new((i as f32 + 0.5) / w as f32 * 2.0 - 1.0, 1.0 - (j as f32 + 0.5) / h as f32 * 2.0, 1.0);
            let far = inverse.project_point3(ndc);
            let eye = plain.camera.eye;
            let dir = far - eye;
            if dir.y >= 0.0 {
                continue;
            }
            let p = eye + dir * ((-1.0 - eye.y) / dir.y);
            if p.x.abs() > 10.0 || p.z < -20.0 || p.z > 3.0 {
                continue;
            }
            seen += 1;
            within += lights.iter().filter(|l| l.position.distance(p) < FLOOR_RANGE).count();
        }
    }
    assert!(seen.abs_diff(fragments) <= fragments / 100, "the floor's pixels: {seen} cast, {fragments} drawn");
    let pixel_share = within as f64 / (seen * lights.len()) as f64;
    let share = culled.evaluated_light_share(&mut fb);
    assert!(share >= 0.99 * pixel_share && share <= 1.5 * pixel_share, "share {share}, per pixel {pixel_share}");
    // the camera sees the floor at a grazing angle, so far rows gather many lights: measured 0.37
    assert!(pixel_share < 0.5, "most lights are out of range of most of the floor: {pixel_share}");
    assert_eq!(windowed.evaluated_light_share(&mut fb), 1.0);
    // the counts: per light, 38 + power 7 + sums 18 (coloured lights folded with the material), plus 7 for the window
    let (f_plain, f_windowed, f_culled) = (
        frame_cost(&plain, fragments, w, h).flops,
        frame_cost(&windowed, fragments, w, h).flops,
        frame_cost(&culled, fragments, w, h).flops,
    );
    let per_fragment = |f: f64| f / fragments as f64;
    let lights_n = lights.len() as f64;
    assert!((per_fragment(f_windowed) - per_fragment(f_plain) - 7.0 * lights_n).abs() < 1e-6);
    // culled: the lights' part scaled by the share, plus the bounding box and the box tests;
    // a windowed coloured point light is 38 + window 7 + power 7 + folded sums 18 (the kernel's table)
    let per_light = 38.0 + 7.0 + 7.0 + 18.0;
    let expected = per_fragment(f_windowed) - lights_n * per_light * (1.0 - share) + 7.0 + 0.75 * lights_n;
    assert!((per_fragment(f_culled) - expected).abs() < 1e-6, "{} against {expected}", per_fragment(f_culled));
    // and so the culled floor is counted at a fraction of the unwindowed one's operations
    let factor = f_culled / f_plain;
    // (the window's 7 operations make each evaluated light dearer than a plain one: 70 against 63)
    assert!(factor < 0.6 && factor > pixel_share, "culled / plain = {factor}, per-pixel share {pixel_share}");
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
    // `bench --roofline` times every default scene: the six, then the coloured ones
    assert_eq!(scenes, all_bench_scenes());
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
