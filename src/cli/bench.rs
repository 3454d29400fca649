//! `lightlab bench [SCENE…]`: time the benchmark scenes, in `llvmpipe_bench.py`'s output format.
//!
//! One line a scene:
//! `SCENE ms/frame=MEDIAN Mfrag/s=M fragments=N min_ms=… max_ms=… renderer=…`.
//! As the script: one frame to count fragments (alpha > 0 after a
//! transparent clear), three warm-up frames, then `--runs` runs of
//! `--frames` frames; the median run's time per frame is reported. A frame
//! is the clear, the vertex stage, setup, rasterization and shading.
//!
//! `--llvmpipe` also draws each scene through OpenGL ([`crate::gl::bench`]) in the same
//! run and prints its line (renderer `llvmpipe …`) and the speed ratio, llvmpipe's ms per
//! frame over lightlab's. No OpenGL context is an internal failure (exit 3).

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
    /// Also draw each scene through OpenGL (Mesa llvmpipe, the crate's own GL module, the
    /// tutorials' shaders) in the same run, and print its line and the speed ratio
    /// (llvmpipe's ms per frame / lightlab's).
    #[arg(long)]
    pub llvmpipe: bool,
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
    /// Who drew it: `lightlab CPU raster (N threads)` or the GL renderer string.
    pub renderer: String,
}

impl BenchLine {
    /// The line of `scene` from each run's milliseconds per frame: the median (the mean of
    /// the two middle values for an even count, as Python's `statistics.median`), the
    /// fastest and the slowest run. `runs_ms` must not be empty.
    pub fn from_runs(scene: &str, fragments: usize, runs_ms: &[f64], renderer: String) -> BenchLine {
        let mut sorted = runs_ms.to_vec();
        sorted.sort_by(f64::total_cmp);
        let n = sorted.len().max(1);
        let at = |k: usize| sorted.get(k).copied().unwrap_or(f64::NAN);
        let median = if n % 2 == 1 { at(n / 2) } else { 0.5 * (at(n / 2 - 1) + at(n / 2)) };
        BenchLine {
            scene: scene.to_string(),
            ms_per_frame: median,
            fragments,
            min_ms: at(0),
            max_ms: at(n - 1),
            renderer,
        }
    }
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
            self.renderer
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
        times.push(t0.elapsed().as_secs_f64() * 1e3 / frames as f64);
    }
    Ok(Some(BenchLine::from_runs(scene, fragments, &times, renderer())))
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
    #[cfg(feature = "gl")]
    let gl = if args.llvmpipe {
        let ctx = crate::gl::GlContext::new()
            .map_err(|e| super::CliError::Internal(format!("--llvmpipe needs an OpenGL context: {e}")))?;
        Some(ctx)
    } else {
        None
    };
    #[cfg(not(feature = "gl"))]
    if args.llvmpipe {
        return Err(super::CliError::Usage("--llvmpipe needs lightlab built with the `gl` feature".into()).into());
    }
    for name in &names {
        let Some(line) = measure(name, args.runs, args.frames, args.save.as_deref())? else { continue };
        super::output::println(&line)?;
        #[cfg(feature = "gl")]
        if let Some(ctx) = &gl {
            let (runs, frames) = (args.runs.clamp(1, MAX_RUNS), args.frames.clamp(1, MAX_FRAMES));
            let run = crate::gl::bench::run_scene(ctx, name, runs, frames)
                .map_err(|e| super::CliError::Internal(format!("{name} through OpenGL: {e}")))?;
            let gl_line = BenchLine::from_runs(name, run.fragments, &run.runs_ms, run.renderer);
            super::output::println(&gl_line)?;
            super::output::println(format!(
                "{:20} speed ratio={:.2} (llvmpipe ms/frame / lightlab ms/frame, same run)",
                name,
                gl_line.ms_per_frame / line.ms_per_frame
            ))?;
        }
    }
    Ok(())
}
