//! How the cost of a frame grows with the number of lights, the resolution and the threads.
//!
//! | axis | scene | values |
//! | --- | --- | --- |
//! | lights | `floor-lights256` with its first `k` lights | [`LIGHT_COUNTS`], at 800 × 600 |
//! | pixels | `quad-multi` (every pixel covered) and `sphere4096-multi` | [`RESOLUTIONS`] |
//! | threads | every benchmark scene | 1 and 2 (those this machine has) |
//!
//! Amdahl's law with a parallel share `p`: `S(n) = 1 / ((1 − p) + p / n)`. From
//! the measured `S(2) = T₁ / T₂`, `p = 2 (1 − T₂ / T₁)` ([`amdahl_share`]); then
//! [`amdahl_speedup`] says what `n` threads would give, `1 / (1 − p)` at most.

use serde::{Deserialize, Serialize};

use super::{time_world, ColorTarget, Timed};
use crate::raster::framebuffer::SizeError;
use crate::raster::pipeline::World;
use crate::raster::presets::{bench_scene_at, BENCH_SCENES, BENCH_SIZE};

/// Light counts of the lights axis.
pub const LIGHT_COUNTS: [usize; 5] = [1, 4, 16, 64, 256];
/// Frame sizes of the pixels axis, 400 × 300 to 3840 × 2160.
pub const RESOLUTIONS: [(u32, u32); 5] = [(400, 300), (800, 600), (1280, 720), (1920, 1080), (3840, 2160)];
/// Scenes of the pixels axis.
pub const PIXEL_SCENES: [&str; 2] = ["quad-multi", "sphere4096-multi"];
/// Thread counts of the threads axis (those above this machine's are skipped).
pub const THREADS: [usize; 2] = [1, 2];

/// One measurement.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ScalingRow {
    /// `lights`, `pixels` or `threads`.
    pub axis: String,
    /// Benchmark scene.
    pub scene: String,
    /// Lights in the scene.
    pub lights: usize,
    /// Frame width.
    pub width: u32,
    /// Frame height.
    pub height: u32,
    /// Threads rendering.
    pub threads: usize,
    /// Covered pixels of a frame.
    pub fragments: usize,
    /// Median milliseconds per frame.
    pub ms: f64,
    /// Fastest run.
    pub ms_min: f64,
    /// Slowest run.
    pub ms_max: f64,
}

impl ScalingRow {
    fn new(axis: &str, scene: &str, world: &World, size: (u32, u32), threads: usize, t: &Timed) -> ScalingRow {
        let timing = t.timing();
        ScalingRow {
            axis: axis.to_owned(),
            scene: scene.to_owned(),
            lights: world.lights.point_lights.len()
                + world.lights.dir_light.is_some() as usize
                + world.lights.spot_light.is_some() as usize,
            width: size.0,
            height: size.1,
            threads,
            fragments: t.fragments,
            ms: timing.ms_median,
            ms_min: timing.ms_min,
            ms_max: timing.ms_max,
        }
    }

    /// Nanoseconds per covered pixel.
    pub fn ns_per_fragment(&self) -> f64 {
        self.ms * 1e6 / self.fragments.max(1) as f64
    }
}

/// `p = 2 (1 − T₂ / T₁)`, the parallel share of Amdahl's law from one- and two-thread
/// times, clamped to [0, 1] (noise can push a measured speed-up past 2 or below 1).
pub fn amdahl_share(t1: f64, t2: f64) -> f64 {
    (2.0 * (1.0 - t2 / t1)).clamp(0.0, 1.0)
}

/// Per benchmark scene, `(scene, T₁, T₂, p)` from the fastest runs of the threads axis
/// (on a shared machine the fastest run is the one least disturbed).
pub fn amdahl_table(rows: &[ScalingRow]) -> Vec<(String, f64, f64, f64)> {
    BENCH_SCENES
        .iter()
        .filter_map(|name| {
            let t = |n: usize| {
                rows.iter().find(|r| r.axis == "threads" && r.scene == *name && r.threads == n).map(|r| r.ms_min)
            };
            let (t1, t2) = (t(1)?, t(2)?);
            Some((name.to_string(), t1, t2, amdahl_share(t1, t2)))
        })
        .collect()
}

/// `S(n) = 1 / ((1 − p) + p / n)`.
pub fn amdahl_speedup(p: f64, n: f64) -> f64 {
    1.0 / ((1.0 - p) + p / n)
}

/// The scene at an aspect; the names come from [`BENCH_SCENES`] and [`PIXEL_SCENES`],
/// which `bench_scene_at` knows (a unit test checks it), so an unknown one is an empty world.
fn scene(name: &str, size: (u32, u32)) -> World {
    bench_scene_at(name, size.0 as f32 / size.1 as f32).unwrap_or_else(|| World {
        camera: crate::raster::camera::Camera::learnopengl(1.0),
        lights: crate::scene::Scene::learnopengl_default(),
        objects: Vec::new(),
        shading: crate::raster::shade::ShadingMode::Phong,
        clear: glam::Vec4::ZERO,
        depth_test: false,
        range_window: None,
        specialisations: crate::raster::kernel::Specialisations::ALL,
    })
}

/// Run `f` on a pool of `threads` threads (the global pool if that fails).
fn with_threads<T: Send>(threads: usize, f: impl FnOnce() -> T + Send) -> T {
    match rayon::ThreadPoolBuilder::new().num_threads(threads).build() {
        Ok(pool) => pool.install(f),
        Err(_) => f(),
    }
}

/// Shortest run: a few frames of a millisecond would measure the scheduler, not the frame.
pub const MIN_RUN_MS: f64 = 100.0;
/// Most frames per run.
pub const MAX_RUN_FRAMES: usize = 200;

/// Time `world` with at least `frames` frames per run, and more (up to
/// [`MAX_RUN_FRAMES`]) so that a run lasts [`MIN_RUN_MS`].
fn time_long_enough(world: &World, size: (u32, u32), runs: usize, frames: usize) -> Result<Timed, SizeError> {
    let probe = time_world(world, size.0, size.1, 1, 1, ColorTarget::Float, None)?;
    let one = probe.timing().ms_median.max(1e-3);
    let frames = frames.max((MIN_RUN_MS / one).ceil() as usize).min(MAX_RUN_FRAMES);
    time_world(world, size.0, size.1, runs, frames, ColorTarget::Float, None)
}

/// Every measurement of the three axes, `runs` runs of at least `frames` frames each
/// (more where a run would be shorter than [`MIN_RUN_MS`]);
/// `progress` sees each row as it is measured.
pub fn measure_scaling(
    runs: usize,
    frames: usize,
    progress: &mut dyn FnMut(&ScalingRow),
) -> Result<Vec<ScalingRow>, SizeError> {
    let mut rows = Vec::new();
    let all = rayon::current_num_threads();
    let mut push = |row: ScalingRow, rows: &mut Vec<ScalingRow>| {
        progress(&row);
        rows.push(row);
    };
    for k in LIGHT_COUNTS {
        let mut world = scene("floor-lights256", BENCH_SIZE);
        world.lights.point_lights.truncate(k);
        let t = time_long_enough(&world, BENCH_SIZE, runs, frames)?;
        push(ScalingRow::new("lights", "floor-lights256", &world, BENCH_SIZE, all, &t), &mut rows);
    }
    for name in PIXEL_SCENES {
        for (w, h) in RESOLUTIONS {
            let world = scene(name, (w, h));
            let t = time_long_enough(&world, (w, h), runs, frames)?;
            push(ScalingRow::new("pixels", name, &world, (w, h), all, &t), &mut rows);
        }
    }
    for name in BENCH_SCENES {
        for threads in THREADS.into_iter().filter(|&n| n <= all.max(1)) {
            let world = scene(name, BENCH_SIZE);
            let t = with_threads(threads, || time_long_enough(&world, BENCH_SIZE, runs, frames))?;
            push(ScalingRow::new("threads", name, &world, BENCH_SIZE, threads, &t), &mut rows);
        }
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raster::presets::bench_scene;

    #[test]
    fn every_scaling_scene_is_a_benchmark_scene() {
        for name in PIXEL_SCENES.iter().chain(["floor-lights256"].iter()) {
            assert!(bench_scene(name).is_some(), "{name}");
        }
    }

    #[test]
    fn amdahl_share_inverts_the_speedup() {
        // p = 0.9 gives S(2) = 1/(0.1 + 0.45) = 1.818…; the share comes back to rounding
        let p = 0.9;
        let s2 = amdahl_speedup(p, 2.0);
        assert!((amdahl_share(1.0, 1.0 / s2) - p).abs() < 1e-12);
        // no speed-up means no parallel share; a perfect one means p = 1
        assert_eq!(amdahl_share(1.0, 1.0), 0.0);
        assert_eq!(amdahl_share(2.0, 1.0), 1.0);
        // noise past the ideal is clamped
        assert_eq!(amdahl_share(2.2, 1.0), 1.0);
        assert_eq!(amdahl_share(1.0, 1.2), 0.0);
        assert_eq!(amdahl_speedup(1.0, 8.0), 8.0);
    }
}
