//! What each value-based specialisation of the kernel brings: `lightlab bench
//! --specialisations`, and the general path of `lightlab bench --general`.
//!
//! | path | the kernel's [`Specialisations`] |
//! | --- | --- |
//! | `general` | none: three channels per light, `pow` as `exp2(y · log2 x)`, `R = reflect(−L, N)` then `R·V` |
//! | `grey-lights`, `whole-exponent`, `phong-rewrite` | that one alone ([`Specialisations::EACH`]) |
//! | `specialised` | all of them, the default |
//!
//! Each scene's five paths are timed in turn within every run (run 1 of each path, then
//! run 2 of each, …, each run starting at the next path), so that a disturbance on a
//! shared machine falls on all of them alike;
//! the median run is reported, as [`super::time_world`] does.

use serde::{Deserialize, Serialize};

use crate::raster::framebuffer::{Framebuffer, SizeError};
use crate::raster::kernel::Specialisations;
use crate::raster::presets::{bench_scene, BENCH_SIZE};
use crate::timing::{time_runs, Timing};

/// The scenes `bench --specialisations` measures by default: the per-fragment benchmark
/// scenes (Gouraud runs the kernel per vertex only) and one coloured-light scene, where the
/// grey path cannot apply.
pub const SPECIALISATION_SCENES: [&str; 6] =
    ["quad-single", "quad-multi", "cube-multi", "sphere4096-multi", "floor-lights256", "quad-multi-desert"];

/// The general path's name.
pub const GENERAL: &str = "general";
/// The fully specialised path's name.
pub const SPECIALISED: &str = "specialised";

/// The five paths, in the order they are timed and printed.
pub fn paths() -> Vec<(&'static str, Specialisations)> {
    let mut all = vec![(GENERAL, Specialisations::NONE)];
    all.extend(Specialisations::EACH);
    all.push((SPECIALISED, Specialisations::ALL));
    all
}

/// One scene on one path: a line of `lightlab bench --specialisations` and of its CSV.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpecialisationRow {
    /// Benchmark scene.
    pub scene: String,
    /// `general`, a specialisation's name, or `specialised`.
    pub path: String,
    /// Covered pixels of a frame.
    pub fragments: usize,
    /// Median milliseconds per frame.
    pub ms: f64,
    /// Fastest run.
    pub ms_min: f64,
    /// Slowest run.
    pub ms_max: f64,
    /// Threads rendering.
    pub threads: usize,
    /// CPU model.
    pub cpu: String,
    /// Instruction set of the kernel.
    pub isa: String,
}

/// Time every path of every scene in `scenes` (unknown names are skipped), `runs` runs of
/// `frames` frames each at [`BENCH_SIZE`]; `on_row` sees each row as it is measured.
pub fn measure(
    scenes: &[String],
    runs: usize,
    frames: usize,
    on_row: &mut dyn FnMut(&SpecialisationRow),
) -> Result<Vec<SpecialisationRow>, SizeError> {
    let paths = paths();
    let mut rows = Vec::new();
    let cpu = super::cpu_name();
    let isa = format!("{:?}", crate::raster::kernel::detect_isa());
    let threads = rayon::current_num_threads();
    for scene in scenes {
        let Some(base) = bench_scene(scene) else { continue };
        let worlds: Vec<_> = paths
            .iter()
            .map(|&(_, allowed)| crate::raster::pipeline::World { specialisations: allowed, ..base.clone() })
            .collect();
        let mut fb = Framebuffer::new(BENCH_SIZE.0, BENCH_SIZE.1)?;
        // one scratch for every path, as `time_world` keeps one for its frames
        let mut scratch = crate::raster::pipeline::FrameScratch::default();
        base.render_with(&mut fb, &mut scratch);
        let fragments = fb.covered();
        for world in &worlds {
            for _ in 0..3 {
                world.render_with(&mut fb, &mut scratch);
            }
        }
        let mut runs_ms = vec![Vec::new(); worlds.len()];
        for run in 0..runs.max(1) {
            // each run starts at the next path, so that no path always follows the same one
            for i in 0..worlds.len() {
                let k = (run + i) % worlds.len();
                let world = &worlds[k];
                runs_ms[k].extend(time_runs(1, frames, || _ = world.render_with(&mut fb, &mut scratch), || {}));
            }
        }
        for ((name, _), ms) in paths.iter().zip(&runs_ms) {
            let t = Timing::of_runs(ms);
            let row = SpecialisationRow {
                scene: scene.clone(),
                path: (*name).to_owned(),
                fragments,
                ms: t.ms_median,
                ms_min: t.ms_min,
                ms_max: t.ms_max,
                threads,
                cpu: cpu.clone(),
                isa: isa.clone(),
            };
            on_row(&row);
            rows.push(row);
        }
    }
    Ok(rows)
}

/// One scene's summary: its name, the general path's and the specialised path's ms per
/// frame, and each specialisation's speed-up over the general path when it alone is on (in
/// [`Specialisations::EACH`]'s order); `None` where a path is missing.
pub type Speedups = (String, Option<f64>, Option<f64>, Vec<Option<f64>>);

/// [`Speedups`] per scene, in first-seen order.
pub fn speedups(rows: &[SpecialisationRow]) -> Vec<Speedups> {
    let mut scenes: Vec<&str> = Vec::new();
    for r in rows {
        if !scenes.contains(&r.scene.as_str()) {
            scenes.push(&r.scene);
        }
    }
    scenes
        .into_iter()
        .map(|scene| {
            let ms = |path: &str| rows.iter().find(|r| r.scene == scene && r.path == path).map(|r| r.ms);
            let general = ms(GENERAL);
            let each = Specialisations::EACH.iter().map(|(name, _)| Some(general? / ms(name)?)).collect();
            (scene.to_owned(), general, ms(SPECIALISED), each)
        })
        .collect()
}
