//! How close each benchmark scene runs to this machine's limits, and how its cost
//! grows: the roofline and the scaling measurements behind `lightlab bench
//! --roofline` and `lightlab bench --scaling`, the same scenes timed through OpenGL
//! (`lightlab bench --llvmpipe`), and the CSV files the book draws from.
//!
//! | module | what it holds |
//! | --- | --- |
//! | [`llvmpipe`] | the benchmark scenes drawn through OpenGL (Mesa llvmpipe), timed as the CPU back end is |
//! | [`roofline`] | the two probes (FMA throughput, store bandwidth), the operation and byte counts of a frame, the bound that applies |
//! | [`scaling`] | cost against the number of lights, the resolution and the threads, and Amdahl's law fitted to the threads |
//! | [`sweep`] | the triangle-size sweep: the sphere from 256 to 262,144 triangles, against llvmpipe |
//! | [`specialisations`] | the kernel's general path against its value-based specialisations, each alone and all together |
//!
//! Timing follows `llvmpipe_bench.py` ([`time_world`]): one frame to count
//! fragments, three warm-up frames, then runs of frames ([`crate::timing`]), the median run
//! reported.

use crate::raster::framebuffer::{Framebuffer, SizeError};
use crate::raster::pipeline::{FrameScratch, World};
use crate::timing::{time_runs, Timing};

pub mod llvmpipe;
pub mod roofline;
pub mod scaling;
pub mod specialisations;
pub mod sweep;

/// One world timed at one size: covered pixels of a frame and milliseconds per frame of each run.
#[derive(Clone, Debug, PartialEq)]
pub struct Timed {
    /// Pixels covered after one frame.
    pub fragments: usize,
    /// Milliseconds per frame, one value per run.
    pub runs_ms: Vec<f64>,
}

impl Timed {
    /// The runs' median, fastest and slowest ([`Timing::of_runs`]).
    #[must_use]
    pub fn timing(&self) -> Timing {
        Timing::of_runs(&self.runs_ms)
    }
}

/// Time `world` on a `width × height` framebuffer as `llvmpipe_bench.py` does: one frame
/// to count fragments, three warm-up frames, then `runs` runs of `frames` frames.
/// `runs` and `frames` below 1 count as 1. `save`, if given, receives the first frame.
pub fn time_world(
    world: &World,
    width: u32,
    height: u32,
    runs: usize,
    frames: usize,
    save: Option<&mut dyn FnMut(&Framebuffer)>,
) -> Result<Timed, SizeError> {
    let (runs, frames) = (runs.max(1), frames.max(1));
    let mut fb = Framebuffer::new(width, height)?;
    // the frame's buffers are allocated once, as a renderer keeps its vertex buffers
    let mut scratch = FrameScratch::default();
    world.render_with(&mut fb, &mut scratch);
    let fragments = fb.covered();
    if let Some(save) = save {
        save(&fb);
    }
    for _ in 0..3 {
        world.render_with(&mut fb, &mut scratch);
    }
    let runs_ms = time_runs(
        runs,
        frames,
        || {
            world.render_with(&mut fb, &mut scratch);
        },
        || {},
    );
    Ok(Timed { fragments, runs_ms })
}

/// The CPU model from `/proc/cpuinfo` (`unknown` elsewhere).
pub fn cpu_name() -> String {
    crate::study::speed::Machine::detect(1, 1).cpu
}
