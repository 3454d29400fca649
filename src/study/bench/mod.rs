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

use crate::raster::framebuffer::{Framebuffer, Rgba8Framebuffer, SizeError};
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

/// The colour buffer a benchmark frame is drawn into, on both sides of a comparison.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ColorTarget {
    /// Linear f32 RGBA, 16 bytes a pixel ([`Framebuffer`]); llvmpipe draws into a
    /// `GL_RGBA32F` renderbuffer, as `llvmpipe_bench.py` does (`dtype="f4"`).
    #[default]
    Float,
    /// RGBA8, 4 bytes a pixel, quantized as written ([`Rgba8Framebuffer`]); llvmpipe draws
    /// into a `GL_RGBA8` renderbuffer (`lightlab bench --rgba8`).
    Rgba8,
}

impl ColorTarget {
    /// Bytes per pixel of the colour buffer: 16 or 4.
    pub fn bytes_per_pixel(self) -> usize {
        match self {
            ColorTarget::Float => 16,
            ColorTarget::Rgba8 => 4,
        }
    }
}

/// Time `world` on a `width × height` framebuffer with a `target` colour buffer, as
/// `llvmpipe_bench.py` does: one frame to count fragments, three warm-up frames, then
/// `runs` runs of `frames` frames. `runs` and `frames` below 1 count as 1. `save`, if
/// given, receives the first frame in RGBA8 (quantized from the float target by
/// [`Rgba8Framebuffer::from_float`]: the same bytes with either target).
pub fn time_world(
    world: &World,
    width: u32,
    height: u32,
    runs: usize,
    frames: usize,
    target: ColorTarget,
    save: Option<&mut dyn FnMut(&Rgba8Framebuffer)>,
) -> Result<Timed, SizeError> {
    let (runs, frames) = (runs.max(1), frames.max(1));
    // the frame's buffers are allocated once, as a renderer keeps its vertex buffers
    let mut scratch = FrameScratch::default();
    let (fragments, runs_ms) = match target {
        ColorTarget::Float => {
            let mut fb = Framebuffer::new(width, height)?;
            world.render_with(&mut fb, &mut scratch);
            if let Some(save) = save {
                save(&Rgba8Framebuffer::from_float(&fb));
            }
            (fb.covered(), time_frames(runs, frames, || _ = world.render_with(&mut fb, &mut scratch)))
        }
        ColorTarget::Rgba8 => {
            let mut fb = Rgba8Framebuffer::new(width, height)?;
            world.render_rgba8_with(&mut fb, &mut scratch);
            if let Some(save) = save {
                save(&fb);
            }
            (fb.covered(), time_frames(runs, frames, || _ = world.render_rgba8_with(&mut fb, &mut scratch)))
        }
    };
    Ok(Timed { fragments, runs_ms })
}

/// Three warm-up frames, then `runs` runs of `frames` frames: ms per frame of each run.
fn time_frames(runs: usize, frames: usize, mut frame: impl FnMut()) -> Vec<f64> {
    for _ in 0..3 {
        frame();
    }
    time_runs(runs, frames, frame, || {})
}

/// The CPU model from `/proc/cpuinfo` (`unknown` elsewhere).
pub fn cpu_name() -> String {
    crate::study::speed::Machine::detect(1, 1).cpu
}
