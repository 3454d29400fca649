//! The roofline of the benchmark scenes: how close each runs to this machine's limit.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `P` | arithmetic peak, GFLOP/s: [`probe_peaks`] runs independent 16-lane FMAs on every thread (an FMA is 2 flops) |
//! | `β` | store bandwidth, GB/s: [`probe_peaks`] fills a buffer the size of the frame's colour and depth buffers, in bands on every thread, as the rasterizer writes them |
//! | `F`, `B` | operations and framebuffer bytes of one frame ([`frame_cost`]) |
//! | `I = F / B` | arithmetic intensity, flops per byte |
//! | `T_min = max(F / P, B / β)` | the roofline: the least time the frame can take on this machine |
//! | fraction | `T_min / T`: the share of the limit reached, 1 at the roof |
//! | bound | `arithmetic` when `F / P ≥ B / β`, else `memory` |
//!
//! The counts are a model, written down where the code is: the kernel's in
//! [`crate::raster::kernel::MultiLightKernel::flops_per_fragment`], the
//! rasterizer's and the framebuffer's in [`frame_cost`]. Triangle setup,
//! binning and the staging of fragments are not counted: they are the overhead
//! the fraction leaves room for.

use serde::{Deserialize, Serialize};

use crate::raster::framebuffer::Framebuffer;
use crate::raster::kernel::MultiLightKernel;
use crate::raster::pipeline::{Geometry, World};
use crate::raster::shade::{with_surface_material, ShadingMode, Surface};

/// Bytes per pixel of the colour buffer (linear `f32` RGBA).
pub const COLOR_BYTES: f64 = 16.0;
/// Bytes per pixel of the depth buffer (`f32`).
pub const DEPTH_BYTES: f64 = 4.0;

/// This machine's two limits.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Peaks {
    /// Arithmetic peak `P`, GFLOP/s, all threads.
    pub gflops: f64,
    /// Store bandwidth `β`, GB/s, all threads.
    pub store_gbs: f64,
    /// Threads both probes ran on.
    pub threads: usize,
}

/// Measure `P` and `β` (the best of three runs each); `frame_bytes` sizes the store
/// probe's buffer (the frame's colour and depth buffers, so that it lives where they do).
pub fn probe_peaks(frame_bytes: usize) -> Peaks {
    use rayon::prelude::*;
    let threads = rayon::current_num_threads();
    // 2^25 rounds of eight FMAs: tens of milliseconds per thread
    const ROUNDS: u64 = 1 << 25;
    // the best of five: on a shared machine the fastest run is the least disturbed
    let best = |f: &dyn Fn() -> f64| (0..5).map(|_| f()).fold(0.0, f64::max);
    let gflops = best(&|| {
        let mut flops = 0.0;
        let ms = crate::timing::time_once(|| {
            let (f, sink) = (0..threads)
                .into_par_iter()
                .map(|k| crate::raster::simd::fma_probe(ROUNDS, k as f32))
                .reduce(|| (0.0, 0.0), |x, y| (x.0 + y.0, x.1 + y.1));
            std::hint::black_box(sink);
            flops = f;
        });
        flops / (ms * 1e-3) / 1e9
    });
    let pixels = (frame_bytes / 16).max(1);
    let mut buffer = vec![[0.0f32; 4]; pixels];
    // bands of 16 rows of 800 pixels, as the rasterizer's
    let band = 16 * 800;
    const REPEATS: usize = 200;
    let store_gbs = best(&|| {
        let mut buffer = buffer.clone();
        let ms = crate::timing::time_once(|| {
            for r in 0..REPEATS {
                let value = [r as f32; 4];
                buffer.par_chunks_mut(band).for_each(|chunk| chunk.fill(value));
            }
        });
        std::hint::black_box(&buffer);
        (REPEATS * pixels * 16) as f64 / (ms * 1e-3) / 1e9
    });
    buffer.clear();
    Peaks { gflops, store_gbs, threads }
}

/// Operations and bytes of one frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameCost {
    /// Floating-point operations `F` (an FMA is 2; compares and selects count 1).
    pub flops: f64,
    /// Framebuffer bytes loaded and stored `B`.
    pub bytes: f64,
}

/// The operations per fragment of interpolating `nv` varyings in the band loop:
/// `1/w = w0 + wdx·x` (2), each varying `(v0 + vdx·x) / w` (3), the pixel's `x` (1).
pub fn interpolation_flops(nv: usize) -> f64 {
    3.0 + 3.0 * nv as f64
}

/// The depth test per fragment: `z = z0 + zdx·x` (2), the compare and the select (2).
pub const DEPTH_TEST_FLOPS: f64 = 4.0;

/// `F` and `B` of one frame of `world` at `width × height` pixels with `fragments` covered.
///
/// The kernel is counted as the world runs it: with its range window's operations and
/// specialisations ([`World::range_window`], [`World::specialisations`]); when the window
/// culls, only the share of lights evaluated, measured over one frame
/// ([`World::evaluated_light_share`]), so a culled scene's fraction is not inflated by
/// lights it skips.
/// - Clear: [`DEPTH_BYTES`] per pixel stored when depth is tested, and [`COLOR_BYTES`] per
///   pixel no fragment covers (the band clears its colour after the draws, only there).
/// - Per fragment: [`COLOR_BYTES`] stored; with the depth test, its [`DEPTH_BYTES`] loaded
///   and stored, and [`DEPTH_TEST_FLOPS`].
///
/// `fragments` is the count of covered pixels, so a frame drawn without overdraw stores
/// each pixel's colour once: cleared or shaded.
/// - Phong and Blinn-Phong: the kernel's operations and the interpolation of six
///   varyings (eight with lighting maps) per fragment. Gouraud: the kernel once per
///   vertex, three varyings per fragment. Flat: the kernel once per triangle.
///
/// Every benchmark scene has one object; with several, each object's per-fragment
/// cost is weighted equally (the covered pixels are not split by object).
pub fn frame_cost(world: &World, fragments: usize, width: u32, height: u32) -> FrameCost {
    let pixels = width as usize * height as usize;
    let share = match Framebuffer::new(width, height) {
        Ok(mut fb) => world.evaluated_light_share(&mut fb),
        Err(_) => 1.0,
    };
    let depth = if world.depth_test { 1.0 } else { 0.0 };
    let mut per_fragment = 0.0;
    let mut per_frame = 0.0;
    for object in &world.objects {
        let kernel = MultiLightKernel::new(
            &world.lights,
            world.camera.eye,
            object.surface.shininess(),
            world.shading.specular(),
        )
        .with_range_window(world.range_window)
        .with_specialisations(world.specialisations);
        let kernel = with_surface_material(kernel, &object.surface);
        let kernel_flops = kernel.flops_per_fragment_evaluating(share);
        let lit = !matches!(object.surface, Surface::Unlit(_));
        let (vertices, triangles) = match &object.geometry {
            Geometry::Mesh(m) => (m.positions.len(), m.triangles.len()),
            Geometry::NdcQuad => (4, 2),
        };
        match world.shading {
            ShadingMode::Phong | ShadingMode::BlinnPhong if lit => {
                let nv = if matches!(object.surface, Surface::Maps(..)) { 8 } else { 6 };
                per_fragment += kernel_flops + interpolation_flops(nv);
            }
            ShadingMode::Flat if lit => {
                per_fragment += interpolation_flops(3);
                per_frame += triangles as f64 * kernel.flops_per_fragment();
            }
            _ => {
                per_fragment += interpolation_flops(3);
                if lit {
                    per_frame += vertices as f64 * kernel.flops_per_fragment();
                }
            }
        }
    }
    let objects = world.objects.len().max(1) as f64;
    let per_fragment = per_fragment / objects + depth * DEPTH_TEST_FLOPS;
    let uncovered = pixels.saturating_sub(fragments);
    let bytes = uncovered as f64 * COLOR_BYTES
        + pixels as f64 * depth * DEPTH_BYTES
        + fragments as f64 * (COLOR_BYTES + depth * 2.0 * DEPTH_BYTES);
    FrameCost { flops: per_frame + fragments as f64 * per_fragment, bytes }
}

/// Which limit applies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Bound {
    /// `F / P ≥ B / β`.
    Arithmetic,
    /// `B / β > F / P`.
    Memory,
}

impl Bound {
    /// `arithmetic` or `memory`.
    pub fn name(self) -> &'static str {
        match self {
            Bound::Arithmetic => "arithmetic",
            Bound::Memory => "memory",
        }
    }
}

/// One scene on the roofline: a line of `lightlab bench --roofline` and of its CSV.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RooflineRow {
    /// Benchmark scene.
    pub scene: String,
    /// Covered pixels of a frame.
    pub fragments: usize,
    /// Pixels of a frame.
    pub pixels: usize,
    /// Median milliseconds per frame `T`.
    pub ms: f64,
    /// `F`.
    pub flops: f64,
    /// `B`.
    pub bytes: f64,
    /// `P`, GFLOP/s.
    pub peak_gflops: f64,
    /// `β`, GB/s.
    pub store_gbs: f64,
    /// Threads of the measurement and the probes.
    pub threads: usize,
    /// CPU model.
    pub cpu: String,
    /// Instruction set of the kernel.
    pub isa: String,
}

impl RooflineRow {
    /// The row of one scene.
    pub fn new(scene: &str, fragments: usize, pixels: usize, ms: f64, cost: FrameCost, peaks: &Peaks) -> RooflineRow {
        RooflineRow {
            scene: scene.to_owned(),
            fragments,
            pixels,
            ms,
            flops: cost.flops,
            bytes: cost.bytes,
            peak_gflops: peaks.gflops,
            store_gbs: peaks.store_gbs,
            threads: peaks.threads,
            cpu: super::cpu_name(),
            isa: format!("{:?}", crate::raster::kernel::detect_isa()),
        }
    }

    /// Achieved GFLOP/s, `F / T`.
    pub fn gflops(&self) -> f64 {
        self.flops / (self.ms * 1e-3) / 1e9
    }

    /// Achieved GB/s, `B / T`.
    pub fn gbs(&self) -> f64 {
        self.bytes / (self.ms * 1e-3) / 1e9
    }

    /// `I = F / B`, flops per byte.
    pub fn intensity(&self) -> f64 {
        self.flops / self.bytes
    }

    /// `T_min` in milliseconds.
    pub fn bound_ms(&self) -> f64 {
        (self.flops / (self.peak_gflops * 1e9)).max(self.bytes / (self.store_gbs * 1e9)) * 1e3
    }

    /// The limit that applies.
    pub fn bound(&self) -> Bound {
        if self.flops / self.peak_gflops >= self.bytes / self.store_gbs {
            Bound::Arithmetic
        } else {
            Bound::Memory
        }
    }

    /// `T_min / T`.
    pub fn fraction(&self) -> f64 {
        self.bound_ms() / self.ms
    }
}

impl std::fmt::Display for RooflineRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{:20} flops/frag={:.0} bytes/frag={:.1} GFLOP/s={:.1} GB/s={:.1} bound={} fraction={:.2} (peak {:.0} GFLOP/s, store {:.1} GB/s, {} threads)",
            self.scene,
            self.flops / self.fragments.max(1) as f64,
            self.bytes / self.fragments.max(1) as f64,
            self.gflops(),
            self.gbs(),
            self.bound().name(),
            self.fraction(),
            self.peak_gflops,
            self.store_gbs,
            self.threads
        )
    }
}

/// Rows as CSV with a header line (the `csv` crate; fields in [`RooflineRow`]'s order).
pub fn to_csv<T: Serialize>(rows: &[T]) -> Result<String, csv::Error> {
    let mut w = csv::Writer::from_writer(Vec::new());
    for r in rows {
        w.serialize(r)?;
    }
    let bytes = w.into_inner().map_err(|e| csv::Error::from(e.into_error()))?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// Rows back from [`to_csv`]'s text; an error names the record, its line and the field.
pub fn from_csv<T: for<'de> Deserialize<'de>>(text: &str) -> csv::Result<Vec<T>> {
    csv::Reader::from_reader(text.as_bytes()).deserialize().collect()
}
