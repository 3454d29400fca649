//! Speed against accuracy: every method timed and compared with the `f64` ray-cast ground truth.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `ms/frame` | median over `runs` timed runs of the wall time of one frame (both cores), with min and max |
//! | `ns/fragment` | `ms/frame` divided by the covered pixels of the frame |
//! | `max err`, `mean err` | largest and mean absolute channel difference from the reference, in 8-bit levels (`255 · |a − b|` on values clamped to [0, 1]) over pixels covered in both images |
//! | `> 1/255` | share of those pixels with some channel off by more than one level |
//! | `FLIP` | mean FLIP (LDR, 67 pixels per degree) of the 8-bit images over those pixels |
//!
//! Three scenes, all at the design's 800 × 600 (quick mode: 160 × 120):
//!
//! - [`SPHERE`]: a unit sphere (rotated, so the normal matrix is not the
//!   identity) under LearnOpenGL's Multiple lights, drawn by the rasterizer.
//!   Tessellation, Gouraud against Phong, where the normal matrix is computed,
//!   the 16-lane kernel against scalar [`crate::scene::Scene::shade`], culling on and off.
//! - [`GBUFFER`]: the same sphere with exact inputs: the ray caster's hit
//!   points and normals, rounded to `f32`, are shaded directly. No geometry
//!   error, so what remains is the shading arithmetic: `powf` against lookup
//!   tables, Schlick and an `exp2`/`log2` polynomial; exact normalize against
//!   rsqrt with one Newton step; `f32` against `f64`; Phong against Blinn-Phong.
//! - [`FLOOR`]: a floor under 25 short-range lights (LearnOpenGL's range-7
//!   attenuation) spaced wider than their cull distance, where
//!   [`crate::study::culling`] does skip lights.
//!
//! The reference is [`crate::raster::raycast`], one ray through each pixel
//! centre (where the rasterizer samples), shading in `f64` with the lobe the
//! method uses. Timings are not deterministic; everything else is.
//!
//! The book's chapter "Speed against accuracy" shows the results.

use glam::{DVec3, Vec3};

use crate::raster::framebuffer::Framebuffer;
use crate::raster::raycast::RayScene;

mod floor;
mod gbuffer;
mod results;
mod scenes;
mod sphere;
mod variants;

pub use floor::floor_skipped_share;
pub use results::*;
pub use scenes::*;
pub use sphere::{sphere_vertices, NormalMatrixAt};
pub use variants::*;

use floor::floor_study;
use gbuffer::gbuffer_study;
#[allow(unused_imports)]
use sphere::PerLane;
use sphere::{sphere_study, RasterFrame, Shading};

/// Name of the rasterized sphere scene.
pub const SPHERE: &str = "sphere-multi";
/// Name of the exact-input (G-buffer) sphere scene.
pub const GBUFFER: &str = "sphere-gbuffer";
/// Name of the many-short-lights floor scene.
pub const FLOOR: &str = "floor-lights";
/// The three scenes, in the order the study runs them.
pub const SCENES: [&str; 3] = [SPHERE, GBUFFER, FLOOR];

/// How big and how long the study is.
#[derive(Clone, Debug, PartialEq)]
pub struct StudyOptions {
    /// Frame width in pixels.
    pub width: u32,
    /// Frame height in pixels.
    pub height: u32,
    /// Timed runs per method (the median, min and max are over these).
    pub runs: usize,
    /// Each run repeats the frame until it lasts at least this long (seconds).
    pub min_run_seconds: f64,
    /// Sphere stacks of the tessellation sweep (slices = 2 · stacks).
    pub tessellations: Vec<u32>,
    /// Stacks of the mesh the other sphere methods use.
    pub method_stacks: u32,
}

impl StudyOptions {
    /// The full study: 800 × 600, 7 runs of at least 60 ms, 8 × 16 … 256 × 512.
    pub fn full() -> StudyOptions {
        StudyOptions {
            width: 800,
            height: 600,
            runs: 7,
            min_run_seconds: 0.06,
            tessellations: vec![8, 16, 32, 64, 128, 256],
            method_stacks: 128,
        }
    }

    /// Seconds, for tests and CI: 160 × 120, 3 runs of one frame, 8 × 16 … 64 × 128.
    pub fn quick() -> StudyOptions {
        StudyOptions {
            width: 160,
            height: 120,
            runs: 3,
            min_run_seconds: 0.0,
            tessellations: vec![8, 16, 32, 64],
            method_stacks: 32,
        }
    }
}

pub use crate::timing::Timing;

/// Error of one image against the reference, over pixels covered in both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelErrorStats {
    /// Largest channel difference, 8-bit levels.
    pub max_levels: f64,
    /// Mean channel difference, 8-bit levels.
    pub mean_levels: f64,
    /// Share (0..1) of pixels with some channel off by more than one level.
    pub over_one: f64,
    /// Mean FLIP over the pixels.
    pub flip: f64,
    /// Pixels compared.
    pub pixels: usize,
}

/// One measured method.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    /// Scene name ([`SCENES`]).
    pub scene: String,
    /// Which comparison it belongs to (`tessellation`, `pow`, `culling`, ...).
    pub group: String,
    /// The method, as the tables and charts label it.
    pub method: String,
    /// Covered pixels of one frame.
    pub fragments: usize,
    /// Cost.
    pub timing: Timing,
    /// Error.
    pub error: PixelErrorStats,
}

impl Row {
    /// Median nanoseconds per covered fragment (`NaN` for no fragments).
    pub fn ns_per_fragment(&self) -> f64 {
        self.timing.ms_median * 1e6 / self.fragments as f64
    }
}

/// The machine the timings come from.
#[derive(Clone, Debug, PartialEq)]
pub struct Machine {
    /// CPU model (`/proc/cpuinfo`'s `model name`, or `unknown`).
    pub cpu: String,
    /// Logical cores available to the process.
    pub cores: usize,
    /// Instruction set the kernel and rasterizer chose (`Avx512`, `Avx2`, `Baseline`).
    pub isa: String,
    /// Frame size, `W×H`.
    pub frame: String,
}

impl Machine {
    /// Describe this machine for a `width × height` frame.
    pub fn detect(width: u32, height: u32) -> Machine {
        let cpu = std::fs::read_to_string("/proc/cpuinfo")
            .ok()
            .and_then(|s| {
                s.lines()
                    .find(|l| l.starts_with("model name"))
                    .and_then(|l| l.split_once(':'))
                    .map(|(_, v)| v.trim().to_owned())
            })
            .unwrap_or_else(|| "unknown".to_owned());
        Machine {
            cpu,
            cores: rayon::current_num_threads(),
            isa: format!("{:?}", crate::raster::kernel::detect_isa()),
            frame: format!("{width}×{height}"),
        }
    }
}

// ---------------------------------------------------------------------------
// Measuring

/// Time `frame`: one warm-up call that also sizes a run (frames per run so a run
/// lasts at least `min_seconds`, at most 200), then `runs` timed runs ([`crate::timing`]).
pub fn time(runs: usize, min_seconds: f64, mut frame: impl FnMut()) -> Timing {
    let first_ms = crate::timing::time_once(&mut frame);
    let frames = ((min_seconds * 1e3 / first_ms).ceil() as usize).clamp(1, 200);
    Timing::of_runs(&crate::timing::time_runs(runs, frames, frame, || {}))
}

/// Error of `test` (linear RGB per pixel, `None` where not covered) against `reference`.
///
/// Pixels covered in only one image are left out (the silhouette of a coarse
/// mesh differs from the true sphere's; that is coverage, not shading). FLIP
/// compares the two 8-bit images as displayed (no gamma, as the tutorials);
/// its per-pixel values are averaged over the compared pixels.
pub fn compare(width: u32, height: u32, test: &[Option<Vec3>], reference: &[Option<DVec3>]) -> PixelErrorStats {
    let (mut max, mut sum, mut over, mut pixels) = (0.0f64, 0.0f64, 0usize, 0usize);
    let mut flip_mask = vec![false; test.len()];
    for (k, (t, r)) in test.iter().zip(reference).enumerate() {
        let (Some(t), Some(r)) = (t, r) else { continue };
        let d = (t.as_dvec3().clamp(DVec3::ZERO, DVec3::ONE) - r.clamp(DVec3::ZERO, DVec3::ONE)).abs() * 255.0;
        max = max.max(d.max_element());
        sum += d.x + d.y + d.z;
        over += usize::from(d.max_element() > 1.0);
        pixels += 1;
        flip_mask[k] = true;
    }
    let to8 = |c: Vec3| crate::color::to_rgb8(c);
    let img_t: Vec<u8> = test.iter().flat_map(|c| to8(c.unwrap_or(Vec3::ZERO))).collect();
    let img_r: Vec<u8> = reference.iter().flat_map(|c| to8(c.unwrap_or(DVec3::ZERO).as_vec3())).collect();
    let flip = flip_mean(width, height, &img_r, &img_t, &flip_mask);
    let p = pixels.max(1) as f64;
    PixelErrorStats { max_levels: max, mean_levels: sum / (3.0 * p), over_one: over as f64 / p, flip, pixels }
}

fn flip_mean(width: u32, height: u32, reference: &[u8], test: &[u8], mask: &[bool]) -> f64 {
    if mask.iter().all(|m| !m) {
        return 0.0;
    }
    let r = nv_flip::FlipImageRgb8::with_data(width, height, reference);
    let t = nv_flip::FlipImageRgb8::with_data(width, height, test);
    let err = nv_flip::flip(r, t, nv_flip::DEFAULT_PIXELS_PER_DEGREE).to_vec();
    let (sum, n) =
        err.iter().zip(mask).filter(|(_, m)| **m).fold((0.0f64, 0usize), |(s, n), (e, _)| (s + *e as f64, n + 1));
    sum / n as f64
}

fn pixels_of(fb: &Framebuffer) -> Vec<Option<Vec3>> {
    fb.color.iter().map(|c| (c[3] > 0.0).then(|| Vec3::new(c[0], c[1], c[2]))).collect()
}

/// Progress callback: one line per method.
pub type Progress<'a> = &'a mut dyn FnMut(&str);

struct Ctx<'a> {
    opts: &'a StudyOptions,
    progress: Progress<'a>,
    rows: Vec<Row>,
}

impl Ctx<'_> {
    fn raster(
        &mut self,
        scene: &str,
        group: &str,
        method: &str,
        frame: &RasterFrame,
        shading: &Shading,
        reference: &[Option<DVec3>],
    ) {
        (self.progress)(&format!("{scene}: {method}"));
        let (w, h) = (self.opts.width, self.opts.height);
        let mut fb = Framebuffer::new(w, h).expect("the study's frame size is valid");
        frame.draw(&mut fb, shading);
        let fragments = fb.covered();
        let error = compare(w, h, &pixels_of(&fb), reference);
        let timing = time(self.opts.runs, self.opts.min_run_seconds, || frame.draw(&mut fb, shading));
        self.push(scene, group, method, fragments, timing, error);
    }

    fn push(
        &mut self,
        scene: &str,
        group: &str,
        method: &str,
        fragments: usize,
        timing: Timing,
        error: PixelErrorStats,
    ) {
        self.rows.push(Row {
            scene: scene.into(),
            group: group.into(),
            method: method.into(),
            fragments,
            timing,
            error,
        });
    }
}

fn ray_reference(scene: &RayScene, w: u32, h: u32) -> Vec<Option<DVec3>> {
    let img = scene.render(w, h, 1).expect("the study's frame size is valid");
    img.color.iter().map(|c| (c[3] > 0.5).then(|| DVec3::new(c[0], c[1], c[2]))).collect()
}

/// Run the whole study; `progress` gets one line per step.
pub fn run_study(opts: &StudyOptions, progress: Progress) -> Vec<Row> {
    let mut ctx = Ctx { opts, progress, rows: Vec::new() };
    sphere_study(&mut ctx);
    gbuffer_study(&mut ctx);
    floor_study(&mut ctx);
    ctx.rows
}
