//! `lightlab bench [SCENE…]`: time the benchmark scenes, in `llvmpipe_bench.py`'s output format.
//!
//! One line a scene:
//! `SCENE ms/frame=MEDIAN Mfrag/s=M fragments=N min_ms=… max_ms=… renderer=…`.
//! As the script: one frame to count fragments (alpha > 0 after a
//! transparent clear), three warm-up frames, then `--runs` runs of
//! `--frames` frames; the median run's time per frame is reported. A frame
//! is the clear, the vertex stage, setup, rasterization and shading.

use std::path::PathBuf;
use std::time::Instant;

use crate::raster::framebuffer::Framebuffer;
use crate::raster::presets::{bench_scene, BENCH_SCENES, BENCH_SIZE};

/// Most timed runs per scene `--runs` accepts (a thousand runs of the slowest scene take minutes).
pub const MAX_RUNS: usize = 1000;
/// Most frames per run `--frames` accepts.
pub const MAX_FRAMES: usize = 100_000;

/// Arguments of `lightlab bench`.
#[derive(clap::Args, Debug, Clone)]
pub struct BenchArgs {
    /// Scene names (default: all six).
    pub scenes: Vec<String>,
    /// Timed runs per scene (1 to 1000).
    #[arg(long, default_value_t = 5, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=MAX_RUNS as u64))]
    pub runs: usize,
    /// Frames per run (1 to 100000).
    #[arg(long, default_value_t = 60, value_parser = clap::builder::RangedU64ValueParser::<usize>::new().range(1..=MAX_FRAMES as u64))]
    pub frames: usize,
    /// Also write SCENE.png of one frame into this directory.
    #[arg(long, value_name = "DIR")]
    pub save: Option<PathBuf>,
}

/// One scene's measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchLine {
    /// Scene name.
    pub scene: String,
    /// Median milliseconds per frame.
    pub ms_per_frame: f64,
    /// Covered pixels of one frame.
    pub fragments: usize,
    /// Fastest run, ms per frame.
    pub min_ms: f64,
    /// Slowest run, ms per frame.
    pub max_ms: f64,
}

impl BenchLine {
    /// Millions of fragments per second at the median.
    pub fn mfrag_per_s(&self) -> f64 {
        self.fragments as f64 / (self.ms_per_frame * 1e-3) / 1e6
    }
}

impl std::fmt::Display for BenchLine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{:20} ms/frame={:.3} Mfrag/s={:.1} fragments={} min_ms={:.3} max_ms={:.3} renderer='{}'",
            self.scene,
            self.ms_per_frame,
            self.mfrag_per_s(),
            self.fragments,
            self.min_ms,
            self.max_ms,
            renderer()
        )
    }
}

/// The renderer string: lightlab, thread count.
pub fn renderer() -> String {
    #[cfg(feature = "book")]
    let threads = rayon::current_num_threads();
    #[cfg(not(feature = "book"))]
    let threads = 1;
    format!("lightlab CPU raster ({threads} threads)")
}

/// Measure one scene; `None` for an unknown name. `runs` and `frames` are
/// clamped to `1..=MAX_RUNS` and `1..=MAX_FRAMES`.
pub fn measure(
    scene: &str,
    runs: usize,
    frames: usize,
    save: Option<&std::path::Path>,
) -> Result<Option<BenchLine>, Box<dyn std::error::Error>> {
    let (runs, frames) = (runs.clamp(1, MAX_RUNS), frames.clamp(1, MAX_FRAMES));
    let Some(world) = bench_scene(scene) else {
        return Ok(None);
    };
    let mut fb = Framebuffer::new(BENCH_SIZE.0, BENCH_SIZE.1)?;
    world.render(&mut fb);
    let fragments = fb.covered();
    if let Some(dir) = save {
        std::fs::create_dir_all(dir)?;
        fb.save_png(&dir.join(format!("{scene}.png")), false)?;
    }
    for _ in 0..3 {
        world.render(&mut fb);
    }
    let mut times = Vec::with_capacity(runs);
    for _ in 0..runs {
        let t0 = Instant::now();
        for _ in 0..frames {
            world.render(&mut fb);
        }
        times.push(t0.elapsed().as_secs_f64() / frames as f64);
    }
    let mut sorted = times.clone();
    sorted.sort_by(f64::total_cmp);
    // Python's statistics.median: the mean of the two middle values for an even count
    let n = sorted.len();
    let median = if n % 2 == 1 { sorted[n / 2] } else { 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]) };
    Ok(Some(BenchLine {
        scene: scene.to_string(),
        ms_per_frame: median * 1e3,
        fragments,
        min_ms: sorted[0] * 1e3,
        max_ms: sorted[n - 1] * 1e3,
    }))
}

/// Run `lightlab bench`: print one line per scene. An unknown scene name is an error naming it.
pub fn run(args: &BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
    let names: Vec<String> =
        if args.scenes.is_empty() { BENCH_SCENES.iter().map(|s| s.to_string()).collect() } else { args.scenes.clone() };
    for name in &names {
        if !BENCH_SCENES.contains(&name.as_str()) {
            return Err(format!("unknown scene {name:?}; known: {}", BENCH_SCENES.join(", ")).into());
        }
    }
    for name in &names {
        if let Some(line) = measure(name, args.runs, args.frames, args.save.as_deref())? {
            super::output::println(line)?;
        }
    }
    Ok(())
}
