//! `lightlab bench [SCENE…]`: time the benchmark scenes, in `llvmpipe_bench.py`'s output format.
//!
//! One line a scene:
//! `SCENE ms/frame=MEDIAN Mfrag/s=M fragments=N min_ms=… max_ms=… renderer=…`.
//! As the script: one frame to count fragments (alpha > 0 after a
//! transparent clear), three warm-up frames, then `--runs` runs of
//! `--frames` frames; the median run's time per frame is reported. A frame
//! is the clear, the vertex stage, setup, rasterization and shading.
//!
//! `--llvmpipe` also draws each scene through OpenGL ([`crate::study::bench::llvmpipe`]) in the same
//! run and prints its line (renderer `llvmpipe …`) and the speed ratio, llvmpipe's ms per
//! frame over lightlab's. No OpenGL context is an internal failure (exit 3).
//!
//! `--roofline` probes this machine's arithmetic peak and store bandwidth and prints, per
//! scene, its operations and bytes and the share of the limit it reaches
//! ([`crate::study::bench::roofline`]). `--scaling` measures cost against lights,
//! resolution and threads ([`crate::study::bench::scaling`]). `--general` draws every scene
//! with the kernel's value-based specialisations off ([`Specialisations::NONE`]), and
//! `--specialisations` times each scene on the general path, with each specialisation
//! alone, and with all ([`crate::study::bench::specialisations`]). With `--csv FILE`,
//! `--roofline`, `--scaling` or `--specialisations` writes its rows there (the book's
//! tables and charts are drawn from `book/data/bench/`).

use std::path::PathBuf;

use crate::raster::kernel::Specialisations;
use crate::raster::pipeline::World;
use crate::raster::presets::{all_bench_scenes, bench_scene, BENCH_SIZE, WINDOWED_SCENES};
use crate::study::bench::{roofline, scaling, specialisations, time_world, ColorTarget};
use crate::timing::Timing;

/// Most timed runs per scene `--runs` accepts (a thousand runs of the slowest scene take minutes).
pub const MAX_RUNS: usize = 1000;
/// Most frames per run `--frames` accepts.
pub const MAX_FRAMES: usize = 100_000;

/// Arguments of `lightlab bench`.
#[derive(clap::Args, Debug, Clone)]
pub struct BenchArgs {
    /// Scene names (default: the six benchmark scenes, then quad-multi-ATM and
    /// sphere4096-multi-ATM under each atmosphere's coloured lights, ATM = desert, factory,
    /// horror, biochemical-lab; floor-lights256-windowed and floor-lights256-windowed-culled
    /// are the 256-light floor with a range window at 7, without and with culling).
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
    /// Probe this machine's arithmetic peak and store bandwidth, and print each scene's
    /// operations, bytes, bound and the fraction of that bound it reaches.
    #[arg(long, conflicts_with = "scaling")]
    pub roofline: bool,
    /// Measure cost against lights (1 to 256), resolution (400x300 to 3840x2160) and
    /// threads (1 and 2) instead of the scene lines (about a minute).
    #[arg(long, conflicts_with = "specialisations")]
    pub scaling: bool,
    /// Draw every scene on the kernel's general path: no value-based specialisation (grey
    /// lights summed on one channel, whole exponents by squaring, Phong's R·V as
    /// L·(2(N·V)N − V), a plain material multiplied into coloured lights once), as a
    /// shader does for any values.
    #[arg(long, conflicts_with = "specialisations")]
    pub general: bool,
    /// Time each scene (default: quad-single, quad-multi, cube-multi, sphere4096-multi,
    /// floor-lights256, quad-multi-desert) on the general path, with each specialisation
    /// alone, and with all of them, in turn within every run.
    #[arg(long, conflicts_with_all = ["roofline", "llvmpipe"])]
    pub specialisations: bool,
    /// The triangle-size sweep: sphere4096-multi's sphere tessellated from 256 to 262144
    /// triangles at 800x600 (with --llvmpipe, each also through OpenGL, and the ratio).
    #[arg(long, conflicts_with_all = ["roofline", "scaling", "specialisations", "general"])]
    pub sweep: bool,
    /// With --roofline, --scaling or --specialisations: also write the rows to this CSV
    /// file (replaced whole, through a temporary file).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,
    /// Draw into an RGBA8 colour buffer, quantized as each pixel is written, instead of
    /// linear f32 RGBA (the same bytes in a --save PNG); with --llvmpipe, llvmpipe draws
    /// into GL_RGBA8 instead of GL_RGBA32F, so both sides store 4-byte pixels.
    /// llvmpipe_bench.py draws into RGBA32F: compare it with the default only.
    #[arg(long, conflicts_with_all = ["roofline", "scaling", "specialisations"])]
    pub rgba8: bool,
}

impl BenchArgs {
    /// The colour buffer of both sides: `--rgba8` or the float default.
    fn target(&self) -> ColorTarget {
        if self.rgba8 {
            ColorTarget::Rgba8
        } else {
            ColorTarget::Float
        }
    }
}

/// One scene's measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct BenchLine {
    /// Scene name.
    pub scene: String,
    /// Milliseconds per frame: the runs' median, fastest and slowest.
    pub timing: Timing,
    /// Covered pixels of one frame.
    pub fragments: usize,
    /// Who drew it: `lightlab CPU raster (N threads)` or the GL renderer string.
    pub renderer: String,
}

impl BenchLine {
    /// The line of `scene` from each run's milliseconds per frame ([`Timing::of_runs`]:
    /// the median as Python's `statistics.median`, the fastest and the slowest run).
    /// `runs_ms` must not be empty.
    pub fn from_runs(scene: &str, fragments: usize, runs_ms: &[f64], renderer: String) -> BenchLine {
        BenchLine { scene: scene.to_string(), timing: Timing::of_runs(runs_ms), fragments, renderer }
    }
}

impl BenchLine {
    /// Millions of fragments per second at the median.
    pub fn mfrag_per_s(&self) -> f64 {
        self.fragments as f64 / (self.timing.ms_median * 1e-3) / 1e6
    }
}

impl std::fmt::Display for BenchLine {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{:20} ms/frame={:.3} Mfrag/s={:.1} fragments={} min_ms={:.3} max_ms={:.3} renderer='{}'",
            self.scene,
            self.timing.ms_median,
            self.mfrag_per_s(),
            self.fragments,
            self.timing.ms_min,
            self.timing.ms_max,
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
    allowed: Specialisations,
    target: ColorTarget,
) -> Result<Option<BenchLine>, Box<dyn std::error::Error>> {
    let (runs, frames) = (runs.clamp(1, MAX_RUNS), frames.clamp(1, MAX_FRAMES));
    let Some(world) = bench_world(scene, allowed) else {
        return Ok(None);
    };
    if let Some(dir) = save {
        create_save_dir(dir)?;
    }
    let mut saved = Ok(());
    let mut save_png = |fb: &crate::raster::framebuffer::Rgba8Framebuffer| {
        if let Some(dir) = save {
            saved = fb.save_png(&dir.join(format!("{scene}.png")));
        }
    };
    // the float frame is quantized for the callback only when there is a PNG to write
    let save_first: Option<&mut dyn FnMut(&crate::raster::framebuffer::Rgba8Framebuffer)> =
        if save.is_some() { Some(&mut save_png) } else { None };
    let timed = time_world(&world, BENCH_SIZE.0, BENCH_SIZE.1, runs, frames, target, save_first)?;
    saved?;
    let mut renderer =
        if allowed == Specialisations::NONE { format!("{}, general path", renderer()) } else { renderer() };
    if target == ColorTarget::Rgba8 {
        renderer.push_str(", RGBA8");
    }
    Ok(Some(BenchLine::from_runs(scene, timed.fragments, &timed.runs_ms, renderer)))
}

/// Benchmark scene `name` with only the `allowed` specialisations; `None` if unknown.
fn bench_world(name: &str, allowed: Specialisations) -> Option<World> {
    bench_scene(name).map(|w| World { specialisations: allowed, ..w })
}

/// Creates `--save DIR`; the error names it.
fn create_save_dir(dir: &std::path::Path) -> Result<(), super::CliError> {
    std::fs::create_dir_all(dir)
        .map_err(|e| super::CliError::Input(format!("--save {}: cannot create the directory: {e}", dir.display())))
}

/// Checks every output before the first frame is timed (otherwise a measurement of
/// minutes would be lost to an unwritable path at the end): `--csv FILE`, and with `--save
/// DIR` the directory (created) and each scene's `DIR/SCENE.png`. Errors name the path.
fn check_outputs(args: &BenchArgs, names: &[String]) -> Result<(), Box<dyn std::error::Error>> {
    if let Some(path) = &args.csv {
        crate::outfile::check_writable(path)?;
    }
    if let Some(dir) = &args.save {
        create_save_dir(dir)?;
        for name in names {
            crate::outfile::check_writable(&dir.join(format!("{name}.png")))?;
        }
    }
    Ok(())
}

/// Run `lightlab bench`: print one line per scene. An unknown scene name is an error naming it.
pub fn run(args: &BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
    let known = all_bench_scenes();
    let names: Vec<String> = match (args.scenes.is_empty(), args.specialisations) {
        (false, _) => args.scenes.clone(),
        (true, true) => specialisations::SPECIALISATION_SCENES.iter().map(|s| s.to_string()).collect(),
        (true, false) => known.clone(),
    };
    for name in &names {
        if !known.contains(name) && !WINDOWED_SCENES.contains(&name.as_str()) {
            return Err(
                format!("unknown scene {name:?}; known: {}, {}", known.join(", "), WINDOWED_SCENES.join(", ")).into()
            );
        }
    }
    if args.csv.is_some() && !(args.roofline || args.scaling || args.specialisations || args.sweep) {
        return Err(
            super::CliError::Usage("--csv needs --roofline, --scaling, --specialisations or --sweep".into()).into()
        );
    }
    check_outputs(args, &names)?;
    if args.scaling {
        return run_scaling(args);
    }
    if args.specialisations {
        return run_specialisations(args, &names);
    }
    if args.sweep {
        return run_sweep(args);
    }
    let allowed = if args.general { Specialisations::NONE } else { Specialisations::ALL };
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
    let pixels = (BENCH_SIZE.0 * BENCH_SIZE.1) as usize;
    let peaks =
        args.roofline.then(|| roofline::probe_peaks(pixels * (roofline::COLOR_BYTES + roofline::DEPTH_BYTES) as usize));
    let mut rows = Vec::new();
    for name in &names {
        let Some(line) = measure(name, args.runs, args.frames, args.save.as_deref(), allowed, args.target())? else {
            continue;
        };
        super::output::println(&line)?;
        if let (Some(peaks), Some(world)) = (&peaks, bench_world(name, allowed)) {
            let cost = roofline::frame_cost(&world, line.fragments, BENCH_SIZE.0, BENCH_SIZE.1);
            let row = roofline::RooflineRow::new(name, line.fragments, pixels, line.timing.ms_median, cost, peaks);
            super::output::println(&row)?;
            rows.push(row);
        }
        #[cfg(feature = "gl")]
        if gl.is_some() && WINDOWED_SCENES.contains(&name.as_str()) {
            super::output::println(format!(
                "{name:20} no llvmpipe line: the range window is not the tutorials' falloff, so llvmpipe's 256-light shader is not the same work"
            ))?;
            continue;
        }
        #[cfg(feature = "gl")]
        if let Some(ctx) = &gl {
            let (runs, frames) = (args.runs.clamp(1, MAX_RUNS), args.frames.clamp(1, MAX_FRAMES));
            let run = crate::study::bench::llvmpipe::run_scene_in(ctx, name, args.target(), runs, frames)
                .map_err(|e| super::CliError::Internal(format!("{name} through OpenGL: {e}")))?;
            let gl_line = BenchLine::from_runs(name, run.fragments, &run.runs_ms, run.renderer);
            super::output::println(&gl_line)?;
            super::output::println(format!(
                "{:20} speed ratio={:.2} (llvmpipe ms/frame / lightlab ms/frame, same run)",
                name,
                gl_line.timing.ms_median / line.timing.ms_median
            ))?;
        }
    }
    if let Some(path) = &args.csv {
        crate::outfile::write_atomically(path, roofline::to_csv(&rows)?)?;
    }
    Ok(())
}

/// `lightlab bench --sweep`: one line per tessellation (and its llvmpipe line and ratio).
fn run_sweep(args: &BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
    use crate::study::bench::sweep::{triangles, SweepRow, SWEEP_STACKS};
    let (runs, frames) = (args.runs.clamp(1, MAX_RUNS), args.frames.clamp(1, MAX_FRAMES));
    #[cfg(feature = "gl")]
    let gl = if args.llvmpipe {
        Some(
            crate::gl::GlContext::new()
                .map_err(|e| super::CliError::Internal(format!("--llvmpipe needs an OpenGL context: {e}")))?,
        )
    } else {
        None
    };
    #[cfg(not(feature = "gl"))]
    if args.llvmpipe {
        return Err(super::CliError::Usage("--llvmpipe needs lightlab built with the `gl` feature".into()).into());
    }
    let mut rows = Vec::new();
    for stacks in SWEEP_STACKS {
        let name = format!("sphere{}-multi", triangles(stacks));
        let world = crate::raster::presets::sphere_multi(stacks)
            .ok_or_else(|| super::CliError::Internal(format!("no sphere of {stacks} stacks")))?;
        let timed = time_world(&world, BENCH_SIZE.0, BENCH_SIZE.1, runs, frames, args.target(), None)?;
        let line = BenchLine::from_runs(&name, timed.fragments, &timed.runs_ms, renderer());
        super::output::println(&line)?;
        #[allow(unused_mut)]
        let mut llvmpipe_ms = None;
        #[cfg(feature = "gl")]
        if let Some(ctx) = &gl {
            let run = crate::study::bench::llvmpipe::run_world_in(ctx, &world, args.target(), runs, frames)
                .map_err(|e| super::CliError::Internal(format!("{name} through OpenGL: {e}")))?;
            let gl_line = BenchLine::from_runs(&name, run.fragments, &run.runs_ms, run.renderer);
            super::output::println(&gl_line)?;
            llvmpipe_ms = Some(gl_line.timing.ms_median);
        }
        let row = SweepRow {
            stacks,
            triangles: triangles(stacks),
            fragments: timed.fragments,
            lightlab_ms: line.timing.ms_median,
            llvmpipe_ms,
        };
        if let Some(ratio) = row.ratio() {
            super::output::println(format!(
                "{name:20} pixels/triangle={:.2} speed ratio={ratio:.2} (llvmpipe ms/frame / lightlab ms/frame, same run)",
                row.pixels_per_triangle()
            ))?;
        }
        rows.push(row);
    }
    if let Some(path) = &args.csv {
        crate::outfile::write_atomically(path, roofline::to_csv(&rows)?)?;
    }
    Ok(())
}

/// `lightlab bench --specialisations`: one line per scene and path, then per scene the
/// speed-ups over the general path.
fn run_specialisations(args: &BenchArgs, names: &[String]) -> Result<(), Box<dyn std::error::Error>> {
    let (runs, frames) = (args.runs.clamp(1, MAX_RUNS), args.frames.clamp(1, MAX_FRAMES));
    let mut printed = Ok(());
    let rows = specialisations::measure(names, runs, frames, &mut |r| {
        if printed.is_ok() {
            printed = super::output::println(format!(
                "{:20} path={:15} ms/frame={:.3} min_ms={:.3} max_ms={:.3} fragments={}",
                r.scene, r.path, r.ms, r.ms_min, r.ms_max, r.fragments
            ));
        }
    })?;
    printed?;
    for (scene, general, specialised, each) in specialisations::speedups(&rows) {
        let (Some(general), Some(specialised)) = (general, specialised) else { continue };
        let alone: Vec<String> = Specialisations::EACH
            .iter()
            .zip(&each)
            .map(|((name, _), x)| format!("{name}={}", x.map_or("-".into(), |x| format!("{x:.2}"))))
            .collect();
        super::output::println(format!(
            "{scene:20} specialised/general speed-up={:.2} alone: {} (general ms/frame / path ms/frame, same run)",
            general / specialised,
            alone.join(" ")
        ))?;
    }
    if let Some(path) = &args.csv {
        crate::outfile::write_atomically(path, roofline::to_csv(&rows)?)?;
    }
    Ok(())
}

/// `lightlab bench --scaling`: one line per measurement, progress on standard error.
fn run_scaling(args: &BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
    let (runs, frames) = (args.runs.clamp(1, MAX_RUNS), args.frames.clamp(1, MAX_FRAMES));
    let mut printed = Ok(());
    let rows = scaling::measure_scaling(runs, frames, &mut |r| {
        if printed.is_ok() {
            printed = super::output::println(format!(
                "{:8} {:20} lights={:3} {:>4}x{:<4} threads={} ms/frame={:.3} ns/fragment={:.2} fragments={}",
                r.axis,
                r.scene,
                r.lights,
                r.width,
                r.height,
                r.threads,
                r.ms,
                r.ns_per_fragment(),
                r.fragments
            ));
        }
    })?;
    printed?;
    for (name, t1, t2, p) in scaling::amdahl_table(&rows) {
        super::output::println(format!(
            "{name:20} speed-up on 2 threads={:.2} (fastest runs) parallel share p={:.2} (Amdahl: 4 threads {:.2}, 8 threads {:.2}, limit {})",
            t1 / t2,
            p,
            scaling::amdahl_speedup(p, 4.0),
            scaling::amdahl_speedup(p, 8.0),
            if p < 1.0 { format!("{:.1}", 1.0 / (1.0 - p)) } else { "none".to_owned() }
        ))?;
    }
    if let Some(path) = &args.csv {
        crate::outfile::write_atomically(path, roofline::to_csv(&rows)?)?;
    }
    Ok(())
}
