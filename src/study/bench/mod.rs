//! How close each benchmark scene runs to this machine's limits, and how its cost
//! grows: the roofline and the scaling measurements behind `lightlab bench
//! --roofline` and `lightlab bench --scaling`, and the CSV files the book draws from.
//!
//! | module | what it holds |
//! | --- | --- |
//! | [`roofline`] | the two probes (FMA throughput, store bandwidth), the operation and byte counts of a frame, the bound that applies |
//! | [`scaling`] | cost against the number of lights, the resolution and the threads, and Amdahl's law fitted to the threads |
//!
//! Timing follows `llvmpipe_bench.py` ([`time_world`]): one frame to count
//! fragments, three warm-up frames, then runs of frames, the median run reported.

use std::time::Instant;

use crate::raster::framebuffer::{Framebuffer, SizeError};
use crate::raster::pipeline::World;

pub mod roofline;
pub mod scaling;

/// One world timed at one size: covered pixels of a frame and milliseconds per frame of each run.
#[derive(Clone, Debug, PartialEq)]
pub struct Timed {
    /// Pixels covered after one frame.
    pub fragments: usize,
    /// Milliseconds per frame, one value per run.
    pub runs_ms: Vec<f64>,
}

impl Timed {
    /// The median run (the mean of the two middle ones for an even count, as Python's
    /// `statistics.median`); NaN without runs.
    pub fn median_ms(&self) -> f64 {
        median(&self.runs_ms)
    }
}

/// The median of `xs` (the mean of the two middle values for an even count, as Python's
/// `statistics.median`); NaN for none.
pub fn median(xs: &[f64]) -> f64 {
    let mut sorted = xs.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
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
    world.render(&mut fb);
    let fragments = fb.covered();
    if let Some(save) = save {
        save(&fb);
    }
    for _ in 0..3 {
        world.render(&mut fb);
    }
    let mut runs_ms = Vec::with_capacity(runs);
    for _ in 0..runs {
        let t0 = Instant::now();
        for _ in 0..frames {
            world.render(&mut fb);
        }
        runs_ms.push(t0.elapsed().as_secs_f64() * 1e3 / frames as f64);
    }
    Ok(Timed { fragments, runs_ms })
}

/// The CPU model from `/proc/cpuinfo` (`unknown` elsewhere).
pub fn cpu_name() -> String {
    crate::study::speed::Machine::detect(1, 1).cpu
}
