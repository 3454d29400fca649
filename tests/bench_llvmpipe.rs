//! `lightlab bench --llvmpipe` draws the same scenes through OpenGL as the CPU back end:
//! the same coverage and, within the tolerance of `tests/raster_images.rs`, the same pixels.
#![cfg(feature = "gl")]

use crate::gl_common;

use lightlab::raster::framebuffer::Framebuffer;
use lightlab::raster::presets::{all_bench_scenes, bench_scene, BENCH_SIZE};
use lightlab::study::bench::llvmpipe::run_scene;

/// One 8-bit step of a linear value, as `Framebuffer::to_rgba8` rounds it.
fn step(x: f32) -> i32 {
    (x.clamp(0.0, 1.0) * 255.0).round() as i32
}

#[test]
fn every_scene_draws_the_cpu_back_ends_image_through_opengl() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let (w, h) = (BENCH_SIZE.0 as usize, BENCH_SIZE.1 as usize);
    for name in all_bench_scenes() {
        let name = name.as_str();
        let gl = run_scene(&ctx, name, 1, 1).unwrap();
        assert_eq!(gl.runs_ms.len(), 1);
        assert!(gl.runs_ms[0] > 0.0, "{name}");
        let world = bench_scene(name).unwrap();
        let mut fb = Framebuffer::new(BENCH_SIZE.0, BENCH_SIZE.1).unwrap();
        world.render(&mut fb);
        let mut over = 0;
        for row in 0..h {
            for x in 0..w {
                let ours = fb.color[row * w + x];
                let theirs = &gl.rgba[((h - 1 - row) * w + x) * 4..][..4]; // GL's rows are bottom first
                let covered = (ours[3] > 0.0) == (theirs[3] > 0.0);
                if !covered || (0..3).any(|c| (step(ours[c]) - step(theirs[c])).abs() > 1) {
                    over += 1;
                }
            }
        }
        println!(
            "{name}: GL {} fragments, CPU {}; {over} pixels differ by more than 1/255",
            gl.fragments,
            fb.covered()
        );
        // the tolerance of tests/raster_images.rs: silhouette pixels whose centre is closer to
        // an edge than one vertex-snapping step may fall either way (measured 1 in cube-multi,
        // 2 in each sphere scene); allow 0.01% of the image (48 pixels)
        assert!(over <= w * h / 10_000, "{name}: {over} pixels differ");
        assert!(gl.fragments.abs_diff(fb.covered()) <= w * h / 10_000, "{name}: coverage");
    }
}

/// The same check fails when the GL image is not the scene's: quad-single's image against
/// quad-multi's CPU render.
#[test]
fn a_different_scene_does_not_pass_for_the_same_image() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let gl = run_scene(&ctx, "quad-single", 1, 1).unwrap();
    let mut fb = Framebuffer::new(BENCH_SIZE.0, BENCH_SIZE.1).unwrap();
    bench_scene("quad-multi").unwrap().render(&mut fb);
    let (w, h) = (BENCH_SIZE.0 as usize, BENCH_SIZE.1 as usize);
    let over = (0..w * h)
        .filter(|&i| {
            let (row, x) = (i / w, i % w);
            let theirs = &gl.rgba[((h - 1 - row) * w + x) * 4..][..4];
            (0..3).any(|c| (step(fb.color[i][c]) - step(theirs[c])).abs() > 1)
        })
        .count();
    assert!(over > w * h / 10_000, "only {over} pixels differ");
    assert!(run_scene(&ctx, "no-such-scene", 1, 1).is_err());
}
