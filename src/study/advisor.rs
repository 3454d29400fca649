//! Advisors: where per-vertex (Gouraud) shading is enough, and how coarse a mesh may be.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `span_deg` | angle between the normals at the two ends of a triangle edge |
//! | `t` | interpolation parameter along the edge, 0 … 1 |
//! | `diffuse_weight` | `light.diffuse · material.diffuse` for one channel |
//! | `specular_weight` | `light.specular · material.specular` for one channel |
//! | `budget` | the largest error allowed, in linear units ([`ONE_LEVEL`] = one 8-bit level) |
//!
//! Both advisors work at the formula level: they evaluate the lighting model
//! at the points a rasterizer would interpolate, without rasterizing.
//!
//! - *Per-fragment* (Phong shading): at each point the normal is
//!   `normalize(lerp(n0, n1, t))` and the lighting model is evaluated there.
//! - *Per-vertex* (Gouraud shading): the lighting model is evaluated at the
//!   vertices and the colors are interpolated, `lerp(c0, c1, t)`.
//!
//! Source: Gouraud 1971 ("Continuous shading of curved surfaces"), Phong 1975;
//! LearnOpenGL, Basic lighting, exercise "Gouraud shading".

use crate::casters::LocalLight as _;
use glam::Vec3;

use crate::casters::PointLight;
use crate::glsl::reflect;
use crate::material::{LightProps, Material};

use super::ONE_LEVEL;

/// Samples along an edge (and of peak placements) used by the edge error
/// estimates. 64 intervals resolve a lobe feature of 1/64 of the edge; the
/// tests check that doubling it changes the estimate by less than 1%.
const EDGE_SAMPLES: usize = 64;

/// The unit normal at angle `a_deg` from +z toward +x, in the xz plane.
fn normal_at(a_deg: f32) -> Vec3 {
    let a = a_deg.to_radians();
    Vec3::new(a.sin(), 0.0, a.cos())
}

/// One channel of the lighting model for a distant light and viewer, no ambient.
fn channel(n: Vec3, light_dir: Vec3, view_dir: Vec3, weights: (f32, f32), shininess: f32) -> f32 {
    let diff = n.dot(light_dir).max(0.0);
    let spec = crate::glsl::pow_or_zero(view_dir.dot(reflect(-light_dir, n)).max(0.0), shininess);
    weights.0 * diff + weights.1 * spec
}

/// The largest per-vertex error along one edge, for one channel.
///
/// ```text
/// n0, n1    = normals at ±span/2 in one plane;  n(t) = normalize(lerp(n0, n1, t))
/// for each peak placement t* on a grid of 65:
///     light_dir = view_dir = n(t*)          (head-on: diffuse and specular peak at t*)
///     c(t) = diffuse_weight · max(n·l, 0) + specular_weight · pow(max(v·r, 0), s)
///     g(t) = lerp(c(0), c(1), t)
///     error = max_t |c(t) − g(t)|
/// result = max over t* of error
/// ```
///
/// The head-on placement is the worst case for a highlight that falls inside
/// the edge: the per-fragment peak is the lobe's full height while the
/// vertices see the lobe `span/2` or more off its axis. Weights are
/// non-negative fractions; shininess ≤ 0 follows [`crate::glsl::pow_or_zero`].
/// A zero span gives 0.
///
/// Source: Gouraud 1971; Phong 1975.
pub fn gouraud_edge_error(diffuse_weight: f32, specular_weight: f32, shininess: f32, span_deg: f32) -> f32 {
    gouraud_edge_error_sampled(diffuse_weight, specular_weight, shininess, span_deg, EDGE_SAMPLES)
}

/// [`gouraud_edge_error`] with an explicit sample count (for convergence tests).
///
/// `samples` intervals along the edge and as many peak placements; 0 is
/// treated as 1.
pub fn gouraud_edge_error_sampled(
    diffuse_weight: f32,
    specular_weight: f32,
    shininess: f32,
    span_deg: f32,
    samples: usize,
) -> f32 {
    let samples = samples.max(1);
    let n0 = normal_at(-0.5 * span_deg);
    let n1 = normal_at(0.5 * span_deg);
    let n_at = |t: f32| n0.lerp(n1, t).normalize_or_zero();
    let weights = (diffuse_weight, specular_weight);
    let mut worst = 0.0f32;
    for p in 0..=samples {
        let peak = n_at(p as f32 / samples as f32);
        let c = |t: f32| channel(n_at(t), peak, peak, weights, shininess);
        let (c0, c1) = (c(0.0), c(1.0));
        for k in 0..=samples {
            let t = k as f32 / samples as f32;
            worst = worst.max((c(t) - (c0 + (c1 - c0) * t)).abs());
        }
    }
    worst
}

/// The largest per-vertex error of a spot's intensity across a span of `span_deg`
/// (the triangle's angular size seen from the spot).
///
/// ```text
/// f(x) = clamp((outer − |x|) / (outer − inner), 0, 1)     x = angle off the axis, degrees
/// error = max over placements c, x in [c, c + span] of |f(x) − lerp(f(c), f(c + span))|
/// ```
///
/// The ramp is taken linear in angle (the shader's is linear in cosine; the
/// two differ by less than 2% over a 15° cone). A cone narrower than the span
/// can fall between the vertices: error 1. `inner ≥ outer` is the hard edge.
/// Non-finite input gives NaN.
///
/// Source: LearnOpenGL, Light casters, "Smooth/Soft edges".
pub fn spot_gouraud_error(inner_deg: f32, outer_deg: f32, span_deg: f32) -> f32 {
    if !(inner_deg.is_finite() && outer_deg.is_finite() && span_deg.is_finite()) {
        return f32::NAN;
    }
    let width = outer_deg - inner_deg;
    let f = |x: f32| {
        if width > 0.0 {
            ((outer_deg - x.abs()) / width).clamp(0.0, 1.0)
        } else if x.abs() < outer_deg {
            1.0
        } else {
            0.0
        }
    };
    let steps = 256;
    let lo = -outer_deg - span_deg;
    let hi = outer_deg;
    let mut worst = 0.0f32;
    for p in 0..=steps {
        let c = lo + (hi - lo) * p as f32 / steps as f32;
        let (f0, f1) = (f(c), f(c + span_deg));
        for k in 0..=EDGE_SAMPLES {
            let t = k as f32 / EDGE_SAMPLES as f32;
            worst = worst.max((f(c + t * span_deg) - (f0 + (f1 - f0) * t)).abs());
        }
    }
    worst
}

/// Which shading frequency a surface needs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadingFrequency {
    /// Per-vertex (Gouraud) shading meets the budget.
    PerVertex,
    /// Per-fragment (Phong) shading is needed.
    PerFragment,
}

/// Why per-vertex shading fails a budget.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Reason {
    /// The diffuse term alone exceeds the budget (a large normal span).
    DiffuseCurvature,
    /// The specular lobe is too tight for the normal span (high shininess).
    TightHighlight,
    /// A spot's edge (or whole cone) is narrower than the triangle.
    SpotEdge,
}

/// The shading-mode advisor's answer.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadingAdvice {
    /// Worst per-vertex error of the diffuse term alone, over channels.
    pub diffuse_error: f32,
    /// Worst per-vertex error of diffuse and specular together, over channels.
    pub shading_error: f32,
    /// Worst error from interpolating the spot intensity, times the light's
    /// largest diffuse + specular weight (0 without a spot).
    pub spot_error: f32,
    /// `shading_error + spot_error`: the estimate compared with the budget.
    pub total_error: f32,
    /// The advice.
    pub mode: ShadingFrequency,
    /// Every reason the budget is exceeded (empty for per-vertex).
    pub reasons: Vec<Reason>,
}

/// A spot's cone and the triangle's angular size seen from the spot.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpotSpan {
    /// Inner cone half-angle φ, degrees.
    pub inner_deg: f32,
    /// Outer cone half-angle γ, degrees.
    pub outer_deg: f32,
    /// Angle the triangle subtends at the spot, degrees.
    pub span_deg: f32,
}

/// Does per-vertex shading meet `budget` for this material, light and triangle?
///
/// ```text
/// per channel c: wd = light.diffuse[c]·material.diffuse[c], ws = light.specular[c]·material.specular[c]
/// shading_error = max_c gouraud_edge_error(wd, ws, s, normal_span)
/// spot_error    = spot_gouraud_error(inner, outer, spot_span) · max_c (wd + ws)
/// PerVertex  iff  shading_error + spot_error <= budget
/// ```
///
/// The light and eye are taken as distant. For a near light or eye, pass the
/// span multiplied by the parallax factor `1 + 1/(2·dl) + 1/(2·de)` (distances
/// in units of the surface's radius of curvature; see [`sphere_parallax`]).
/// The ambient term is constant across a triangle and never adds error.
/// Reasons name each part that alone exceeds the budget (the diffuse part
/// with `ws = 0`; the highlight when diffuse alone passes; the spot); when
/// only the sum exceeds it, the larger part is named. Negative light
/// channels are taken by absolute value. NaN input gives `PerFragment`.
///
/// Source: Gouraud 1971; LearnOpenGL, Basic lighting, Gouraud exercise
/// ("the specular highlight is less bright and blocky").
pub fn advise_shading(
    material: &Material,
    light: &LightProps,
    normal_span_deg: f32,
    spot: Option<SpotSpan>,
    budget: f32,
) -> ShadingAdvice {
    let wd = (light.diffuse * material.diffuse).abs();
    let ws = (light.specular * material.specular).abs();
    let per_channel = |f: &dyn Fn(f32, f32) -> f32| (0..3).map(|c| f(wd[c], ws[c])).fold(0.0f32, f32::max);
    let s = material.shininess;
    let diffuse_error = per_channel(&|d, _| gouraud_edge_error(d, 0.0, s, normal_span_deg));
    let shading_error = per_channel(&|d, sp| gouraud_edge_error(d, sp, s, normal_span_deg));
    let spot_error =
        spot.map_or(0.0, |sp| spot_gouraud_error(sp.inner_deg, sp.outer_deg, sp.span_deg) * per_channel(&|d, s| d + s));
    let total_error = shading_error + spot_error;
    let passes = total_error <= budget;
    let mut reasons = Vec::new();
    if !passes {
        if diffuse_error > budget {
            reasons.push(Reason::DiffuseCurvature);
        } else if shading_error > budget {
            reasons.push(Reason::TightHighlight);
        }
        if spot_error > budget {
            reasons.push(Reason::SpotEdge);
        }
        if reasons.is_empty() {
            reasons.push(if spot_error > shading_error { Reason::SpotEdge } else { Reason::TightHighlight });
        }
    }
    let mode = if passes { ShadingFrequency::PerVertex } else { ShadingFrequency::PerFragment };
    ShadingAdvice { diffuse_error, shading_error, spot_error, total_error, mode, reasons }
}

/// The largest normal span (degrees, to 0.01°) whose per-vertex error meets `budget`.
///
/// Bisection on [`gouraud_edge_error`] over (0, 90]; assumes the error grows
/// with the span, which the tests check on a grid. Returns 90 when even a
/// 90° span meets the budget, and 0 when nothing positive does.
pub fn max_span_for_budget(diffuse_weight: f32, specular_weight: f32, shininess: f32, budget: f32) -> f32 {
    let err = |span: f32| gouraud_edge_error(diffuse_weight, specular_weight, shininess, span);
    if err(90.0) <= budget {
        return 90.0;
    }
    let (mut lo, mut hi) = (0.0f32, 90.0f32);
    while hi - lo > 0.01 {
        let mid = 0.5 * (lo + hi);
        if err(mid) <= budget {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// What the tessellation advisor compares against the reference sphere.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Per-vertex colors, interpolated.
    Gouraud,
    /// Per-fragment shading with interpolated position and normalized interpolated normal.
    Phong,
}

/// A unit sphere at the origin under one point light, seen from `eye`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereScene {
    /// The light.
    pub light: PointLight,
    /// The sphere's material.
    pub material: Material,
    /// Eye position (outside the sphere).
    pub eye: Vec3,
}

impl SphereScene {
    /// DESIGN's sphere: eye at (0, 0, 3), coral material (diffuse (1, 0.5,
    /// 0.31), specular 0.5, shininess 32), LearnOpenGL's light position
    /// (1.2, 1, 2), white light (ambient 0.1, diffuse 1, specular 1), no
    /// attenuation (Kc = 1).
    pub fn design() -> SphereScene {
        let props = LightProps { ambient: Vec3::splat(0.1), diffuse: Vec3::ONE, specular: Vec3::ONE };
        let attenuation = crate::casters::Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 };
        SphereScene {
            light: PointLight { position: Vec3::new(1.2, 1.0, 2.0), attenuation, props },
            material: Material {
                ambient: crate::color::CORAL,
                diffuse: crate::color::CORAL,
                specular: Vec3::splat(0.5),
                shininess: 32.0,
            },
            eye: Vec3::new(0.0, 0.0, 3.0),
        }
    }

    fn shade(&self, position: Vec3, normal: Vec3) -> Vec3 {
        let view_dir = (self.eye - position).normalize_or_zero();
        self.light.terms(&self.material, normal.normalize_or_zero(), position, view_dir).sum()
    }
}

/// The UV sphere tessellations of the study, 8×16 up to 256×512 (stacks × slices).
pub const TESSELLATIONS: [(u32, u32); 6] = [(8, 16), (16, 32), (32, 64), (64, 128), (128, 256), (256, 512)];

fn sphere_vertex(stacks: u32, slices: u32, i: u32, j: u32) -> Vec3 {
    let theta = std::f32::consts::PI * i as f32 / stacks as f32;
    let phi = std::f32::consts::TAU * j as f32 / slices as f32;
    Vec3::new(theta.sin() * phi.cos(), theta.cos(), theta.sin() * phi.sin())
}

/// Barycentric sample grid on a triangle: `(i, j, k)/4`, 15 points, corners included.
const BARY: usize = 4;

/// The largest error of `method` on a `stacks × slices` UV sphere, in linear units.
///
/// ```text
/// vertex (i, j): θ = π i / stacks, φ = 2π j / slices,
///                p = (sin θ cos φ, cos θ, sin θ sin φ),  n = p
/// for each front-facing triangle and barycentric sample (a, b, c) with denominator 4:
///     p = a p0 + b p1 + c p2;     n = a n0 + b n1 + c n2
///     reference = shade(normalize(p), normalize(p))           (the true sphere point)
///     Gouraud   = a shade(p0, n0) + b shade(p1, n1) + c shade(p2, n2)
///     Phong     = shade(p, normalize(n))
///     error = max over channels of |method − reference|, colors unclamped
/// ```
///
/// `shade` is [`PointLight::terms`] summed (LearnOpenGL's `CalcPointLight`).
/// Zero-area triangles at the poles are skipped, as a rasterizer covers no
/// pixel with them. Fewer than 2 stacks or 3 slices give `None`.
///
/// Source: DESIGN's sphere scenes; LearnOpenGL, Basic lighting.
pub fn sphere_error(scene: &SphereScene, stacks: u32, slices: u32, method: Method) -> Option<f32> {
    if stacks < 2 || slices < 3 {
        return None;
    }
    let cols = slices + 1;
    let mut verts = Vec::with_capacity(((stacks + 1) * cols) as usize);
    for i in 0..=stacks {
        for j in 0..=slices {
            let p = sphere_vertex(stacks, slices, i, j);
            verts.push((p, scene.shade(p, p)));
        }
    }
    let index = |i: u32, j: u32| (i * cols + j) as usize;
    let mut worst = 0.0f32;
    for i in 0..stacks {
        for j in 0..slices {
            let quad = [index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)];
            for tri in [[quad[0], quad[1], quad[2]], [quad[0], quad[2], quad[3]]] {
                let corners = tri.map(|k| verts[k]);
                worst = worst.max(triangle_error(scene, corners, method));
            }
        }
    }
    Some(worst)
}

fn triangle_error(scene: &SphereScene, corners: [(Vec3, Vec3); 3], method: Method) -> f32 {
    let [(p0, c0), (p1, c1), (p2, c2)] = corners;
    let area = (p1 - p0).cross(p2 - p0);
    let centroid = (p0 + p1 + p2) / 3.0;
    if area.length_squared() == 0.0 || (scene.eye - centroid).dot(centroid) <= 0.0 {
        return 0.0;
    }
    let mut worst = 0.0f32;
    for a in 0..=BARY {
        for b in 0..=(BARY - a) {
            let w = Vec3::new(a as f32, b as f32, (BARY - a - b) as f32) / BARY as f32;
            let p = w.x * p0 + w.y * p1 + w.z * p2;
            let on_sphere = p.normalize_or_zero();
            let reference = scene.shade(on_sphere, on_sphere);
            let value = match method {
                Method::Gouraud => w.x * c0 + w.y * c1 + w.z * c2,
                Method::Phong => scene.shade(p, p0 * w.x + p1 * w.y + p2 * w.z),
            };
            worst = worst.max((value - reference).abs().max_element());
        }
    }
    worst
}

/// The largest angle between the normals of two vertices sharing an edge of
/// a `stacks × slices` UV sphere, in degrees: the equator's edges are the
/// longest, and of those the quad diagonal is the widest.
///
/// ```text
/// span = max(angle(n(i, j), n(i+1, j)), angle(n(i, j), n(i, j+1)), angle(n(i, j), n(i+1, j+1)))
///        at the stack next to the equator
/// ```
///
/// `None` for fewer than 2 stacks or 3 slices.
pub fn sphere_max_span_deg(stacks: u32, slices: u32) -> Option<f32> {
    if stacks < 2 || slices < 3 {
        return None;
    }
    let i = stacks / 2;
    let v = |a: u32, b: u32| sphere_vertex(stacks, slices, a, b);
    let angle = |a: Vec3, b: Vec3| a.cross(b).length().atan2(a.dot(b)).to_degrees();
    let rows = [i.saturating_sub(1), i];
    let span = rows
        .iter()
        .map(|&r| angle(v(r, 0), v(r + 1, 0)).max(angle(v(r, 0), v(r, 1))).max(angle(v(r, 0), v(r + 1, 1))))
        .fold(0.0, f32::max);
    Some(span)
}

/// How much faster the highlight moves across a unit sphere than its normal
/// turns, because the light and the eye are at finite distances.
///
/// ```text
/// parallax = 1 + 1/(2·dl) + 1/(2·de)
/// dl = |light| − 1, de = |eye| − 1   (nearest distances from the sphere, at least 1e-3)
/// ```
///
/// Moving an arc δ over the sphere turns the normal by δ, the direction to
/// the light by at most δ/dl and to the eye by at most δ/de; the halfway
/// vector turns by at most their mean, and `reflect_dir` against `view_dir`
/// by at most `2δ · parallax`. So an edge of normal span Δ sweeps the lobe
/// like a span of `Δ · parallax` under a distant light and eye.
pub fn sphere_parallax(scene: &SphereScene) -> f32 {
    let near = |p: Vec3| (p.length() - 1.0).max(1e-3);
    1.0 + 0.5 / near(scene.light.position) + 0.5 / near(scene.eye)
}

/// The formula-level worst case of Gouraud shading on a `stacks × slices` sphere.
///
/// ```text
/// span = sphere_max_span_deg(stacks, slices) · sphere_parallax(scene), at most 179°
/// a    = attenuation at the sphere point nearest the light (|light| − 1, at least 0)
/// per channel c: wd = a·Ld_c·Md_c, ws = a·Ls_c·Ms_c
/// error = max_c gouraud_edge_error(wd, ws, s, span)
/// ```
///
/// It assumes the highlight can fall anywhere on an edge of the widest span
/// (the worst placement), so it does not depend on where the mesh's
/// vertices happen to fall, and it never grows when the mesh is refined
/// (the span shrinks and [`gouraud_edge_error`] grows with the span). The
/// tests check that it bounds the measured error ([`sphere_error_worst_placement`])
/// of the study's scenes. `None` for an invalid tessellation.
pub fn sphere_gouraud_worst_case(scene: &SphereScene, stacks: u32, slices: u32) -> Option<f32> {
    let span = (sphere_max_span_deg(stacks, slices)? * sphere_parallax(scene)).min(179.0);
    let a = scene.light.attenuation.at((scene.light.position.length() - 1.0).max(0.0));
    let m = &scene.material;
    let wd = (a * scene.light.props.diffuse * m.diffuse).abs();
    let ws = (a * scene.light.props.specular * m.specular).abs();
    Some((0..3).map(|c| gouraud_edge_error(wd[c], ws[c], m.shininess, span)).fold(0.0, f32::max))
}

/// [`sphere_error`] at the worst of `placements` positions of the mesh under
/// the scene: light and eye are turned together about +y by
/// `k / placements` of one slice, `k = 0 … placements − 1`, which moves the
/// highlight across the triangles while the picture stays the same.
///
/// `placements = 0` is treated as 1. `None` for an invalid tessellation.
pub fn sphere_error_worst_placement(
    scene: &SphereScene,
    stacks: u32,
    slices: u32,
    method: Method,
    placements: u32,
) -> Option<f32> {
    let placements = placements.max(1);
    (0..placements)
        .map(|k| {
            let turn =
                glam::Quat::from_rotation_y(std::f32::consts::TAU / slices as f32 * k as f32 / placements as f32);
            let mut turned = *scene;
            turned.light.position = turn * scene.light.position;
            turned.eye = turn * scene.eye;
            sphere_error(&turned, stacks, slices, method)
        })
        .try_fold(0.0f32, |acc, e| e.map(|e| acc.max(e)))
}

/// The tessellation advisor's answer.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TessellationAdvice {
    /// Stacks of the coarsest passing mesh.
    pub stacks: u32,
    /// Slices of the coarsest passing mesh.
    pub slices: u32,
    /// Its error estimate, linear units.
    pub error: f32,
}

/// The coarsest tessellation from `candidates` (tried in order) whose error
/// for `method` is within `budget`.
///
/// - Gouraud: the formula-level worst case [`sphere_gouraud_worst_case`]
///   (independent of where the highlight falls; never worse when refined).
/// - Phong: the measured [`sphere_error_worst_placement`] with 4 placements
///   (per-fragment error comes from the mesh's flat positions and
///   interpolated normals, which the formula-level edge model does not see).
///
/// `None` when no candidate meets the budget (or all are invalid). Pass
/// [`TESSELLATIONS`] for the study's list and [`DEFAULT_BUDGET`] for one level.
pub fn advise_tessellation(
    scene: &SphereScene,
    method: Method,
    budget: f32,
    candidates: &[(u32, u32)],
) -> Option<TessellationAdvice> {
    candidates.iter().find_map(|&(stacks, slices)| {
        let error = match method {
            Method::Gouraud => sphere_gouraud_worst_case(scene, stacks, slices)?,
            Method::Phong => sphere_error_worst_placement(scene, stacks, slices, method, 4)?,
        };
        (error <= budget).then_some(TessellationAdvice { stacks, slices, error })
    })
}

/// The default error budget of both advisors: one 8-bit level.
pub const DEFAULT_BUDGET: f32 = ONE_LEVEL;
