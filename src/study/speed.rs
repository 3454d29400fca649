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
//!   the 16-lane kernel against scalar [`Scene::shade`], culling on and off.
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
//! Source: lightlab issue 6, part 1, "The speed-against-accuracy study".

use std::time::Instant;

use glam::{DVec3, Mat3, Mat4, Vec2, Vec3, Vec4};
use rayon::prelude::*;

use crate::casters::{Attenuation, DirLight, PointLight, RANGE_TABLE};
use crate::material::{LightProps, Material};
use crate::normals::{normal_matrix_cofactor, normal_matrix_inverse_transpose};
use crate::raster::camera::Camera;
use crate::raster::clip::{ClipVertex, MAX_VARYINGS};
use crate::raster::framebuffer::Framebuffer;
use crate::raster::kernel::{pow_or_zero, LaneMaterial, Lanes, MultiLightKernel, Specular, LANES};
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::light_points;
use crate::raster::rasterize::{render, CullMode, DrawCall, FragmentBatch, FragmentShader};
use crate::raster::raycast::{shade_f64, RayObject, RayScene, Shape};
use crate::raster::shade::{ColorShader, LitShader, Surface};
use crate::scene::Scene;

use super::culling::{cull, threshold_for, CulledScene, MaterialBound};

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

/// Wall time of one frame over the timed runs, milliseconds.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// Median run.
    pub median_ms: f64,
    /// Fastest run.
    pub min_ms: f64,
    /// Slowest run.
    pub max_ms: f64,
}

/// Error of one image against the reference, over pixels covered in both.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorStats {
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
    pub error: ErrorStats,
}

impl Row {
    /// Median nanoseconds per covered fragment (`NaN` for no fragments).
    pub fn ns_per_fragment(&self) -> f64 {
        self.timing.median_ms * 1e6 / self.fragments as f64
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
// Shading variants (scalar f32, written out so each approximation can be swapped in)

/// How `pow(base, shininess)` is evaluated for `base ∈ [0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub enum PowMethod {
    /// `f32::powf` (0 for a base ≤ 0).
    Powf,
    /// A table of `base^s` at `n` evenly spaced bases in [0, 1], linearly
    /// interpolated, in the manner of Mesa's fixed-function shininess table.
    Lut(Vec<f32>),
    /// Schlick 1994: `x / (s − s·x + x)`, a rational stand-in for `x^s`.
    Schlick,
    /// `exp2(s · log2 x)` with polynomial `exp2` and `log2` ([`pow_or_zero`] of the kernel).
    Exp2Log2,
}

impl PowMethod {
    /// A lookup table of `entries` values of `x^shininess` (`entries` below 2 is raised to 2).
    pub fn lut(entries: usize, shininess: f32) -> PowMethod {
        let n = entries.max(2);
        PowMethod::Lut((0..n).map(|k| (k as f32 / (n - 1) as f32).powf(shininess)).collect())
    }

    /// `base^s` for `base ≥ 0` (a negative or NaN base gives 0, as the shaders' clamp).
    pub fn eval(&self, base: f32, s: f32) -> f32 {
        if base.is_nan() || base <= 0.0 {
            return 0.0;
        }
        match self {
            PowMethod::Powf => base.powf(s),
            PowMethod::Lut(table) => {
                let f = base.min(1.0) * (table.len() - 1) as f32;
                let k = (f as usize).min(table.len() - 2);
                let t = f - k as f32;
                table[k] + t * (table[k + 1] - table[k])
            }
            PowMethod::Schlick => base / (s - s * base + base),
            PowMethod::Exp2Log2 => pow_or_zero(base, s),
        }
    }
}

/// How vectors are normalized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Normalize {
    /// `v / |v|` (glam's `normalize_or_zero`).
    Exact,
    /// `v · r` with `r` the magic-constant estimate of `1/√(v·v)` (Lomont's
    /// `0x5f375a86`) refined by one Newton step: relative error below 2e-3.
    RsqrtNewton,
}

/// `1/√x` by the magic-constant estimate and one Newton step; 0 for `x ≤ 0` or non-finite `x`.
pub fn rsqrt_newton(x: f32) -> f32 {
    if !(x > 0.0 && x.is_finite()) {
        return 0.0;
    }
    let y = f32::from_bits(0x5f37_5a86 - (x.to_bits() >> 1));
    y * (1.5 - 0.5 * x * y * y)
}

impl Normalize {
    fn apply(self, v: Vec3) -> Vec3 {
        match self {
            Normalize::Exact => v.normalize_or_zero(),
            Normalize::RsqrtNewton => v * rsqrt_newton(v.length_squared()),
        }
    }

    fn length(self, v: Vec3) -> f32 {
        match self {
            Normalize::Exact => v.length(),
            Normalize::RsqrtNewton => v.length_squared() * rsqrt_newton(v.length_squared()),
        }
    }
}

/// The Multiple lights sum in `f32` with a choice of `pow`, normalize and lobe.
///
/// Same formula as [`Scene::shade`] (and the `f64` [`shade_f64`]); with
/// [`PowMethod::Powf`] and [`Normalize::Exact`] it is the plain shader.
#[derive(Clone, Debug, PartialEq)]
pub struct VariantShader {
    /// The lights.
    pub scene: Scene,
    /// The material.
    pub material: Material,
    /// The eye (`viewPos`).
    pub eye: Vec3,
    /// `pow` method.
    pub pow: PowMethod,
    /// Normalize method.
    pub normalize: Normalize,
    /// Specular lobe.
    pub specular: Specular,
}

impl VariantShader {
    /// Shade one fragment at `p` with (not necessarily unit) normal `n`.
    pub fn shade(&self, p: Vec3, n: Vec3) -> Vec3 {
        let nz = self.normalize;
        let n = nz.apply(n);
        let view_dir = nz.apply(self.eye - p);
        let m = &self.material;
        let s = m.shininess;
        let term = |l: Vec3, props: &LightProps| -> Vec3 {
            let diff = n.dot(l).max(0.0);
            let base = match self.specular {
                Specular::Phong => view_dir.dot(2.0 * n.dot(l) * n - l),
                Specular::Blinn => n.dot(nz.apply(l + view_dir)),
            };
            let spec = self.pow.eval(base.max(0.0), s);
            props.ambient * m.ambient + props.diffuse * m.diffuse * diff + props.specular * m.specular * spec
        };
        let attenuation = |a: &Attenuation, d: f32| 1.0 / (a.constant + a.linear * d + a.quadratic * d * d);
        let mut sum = Vec3::ZERO;
        if let Some(d) = &self.scene.dir_light {
            sum += term(nz.apply(-d.direction), &d.props);
        }
        for pl in &self.scene.point_lights {
            let to = pl.position - p;
            sum += term(nz.apply(to), &pl.props) * attenuation(&pl.attenuation, nz.length(to));
        }
        if let Some(sp) = &self.scene.spot_light {
            let to = sp.position - p;
            let l = nz.apply(to);
            let theta = l.dot(nz.apply(-sp.direction));
            let epsilon = sp.cut_off - sp.outer_cut_off;
            let intensity = if epsilon > 0.0 {
                ((theta - sp.outer_cut_off) / epsilon).clamp(0.0, 1.0)
            } else if theta > sp.outer_cut_off {
                1.0
            } else {
                0.0
            };
            sum += term(l, &sp.props) * attenuation(&sp.attenuation, nz.length(to)) * intensity;
        }
        sum
    }
}

// ---------------------------------------------------------------------------
// Scenes

/// The study's material: LearnOpenGL's coral (ambient = diffuse = (1, 0.5, 0.31)), specular 0.5, shininess 32.
pub fn study_material() -> Material {
    Material {
        ambient: Vec3::new(1.0, 0.5, 0.31),
        diffuse: Vec3::new(1.0, 0.5, 0.31),
        specular: Vec3::splat(0.5),
        shininess: 32.0,
    }
}

/// The sphere's model matrix: `rotate(50°, (1, 0.3, 0.5))`, the tutorials' cube
/// rotation; it maps the unit sphere onto itself, so the ray caster's sphere is exact.
pub fn sphere_model() -> Mat4 {
    Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50f32.to_radians())
}

/// The floor scene's lights: a dim directional light and a 5 × 5 grid of white
/// range-7 point lights (LearnOpenGL's `(1, 0.7, 1.8)`), 100 units apart, 1 unit above the floor.
pub fn floor_scene() -> Scene {
    let attenuation = RANGE_TABLE[0].attenuation;
    let props = LightProps { ambient: Vec3::splat(0.05), diffuse: Vec3::splat(0.8), specular: Vec3::ONE };
    let mut point_lights = Vec::new();
    for i in -2..=2 {
        for j in -2..=2 {
            let position = Vec3::new(100.0 * i as f32, 1.0, 100.0 * j as f32);
            point_lights.push(PointLight { position, attenuation, props });
        }
    }
    let dir = LightProps { ambient: Vec3::splat(0.05), diffuse: Vec3::splat(0.2), specular: Vec3::ZERO };
    Scene {
        dir_light: Some(DirLight { direction: Vec3::new(-0.2, -1.0, -0.3), props: dir }),
        point_lights,
        spot_light: None,
        clear_color: Vec3::ZERO,
    }
}

fn floor_camera(aspect: f32) -> Camera {
    Camera::new(Vec3::new(0.0, 260.0, 260.0), Vec3::ZERO, Vec3::Y, 45.0, aspect, 1.0, 2000.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect))
}

// ---------------------------------------------------------------------------
// Measuring

/// Time `frame`: one warm-up call that also sizes a run (frames per run so a run
/// lasts at least `min_seconds`, at most 200), then `runs` timed runs.
pub fn time(runs: usize, min_seconds: f64, mut frame: impl FnMut()) -> Timing {
    let t0 = Instant::now();
    frame();
    let first = t0.elapsed().as_secs_f64().max(1e-7);
    let frames = ((min_seconds / first).ceil() as usize).clamp(1, 200);
    let mut per_frame: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let t = Instant::now();
            for _ in 0..frames {
                frame();
            }
            t.elapsed().as_secs_f64() / frames as f64 * 1e3
        })
        .collect();
    per_frame.sort_by(f64::total_cmp);
    let n = per_frame.len();
    let median = if n % 2 == 1 { per_frame[n / 2] } else { 0.5 * (per_frame[n / 2 - 1] + per_frame[n / 2]) };
    Timing { median_ms: median, min_ms: per_frame[0], max_ms: per_frame[n - 1] }
}

/// Error of `test` (linear RGB per pixel, `None` where not covered) against `reference`.
///
/// Pixels covered in only one image are left out (the silhouette of a coarse
/// mesh differs from the true sphere's; that is coverage, not shading). FLIP
/// compares the two 8-bit images as displayed (no gamma, as the tutorials);
/// its per-pixel values are averaged over the compared pixels.
pub fn compare(width: u32, height: u32, test: &[Option<Vec3>], reference: &[Option<DVec3>]) -> ErrorStats {
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
    ErrorStats { max_levels: max, mean_levels: sum / (3.0 * p), over_one: over as f64 / p, flip, pixels }
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

// ----- the rasterized sphere -----

/// Where the normal matrix is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalMatrixAt {
    /// `transpose(inverse(mat3(model)))` for every vertex, as a vertex shader that computes it.
    PerVertex,
    /// The inverse-transpose once per draw (a uniform).
    PerDraw,
    /// The cofactor matrix once per draw.
    Cofactor,
}

/// The vertex stage: clip position, world position, world normal per vertex.
pub fn sphere_vertices(mesh: &Mesh, model: Mat4, camera: &Camera, at: NormalMatrixAt) -> Vec<(Vec4, Vec3, Vec3)> {
    let vp = camera.view_projection();
    let nm_of = |m: Mat4| {
        let m3 = Mat3::from_mat4(m);
        normal_matrix_inverse_transpose(m3).unwrap_or_else(|| normal_matrix_cofactor(m3))
    };
    let once = match at {
        NormalMatrixAt::Cofactor => normal_matrix_cofactor(Mat3::from_mat4(model)),
        _ => nm_of(model),
    };
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .map(|(&p, &n)| {
            let nm = if at == NormalMatrixAt::PerVertex { nm_of(std::hint::black_box(model)) } else { once };
            let world = model.transform_point3(p);
            (vp * world.extend(1.0), world, nm * n)
        })
        .collect()
}

/// Per-fragment shading by a scalar function of (world position, normal), lane by lane.
struct PerLane<F: Fn(Vec3, Vec3) -> Vec3 + Sync>(F);

impl<F: Fn(Vec3, Vec3) -> Vec3 + Sync> FragmentShader for PerLane<F> {
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
        let v = &batch.varyings;
        for l in 0..batch.len {
            let c = (self.0)(Vec3::new(v[0][l], v[1][l], v[2][l]), Vec3::new(v[3][l], v[4][l], v[5][l]));
            for k in 0..3 {
                out[k][l] = c[k];
            }
        }
    }
}

/// How a rasterized frame is shaded.
enum Shading<'a> {
    /// Lit per vertex by the kernel, colors interpolated.
    Gouraud(&'a MultiLightKernel),
    /// Lit per fragment by this shader.
    PerFragment(&'a dyn FragmentShader),
}

struct RasterFrame<'a> {
    mesh: &'a Mesh,
    model: Mat4,
    camera: &'a Camera,
    at: NormalMatrixAt,
    surface: Surface,
}

impl RasterFrame<'_> {
    fn draw(&self, fb: &mut Framebuffer, shading: &Shading) {
        let verts = sphere_vertices(self.mesh, self.model, self.camera, self.at);
        let (vertices, count, shader): (Vec<ClipVertex>, usize, &dyn FragmentShader) = match shading {
            Shading::Gouraud(kernel) => {
                let points: Vec<_> = verts.iter().map(|v| (v.1, v.2, Vec2::ZERO)).collect();
                let colors = light_points(kernel, &self.surface, &points);
                let vs = verts.iter().zip(&colors).map(|(v, c)| clip_vertex(v.0, &[*c])).collect();
                (vs, 3, &ColorShader)
            }
            Shading::PerFragment(shader) => (verts.iter().map(|v| clip_vertex(v.0, &[v.1, v.2])).collect(), 6, *shader),
        };
        let draw = DrawCall {
            vertices: &vertices,
            triangles: &self.mesh.triangles,
            varying_count: count,
            cull: CullMode::Back,
            depth_test: true,
            shader,
        };
        render(fb, Some(Vec4::new(0.0, 0.0, 0.0, 0.0)), &[draw]);
    }
}

fn clip_vertex(clip: Vec4, parts: &[Vec3]) -> ClipVertex {
    let mut varyings = [0.0; MAX_VARYINGS];
    for (k, v) in parts.iter().enumerate() {
        varyings[3 * k..3 * k + 3].copy_from_slice(&v.to_array());
    }
    ClipVertex { clip, varyings }
}

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

    fn push(&mut self, scene: &str, group: &str, method: &str, fragments: usize, timing: Timing, error: ErrorStats) {
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

fn sphere_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let camera = Camera::learnopengl(w as f32 / h as f32);
    let lights = Scene::learnopengl_default();
    let material = study_material();
    let surface = Surface::Material(material);
    let ray = RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Sphere { center: DVec3::ZERO, radius: 1.0 }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    };
    (ctx.progress)(&format!("{SPHERE}: ray-cast reference"));
    let reference = ray_reference(&ray, w, h);
    let kernel = MultiLightKernel::new(&lights, camera.eye, material.shininess, Specular::Phong);
    let lit = LitShader::new(kernel.clone(), surface.clone());
    let model = sphere_model();
    for &stacks in &ctx.opts.tessellations.clone() {
        let mesh = Mesh::uv_sphere(stacks, 2 * stacks);
        let frame =
            RasterFrame { mesh: &mesh, model, camera: &camera, at: NormalMatrixAt::PerDraw, surface: surface.clone() };
        let size = format!("{stacks}×{}", 2 * stacks);
        ctx.raster(SPHERE, "tessellation", &format!("Gouraud {size}"), &frame, &Shading::Gouraud(&kernel), &reference);
        ctx.raster(SPHERE, "tessellation", &format!("Phong {size}"), &frame, &Shading::PerFragment(&lit), &reference);
    }
    let stacks = ctx.opts.method_stacks;
    let mesh = Mesh::uv_sphere(stacks, 2 * stacks);
    let size = format!("{stacks}×{}", 2 * stacks);
    let frame = |at| RasterFrame { mesh: &mesh, model, camera: &camera, at, surface: surface.clone() };
    for (at, label) in [
        (NormalMatrixAt::PerVertex, "normal matrix per vertex"),
        (NormalMatrixAt::PerDraw, "normal matrix per draw"),
        (NormalMatrixAt::Cofactor, "normal matrix cofactor"),
    ] {
        ctx.raster(
            SPHERE,
            "normal matrix",
            &format!("{label}, {size}"),
            &frame(at),
            &Shading::PerFragment(&lit),
            &reference,
        );
    }
    let eye = camera.eye;
    let scalar = PerLane(|p, n| lights.shade(&material, p, n, eye).rgb());
    let culled = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len() + 1));
    let culled_shader = PerLane(|p, n| culled.shade(&material, p, n, eye).shaded.rgb());
    let f = frame(NormalMatrixAt::PerDraw);
    ctx.raster(SPHERE, "simd", &format!("16-lane kernel, {size}"), &f, &Shading::PerFragment(&lit), &reference);
    ctx.raster(SPHERE, "simd", &format!("scalar Scene::shade, {size}"), &f, &Shading::PerFragment(&scalar), &reference);
    ctx.raster(
        SPHERE,
        "culling",
        &format!("culling on (scalar), {size}"),
        &f,
        &Shading::PerFragment(&culled_shader),
        &reference,
    );
}

// ----- the exact-input sphere -----

struct GFragment {
    pixel: usize,
    p: Vec3,
    n: Vec3,
    p64: DVec3,
    n64: DVec3,
}

fn gbuffer(ray: &RayScene, w: u32, h: u32) -> Vec<GFragment> {
    let inv_vp = (ray.camera.projection.as_dmat4() * ray.camera.view.as_dmat4()).inverse();
    let mut out = Vec::new();
    for row in 0..h {
        let j = (h - 1 - row) as f64 + 0.5;
        for i in 0..w {
            let ndc = |v: f64, size: u32| 2.0 * v / size as f64 - 1.0;
            let (x, y) = (ndc(i as f64 + 0.5, w), ndc(j, h));
            let near = inv_vp.project_point3(DVec3::new(x, y, -1.0));
            let far = inv_vp.project_point3(DVec3::new(x, y, 1.0));
            let dir = (far - near).normalize_or_zero();
            if let Some(hit) = ray.hit(near, dir) {
                let p64 = near + hit.t * dir;
                out.push(GFragment {
                    pixel: (row * w + i) as usize,
                    p: p64.as_vec3(),
                    n: hit.n.as_vec3(),
                    p64,
                    n64: hit.n,
                });
            }
        }
    }
    out
}

/// Shade every fragment of the G-buffer, 16 at a time, on all cores.
fn shade_gbuffer(frags: &[GFragment], out: &mut [Vec3], shade: &(dyn Fn(&[GFragment], &mut [Vec3]) + Sync)) {
    frags.par_chunks(4 * LANES).zip(out.par_chunks_mut(4 * LANES)).for_each(|(f, o)| shade(f, o));
}

fn gbuffer_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let camera = Camera::learnopengl(w as f32 / h as f32);
    let lights = Scene::learnopengl_default();
    let material = study_material();
    let eye = camera.eye;
    let ray = RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Sphere { center: DVec3::ZERO, radius: 1.0 }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    };
    (ctx.progress)(&format!("{GBUFFER}: exact inputs and references"));
    let frags = gbuffer(&ray, w, h);
    let reference_for = |spec: Specular| -> Vec<Option<DVec3>> {
        let mut r = vec![None; (w * h) as usize];
        for f in &frags {
            r[f.pixel] = Some(shade_f64(&lights, &material, f.p64, f.n64, eye.as_dvec3(), spec));
        }
        r
    };
    let ref_phong = reference_for(Specular::Phong);
    let ref_blinn = reference_for(Specular::Blinn);
    let variant = |pow: PowMethod, normalize: Normalize, specular: Specular| VariantShader {
        scene: lights.clone(),
        material,
        eye,
        pow,
        normalize,
        specular,
    };
    let s = material.shininess;
    let scalar = |v: VariantShader| {
        move |f: &[GFragment], o: &mut [Vec3]| {
            for (g, c) in f.iter().zip(o) {
                *c = v.shade(g.p, g.n);
            }
        }
    };
    type Method<'a> = (&'static str, &'static str, Specular, Box<dyn Fn(&[GFragment], &mut [Vec3]) + Sync + 'a>);
    let lights_ref = &lights;
    let kernel_fn = |spec: Specular| {
        let kernel = MultiLightKernel::new(&lights, eye, s, spec);
        let lm = LaneMaterial::uniform(&material);
        move |f: &[GFragment], o: &mut [Vec3]| {
            for (fc, oc) in f.chunks(LANES).zip(o.chunks_mut(LANES)) {
                let (mut pos, mut nrm, mut rgb) = ([[0.0; LANES]; 3], [[0.0; LANES]; 3], [[0.0; LANES]; 3]);
                for (l, g) in fc.iter().enumerate() {
                    for k in 0..3 {
                        pos[k][l] = g.p[k];
                        nrm[k][l] = g.n[k];
                    }
                }
                kernel.shade(&pos, &nrm, &lm, &mut rgb);
                for (l, c) in oc.iter_mut().enumerate() {
                    *c = Vec3::new(rgb[0][l], rgb[1][l], rgb[2][l]);
                }
            }
        }
    };
    let methods: Vec<Method<'_>> = vec![
        (
            "pow",
            "powf (scalar f32)",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::Powf, Normalize::Exact, Specular::Phong))),
        ),
        (
            "pow",
            "LUT 256",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::lut(256, s), Normalize::Exact, Specular::Phong))),
        ),
        (
            "pow",
            "LUT 1024",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::lut(1024, s), Normalize::Exact, Specular::Phong))),
        ),
        (
            "pow",
            "Schlick x/(n−nx+x)",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::Schlick, Normalize::Exact, Specular::Phong))),
        ),
        (
            "pow",
            "exp2/log2 polynomial",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::Exp2Log2, Normalize::Exact, Specular::Phong))),
        ),
        (
            "normalize",
            "rsqrt + 1 Newton step",
            Specular::Phong,
            Box::new(scalar(variant(PowMethod::Powf, Normalize::RsqrtNewton, Specular::Phong))),
        ),
        (
            "lobe",
            "Blinn-Phong (scalar f32)",
            Specular::Blinn,
            Box::new(scalar(variant(PowMethod::Powf, Normalize::Exact, Specular::Blinn))),
        ),
        (
            "precision",
            "f64 shading",
            Specular::Phong,
            Box::new(move |f: &[GFragment], o: &mut [Vec3]| {
                for (g, c) in f.iter().zip(o) {
                    let n = g.n.as_dvec3().normalize_or_zero();
                    *c = shade_f64(lights_ref, &material, g.p.as_dvec3(), n, eye.as_dvec3(), Specular::Phong).as_vec3();
                }
            }),
        ),
        (
            "simd",
            "Scene::shade (scalar core)",
            Specular::Phong,
            Box::new(move |f: &[GFragment], o: &mut [Vec3]| {
                for (g, c) in f.iter().zip(o) {
                    *c = lights_ref.shade(&material, g.p, g.n, eye).rgb();
                }
            }),
        ),
        ("simd", "16-lane kernel, Phong", Specular::Phong, Box::new(kernel_fn(Specular::Phong))),
        ("simd", "16-lane kernel, Blinn-Phong", Specular::Blinn, Box::new(kernel_fn(Specular::Blinn))),
    ];
    let mut out = vec![Vec3::ZERO; frags.len()];
    for (group, method, spec, shade) in &methods {
        (ctx.progress)(&format!("{GBUFFER}: {method}"));
        shade_gbuffer(&frags, &mut out, shade.as_ref());
        let mut img = vec![None; (w * h) as usize];
        for (f, c) in frags.iter().zip(&out) {
            img[f.pixel] = Some(*c);
        }
        let reference = if *spec == Specular::Blinn { &ref_blinn } else { &ref_phong };
        let error = compare(w, h, &img, reference);
        let timing = time(ctx.opts.runs, ctx.opts.min_run_seconds, || shade_gbuffer(&frags, &mut out, shade.as_ref()));
        ctx.push(GBUFFER, group, method, frags.len(), timing, error);
    }
}

// ----- the floor under many short-range lights -----

fn floor_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let camera = floor_camera(w as f32 / h as f32);
    let lights = floor_scene();
    let material = study_material();
    let surface = Surface::Material(material);
    let ray = RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Plane { point: DVec3::ZERO, normal: DVec3::Y }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    };
    (ctx.progress)(&format!("{FLOOR}: ray-cast reference"));
    let reference = ray_reference(&ray, w, h);
    let mesh = Mesh::plane(8);
    let model = Mat4::from_scale(Vec3::new(2000.0, 1.0, 2000.0));
    let frame =
        RasterFrame { mesh: &mesh, model, camera: &camera, at: NormalMatrixAt::PerDraw, surface: surface.clone() };
    let eye = camera.eye;
    let kernel = MultiLightKernel::new(&lights, eye, material.shininess, Specular::Phong);
    let lit = LitShader::new(kernel, surface);
    let scalar = PerLane(|p, n| lights.shade(&material, p, n, eye).rgb());
    let culled: CulledScene = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len()));
    let culled_shader = PerLane(|p, n| culled.shade(&material, p, n, eye).shaded.rgb());
    ctx.raster(FLOOR, "culling", "culling off (scalar)", &frame, &Shading::PerFragment(&scalar), &reference);
    ctx.raster(FLOOR, "culling", "culling on (scalar)", &frame, &Shading::PerFragment(&culled_shader), &reference);
    ctx.raster(FLOOR, "simd", "16-lane kernel (no culling)", &frame, &Shading::PerFragment(&lit), &reference);
}

/// The share of light evaluations culling skips on the floor scene's visible
/// fragments (`width × height` frame), from [`super::culling::skipped_share`].
pub fn floor_skipped_share(width: u32, height: u32) -> f32 {
    let camera = floor_camera(width as f32 / height.max(1) as f32);
    let lights = floor_scene();
    let material = study_material();
    let ray = RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Plane { point: DVec3::ZERO, normal: DVec3::Y }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    };
    let frags: Vec<(Vec3, Vec3)> = gbuffer(&ray, width, height).iter().map(|f| (f.p, f.n)).collect();
    let culled = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len()));
    super::culling::skipped_share(&culled, &material, &frags, camera.eye)
}

/// Run the whole study; `progress` gets one line per step.
pub fn run_study(opts: &StudyOptions, progress: Progress) -> Vec<Row> {
    let mut ctx = Ctx { opts, progress, rows: Vec::new() };
    sphere_study(&mut ctx);
    gbuffer_study(&mut ctx);
    floor_study(&mut ctx);
    ctx.rows
}

// ---------------------------------------------------------------------------
// Pareto front, CSV, tables

/// The cost-error pair a row is ranked by: (median ms/frame, mean error in levels).
pub fn cost_error(row: &Row) -> (f64, f64) {
    (row.timing.median_ms, row.error.mean_levels)
}

/// Relative difference below which two mean errors count as equal (1 %): rows
/// that share the geometry and differ only in rounding (the three normal-matrix
/// placements, the kernel against scalar code) would otherwise split hairs.
pub const ERROR_TIE: f64 = 0.01;

/// Absolute difference (8-bit levels) below which two mean errors count as equal:
/// a thousandth of a level cannot show in an 8-bit image.
pub const ERROR_TIE_LEVELS: f64 = 1e-3;

/// Whether row `q` dominates row `r` (same scene; at most as costly and at most as
/// wrong, errors within [`ERROR_TIE`] or [`ERROR_TIE_LEVELS`] counting as equal; strictly better in one).
pub fn dominates(q: &Row, r: &Row) -> bool {
    let ((qc, qe), (rc, re)) = (cost_error(q), cost_error(r));
    let tie = (qe - re).abs() <= (ERROR_TIE * qe.max(re)).max(ERROR_TIE_LEVELS);
    let err_le = qe <= re || tie;
    let err_lt = qe < re && !tie;
    q.scene == r.scene && qc <= rc && err_le && (qc < rc || err_lt)
}

/// For each row, whether it is on the Pareto front of its scene: no row dominates it ([`dominates`]).
pub fn pareto(rows: &[Row]) -> Vec<bool> {
    rows.iter().map(|r| !rows.iter().any(|q| dominates(q, r))).collect()
}

/// The CSV header line (after the `#` comment lines of the machine).
pub const CSV_HEADER: &str =
    "scene,group,method,fragments,ms_median,ms_min,ms_max,ns_per_fragment,max_err_levels,mean_err_levels,share_over_1_level,mean_flip,pixels_compared";

fn quote(s: &str) -> String {
    if s.contains([',', '"']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_owned()
    }
}

/// One scene's rows as CSV: `# key: value` lines for the machine, the header, one line per row.
pub fn to_csv(machine: &Machine, rows: &[Row]) -> String {
    let mut s = format!(
        "# cpu: {}\n# cores: {}\n# isa: {}\n# frame: {}\n{CSV_HEADER}\n",
        machine.cpu, machine.cores, machine.isa, machine.frame
    );
    for r in rows {
        let e = &r.error;
        s += &format!(
            "{},{},{},{},{:.4},{:.4},{:.4},{:.3},{:.4e},{:.4e},{:.4e},{:.4e},{}\n",
            quote(&r.scene),
            quote(&r.group),
            quote(&r.method),
            r.fragments,
            r.timing.median_ms,
            r.timing.min_ms,
            r.timing.max_ms,
            r.ns_per_fragment(),
            e.max_levels,
            e.mean_levels,
            e.over_one,
            e.flip,
            e.pixels
        );
    }
    s
}

fn split_csv_line(line: &str) -> Vec<String> {
    let mut fields = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                if let Some(f) = fields.last_mut() {
                    f.push('"');
                }
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(String::new()),
            _ => {
                if let Some(f) = fields.last_mut() {
                    f.push(c)
                }
            }
        }
    }
    fields
}

/// Parse [`to_csv`]'s output. Errors name the line and field.
pub fn from_csv(text: &str) -> Result<(Machine, Vec<Row>), String> {
    let mut machine = Machine { cpu: String::new(), cores: 0, isa: String::new(), frame: String::new() };
    let mut rows = Vec::new();
    let mut header_seen = false;
    for (i, line) in text.lines().enumerate() {
        if let Some(kv) = line.strip_prefix("# ") {
            let (k, v) = kv.split_once(": ").ok_or(format!("line {}: expected '# key: value'", i + 1))?;
            match k {
                "cpu" => machine.cpu = v.to_owned(),
                "cores" => machine.cores = v.parse().map_err(|_| format!("line {}: cores {v:?}", i + 1))?,
                "isa" => machine.isa = v.to_owned(),
                "frame" => machine.frame = v.to_owned(),
                _ => {}
            }
            continue;
        }
        if !header_seen {
            if line != CSV_HEADER {
                return Err(format!("line {}: expected the header {CSV_HEADER:?}", i + 1));
            }
            header_seen = true;
            continue;
        }
        let f = split_csv_line(line);
        if f.len() != 13 {
            return Err(format!("line {}: {} fields, expected 13", i + 1, f.len()));
        }
        let num = |k: usize| -> Result<f64, String> {
            f[k].parse().map_err(|_| format!("line {}: field {} = {:?} is not a number", i + 1, k + 1, f[k]))
        };
        rows.push(Row {
            scene: f[0].clone(),
            group: f[1].clone(),
            method: f[2].clone(),
            fragments: num(3)? as usize,
            timing: Timing { median_ms: num(4)?, min_ms: num(5)?, max_ms: num(6)? },
            error: ErrorStats {
                max_levels: num(8)?,
                mean_levels: num(9)?,
                over_one: num(10)?,
                flip: num(11)?,
                pixels: num(12)? as usize,
            },
        });
    }
    if !header_seen {
        return Err("no header line".to_owned());
    }
    Ok((machine, rows))
}

/// `x` with three significant digits (`0` for zero, scientific below 0.001).
pub fn sig(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if x.abs() < 1e-3 {
        return format!("{x:.2e}");
    }
    let decimals = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    format!("{x:.decimals$}")
}

/// The rows of one scene as a [`super::Table`] (method, cost, error, Pareto mark).
pub fn table(title: &str, rows: &[Row]) -> super::Table {
    let front = pareto(rows);
    let header = [
        "method",
        "ms/frame median [min, max]",
        "ns/fragment",
        "max err (levels)",
        "mean err (levels)",
        "% > 1/255",
        "mean FLIP",
        "Pareto",
    ];
    let mut out = vec![header.iter().map(|s| s.to_string()).collect::<Vec<_>>()];
    for (r, on) in rows.iter().zip(front) {
        let t = &r.timing;
        let e = &r.error;
        out.push(vec![
            r.method.clone(),
            format!("{:.2} [{:.2}, {:.2}]", t.median_ms, t.min_ms, t.max_ms),
            format!("{:.1}", r.ns_per_fragment()),
            sig(e.max_levels),
            sig(e.mean_levels),
            sig(100.0 * e.over_one),
            sig(e.flip),
            if on { "●".into() } else { String::new() },
        ]);
    }
    super::Table { title: title.into(), rows: out }
}
