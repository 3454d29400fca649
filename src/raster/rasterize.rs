//! Triangle setup, the top-left fill rule, depth test and perspective-correct varyings.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `X, Y` | window position snapped to 1/256 pixel ([`SUBPIXEL_BITS`]), relative to the pixel-centre lattice |
//! | `E(i, j)` | edge function `(Xb − Xa)(j·256 − Ya) − (Yb − Ya)(i·256 − Xa)`, > 0 left of `a → b` |
//! | top-left rule | a sample exactly on an edge belongs to the triangle only if the edge is a top or left edge |
//! | `1/w` | interpolated linearly in window space; each varying `v` as `v/w`, then divided |
//!
//! Coverage is computed exactly in 64-bit integers on snapped vertices, so
//! two triangles sharing an edge never both cover (nor both miss) a sample on
//! it: a closed mesh is watertight. Window space is OpenGL's (origin lower
//! left, y up); "top" means larger y. Front faces are counter-clockwise in
//! window space (`glFrontFace(GL_CCW)`).
//!
//! Work is split into bands of rows; each band clears its rows, then runs
//! every draw's triangles that touch it, so bands run in parallel with no
//! shared writes. Fragments that pass the depth test are gathered 16 at a
//! time (structure of arrays) and shaded together.
//!
//! Sources: Pineda 1988 (edge functions); OpenGL 3.3 core §3.6.1 (polygon
//! rasterization, "point sampling", the interpolation formula 3.9);
//! Direct3D 10 top-left rule.

#![allow(clippy::needless_range_loop)] // lane-indexed loops are the structure-of-arrays form LLVM vectorizes

use glam::Vec4;

use super::clip::{clip_triangle, inside_all, ClipVertex, MAX_VARYINGS};
use super::framebuffer::{quantize, Framebuffer, Rgba8Framebuffer};
use super::simd::{per_isa, Isa, RowPlanes, Simd};
use super::simd::{Lanes, LANES};

/// Fractional bits of snapped window coordinates (llvmpipe uses 8 too).
pub const SUBPIXEL_BITS: u32 = 8;
const ONE: i64 = 1 << SUBPIXEL_BITS;
/// Rows per band of parallel work: 32 rows of 800 pixels keep a band's colour and depth
/// (500 KiB) in a core's L2 cache, and make few enough tasks that waking threads costs
/// little (16 rows measured 15 to 20 % slower on the sphere scenes).
pub const BAND_ROWS: usize = 32;

/// Which faces are discarded.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CullMode {
    /// Draw both sides.
    None,
    /// Discard clockwise (back) faces, as `glEnable(GL_CULL_FACE)`.
    Back,
    /// Discard counter-clockwise (front) faces.
    Front,
}

/// Up to 16 fragments to shade, structure of arrays. Aligned to 64 bytes, so that each
/// varying's 16 lanes are one cache line: written by 64-byte stores and read back by the
/// kernel's 64-byte loads, a batch that straddled lines (as the stack happened to place it
/// once the band loop became generic over its pixel type) failed store forwarding, and the
/// kernel's first loads were a tenth of quad-single's kernel time.
#[derive(Clone, Debug)]
#[repr(align(64))]
pub struct FragmentBatch {
    /// Interpolated varyings: `varyings[k][lane]`.
    pub varyings: [Lanes; MAX_VARYINGS],
    /// Lanes in use (`0..len`); the others hold stale values.
    pub len: usize,
}

impl FragmentBatch {
    fn new() -> FragmentBatch {
        FragmentBatch { varyings: [[0.0; LANES]; MAX_VARYINGS], len: 0 }
    }

    /// A batch holding `varyings` in lanes `0..len` (`len` is clamped to 16), for
    /// running a fragment stage outside the rasterizer.
    pub fn from_varyings(varyings: [Lanes; MAX_VARYINGS], len: usize) -> FragmentBatch {
        FragmentBatch { varyings, len: len.min(LANES) }
    }
}

/// A fragment stage: turns a batch of interpolated varyings into linear RGB.
pub trait FragmentShader: Sync {
    /// Shade lanes `0..batch.len`; write RGB to `out[channel][lane]`. Lanes
    /// past `len` may be shaded too (their output is ignored), so the shader
    /// must not panic on stale values.
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]);

    /// Shade several batches, `out[b]` from `batches[b]`: the same values as
    /// [`FragmentShader::shade`] on each in turn, which the default does. A shader
    /// overrides it to pay its dispatch once per call, not once per batch, and to give the
    /// CPU independent batches back to back (the rasterizer hands it the whole chunks of
    /// a span, four at a time).
    fn shade_batches(&self, batches: &[FragmentBatch], out: &mut [[Lanes; 3]]) {
        for (batch, out) in batches.iter().zip(out) {
            self.shade(batch, out);
        }
    }

    /// Whether the output is the first three varyings as they are (Gouraud and flat
    /// shading's colour): the rasterizer then writes them straight to the pixels,
    /// without gathering fragments into batches. `false` unless a shader says so.
    fn passes_varyings_through(&self) -> bool {
        false
    }
}

/// One draw: vertices after the vertex stage, triangles, and state.
pub struct DrawCall<'a> {
    /// Vertex stage outputs.
    pub vertices: &'a [ClipVertex],
    /// Index triples into `vertices` (out-of-range triples are skipped).
    pub triangles: &'a [[u32; 3]],
    /// How many varyings to interpolate (at most [`MAX_VARYINGS`]).
    pub varying_count: usize,
    /// Face culling.
    pub cull: CullMode,
    /// Depth test `LESS` and depth writes on or off.
    pub depth_test: bool,
    /// The fragment stage.
    pub shader: &'a dyn FragmentShader,
}

/// Counts from one [`render`] call.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RenderStats {
    /// Triangles submitted.
    pub triangles: usize,
    /// Triangles skipped: zero area after snapping, non-finite, out-of-range indices, or fully clipped.
    pub skipped: usize,
    /// Triangles discarded by culling.
    pub culled: usize,
}

/// Widest bounding box (pixels) whose rows [`LaneEdges`] finds by evaluating the edge
/// functions at every pixel, 32 lanes: it covers the 4096-triangle sphere's triangles
/// (up to about 25 pixels wide at its equator). A wider box is walked ([`RowWalk`]). A
/// box at most [`LANES`] wide evaluates 16.
///
/// The walk for every triangle measured no faster than the lanes on the spheres, and in
/// two sets of 16 and 18 rounds of the sweep 1.03 to 1.13 times the frame at 16,384 to
/// 262,144 triangles (within this machine's noise, but never below 1): its six divisions
/// per triangle and band ([`RowWalk::new`]) cost more than a small triangle's one or two
/// rows of lanes. So the lanes stay for narrow boxes, and the walk replaces only the three
/// divisions a row that a wider box took.
///
/// 32 measured 20 to 30 % slower than 16 on sphere4096-gouraud (twelve alternating rounds,
/// one thread) while the lanes were a loop over booleans that LLVM vectorized badly into
/// 2-, 4- and 8-lane pieces. With [`Simd::edge_mask`] they are a few vector compares,
/// and 32 lanes with it measured 2 to 6 % faster than the loop at 16 on that scene (the
/// same rounds, one and two threads) and the same on sphere4096-multi.
const SPAN_LANES: usize = 32;

#[derive(Clone, Copy, Debug, Default)]
struct Plane {
    c: f64,
    dx: f32,
    dy: f64,
}

impl Plane {
    #[inline]
    fn row(&self, j: i32) -> (f32, f32) {
        ((self.c + self.dy * j as f64) as f32, self.dx)
    }
}

/// One edge `a → b` of a triangle, in 16 bytes: its edge function is
/// `E(i, j) = A·i + B·j + c` with `A = −dy·256`, `B = dx·256`, and a pixel is on its
/// inner side when `E(i, j) ≥ threshold`, tested as `E(i, j) − threshold ≥ 0`, so `c`
/// holds `c − threshold`.
#[derive(Clone, Copy, Debug)]
struct Edge {
    /// `Xb − Xa`: inside the guard band, `|X| < 2^24` ([`Tri::lane_edges`]), so it fits.
    dx: i32,
    /// `Yb − Ya`.
    dy: i32,
    /// The edge function's constant, less the top-left rule's threshold.
    c: i64,
}

impl Edge {
    /// `A`, the edge function's change per pixel in x.
    #[inline(always)]
    fn a(&self) -> i64 {
        -(self.dy as i64) * ONE
    }

    /// `B`, its change per pixel row.
    #[inline(always)]
    fn b(&self) -> i64 {
        self.dx as i64 * ONE
    }
}

/// A triangle after setup: 112 bytes. Its varyings' planes are stored beside it, only
/// as many as the draw interpolates ([`SetupPart::varyings`]): with all eight inside, it
/// was 352 bytes, and at 262,144 triangles the copies of those records were 8 % of the
/// frame.
#[derive(Clone, Debug)]
struct Tri {
    edges: [Edge; 3],
    x_min: i32,
    x_max: i32,
    y_min: i32,
    y_max: i32,
    z: Plane,
    inv_w: Plane,
}

/// A corner snapped to the subpixel lattice, with the values its planes interpolate.
#[derive(Clone, Copy, Debug)]
struct Projected {
    x: i64,
    y: i64,
    z: f64,
    inv_w: f64,
}

fn project(v: &ClipVertex, width: u32, height: u32) -> Option<Projected> {
    let inv_w = 1.0 / v.clip.w;
    let ndc = v.clip.truncate() * inv_w;
    let window = super::camera::Viewport { width, height }.to_window(ndc);
    if !(window.is_finite() && inv_w.is_finite()) {
        return None;
    }
    let snap = |p: f32| round_half_away(((p as f64) - 0.5) * ONE as f64);
    Some(Projected { x: snap(window.x), y: snap(window.y), z: window.z as f64, inv_w: inv_w as f64 })
}

/// `x.round() as i64` (halves away from zero, saturating) without the C library's
/// `round`, which the portable build calls (no SSE4.1) once per vertex coordinate:
/// truncate, then correct by the exact remainder `x − trunc(x)`.
#[inline]
fn round_half_away(x: f64) -> i64 {
    let t = x as i64;
    // exact below 2^53; above it x is an integer (or the cast saturated) and the remainder is 0
    let f = x - t as f64;
    if f >= 0.5 {
        t.saturating_add(1)
    } else if f <= -0.5 {
        t.saturating_sub(1)
    } else {
        t
    }
}

fn plane(p: &[Projected; 3], f: [f64; 3], det: f64) -> Plane {
    let (x0, y0) = (p[0].x as f64 / ONE as f64, p[0].y as f64 / ONE as f64);
    let (x1, y1) = (p[1].x as f64 / ONE as f64 - x0, p[1].y as f64 / ONE as f64 - y0);
    let (x2, y2) = (p[2].x as f64 / ONE as f64 - x0, p[2].y as f64 / ONE as f64 - y0);
    let (f1, f2) = (f[1] - f[0], f[2] - f[0]);
    let dx = (f1 * y2 - f2 * y1) / det;
    let dy = (f2 * x1 - f1 * x2) / det;
    // the lattice point (i, j) is the pixel centre, which snapped coordinates measure from
    Plane { c: f[0] - dx * x0 - dy * y0, dx: dx as f32, dy }
}

/// The edge `a → b`, or `None` if its extent does not fit 32 bits (never inside the guard band).
fn edge(a: &Projected, b: &Projected) -> Option<Edge> {
    let (dx, dy) = (b.x - a.x, b.y - a.y);
    // top edge: horizontal with the interior below (dx < 0 for CCW, y up); left edge: going down
    let top_left = dy < 0 || (dy == 0 && dx < 0);
    let threshold = if top_left { 0 } else { 1 };
    Some(Edge { dx: i32::try_from(dx).ok()?, dy: i32::try_from(dy).ok()?, c: -dx * a.y + dy * a.x - threshold })
}

/// Set up one triangle from its snapped corners `p` and their varyings, or `None` when
/// it has zero area, is culled (counted in `stats`) or misses the window. The planes of
/// the draw's varyings are pushed onto `varyings` when it is kept.
fn setup(
    mut p: [Projected; 3],
    mut varyings_at: [&[f32; MAX_VARYINGS]; 3],
    width: u32,
    height: u32,
    draw: &DrawCall,
    stats: &mut RenderStats,
    varyings: &mut Vec<Plane>,
) -> Option<Tri> {
    let cull = draw.cull;
    let area2 = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if area2 == 0 {
        return None;
    }
    let front = area2 > 0;
    if (cull == CullMode::Back && !front) || (cull == CullMode::Front && front) {
        stats.culled += 1;
        return None;
    }
    if !front {
        p.swap(1, 2);
        varyings_at.swap(1, 2);
    }
    let det = area2.abs() as f64 / (ONE * ONE) as f64;
    let edges = [edge(&p[0], &p[1])?, edge(&p[1], &p[2])?, edge(&p[2], &p[0])?];
    let lo = |v: i64| ((v + ONE - 1).div_euclid(ONE)) as i32;
    let hi = |v: i64| (v.div_euclid(ONE)) as i32;
    let x_min = lo(p.iter().map(|q| q.x).min()?).max(0);
    let x_max = hi(p.iter().map(|q| q.x).max()?).min(width as i32 - 1);
    let y_min = lo(p.iter().map(|q| q.y).min()?).max(0);
    let y_max = hi(p.iter().map(|q| q.y).max()?).min(height as i32 - 1);
    if x_min > x_max || y_min > y_max {
        return None;
    }
    let z = plane(&p, [p[0].z, p[1].z, p[2].z], det);
    let inv_w = plane(&p, [p[0].inv_w, p[1].inv_w, p[2].inv_w], det);
    // only the draw's varyings: the band loop reads no others
    varyings.extend((0..live_varyings(draw)).map(|k| {
        let f = |c: usize| varyings_at[c][k] as f64 * p[c].inv_w;
        plane(&p, [f(0), f(1), f(2)], det)
    }));
    Some(Tri { edges, x_min, x_max, y_min, y_max, z, inv_w })
}

/// How many varyings a draw interpolates: its count, at most [`MAX_VARYINGS`].
fn live_varyings(draw: &DrawCall) -> usize {
    draw.varying_count.min(MAX_VARYINGS)
}

impl Tri {
    /// The finder of this triangle's rows, from row `j0` on: its lanes when its box is
    /// at most [`SPAN_LANES`] pixels wide ([`Tri::lane_edges`]), else its edge walk.
    #[inline(always)]
    fn rows_from(&self, j0: i32) -> Rows {
        match self.lane_edges() {
            Some(lanes) => Rows::Lanes(lanes),
            None => Rows::Walk(RowWalk::new(self, j0)),
        }
    }

    /// The edge functions of a triangle whose bounding box is at most [`SPAN_LANES`] pixels
    /// wide, set up once for all its rows' lanes ([`LaneEdges::mask`]), or `None` for a
    /// wider one.
    #[inline(always)]
    fn lane_edges(&self) -> Option<LaneEdges> {
        let width = self.x_max - self.x_min + 1;
        if width > SPAN_LANES as i32 {
            return None;
        }
        // inside the guard band of a window up to 8192 wide, |X|, |Y| < 4.5 · 2^13 · 2^8 < 2^24,
        // so |a·i|, |b·j| < 2^25 · 2^8 · 2^13 = 2^46 and |c| < 2^50: every value here and every
        // sum the lanes form (|a·l| < 2^25 · 2^8 · 2^5 = 2^38) is an integer below 2^53,
        // exact in f64
        let mut lanes = LaneEdges {
            x_min: self.x_min,
            at_row0: [0.0; 3],
            b: [0.0; 3],
            a: [0.0; 3],
            width_mask: ((1u64 << width) - 1) as u32,
        };
        // a loop, not `map` closures (see `LaneEdges::mask`)
        for (k, e) in self.edges.iter().enumerate() {
            lanes.at_row0[k] = (e.a() * self.x_min as i64 + e.c) as f64;
            lanes.b[k] = e.b() as f64;
            lanes.a[k] = e.a() as f64;
        }
        Some(lanes)
    }

    /// The span of row `j` from each edge's crossing of the row, `i ≥ ⌈(threshold − b·j − c)/a⌉`
    /// for `a > 0` (and `≤ ⌊…⌋` for `a < 0`), clamped to the bounding box: the reference
    /// that the lanes and the walk are tested against.
    #[cfg(test)]
    fn span_by_division(&self, j: i32) -> Option<(i32, i32)> {
        let (mut lo, mut hi) = (self.x_min as i64, self.x_max as i64);
        for e in &self.edges {
            // need a·i + row ≥ 0, where row holds b·j + c − threshold
            let need = -(e.b() * j as i64 + e.c);
            let a = e.a();
            if a > 0 {
                lo = lo.max(-((-need).div_euclid(a)));
            } else if a < 0 {
                hi = hi.min((-need).div_euclid(-a));
            } else if need > 0 {
                return None;
            }
        }
        (lo <= hi).then_some((lo as i32, hi as i32))
    }
}

/// `v = q·d + r` with `0 ≤ r < d`, stepped by a constant `δ = qδ·d + rδ` per row without
/// dividing: `r += rδ`, `q += qδ`, and a carry when `r ≥ d`. Exact in integers.
#[derive(Clone, Copy, Debug)]
struct Stepper {
    q: i64,
    r: i64,
    d: i64,
    q_step: i64,
    r_step: i64,
}

impl Stepper {
    /// `v` and its step `delta` over the divisor `d > 0`.
    fn new(v: i64, delta: i64, d: i64) -> Stepper {
        Stepper { q: v.div_euclid(d), r: v.rem_euclid(d), d, q_step: delta.div_euclid(d), r_step: delta.rem_euclid(d) }
    }

    /// `⌊v / d⌋`.
    #[inline(always)]
    fn floor(&self) -> i64 {
        self.q
    }

    /// `⌈v / d⌉`.
    #[inline(always)]
    fn ceil(&self) -> i64 {
        self.q + i64::from(self.r != 0)
    }

    /// `v += δ`.
    #[inline(always)]
    fn step(&mut self) {
        self.r += self.r_step;
        let carry = self.r >= self.d;
        self.q += self.q_step + i64::from(carry);
        self.r -= if carry { self.d } else { 0 };
    }
}

/// One edge's bound on a row's span, row after row ([`RowWalk`]).
#[derive(Clone, Copy, Debug)]
enum Bound {
    /// `a > 0`: `i ≥ ⌈need / a⌉`, `need = −(b·j + c)` stepping by `−b`.
    Left(Stepper),
    /// `a < 0`: `i ≤ ⌊−need / −a⌋`, `−need` stepping by `b`.
    Right(Stepper),
    /// `a = 0`: the row is inside only while `need ≤ 0`.
    Flat { need: i64, b: i64 },
}

/// The spans of a triangle's rows `j0, j0 + 1, …`, each the one
/// [`Tri::span_by_division`] gives, from two divisions per edge at `j0` (its crossing of
/// the row and its step, each a quotient and remainder) and then only additions: each edge's crossing of the row moves by the constant `−b/a` a row, kept
/// as a quotient and a remainder ([`Stepper`]), as a scanline rasterizer walks its edges.
#[derive(Clone, Copy, Debug)]
struct RowWalk {
    bounds: [Bound; 3],
    x_min: i64,
    x_max: i64,
}

impl RowWalk {
    /// The walk of `tri` from row `j0`.
    fn new(tri: &Tri, j0: i32) -> RowWalk {
        let bounds = tri.edges.map(|e| {
            let (a, b) = (e.a(), e.b());
            let need = -(b * j0 as i64 + e.c);
            if a > 0 {
                Bound::Left(Stepper::new(need, -b, a))
            } else if a < 0 {
                Bound::Right(Stepper::new(-need, b, -a))
            } else {
                Bound::Flat { need, b }
            }
        });
        RowWalk { bounds, x_min: tri.x_min as i64, x_max: tri.x_max as i64 }
    }

    /// The current row's span, inclusive, or `None`.
    #[inline(always)]
    fn span(&self) -> Option<(i32, i32)> {
        let (mut lo, mut hi, mut empty) = (self.x_min, self.x_max, false);
        for bound in &self.bounds {
            match bound {
                Bound::Left(st) => lo = lo.max(st.ceil()),
                Bound::Right(st) => hi = hi.min(st.floor()),
                Bound::Flat { need, .. } => empty |= *need > 0,
            }
        }
        (lo <= hi && !empty).then_some((lo as i32, hi as i32))
    }

    /// On to the next row.
    #[inline(always)]
    fn step(&mut self) {
        for bound in &mut self.bounds {
            match bound {
                Bound::Left(st) | Bound::Right(st) => st.step(),
                Bound::Flat { need, b } => *need -= *b,
            }
        }
    }
}

/// A narrow triangle's three edge functions, ready for one row's lanes: a 16 × 1 (or
/// 32 × 1) block of Pineda's edge functions from the box's left column `x_min`,
///
/// ```text
/// inside(l) = ∧ₑ  Eₑ(x_min, j) + aₑ·l ≥ thresholdₑ,   l = 0 … 31, x_min + l ≤ x_max
/// ```
///
/// as the block rasterizers of Abrash ("Rasterization on Larrabee", 2009) and Giesen
/// ("Optimizing the basic rasterizer", 2013) evaluate them. A row of a triangle is one
/// interval, so the covered lanes are contiguous. A row costs a few vector compares
/// ([`Simd::edge_mask`]), where `Tri::span_by_division` divides three times.
///
/// The values are f64 and exact: every term is an integer below 2^53 (bounds in
/// [`Tri::lane_edges`]), so each lane's sign is the integer edge function's.
#[derive(Clone, Copy, Debug)]
struct LaneEdges {
    /// The box's left column, lane 0.
    x_min: i32,
    /// `Eₑ(x_min, 0) − thresholdₑ`.
    at_row0: [f64; 3],
    /// `bₑ`, the change per row.
    b: [f64; 3],
    /// `aₑ`, the change per pixel.
    a: [f64; 3],
    /// The box's `x_max − x_min + 1` first lanes: a box wider than 16 pixels (a mask
    /// above `2^16 − 1`) takes 32 lanes, a narrower one 16.
    width_mask: u32,
}

impl LaneEdges {
    /// The covered pixel columns of window row `j`, inclusive, or `None`: the first and
    /// last lanes of [`LaneEdges::mask`] (a row of a triangle is one interval).
    #[inline(always)]
    fn span<S: Simd>(&self, s: S, j: i32) -> Option<(i32, i32)> {
        let mask = self.mask(s, j);
        (mask != 0).then(|| (self.x_min + mask.trailing_zeros() as i32, self.x_min + 31 - mask.leading_zeros() as i32))
    }

    /// Bit `l` set when pixel `x_min + l` of row `j` is covered.
    #[inline(always)]
    fn mask<S: Simd>(&self, s: S, j: i32) -> u32 {
        // indexed, not `[0, 1, 2].map(…)`: that closure was compiled out of line (a closure is
        // a function of its own, without the band loop's target features) and called three
        // times a row, 2.7 % of sphere4096-gouraud's profile
        let (r, b, j) = (&self.at_row0, &self.b, j as f64);
        let at = [r[0] + b[0] * j, r[1] + b[1] * j, r[2] + b[2] * j];
        // `edge_mask::<BLOCKS>` tests 8·BLOCKS lanes
        let lanes = if self.width_mask > first_lanes(LANES) {
            s.edge_mask::<{ SPAN_LANES / 8 }>(at, self.a)
        } else {
            s.edge_mask::<{ LANES / 8 }>(at, self.a)
        };
        lanes & self.width_mask
    }
}

/// How a band finds a triangle's rows, one after the other from the first
/// ([`Tri::rows_from`]): a narrow triangle's lanes, a wider one's edge walk. Both give
/// the pixels `E(i, j) ≥ threshold` gives.
enum Rows {
    Lanes(LaneEdges),
    Walk(RowWalk),
}

impl Rows {
    /// The span of row `j`, inclusive, or `None`: `j` is the first row on the first call
    /// and one more on each call after it (the walk steps once per call).
    #[inline(always)]
    fn next<S: Simd>(&mut self, s: S, j: i32) -> Option<(i32, i32)> {
        match self {
            Rows::Lanes(lanes) => lanes.span(s, j),
            Rows::Walk(walk) => {
                let span = walk.span();
                walk.step();
                span
            }
        }
    }
}

/// A draw's triangles after setup, in chunks of [`SETUP_CHUNK`] submitted triangles set
/// up in parallel; each chunk keeps its own triangles and band bins, so the chunks are
/// never copied into one list (at 262,144 triangles that copy and its fresh pages
/// took a tenth of the frame).
#[derive(Debug, Default)]
struct SetupPart {
    tris: Vec<Tri>,
    /// The planes of the draw's `nv` varyings (`v/w`), `nv` per triangle: triangle `t`'s
    /// are `varyings[t·nv .. (t + 1)·nv]`.
    varyings: Vec<Plane>,
    /// Per band of [`BAND_ROWS`] rows, the indices into `tris` (in order) of the
    /// triangles that touch it.
    bins: Vec<Vec<u32>>,
}

/// Submitted triangles per chunk of parallel setup.
const SETUP_CHUNK: usize = 512;

/// The buffers a frame's setup fills, kept from one [`render_with`] call to the next:
/// the snapped vertices and, per draw, the set-up triangles and their band bins.
///
/// At 262,144 triangles (131,841 vertices, about 131,000 triangles kept after culling)
/// they are about 40 MB: 5 MB of snapped vertices, 15 MB of triangles (112 bytes each)
/// and 19 MB of varying planes (6 × 24 bytes each). Allocated afresh each frame, they were
/// mapped and unmapped by the allocator every frame, and the kernel's page faults on
/// their first touch took about a seventh of the frame. A reused scratch touches pages
/// that are already mapped. It holds no result: any scratch gives the same image.
#[derive(Debug, Default)]
pub struct RasterScratch {
    /// Each vertex of the draw being set up, snapped ([`project_vertices`]).
    projected: Vec<Option<Projected>>,
    /// Per draw, its chunks after setup.
    setups: Vec<Vec<SetupPart>>,
}

/// Each vertex snapped once into `out`, or `None` when it lies outside a clip plane (its
/// triangles are clipped and set up from the clipped polygon) or does not project to a
/// finite point. A vertex is shared by about six triangles of a mesh, so this projects it
/// once instead of once per corner.
fn project_vertices(vertices: &[ClipVertex], width: u32, height: u32, out: &mut Vec<Option<Projected>>) {
    let one = |v: &ClipVertex| if inside_all(&[*v; 3]) { project(v, width, height) } else { None };
    out.clear();
    #[cfg(feature = "book")]
    {
        use rayon::prelude::*;
        if vertices.len() > SETUP_CHUNK {
            // an indexed parallel iterator writes in place into the reserved capacity
            out.par_extend(vertices.par_iter().with_min_len(SETUP_CHUNK).map(one));
            return;
        }
    }
    out.extend(vertices.iter().map(one));
}

/// Set up `triangles` of `draw` into `tris` (cleared first), and count them.
fn setup_draw(
    draw: &DrawCall,
    triangles: &[[u32; 3]],
    projected: &[Option<Projected>],
    width: u32,
    height: u32,
    SetupPart { tris, varyings, .. }: &mut SetupPart,
) -> RenderStats {
    let mut stats = RenderStats { triangles: triangles.len(), ..RenderStats::default() };
    tris.clear();
    varyings.clear();
    for t in triangles {
        let corner = |k: usize| draw.vertices.get(t[k] as usize).zip(projected.get(t[k] as usize));
        let (Some((a, pa)), Some((b, pb)), Some((c, pc))) = (corner(0), corner(1), corner(2)) else {
            stats.skipped += 1;
            continue;
        };
        let before = tris.len() + stats.culled;
        if let (Some(pa), Some(pb), Some(pc)) = (pa, pb, pc) {
            // every corner inside every plane: no clipping
            tris.extend(setup(
                [*pa, *pb, *pc],
                [&a.varyings, &b.varyings, &c.varyings],
                width,
                height,
                draw,
                &mut stats,
                varyings,
            ));
        } else {
            let poly = clip_triangle(&[*a, *b, *c]);
            for k in 1..poly.len().saturating_sub(1) {
                let corners = [&poly[0], &poly[k], &poly[k + 1]];
                let snapped = (
                    project(corners[0], width, height),
                    project(corners[1], width, height),
                    project(corners[2], width, height),
                );
                if let (Some(pa), Some(pb), Some(pc)) = snapped {
                    let corner_varyings = [&corners[0].varyings, &corners[1].varyings, &corners[2].varyings];
                    tris.extend(setup([pa, pb, pc], corner_varyings, width, height, draw, &mut stats, varyings));
                }
            }
        }
        if tris.len() + stats.culled == before {
            stats.skipped += 1;
        }
    }
    stats
}

/// The sum of two [`RenderStats`].
fn add_stats(a: RenderStats, b: RenderStats) -> RenderStats {
    RenderStats { triangles: a.triangles + b.triangles, skipped: a.skipped + b.skipped, culled: a.culled + b.culled }
}

/// Set up and bin a draw's triangles into `parts`, one per chunk of [`SETUP_CHUNK`]
/// triangles (in parallel with the `book` feature), reusing the parts' buffers.
fn setup_parallel(
    draw: &DrawCall,
    width: u32,
    height: u32,
    projected: &mut Vec<Option<Projected>>,
    parts: &mut Vec<SetupPart>,
) -> RenderStats {
    project_vertices(draw.vertices, width, height, projected);
    let projected = &projected[..];
    parts.resize_with(draw.triangles.len().div_ceil(SETUP_CHUNK), SetupPart::default);
    let fill = |(part, chunk): (&mut SetupPart, &[[u32; 3]])| {
        let stats = setup_draw(draw, chunk, projected, width, height, part);
        bin_by_band(&part.tris, height, &mut part.bins);
        stats
    };
    #[cfg(feature = "book")]
    {
        use rayon::prelude::*;
        parts
            .par_iter_mut()
            .zip(draw.triangles.par_chunks(SETUP_CHUNK))
            .map(fill)
            .reduce(RenderStats::default, add_stats)
    }
    #[cfg(not(feature = "book"))]
    parts.iter_mut().zip(draw.triangles.chunks(SETUP_CHUNK)).map(fill).fold(RenderStats::default(), add_stats)
}

/// Draw a frame: optionally clear to `clear` (depth to 1), then run the draws in order.
///
/// The depth buffer is cleared only when one of the draws tests depth: a frame with
/// no depth test neither reads nor writes it, and leaves it as it was.
///
/// Triangles that are degenerate (zero area after snapping to 1/256 pixel,
/// non-finite coordinates, out-of-range indices) are skipped and counted;
/// nothing panics. Bands of [`BAND_ROWS`] rows run in parallel when the
/// `book` feature (rayon) is on; the result does not depend on it.
pub fn render(fb: &mut Framebuffer, clear: Option<Vec4>, draws: &[DrawCall]) -> RenderStats {
    render_with(fb, clear, draws, &mut RasterScratch::default())
}

/// [`render`], with the setup's buffers taken from `scratch` and left there for the next
/// frame. The image does not depend on what `scratch` held.
pub fn render_with(
    fb: &mut Framebuffer,
    clear: Option<Vec4>,
    draws: &[DrawCall],
    scratch: &mut RasterScratch,
) -> RenderStats {
    let (width, height) = (fb.width(), fb.height());
    render_into(width, height, &mut fb.color, &mut fb.depth, clear, draws, scratch, band_per_isa)
}

/// [`render_with`] into an RGBA8 colour buffer: each pixel's colour is [`quantize`]d as it
/// is written (the clear colour once), so the bytes are [`Framebuffer::to_rgba8`]`(false)`
/// of the frame [`render_with`] draws, and the depth buffer is the same.
pub fn render_rgba8_with(
    fb: &mut Rgba8Framebuffer,
    clear: Option<Vec4>,
    draws: &[DrawCall],
    scratch: &mut RasterScratch,
) -> RenderStats {
    let (width, height) = (fb.width(), fb.height());
    render_into(width, height, &mut fb.color, &mut fb.depth, clear, draws, scratch, band_rgba8_per_isa)
}

/// The body of [`render_with`] for either colour buffer: `band` is the band loop
/// compiled for its pixel type.
#[allow(clippy::too_many_arguments)]
fn render_into<P: Pixel>(
    width: u32,
    height: u32,
    color: &mut [P],
    depth: &mut [f32],
    clear: Option<Vec4>,
    draws: &[DrawCall],
    scratch: &mut RasterScratch,
    band: fn(Isa, &BandJob, &mut [P], &mut [f32]),
) -> RenderStats {
    let RasterScratch { projected, setups } = scratch;
    setups.resize_with(draws.len(), Vec::new);
    let stats = draws
        .iter()
        .zip(setups.iter_mut())
        .map(|(d, parts)| setup_parallel(d, width, height, projected, parts))
        .fold(RenderStats::default(), add_stats);
    let setups = &setups[..];
    let band_len = BAND_ROWS * width as usize;
    let isa = Isa::detect();
    let frame = Frame::of(color, depth);
    let job = |(index, (color, depth)): (usize, (&mut [P], &mut [f32]))| {
        let job = BandJob { band: index, width, height, clear, draws, setups, frame };
        band(isa, &job, color, depth);
    };
    #[cfg(feature = "book")]
    {
        use rayon::prelude::*;
        color.par_chunks_mut(band_len).zip(depth.par_chunks_mut(band_len)).enumerate().for_each(job);
    }
    #[cfg(not(feature = "book"))]
    color.chunks_mut(band_len).zip(depth.chunks_mut(band_len)).enumerate().for_each(job);
    stats
}

struct BandJob<'a> {
    band: usize,
    width: u32,
    height: u32,
    clear: Option<Vec4>,
    draws: &'a [DrawCall<'a>],
    /// Per draw, its triangles after setup with their band bins.
    setups: &'a [Vec<SetupPart>],
    /// Where the whole frame's buffers lie, for [`Ahead`].
    frame: Frame,
}

/// The addresses and length (pixels) of a frame's colour and depth buffers, only ever
/// used as prefetch hints ([`Ahead`]), never dereferenced.
#[derive(Clone, Copy, Debug)]
struct Frame {
    color: usize,
    depth: usize,
    pixel_bytes: usize,
    pixels: usize,
}

impl Frame {
    fn of<P>(color: &[P], depth: &[f32]) -> Frame {
        let pixel_bytes = std::mem::size_of::<P>();
        Frame { color: color.as_ptr() as usize, depth: depth.as_ptr() as usize, pixel_bytes, pixels: color.len() }
    }
}

/// The next band's pixels, fetched into L2 while this band is shaded: each 16-pixel chunk
/// of this band fetches the next 16 pixels of colour and depth there, so that the next
/// band's depth clear and first colour stores find their lines in L2.
///
/// A band's first store to a line has to fetch it from L3 (the frame does not fit L2), and
/// the clear did it in a loop that waited on each line (a fifth of quad-single's frame);
/// a prefetch does it in the background, under the shading. (The clear is now a string
/// store, [`store_words`], which needs no read; the prefetch still brings the lines that
/// a band without a clear reads, and turning it off made no difference we could measure.) A full-screen draw has as
/// many chunks as the next band has 16-pixel groups. Prefetches are hints: they never
/// fault and never change memory, so the image does not depend on them.
struct Ahead {
    color: usize,
    color_end: usize,
    depth: usize,
    pixel_bytes: usize,
}

impl Ahead {
    /// The band after `band` (of `band_len` pixels) in `frame`, or nothing to fetch.
    fn after(frame: Frame, band: usize, band_len: usize) -> Ahead {
        let start = ((band + 1) * band_len).min(frame.pixels);
        let end = ((band + 2) * band_len).min(frame.pixels);
        Ahead {
            color: frame.color + start * frame.pixel_bytes,
            color_end: frame.color + end * frame.pixel_bytes,
            depth: frame.depth + start * 4,
            pixel_bytes: frame.pixel_bytes,
        }
    }

    /// Fetch the next 16 pixels' colour and depth lines into L2.
    #[inline(always)]
    fn fetch(&mut self) {
        if self.color >= self.color_end {
            return;
        }
        let color_bytes = LANES * self.pixel_bytes;
        for line in (0..color_bytes).step_by(64) {
            prefetch_l2(self.color + line);
        }
        prefetch_l2(self.depth);
        self.color += color_bytes;
        self.depth += LANES * 4;
    }
}

/// Hint the CPU to bring the cache line at `address` into L2 (nothing elsewhere than x86-64).
#[inline(always)]
fn prefetch_l2(address: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T1};
        // SAFETY: a prefetch is a hint: it never faults and never reads or writes memory
        // the program sees, whatever the address (SSE, part of x86-64).
        unsafe { _mm_prefetch::<_MM_HINT_T1>(address as *const i8) }
    }
    #[cfg(not(target_arch = "x86_64"))]
    let _ = address;
}

/// `dst.fill(v)`, as one string store ([`store_words`]).
#[inline(always)]
fn fill_f32(dst: &mut [f32], v: f32) {
    // SAFETY: the `dst.len()` words from its start are `dst`'s, and any bits are an f32.
    unsafe { store_words(dst.as_mut_ptr().cast(), dst.len(), v.to_bits()) }
}

/// `dst.fill(px)`, as one string store ([`store_words`]).
#[inline(always)]
fn fill_rgba8(dst: &mut [[u8; 4]], px: [u8; 4]) {
    // SAFETY: the `dst.len()` 4-byte words from its start are `dst`'s, and any bits are four u8.
    unsafe { store_words(dst.as_mut_ptr().cast(), dst.len(), u32::from_ne_bytes(px)) }
}

/// Write `word` (in native byte order) to the `count` 4-byte words from `dst`, which need
/// no alignment.
///
/// On x86-64 this is one `rep stosd`. A string store of a whole band (hundreds of
/// kilobytes) takes its cache lines without reading them first (no read for ownership),
/// where a loop of wide stores waited on each line fetched from L3: the clear was a fifth
/// of quad-single's band loop and a quarter of sphere4096-gouraud's, and this made both
/// frames 7 to 15 % faster on one thread (the fastest of 32 runs each).
///
/// # Safety
/// `dst .. dst + 4·count` must be writable memory that no reference reads meanwhile, and
/// any 4 bytes must be a valid value of what it holds.
#[inline(always)]
unsafe fn store_words(dst: *mut u8, count: usize, word: u32) {
    #[cfg(target_arch = "x86_64")]
    // SAFETY: `rep stosd` writes `rcx` words from `rdi` upward: the direction flag is
    // clear at every call (the System V and Windows ABIs require it), so exactly the caller's
    // `count` words are written; it touches no stack and no flags.
    unsafe {
        std::arch::asm!(
            "rep stosd",
            inout("rcx") count => _,
            inout("rdi") dst => _,
            in("eax") word,
            options(nostack, preserves_flags),
        );
    }
    #[cfg(not(target_arch = "x86_64"))]
    for k in 0..count {
        // SAFETY: word `k < count` is the caller's (above); unaligned writes need no alignment.
        unsafe { dst.cast::<u32>().add(k).write_unaligned(word) };
    }
}

/// Fill `bins` with, for each band of [`BAND_ROWS`] image rows, the indices (in order) of
/// the triangles whose rows reach into it (the bins' buffers are reused). A band then visits only its own triangles instead of
/// reading every triangle's bounds (a few per cent on the 4096-triangle sphere).
fn bin_by_band(tris: &[Tri], height: u32, bins: &mut Vec<Vec<u32>>) {
    bins.resize_with((height as usize).div_ceil(BAND_ROWS), Vec::new);
    for bin in bins.iter_mut() {
        bin.clear();
    }
    for (t, tri) in tris.iter().enumerate() {
        // window rows y_min..=y_max are image rows height-1-y_max ..= height-1-y_min
        let top = (height as i32 - 1 - tri.y_max).max(0) as usize / BAND_ROWS;
        let bottom = (height as i32 - 1 - tri.y_min).max(0) as usize / BAND_ROWS;
        for bin in bins.iter_mut().take(bottom + 1).skip(top) {
            bin.push(t as u32);
        }
    }
}

per_isa! {
    fn band_per_isa(job: &BandJob, color: &mut [[f32; 4]], depth: &mut [f32]) = band_body;
}

per_isa! {
    fn band_rgba8_per_isa(job: &BandJob, color: &mut [[u8; 4]], depth: &mut [f32]) = band_body;
}

/// A pixel of a colour buffer the band loop writes: linear `[f32; 4]` ([`Framebuffer`]) or
/// quantized `[u8; 4]` ([`Rgba8Framebuffer`]).
trait Pixel: Copy + Send + Sync {
    /// Fill `color` with the clear colour `c`.
    fn clear(color: &mut [Self], c: [f32; 4]);

    /// One pixel of the clear colour `c`, as [`Pixel::clear`] writes it.
    fn cleared(c: [f32; 4]) -> Self;

    /// 16 pixels `[r, g, b, 1]` from the shader's structure of arrays `rgb[channel][lane]`.
    fn from_lanes<S: Simd>(s: S, rgb: &[Lanes; 3], out: &mut [Self; LANES]);

    /// [`Pixel::from_lanes`] stored only to the pixels `l` whose bit `l` of `mask` is set;
    /// the others keep their value.
    fn from_lanes_where<S: Simd>(s: S, rgb: &[Lanes; 3], mask: u32, out: &mut [Self; LANES]);

    /// Storage for 16 pixels (overwritten before use).
    fn block() -> [Self; LANES];
}

impl Pixel for [f32; 4] {
    #[inline(always)]
    fn clear(color: &mut [Self], c: [f32; 4]) {
        if c.iter().all(|v| v.to_bits() == c[0].to_bits()) {
            // one repeated word (the benchmarks' transparent black): a string store
            fill_f32(color.as_flattened_mut(), c[0]);
            return;
        }
        // four pixels (64 bytes) at a time: one wide store per chunk
        let mut pattern = [0.0f32; 16];
        for (k, v) in pattern.iter_mut().enumerate() {
            *v = c[k % 4];
        }
        let mut chunks = color.as_flattened_mut().chunks_exact_mut(16);
        for chunk in &mut chunks {
            chunk.copy_from_slice(&pattern);
        }
        for (k, v) in chunks.into_remainder().iter_mut().enumerate() {
            *v = pattern[k];
        }
    }

    #[inline(always)]
    fn cleared(c: [f32; 4]) -> Self {
        c
    }

    #[inline(always)]
    fn from_lanes<S: Simd>(s: S, rgb: &[Lanes; 3], out: &mut [Self; LANES]) {
        s.rgba_pixels(rgb, out);
    }

    #[inline(always)]
    fn from_lanes_where<S: Simd>(s: S, rgb: &[Lanes; 3], mask: u32, out: &mut [Self; LANES]) {
        s.rgba_pixels_where(rgb, mask, out);
    }

    #[inline(always)]
    fn block() -> [Self; LANES] {
        [[1.0; 4]; LANES]
    }
}

impl Pixel for [u8; 4] {
    #[inline(always)]
    fn clear(color: &mut [Self], c: [f32; 4]) {
        fill_rgba8(color, Self::cleared(c));
    }

    #[inline(always)]
    fn cleared(c: [f32; 4]) -> Self {
        c.map(quantize)
    }

    #[inline(always)]
    fn from_lanes<S: Simd>(s: S, rgb: &[Lanes; 3], out: &mut [Self; LANES]) {
        s.rgba8_pixels(rgb, out);
    }

    #[inline(always)]
    fn from_lanes_where<S: Simd>(s: S, rgb: &[Lanes; 3], mask: u32, out: &mut [Self; LANES]) {
        s.rgba8_pixels_where(rgb, mask, out);
    }

    #[inline(always)]
    fn block() -> [Self; LANES] {
        [[0; 4]; LANES]
    }
}

std::thread_local! {
    /// A band's [`Covered`] bits, kept from one band to the next on each thread (taken
    /// out for the band and put back after it, so that no closure holds the band loop: a
    /// closure is a function of its own, which need not be compiled with the caller's
    /// `target_feature`s, and one measured up to a third slower on two threads).
    static COVERED: std::cell::Cell<Vec<u64>> = const { std::cell::Cell::new(Vec::new()) };
}

/// Run every draw's triangles that touch one band's rows, with the band cleared first.
///
/// The depth is cleared before the draws (the test reads it), the colour after them, and
/// only on the pixels no fragment was written to ([`Covered`]). The image is the same as
/// clearing first: nothing reads a colour before the band ends (there is no blending), and
/// every fragment overwrites its pixel whole. A pixel the draws cover is then written once,
/// not twice: a whole-screen quad stores no clear at all.
#[inline(always)]
fn band_body<S: Simd, P: Pixel>(s: S, job: &BandJob, color: &mut [P], depth: &mut [f32]) {
    let width = job.width as usize;
    let first_row = job.band * BAND_ROWS;
    let rows = color.len() / width;
    if job.clear.is_some() && job.draws.iter().any(|d| d.depth_test) {
        fill_f32(depth, 1.0);
    }
    // image rows first_row.. are window rows height-1-r
    let j_hi = job.height as i32 - 1 - first_row as i32;
    let j_lo = j_hi - rows as i32 + 1;
    let ahead = Ahead::after(job.frame, job.band, BAND_ROWS * width);
    let mut bits = COVERED.take();
    let covered = Covered::new(&mut bits, color.len());
    let mut band = Band { color, depth, width, j_hi, ahead, covered };
    for (d, parts) in job.draws.iter().zip(job.setups) {
        band.draw(s, d, parts, job.band, j_lo);
    }
    if let Some(c) = job.clear {
        band.covered.clear_the_rest(band.color, c.to_array());
    }
    COVERED.set(bits);
}

/// One bit per pixel of a band: set once a fragment passed there (it is stored before the
/// band ends). Bit `p mod 64` of word `p / 64` is pixel `p`; one word more than the pixels
/// need, so that a 16-pixel mask at any `p` sets at most two words.
struct Covered<'a> {
    words: &'a mut [u64],
}

impl<'a> Covered<'a> {
    /// No pixel of `pixels` covered, in `bits` (resized, its buffer reused).
    fn new(bits: &'a mut Vec<u64>, pixels: usize) -> Covered<'a> {
        bits.clear();
        bits.resize(pixels / 64 + 2, 0);
        Covered { words: bits }
    }

    /// Mark the pixels `base + l` of the bits `l` set in `mask` (`mask < 2^16`):
    ///
    /// ```text
    /// words[base / 64]     |= mask << (base mod 64)
    /// words[base / 64 + 1] |= mask >> (64 − base mod 64)     (the bits that crossed)
    /// ```
    #[inline(always)]
    fn mark(&mut self, base: usize, mask: u32) {
        let (w, shift) = (base / 64, base % 64);
        let wide = u128::from(mask) << shift;
        if let Some([lo, hi]) = self.words.get_mut(w..w + 2).and_then(|p| <&mut [u64; 2]>::try_from(p).ok()) {
            *lo |= wide as u64;
            *hi |= (wide >> 64) as u64;
        }
    }

    /// Write the clear colour `c` to every pixel of `color` not marked: a run of whole
    /// uncovered words as one [`Pixel::clear`] (a string store), a partly covered word
    /// pixel by pixel.
    fn clear_the_rest<P: Pixel>(&self, color: &mut [P], c: [f32; 4]) {
        let pixels = color.len();
        let value = P::cleared(c);
        let mut w = 0;
        while w * 64 < pixels {
            let word = self.words[w];
            if word == 0 {
                let start = w;
                while w * 64 < pixels && self.words[w] == 0 {
                    w += 1;
                }
                P::clear(&mut color[start * 64..(w * 64).min(pixels)], c);
                continue;
            }
            let mut free = !word;
            while free != 0 {
                let p = w * 64 + free.trailing_zeros() as usize;
                if p >= pixels {
                    break;
                }
                color[p] = value;
                free &= free - 1;
            }
            w += 1;
        }
    }
}

/// The mask of the first `n ≤ 16` lanes: `2^n − 1`.
#[inline(always)]
fn first_lanes(n: usize) -> u32 {
    (1u32 << n) - 1
}

/// Batches of waiting fragments shaded per flush, in one
/// [`FragmentShader::shade_batches`] call: the call is paid once for them, and the
/// kernel shades a pair side by side.
const FLUSH: usize = 2;

/// Fragments waiting to be shaded: [`FLUSH`] batches and one more, so a whole 16-pixel
/// chunk always fits after the ones already waiting. Cache-line aligned, as
/// [`FragmentBatch`].
#[repr(align(64))]
struct Staging {
    /// The draw's shader passes its varyings through (asked once per draw, not per
    /// chunk): its fragments go straight to the pixels and never wait here.
    through: bool,
    varyings: [[f32; STAGED]; MAX_VARYINGS],
    index: [u32; STAGED],
    len: usize,
}

/// [`Staging`]'s capacity in fragments.
const STAGED: usize = (FLUSH + 1) * LANES;

impl Staging {
    /// Whether no waiting fragment lies on one of the 16 pixels `base .. base + 16`:
    ///
    /// ```text
    /// misses(base) = ∀ l < len:  index[l] − base ∉ [0, 16)
    /// ```
    ///
    /// Then a whole chunk there can be shaded and stored at once, ahead of the waiting
    /// ones, and every pixel still receives its fragments in draw order, so the image is
    /// the same. Without it, the fast path waited for an empty staging: inside a quad
    /// the remainder of one row's span stayed waiting, and every chunk of every later row
    /// went through the staging copies (most of quad-single's band loop).
    #[inline(always)]
    fn misses(&self, base: usize) -> bool {
        let mut hit = false;
        for l in 0..STAGED {
            hit |= (l < self.len) & ((self.index[l] as usize).wrapping_sub(base) < LANES);
        }
        !hit
    }
}

/// Whole chunks of a span shaded per [`FragmentShader::shade_batches`] call.
const RUN: usize = 4;

/// Up to [`RUN`] whole chunks of one span, interpolated and depth-tested, waiting to be
/// shaded together: `batches[k]` goes to the 16 pixels from `bases[k]`.
///
/// They are shaded at the latest when their span ends. Until then no other fragment can
/// reach their pixels: the span's other chunks cover other pixels, and a chunk joins the
/// run only when no waiting fragment of [`Staging`] is on its pixels. So every pixel still
/// receives its fragments in draw order.
struct Run {
    batches: [FragmentBatch; RUN],
    out: Aligned<[[Lanes; 3]; RUN]>,
    bases: [usize; RUN],
    len: usize,
}

impl Run {
    fn new() -> Run {
        Run {
            batches: std::array::from_fn(|_| FragmentBatch::new()),
            out: Aligned([[[0.0; LANES]; 3]; RUN]),
            bases: [0; RUN],
            len: 0,
        }
    }
}

/// The batches of one [`Band::flush`] and their colours.
struct Flushed {
    batches: [FragmentBatch; FLUSH],
    out: Aligned<[[Lanes; 3]; FLUSH]>,
}

impl Flushed {
    fn new() -> Flushed {
        Flushed { batches: std::array::from_fn(|_| FragmentBatch::new()), out: Aligned([[[0.0; LANES]; 3]; FLUSH]) }
    }
}

/// A value on its own cache line(s): lane arrays that are stored and loaded 64 bytes at a
/// time (see [`FragmentBatch`]).
#[repr(align(64))]
struct Aligned<T>(T);

struct Band<'a, P> {
    color: &'a mut [P],
    depth: &'a mut [f32],
    width: usize,
    /// Window row of the band's first (top) image row.
    j_hi: i32,
    ahead: Ahead,
    /// The pixels a fragment passed at, for the clear after the draws ([`band_body`]).
    covered: Covered<'a>,
}

impl<P: Pixel> Band<'_, P> {
    #[inline(always)]
    fn draw<S: Simd>(&mut self, s: S, d: &DrawCall, parts: &[SetupPart], band: usize, j_lo: i32) {
        let nv = live_varyings(d);
        let mut staging = Staging {
            through: d.shader.passes_varyings_through(),
            varyings: [[0.0; STAGED]; MAX_VARYINGS],
            index: [0; STAGED],
            len: 0,
        };
        let mut flushed = Flushed::new();
        let mut run = Run::new();
        let tris = parts.iter().flat_map(|p| {
            let bin = p.bins.get(band).map_or(&[][..], |b| &b[..]);
            bin.iter().filter_map(move |&t| {
                let t = t as usize;
                Some((p.tris.get(t)?, p.varyings.get(t * nv..(t + 1) * nv)?))
            })
        });
        for (tri, varyings) in tris {
            if tri.y_max < j_lo || tri.y_min > self.j_hi {
                continue;
            }
            let j0 = tri.y_min.max(j_lo);
            let mut rows = tri.rows_from(j0);
            for j in j0..=tri.y_max.min(self.j_hi) {
                if let Some((i0, i1)) = rows.next(s, j) {
                    let row_start = (self.j_hi - j) as usize * self.width;
                    self.span(s, tri, varyings, j, i0, i1, row_start, d, &mut staging, &mut run, &mut flushed);
                }
            }
        }
        while staging.len > 0 {
            self.flush(s, d.shader, nv, &mut staging, &mut flushed);
        }
    }

    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn span<S: Simd>(
        &mut self,
        s: S,
        tri: &Tri,
        varyings: &[Plane],
        j: i32,
        i0: i32,
        i1: i32,
        row_start: usize,
        d: &DrawCall,
        staging: &mut Staging,
        run: &mut Run,
        flushed: &mut Flushed,
    ) {
        let (z0, zdx) = tri.z.row(j);
        let nv = varyings.len();
        let mut planes = RowPlanes { w: tri.inv_w.row(j), v0: [0.0; MAX_VARYINGS], vdx: [0.0; MAX_VARYINGS], nv };
        for (k, v) in varyings.iter().enumerate() {
            (planes.v0[k], planes.vdx[k]) = v.row(j);
        }
        let mut i = i0;
        while i <= i1 {
            self.ahead.fetch();
            let start = staging.len;
            let n = ((i1 - i + 1) as usize).min(LANES);
            let base = row_start + i as usize;
            // bit l: pixel base + l passed (only lanes l < n can)
            let pass = if !d.depth_test {
                first_lanes(n)
            } else if let Some(block) = self.depth.get_mut(base..base + LANES) {
                s.depth_less(block.try_into().expect("16 lanes"), z0, zdx, i as f32, first_lanes(n))
            } else {
                // the band's last pixels: fewer than 16 left after `base`
                let depth = &mut self.depth[base..base + n];
                let mut pass = 0;
                for l in 0..n {
                    let z = z0 + zdx * (i + l as i32) as f32;
                    if z < depth[l] {
                        depth[l] = z;
                        pass |= 1 << l;
                    }
                }
                pass
            };
            // every passed lane is stored before the band ends (in place, in the run or
            // from the staging)
            self.covered.mark(base, pass);
            let whole = pass == first_lanes(LANES);
            // a whole chunk of 16 that passed, with no waiting fragment on its pixels (so the
            // pixels' writes stay in draw order): interpolate it into the run, to be shaded
            // and stored in place, without the staging copies and the per-pixel index
            if whole && !staging.through && staging.misses(base) {
                let k = run.len;
                s.interpolate(i as f32, &planes, &mut run.batches[k].varyings);
                run.batches[k].len = LANES;
                run.bases[k] = base;
                run.len += 1;
                if run.len == RUN {
                    self.shade_run(s, d.shader, run);
                }
                i += n as i32;
                continue;
            }
            // all 16 lanes are computed (vectorized); only the passed ones are kept
            let mut vals = Aligned([[0.0f32; LANES]; MAX_VARYINGS]);
            let vals = &mut vals.0;
            s.interpolate(i as f32, &planes, vals);
            if staging.through {
                // the colour is the first three varyings, read in place (not copied)
                let rgb = vals.first_chunk::<3>().expect("MAX_VARYINGS ≥ 3");
                if let Some(pixels) = self.color.get_mut(base..base + LANES) {
                    // the passed pixels stored in place, the others left as they were
                    P::from_lanes_where(s, rgb, pass, pixels.try_into().expect("16 pixels"));
                } else {
                    // the band's last pixels: fewer than 16 left after `base`
                    let mut rgba = P::block();
                    P::from_lanes(s, rgb, &mut rgba);
                    let pixels = &mut self.color[base..base + n];
                    for (l, (px, &value)) in pixels.iter_mut().zip(&rgba).enumerate() {
                        if pass & (1 << l) != 0 {
                            *px = value;
                        }
                    }
                }
                i += n as i32;
                continue;
            }
            // the passed lanes, packed after the waiting ones
            let mut index = [0u32; LANES];
            for (l, idx) in index.iter_mut().enumerate() {
                *idx = (base + l) as u32;
            }
            let to: &mut [u32; LANES] = (&mut staging.index[start..start + LANES]).try_into().expect("16 lanes");
            if pass == first_lanes(n) {
                // the usual case (a closed mesh with culling rarely fails the depth test): a
                // plain copy, which does not wait on a compaction's latency
                *to = index;
                for k in 0..nv {
                    staging.varyings[k][start..start + LANES].copy_from_slice(&vals[k]);
                }
            } else {
                s.compress_u32(&index, pass, to);
                for k in 0..nv {
                    let to: &mut Lanes = (&mut staging.varyings[k][start..start + LANES]).try_into().expect("16 lanes");
                    s.compress(&vals[k], pass, to);
                }
            }
            staging.len += pass.count_ones() as usize;
            if staging.len >= FLUSH * LANES {
                self.flush(s, d.shader, nv, staging, flushed);
            }
            i += n as i32;
        }
        if run.len > 0 {
            self.shade_run(s, d.shader, run);
        }
    }

    /// Shade the run's whole chunks in one call and store each in place.
    #[inline(always)]
    fn shade_run<S: Simd>(&mut self, s: S, shader: &dyn FragmentShader, run: &mut Run) {
        let len = run.len;
        shader.shade_batches(&run.batches[..len], &mut run.out.0[..len]);
        for (&base, rgb) in run.bases[..len].iter().zip(&run.out.0) {
            let pixels: &mut [P; LANES] = (&mut self.color[base..base + LANES]).try_into().expect("16 pixels");
            P::from_lanes(s, rgb, pixels);
        }
        run.len = 0;
    }

    /// Shade the first (up to) [`FLUSH`] · 16 waiting fragments in one call, store them,
    /// and move the rest (fewer than 16) down.
    #[inline(always)]
    fn flush<S: Simd>(
        &mut self,
        s: S,
        shader: &dyn FragmentShader,
        nv: usize,
        staging: &mut Staging,
        flushed: &mut Flushed,
    ) {
        let len = staging.len.min(FLUSH * LANES);
        let count = len.div_ceil(LANES);
        for (b, batch) in flushed.batches[..count].iter_mut().enumerate() {
            for k in 0..nv {
                batch.varyings[k].copy_from_slice(&staging.varyings[k][b * LANES..(b + 1) * LANES]);
            }
            batch.len = (len - b * LANES).min(LANES);
        }
        shader.shade_batches(&flushed.batches[..count], &mut flushed.out.0[..count]);
        for (b, (batch, out)) in flushed.batches[..count].iter().zip(&flushed.out.0).enumerate() {
            // transpose to pixels first, then one 16-byte store per pixel (not a 4-way scatter)
            let mut rgba = P::block();
            P::from_lanes(s, out, &mut rgba);
            for (&idx, px) in staging.index[b * LANES..b * LANES + batch.len].iter().zip(&rgba) {
                if let Some(dst) = self.color.get_mut(idx as usize) {
                    *dst = *px;
                }
            }
        }
        let rest = staging.len - len;
        // a fixed 16-lane move from the lanes after the flushed ones (those past `rest` are
        // stale and ignored): a copy of `rest` lanes was a memmove call per varying and per batch
        let from = FLUSH * LANES;
        for k in 0..nv {
            staging.varyings[k].copy_within(from..from + LANES, 0);
        }
        staging.index.copy_within(from..from + LANES, 0);
        staging.len = rest;
    }
}

/// How many of `draw`'s triangles cover each pixel (image order, top row
/// first), by the same setup, clipping, culling and fill rule as [`render`].
///
/// A closed mesh seen from outside covers each pixel of its silhouette
/// exactly once (front faces) when culling is on; a tiled plane covers each
/// pixel inside it exactly once. The fragment stage is not run.
pub fn coverage(width: u32, height: u32, draw: &DrawCall) -> Vec<u32> {
    let mut counts = vec![0u32; width as usize * height as usize];
    let mut parts = Vec::new();
    setup_parallel(draw, width, height, &mut Vec::new(), &mut parts);
    for tri in parts.iter().flat_map(|p| &p.tris) {
        let mut rows = tri.rows_from(tri.y_min);
        for j in tri.y_min..=tri.y_max {
            if let Some((i0, i1)) = rows.next(super::simd::Baseline, j) {
                let row = (height as i32 - 1 - j) as usize * width as usize;
                for c in &mut counts[row + i0 as usize..=row + i1 as usize] {
                    *c += 1;
                }
            }
        }
    }
    counts
}

#[cfg(test)]
mod snap_tests {
    use super::round_half_away;

    #[test]
    fn round_half_away_is_rounds_to_i64() {
        let mut cases = vec![0.0, -0.0, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994];
        cases.extend([1e15 + 0.5, -1e15 - 0.5, 9.007_199_254_740_993e15, 1e300, -1e300, f64::MAX, f64::MIN]);
        // a sweep over window coordinates times 256, with the ties of every half pixel
        let mut x = -3.0e6;
        while x < 3.0e6 {
            cases.extend([x, x + 0.5, x - 0.5, x + 0.25, x + 0.75]);
            x += 12_345.678_9;
        }
        for v in cases {
            assert_eq!(round_half_away(v), v.round() as i64, "{v:e}");
        }
    }
}

#[cfg(test)]
mod span_tests {
    use super::*;
    use proptest::prelude::*;

    struct Unused;
    impl FragmentShader for Unused {
        fn shade(&self, _: &FragmentBatch, _: &mut [Lanes; 3]) {}
    }

    /// The triangle with snapped corners `(x, y)` (1/256 pixel) in a 64 × 64 window, both
    /// windings kept (no culling).
    fn tri(corners: [(i64, i64); 3]) -> Option<Tri> {
        let p = corners.map(|(x, y)| Projected { x, y, z: 0.5, inv_w: 1.0 });
        let draw = DrawCall {
            vertices: &[],
            triangles: &[],
            varying_count: 0,
            cull: CullMode::None,
            depth_test: false,
            shader: &Unused,
        };
        let none = [0.0; MAX_VARYINGS];
        setup(p, [&none; 3], 64, 64, &draw, &mut RenderStats::default(), &mut Vec::new())
    }

    /// The record the band loop reads per triangle is 112 bytes, as its doc says.
    #[test]
    fn a_set_up_triangle_is_112_bytes() {
        assert_eq!(std::mem::size_of::<Tri>(), 112);
    }

    per_isa! {
        fn lane_spans_per_isa(t: &Tri, rows: std::ops::RangeInclusive<i32>) -> Vec<Option<(i32, i32)>> = lane_spans;
    }

    /// The spans of `rows` found by `t`'s lanes ([`Tri::lane_edges`]) in the build `s`.
    #[inline(always)]
    fn lane_spans<S: Simd>(s: S, t: &Tri, rows: std::ops::RangeInclusive<i32>) -> Vec<Option<(i32, i32)>> {
        match t.lane_edges() {
            Some(lanes) => rows.map(|j| lanes.span(s, j)).collect(),
            None => Vec::new(),
        }
    }

    /// `t` is narrow enough for the lanes, and they give the span `span_by_division` gives
    /// on every row of `t` and on the row above and below it, in this CPU's build and in
    /// the portable one.
    fn spans_agree(t: &Tri) -> Result<(), TestCaseError> {
        prop_assert!(t.lane_edges().is_some(), "box {}..={} wider than the lanes", t.x_min, t.x_max);
        let rows = t.y_min - 1..=t.y_max + 1;
        let by_division: Vec<_> = rows.clone().map(|j| t.span_by_division(j)).collect();
        for isa in [Isa::detect(), Isa::BASELINE] {
            prop_assert_eq!(&lane_spans_per_isa(isa, t, rows.clone()), &by_division, "{:?}, rows {:?}", isa, rows);
        }
        Ok(())
    }

    /// [`Stepper`]'s quotient is the division's on every step, for every divisor 1 to 24,
    /// start and step −50 to 50 (so every remainder, including a step that lands exactly
    /// on the divisor, where the carry decides), over 30 steps.
    #[test]
    fn stepper_is_the_division_on_every_step() {
        for d in 1i64..=24 {
            for delta in -50i64..=50 {
                for v0 in -50i64..=50 {
                    let mut st = Stepper::new(v0, delta, d);
                    for k in 0..30 {
                        let v = v0 + k * delta;
                        assert_eq!((st.floor(), st.ceil()), (v.div_euclid(d), -(-v).div_euclid(d)), "v = {v}, d = {d}");
                        st.step();
                    }
                }
            }
        }
    }

    /// [`RowWalk`] gives the span `span_by_division` gives on every row of `t` and on the
    /// rows above and below it, walking from each of its first rows (the band loop starts
    /// at the band's first row of the triangle) and from the row below it.
    fn walk_agrees(t: &Tri) -> Result<(), TestCaseError> {
        let last = t.y_max + 1;
        for j0 in [t.y_min - 1, t.y_min, t.y_min + 1, (t.y_min + t.y_max) / 2] {
            let mut walk = RowWalk::new(t, j0);
            for j in j0..=last {
                prop_assert_eq!(walk.span(), t.span_by_division(j), "row {} walked from {}", j, j0);
                walk.step();
            }
        }
        Ok(())
    }

    proptest! {
        /// The walk and `span_by_division` test the same edge functions: on every row of a
        /// triangle, narrow or as wide as the window, they give the same span, including
        /// on corners snapped exactly to pixel centres (multiples of 256), where the
        /// top-left rule decides, and on horizontal edges (`a = 0`).
        #[test]
        fn walk_and_division_give_the_same_spans(
            corners in prop::array::uniform3((0i64..64 * 256, 0i64..64 * 256)),
            small in any::<bool>(),
            offset in (0i64..28, 0i64..30),
            on_centres in any::<bool>(),
            flat in any::<bool>(),
        ) {
            let snap = |v: i64| if on_centres { v / 256 * 256 } else { v };
            let mut corners = corners.map(|(x, y)| {
                if small {
                    (snap(x / 2) + offset.0 * 256, snap(y / 2) + offset.1 * 256)
                } else {
                    (snap(x), snap(y))
                }
            });
            if flat {
                corners[1].1 = corners[0].1;
            }
            if let Some(t) = tri(corners) {
                walk_agrees(&t)?;
            }
        }

        /// The lanes and `span_by_division` test the same edge functions: on every row of a
        /// triangle at most 32 pixels wide (so 16 and 32 lanes) they give the same span,
        /// including on corners snapped exactly to pixel centres (multiples of 256), where
        /// the top-left rule decides.
        #[test]
        fn lanes_and_division_give_the_same_spans(
            corners in prop::array::uniform3((0i64..34 * 256, 0i64..30 * 256)),
            offset in (0i64..28, 0i64..30),
            on_centres in any::<bool>(),
        ) {
            let snap = |v: i64| if on_centres { v / 256 * 256 } else { v };
            let corners = corners.map(|(x, y)| (snap(x) + offset.0 * 256, snap(y) + offset.1 * 256));
            if let Some(t) = tri(corners) {
                prop_assume!(t.x_max - t.x_min < SPAN_LANES as i32);
                spans_agree(&t)?;
            }
        }

        /// The same, for the lanes and the walk, on triangles reaching far outside the
        /// 64 × 64 window, up to the guard band's 2^24 subpixels: one corner in the window,
        /// in a column 1 to 30 pixels wide at its left or right border, the other two
        /// beyond that column, so the clamped box is narrow and the lanes test it. Their
        /// steps `a` reach 2^33 and the edge functions at `x_min` 2^40, past 32 bits: the
        /// lanes' sums must be wider than i32 or f32, and so must the walk's quotients and
        /// remainders.
        #[test]
        fn lanes_walk_and_division_agree_on_triangles_from_far_outside_the_window(
            right in any::<bool>(),
            inside in 1i64..31,
            near in (0i64..256, 0i64..64 * 256),
            far in prop::array::uniform2((0i64..1 << 24, -(1i64 << 24)..1 << 24)),
        ) {
            // beyond the column's inner line, by `near` of its width (and inside the window)
            // or by `far`
            let beyond = [near.0 * inside, far[0].0, far[1].0];
            let x = |k: usize| if right { (64 - inside) * 256 + beyond[k] } else { inside * 256 - beyond[k] };
            let corners = [(x(0), near.1), (x(1), far[0].1), (x(2), far[1].1)];
            if let Some(t) = tri(corners) {
                // the column keeps the clamped box at most 31 pixels wide (spans_agree checks it)
                spans_agree(&t)?;
                walk_agrees(&t)?;
            }
        }
    }
}

#[cfg(test)]
mod order_tests {
    use super::*;

    /// Writes the first three varyings as its colour, through the batches (not a
    /// pass-through shader, so its fragments wait in staging).
    struct Batched;
    impl FragmentShader for Batched {
        fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
            out.copy_from_slice(&batch.varyings[..3]);
        }
    }

    /// A vertex at window position `(x, y)` of a 32 × 32 window, coloured `rgb`.
    fn at(x: f32, y: f32, rgb: [f32; 3]) -> ClipVertex {
        let mut varyings = [0.0; MAX_VARYINGS];
        varyings[..3].copy_from_slice(&rgb);
        ClipVertex { clip: Vec4::new(x / 16.0 - 1.0, y / 16.0 - 1.0, 0.5, 1.0), varyings }
    }

    /// A whole chunk that could be stored at once, [`Staging::misses`], must not overtake
    /// a waiting fragment on one of its pixels: with the depth test off, the later of two
    /// triangles wins every pixel they share. The first is three pixels of one row (they
    /// wait in staging); the second covers the window, so its chunks of 16 pass whole,
    /// and the one over those three pixels must wait behind them.
    #[test]
    fn a_chunk_over_a_waiting_fragment_is_written_after_it() {
        let (red, green) = ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]);
        let vertices = [
            at(2.0, 20.0, red),
            at(5.2, 20.0, red),
            at(2.0, 21.2, red),
            at(-1.0, -1.0, green),
            at(80.0, -1.0, green),
            at(-1.0, 80.0, green),
        ];
        let triangles = [[0, 1, 2], [3, 4, 5]];
        let draw = |triangles| DrawCall {
            vertices: &vertices,
            triangles,
            varying_count: 3,
            cull: CullMode::None,
            depth_test: false,
            shader: &Batched,
        };
        // the small triangle alone covers a few pixels, all in one row
        let small = coverage(32, 32, &draw(&triangles[..1]));
        assert!((1..16).contains(&small.iter().sum::<u32>()), "{small:?}");
        let mut fb = Framebuffer::new(32, 32).unwrap();
        render(&mut fb, Some(Vec4::ZERO), &[draw(&triangles)]);
        for (p, c) in fb.color.iter().enumerate() {
            assert_eq!(*c, [0.0, 1.0, 0.0, 1.0], "pixel {p} (the small triangle's: {})", small[p]);
        }
    }

    /// Passes its first three varyings through ([`FragmentShader::passes_varyings_through`]):
    /// its fragments are stored in place, never staged.
    struct Through;
    impl FragmentShader for Through {
        fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
            out.copy_from_slice(&batch.varyings[..3]);
        }
        fn passes_varyings_through(&self) -> bool {
            true
        }
    }

    proptest::proptest! {
        /// The band clears its colour after the draws, only where no fragment passed
        /// ([`Covered`]). That must give exactly the image of clearing first: here a
        /// frame whose colour holds a stale value is drawn with a clear, and compared
        /// bit for bit with the same draws over a colour already holding the clear.
        /// Sizes that are not multiples of 64 or of a band put partly covered words at
        /// every row end and a short last band; both pixel types, both shader paths,
        /// with and without the depth test, a one-word clear and a four-word one.
        #[test]
        fn clearing_after_the_draws_gives_the_image_of_clearing_first(
            size in (1u32..150, 1u32..100),
            corners in proptest::collection::vec(((-10.0f32..42.0, -10.0f32..42.0), 0.0f32..1.0), 3..10),
            depth_test in proptest::bool::ANY,
            through in proptest::bool::ANY,
            grey_clear in proptest::bool::ANY,
        ) {
            let clear = if grey_clear { Vec4::ZERO } else { Vec4::new(0.25, 0.5, 0.75, 1.0) };
            let vertices: Vec<ClipVertex> = corners
                .iter()
                .map(|&((x, y), z)| {
                    let mut v = at(x, y, [x / 32.0, y / 32.0, z]);
                    v.clip.z = z;
                    v
                })
                .collect();
            let triangles: Vec<[u32; 3]> = (0..vertices.len() as u32 - 2).map(|k| [k, k + 1, k + 2]).collect();
            let shader: &dyn FragmentShader = if through { &Through } else { &Batched };
            let draws = [DrawCall { vertices: &vertices, triangles: &triangles, varying_count: 3, cull: CullMode::None, depth_test, shader }];
            let (w, h) = size;
            let mut expected = Framebuffer::new(w, h).unwrap();
            expected.color.fill(clear.to_array());
            render(&mut expected, None, &draws);
            let mut drawn = Framebuffer::new(w, h).unwrap();
            drawn.color.fill([9.0, -3.0, 0.5, 2.0]);
            drawn.depth.fill(0.0);
            render(&mut drawn, Some(clear), &draws);
            for (p, (a, b)) in drawn.color.iter().zip(&expected.color).enumerate() {
                proptest::prop_assert_eq!(a.map(f32::to_bits), b.map(f32::to_bits), "pixel {} of {}x{}", p, w, h);
            }
            let mut expected = Rgba8Framebuffer::new(w, h).unwrap();
            expected.color.fill(clear.to_array().map(quantize));
            render_into(w, h, &mut expected.color, &mut expected.depth, None, &draws, &mut RasterScratch::default(), band_rgba8_per_isa);
            let mut drawn = Rgba8Framebuffer::new(w, h).unwrap();
            drawn.color.fill([7, 6, 5, 4]);
            drawn.depth.fill(0.0);
            render_rgba8_with(&mut drawn, Some(clear), &draws, &mut RasterScratch::default());
            proptest::prop_assert_eq!(drawn.color, expected.color);
        }
    }
}

#[cfg(test)]
mod rgba8_tests {
    use super::*;

    /// Values around every rounding threshold `(k + ½)/255` (a thousand floats either
    /// side), the ends, out of range, ±∞, NaN and −0.
    fn hard_values() -> Vec<f32> {
        let mut values = vec![0.0, -0.0, 1.0, -1.0, 2.0, 255.0, f32::NAN, -f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
        values.extend([f32::MIN_POSITIVE, f32::MAX, f32::MIN, 1.0 / 510.0, 254.5 / 255.0]);
        for k in 0..=255u32 {
            let threshold = (k as f32 + 0.5) / 255.0;
            for d in -1000i32..=1000 {
                values.push(f32::from_bits((threshold.to_bits() as i32 + d) as u32));
            }
        }
        values
    }

    /// The band loop's 16-pixel RGBA8 writes are [`quantize`] of each channel and alpha
    /// 255, in the detected instruction set and in the portable build, including at every
    /// rounding threshold: the vectorized conversion rounds as the scalar one.
    #[test]
    fn rgba8_lanes_are_the_quantized_channels_in_every_build() {
        per_isa! {
            fn lanes_per_isa(rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) = lanes_body;
        }
        #[inline(always)]
        fn lanes_body<S: Simd>(s: S, rgb: &[Lanes; 3], out: &mut [[u8; 4]; LANES]) {
            <[u8; 4] as Pixel>::from_lanes(s, rgb, out)
        }
        let values = hard_values();
        for isa in [Isa::detect(), Isa::BASELINE] {
            for (n, chunk) in values.chunks(3 * LANES).enumerate() {
                let mut rgb = [[0.0f32; LANES]; 3];
                for (i, &v) in chunk.iter().enumerate() {
                    // rotate the channels so every value meets every channel's shift
                    rgb[(i + n) % 3][i / 3] = v;
                }
                let mut out = [[0u8; 4]; LANES];
                lanes_per_isa(isa, &rgb, &mut out);
                for l in 0..LANES {
                    let expected = [quantize(rgb[0][l]), quantize(rgb[1][l]), quantize(rgb[2][l]), 255];
                    assert_eq!(out[l], expected, "{isa:?} lane {l}: rgb {:?}", [rgb[0][l], rgb[1][l], rgb[2][l]]);
                }
            }
        }
    }

    /// [`quantize`] is `round(255 · clamp(x, 0, 1))` with halves away from zero and NaN as
    /// 0, checked in f64 (where `255 · x` is exact) around every threshold.
    #[test]
    fn a_string_store_writes_its_words_and_no_other() {
        for (start, len) in [(0, 0), (1, 1), (3, 17), (5, 64)] {
            let mut buf = vec![7.5f32; 80];
            fill_f32(&mut buf[start..start + len], -0.25);
            for (k, &v) in buf.iter().enumerate() {
                let inside = (start..start + len).contains(&k);
                assert_eq!(v, if inside { -0.25 } else { 7.5 }, "word {k} of fill({start}..{})", start + len);
            }
            let mut px = vec![[1u8, 2, 3, 4]; 80];
            fill_rgba8(&mut px[start..start + len], [9, 8, 7, 6]);
            for (k, &p) in px.iter().enumerate() {
                let inside = (start..start + len).contains(&k);
                assert_eq!(p, if inside { [9, 8, 7, 6] } else { [1, 2, 3, 4] }, "pixel {k}");
            }
        }
    }

    #[test]
    fn quantize_rounds_halves_up() {
        for x in hard_values() {
            let expected = if x.is_nan() { 0 } else { (f64::from(x).clamp(0.0, 1.0) * 255.0).round() as u8 };
            // f32's 255·x is rounded once; it can only land on the other side of a
            // threshold when the exact product is within half an ulp of it
            let exact = f64::from(x) * 255.0;
            let near_tie = (exact - exact.floor() - 0.5).abs() < 1e-5;
            if !near_tie {
                assert_eq!(quantize(x), expected, "x = {x:e}");
            }
        }
    }
}
