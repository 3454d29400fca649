//! Light culling with a bound: skip a light only where it cannot matter.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `T` | a light's maximum possible term: the largest channel of `|La|·Ma + |Ld|·Md + |Ls|·Ms` |
//! | `Ma`, `Md`, `Ms` | upper bounds on the material's ambient, diffuse, specular reflectance ([`MaterialBound`]) |
//! | `τ` | `threshold`: the most one skipped light may change a channel, linear units |
//! | `d_cull` | cull distance: the smallest `d` with `attenuation(d) · T ≤ τ` |
//!
//! Why the bound holds: a point light's contribution to one channel is
//! `attenuation(d) · (La·Ma' + Ld·Md'·diff + Ls·Ms'·spec)` with `diff`, `spec`
//! in [0, 1] and the material's reflectances `Ma' ≤ Ma` etc. A spot multiplies
//! this by `intensity ∈ [0, 1]`. So the contribution is at most
//! `attenuation(d) · T`, and `attenuation` is non-increasing in `d` for
//! non-negative coefficients (also in `f32`, where every rounding step is
//! monotone). Skipping the light at `d ≥ d_cull` therefore changes each
//! channel by at most `τ` (plus `f32` rounding: a relative `1e-5` covers the
//! dozen roundings in the bound and the shader, each ≤ `2^-24`).
//!
//! With `N` lights that may be culled and `τ = 1/(2·255·N)` ([`threshold_for`]),
//! the total skipped light is at most half an 8-bit level per channel, so no
//! 8-bit output changes by more than one level, and none changes at all unless
//! the unculled value lies within half a level of a rounding boundary.
//! Directional lights are never culled (no attenuation).
//!
//! Source: attenuation from LearnOpenGL, Light casters; the bound is derived in
//! the book's chapter "Speed against accuracy", section on culling.

use crate::casters::LocalLight as _;
use glam::Vec3;

use crate::casters::{Attenuation, RANGE_TABLE};
use crate::material::{LightProps, Material};
use crate::scene::{LightId, Scene, Shaded};

use super::ONE_LEVEL;
use crate::table::Table;

/// Upper bounds on a material's reflectance per term, over channels (and
/// over texels, for a mapped material).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaterialBound {
    /// Largest ambient reflectance.
    pub ambient: f32,
    /// Largest diffuse reflectance.
    pub diffuse: f32,
    /// Largest specular reflectance.
    pub specular: f32,
}

impl MaterialBound {
    /// Reflectances of at most 1 in every term: any physically plausible
    /// material, and every row of the classic table.
    pub const UNIT: MaterialBound = MaterialBound { ambient: 1.0, diffuse: 1.0, specular: 1.0 };

    /// The bound of one material: the largest absolute channel of each term.
    /// NaN channels are ignored (`f32::max` drops NaN).
    pub fn of(material: &Material) -> MaterialBound {
        MaterialBound {
            ambient: material.ambient.abs().max_element(),
            diffuse: material.diffuse.abs().max_element(),
            specular: material.specular.abs().max_element(),
        }
    }
}

/// A light's maximum possible term `T` under a material bound.
///
/// ```text
/// T = max over channels c of |La_c|·Ma + |Ld_c|·Md + |Ls_c|·Ms
/// ```
///
/// The diffuse factor, the specular factor and a spot's intensity are each at
/// most 1, so no fragment receives more than `attenuation(d) · T` from the
/// light. Negative light channels (the Materials chapter's time-varying light)
/// count by magnitude. NaN channels are dropped by `f32::max`; prefer finite
/// lights.
pub fn max_term(props: &LightProps, bound: &MaterialBound) -> f32 {
    let per_channel = props.ambient.abs() * bound.ambient.abs()
        + props.diffuse.abs() * bound.diffuse.abs()
        + props.specular.abs() * bound.specular.abs();
    per_channel.max_element()
}

/// The distance beyond which a light of maximum term `max_term` changes no
/// channel by more than `threshold`.
///
/// ```text
/// d_cull = attenuation.distance_for(threshold / T), then raised by a few ulps
///          until attenuation.at(d_cull) · T <= threshold holds in f32
/// ```
///
/// - `Some(0)`: the light never exceeds the threshold (also when `T = 0`).
/// - `None`: never cull: the light never falls that far (`Kl = Kq = 0`), or
///   `threshold` is not positive and finite, or `T` is not finite.
///
/// Source: [`Attenuation::distance_for`].
pub fn cull_distance(attenuation: &Attenuation, max_term: f32, threshold: f32) -> Option<f32> {
    if !(threshold > 0.0 && threshold.is_finite() && max_term.is_finite()) {
        return None;
    }
    if max_term <= 0.0 {
        return Some(0.0);
    }
    let mut d = attenuation.distance_for(threshold / max_term)?;
    for _ in 0..64 {
        if attenuation.at(d) * max_term <= threshold {
            return Some(d);
        }
        d = (d * (1.0 + 4.0 * f32::EPSILON)).max(d.next_up());
    }
    None
}

/// `τ = 1 / (2 · 255 · lights)`: the per-light threshold that keeps the total
/// skipped light of `lights` cullable lights within half an 8-bit level.
///
/// `lights = 0` is treated as 1.
pub fn threshold_for(lights: usize) -> f32 {
    0.5 * ONE_LEVEL / lights.max(1) as f32
}

/// A scene with a cull distance for each attenuated light.
#[derive(Clone, Debug, PartialEq)]
pub struct CulledScene {
    /// The scene, unchanged.
    pub scene: Scene,
    /// The per-light threshold τ it was culled with.
    pub threshold: f32,
    /// Cull distance of each point light, in order (`None`: never culled).
    pub point_cull: Vec<Option<f32>>,
    /// Cull distance of the spot (`None`: never culled, or no spot).
    pub spot_cull: Option<f32>,
}

/// The result of shading with culling.
#[derive(Clone, Debug, PartialEq)]
pub struct CulledShade {
    /// The lights that were evaluated, as [`Scene::shade`] lists them.
    pub shaded: Shaded,
    /// The lights that were skipped.
    pub skipped: Vec<LightId>,
}

/// Compute the cull distances of every point light and the spot.
///
/// Each light's distance comes from its own attenuation and maximum term
/// ([`max_term`], [`cull_distance`]); the directional light is never culled.
/// Use [`threshold_for`] with the number of point lights and spots to keep
/// the total within half an 8-bit level.
pub fn cull(scene: &Scene, bound: &MaterialBound, threshold: f32) -> CulledScene {
    let distance = |att: &Attenuation, props: &LightProps| cull_distance(att, max_term(props, bound), threshold);
    CulledScene {
        scene: scene.clone(),
        threshold,
        point_cull: scene.point_lights.iter().map(|p| distance(&p.attenuation, &p.props)).collect(),
        spot_cull: scene.spot_light.as_ref().and_then(|s| distance(&s.attenuation, &s.props)),
    }
}

fn beyond(cull: Option<f32>, position: Vec3, frag_pos: Vec3) -> bool {
    cull.is_some_and(|d| (position - frag_pos).length() >= d)
}

impl CulledScene {
    /// Shade one fragment as [`Scene::shade`] does, skipping every light whose
    /// distance to the fragment is at least its cull distance.
    ///
    /// The distance is the shader's own `length(position − frag_pos)` in
    /// `f32`. Each skipped light changes each channel by at most
    /// `threshold · (1 + 1e-5)` when the material is within the bound the scene
    /// was culled with (see the module docs). Degenerate input as [`Scene::shade`].
    pub fn shade(&self, material: &Material, frag_pos: Vec3, normal: Vec3, view_pos: Vec3) -> CulledShade {
        let norm = normal.normalize_or_zero();
        let view_dir = (view_pos - frag_pos).normalize_or_zero();
        let mut lights = Vec::new();
        let mut skipped = Vec::new();
        if let Some(d) = &self.scene.dir_light {
            lights.push((LightId::Dir, d.terms(material, norm, view_dir)));
        }
        for (i, p) in self.scene.point_lights.iter().enumerate() {
            if beyond(self.point_cull[i], p.position, frag_pos) {
                skipped.push(LightId::Point(i));
            } else {
                lights.push((LightId::Point(i), p.terms(material, norm, frag_pos, view_dir)));
            }
        }
        if let Some(s) = &self.scene.spot_light {
            if beyond(self.spot_cull, s.position, frag_pos) {
                skipped.push(LightId::Spot);
            } else {
                lights.push((LightId::Spot, s.terms(material, norm, frag_pos, view_dir)));
            }
        }
        CulledShade { shaded: Shaded { lights }, skipped }
    }
}

/// The share of light evaluations culling skips over a set of fragments.
///
/// ```text
/// share = Σ skipped lights / Σ cullable lights (point lights + spot), over fragments
/// ```
///
/// `fragments` are `(frag_pos, normal)` pairs seen from `view_pos`. The
/// study's timing harness uses it to explain the speed it gains. 0 for no
/// fragments or no cullable lights.
pub fn skipped_share(culled: &CulledScene, material: &Material, fragments: &[(Vec3, Vec3)], view_pos: Vec3) -> f32 {
    let cullable = culled.scene.point_lights.len() + usize::from(culled.scene.spot_light.is_some());
    let total = cullable * fragments.len();
    if total == 0 {
        return 0.0;
    }
    let skipped: usize = fragments.iter().map(|&(p, n)| culled.shade(material, p, n, view_pos).skipped.len()).sum();
    skipped as f32 / total as f32
}

/// The strict cull distance of each row of LearnOpenGL's range table.
///
/// For a white light and material bound (`T = 3`: ambient, diffuse and
/// specular intensities 1 and reflectances 1) and for `T = 1`, at
/// τ = half a level (`0.5/255`), next to the range the table names and the
/// attenuation at that range in 8-bit levels. It shows that the table's
/// "range" is where a light falls to about 1%, a few 8-bit levels, not where
/// it stops mattering.
///
/// Source: LearnOpenGL, Light casters, "Choosing the right values".
pub fn range_table() -> Table {
    let header = ["range", "Kl", "Kq", "attenuation at range (levels)", "d_cull, T = 1", "d_cull, T = 3"];
    let mut t = Table::new("Strict cull distance (τ = half an 8-bit level) against the range table", "", &header);
    let tau = 0.5 * ONE_LEVEL;
    let fmt = |d: Option<f32>| d.map_or("never".to_string(), |d| format!("{d:.0}"));
    for row in RANGE_TABLE {
        let a = row.attenuation;
        t.push(vec![
            format!("{}", row.range),
            format!("{}", a.linear),
            format!("{}", a.quadratic),
            format!("{:.2}", a.at(row.range) * 255.0),
            fmt(cull_distance(&a, 1.0, tau)),
            fmt(cull_distance(&a, 3.0, tau)),
        ]);
    }
    t
}
