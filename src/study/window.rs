//! Culling, honestly: what LearnOpenGL's attenuation lets a renderer skip on the
//! `floor-lights256` scene, and what the range window ([`crate::casters::range_window`])
//! changes.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | pair | one floor point and one of the 256 lights |
//! | skipped light | what the skipped pairs would have added: `Σ att(d)·(La·Ma + Ld·Md·max(N·L, 0))` per channel, in 8-bit levels |
//! | change | the largest difference from the unculled LearnOpenGL image, in 8-bit levels |
//!
//! The floor is sampled on a grid of [`GRID_STEP`] over its whole extent (x ∈ [-10, 10],
//! z ∈ [-20, 3], y = -1; the lights hang 0.25 above it, 1 apart). The skipped light counts
//! the ambient and diffuse terms exactly (they do not depend on the eye); the specular
//! term, which does, is left out, so the errors shown are lower bounds of the worst case
//! for a specular surface and exact for a matte one.
//!
//! LearnOpenGL's `1/(Kc + Kl·d + Kq·d²)` is never zero, so a light can only be skipped
//! where its contribution is provably small: [`crate::study::culling`]'s bound, which keeps
//! the 256 skipped lights of a fragment under half a level together. Culling at the
//! light's nominal range (7 for these coefficients) skips far more, and changes the image.
//! The range window is zero beyond the range, so culling there changes nothing; what
//! changes the image is the window itself, inside the range.

use glam::Vec3;

use super::culling::{cull_distance, max_term, threshold_for, MaterialBound};
use crate::casters::Attenuation;
use crate::raster::presets::{bench_scene, floor_lights};
use crate::raster::shade::Surface;
use crate::table::Table;

/// The floor's sampling step, world units (40 000 points over the 20 × 23 floor).
pub const GRID_STEP: f32 = 0.1;

/// The nominal range of the floor's lights: the range-table row of their coefficients.
pub const NOMINAL_RANGE: f32 = crate::raster::presets::FLOOR_RANGE;

/// How one way of evaluating the floor's lights fares.
#[derive(Debug, Clone, PartialEq)]
pub struct WindowRow {
    /// The falloff and the culling rule.
    pub method: &'static str,
    /// The distance beyond which a light is skipped (`None`: never).
    pub cull_distance: Option<f32>,
    /// Mean number of the 256 lights evaluated per floor point.
    pub lights_per_point: f64,
    /// The largest skipped light at a point, 8-bit levels.
    pub skipped_levels: f64,
    /// The largest change from the unculled LearnOpenGL image, 8-bit levels.
    pub change_levels: f64,
}

/// The floor points of `floor-lights256`: its plane sampled every [`GRID_STEP`].
fn floor_points() -> Vec<Vec3> {
    let nx = (20.0 / GRID_STEP).round() as usize;
    let nz = (23.0 / GRID_STEP).round() as usize;
    (0..=nz)
        .flat_map(|j| {
            (0..=nx).map(move |i| Vec3::new(-10.0 + i as f32 * GRID_STEP, -1.0, -20.0 + j as f32 * GRID_STEP))
        })
        .collect()
}

/// The floor's material bound (its reflectances), from the benchmark scene.
fn floor_bound() -> Option<MaterialBound> {
    let world = bench_scene("floor-lights256")?;
    match &world.objects.first()?.surface {
        Surface::Material(m) => Some(MaterialBound::of(m)),
        _ => None,
    }
}

/// The ambient + diffuse light of one light at `p` per unit of falloff, per channel (the
/// floor's normal is +y).
fn unit_light(light: &crate::casters::PointLight, bound: &MaterialBound, p: Vec3) -> Vec3 {
    let to_light = light.position - p;
    let n_dot_l = (to_light.y / to_light.length()).max(0.0);
    light.props.ambient.abs() * bound.ambient + light.props.diffuse.abs() * bound.diffuse * n_dot_l
}

/// The study's rows (see the module docs). `None` if the benchmark scene has no
/// material floor (a preset out of date).
pub fn rows() -> Option<Vec<WindowRow>> {
    let lights = floor_lights().point_lights;
    let bound = floor_bound()?;
    let tau = threshold_for(lights.len());
    let att: Attenuation = lights.first()?.attenuation;
    let bound_cull = lights
        .iter()
        .filter_map(|l| cull_distance(&l.attenuation, max_term(&l.props, &bound), tau))
        .fold(0.0f32, f32::max);
    let points = floor_points();
    let measure = |method: &'static str, cull: Option<f32>, window: Option<f32>| {
        let (mut evaluated, mut skipped_max, mut change_max) = (0usize, 0.0f64, 0.0f64);
        for &p in &points {
            let (mut skipped, mut change) = (Vec3::ZERO, Vec3::ZERO);
            for light in &lights {
                let d = (light.position - p).length();
                let unit = unit_light(light, &bound, p);
                let full = att.at(d);
                let used = window.map_or(full, |r| att.windowed_at(d, r));
                if cull.is_some_and(|c| d >= c) {
                    skipped += unit * used;
                    change += unit * full;
                } else {
                    evaluated += 1;
                    change += unit * (full - used);
                }
            }
            skipped_max = skipped_max.max(f64::from(skipped.max_element()) * 255.0);
            change_max = change_max.max(f64::from(change.max_element()) * 255.0);
        }
        WindowRow {
            method,
            cull_distance: cull,
            lights_per_point: evaluated as f64 / points.len() as f64,
            skipped_levels: skipped_max,
            change_levels: change_max,
        }
    };
    // The smallest whole range whose window changes the image by at most one level
    // (the change falls as the range grows; bisection over whole ranges).
    let (mut lo, mut hi) = (NOMINAL_RANGE as u32, 64u32);
    while lo < hi {
        let mid = (lo + hi) / 2;
        let r = mid as f32;
        if measure("", Some(r), Some(r)).change_levels <= 1.0 {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    let faithful = lo as f32;
    Some(vec![
        measure("LearnOpenGL attenuation, every light", None, None),
        measure("LearnOpenGL attenuation, skipped beyond the proven bound", Some(bound_cull), None),
        measure("LearnOpenGL attenuation, skipped beyond the nominal range 7", Some(NOMINAL_RANGE), None),
        measure("range window at 7, skipped beyond 7 (exact)", Some(NOMINAL_RANGE), Some(NOMINAL_RANGE)),
        measure(FAITHFUL, Some(faithful), Some(faithful)),
    ])
}

/// The smallest whole range whose window keeps the floor within one level of
/// LearnOpenGL's image (the last row's cull distance).
pub fn faithful_range() -> Option<f32> {
    rows()?.last()?.cull_distance
}

/// The last row's method: the window at the smallest whole range that keeps the image
/// within one level of LearnOpenGL's.
const FAITHFUL: &str = "range window at the smallest range within 1 level of LearnOpenGL, skipped beyond it (exact)";

/// The rows as the book's table.
pub fn table() -> Table {
    let mut t = Table::new(
        "Culling the 256 lights of floor-lights256: LearnOpenGL's attenuation against the range window",
        "Every floor point every 0.1 units; ambient + diffuse light (the specular term depends on the eye and is \
         left out, so the errors are lower bounds for a shiny floor). Levels are 8-bit steps; half a level changes \
         no pixel.",
        &[
            "falloff and culling",
            "skipped beyond",
            "lights per point (of 256)",
            "largest skipped light (levels)",
            "largest change from LearnOpenGL (levels)",
        ],
    );
    for r in rows().unwrap_or_default() {
        t.push(vec![
            r.method.to_string(),
            r.cull_distance.map_or("never".into(), |d| format!("{d:.1}")),
            format!("{:.1}", r.lights_per_point),
            format!("{:.2}", r.skipped_levels),
            format!("{:.2}", r.change_levels),
        ]);
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bound_keeps_its_promise_and_the_window_culls_exactly() {
        let rows = rows().expect("the floor scene");
        let [all, bound, nominal, window, faithful] = rows.as_slice() else { panic!("{rows:?}") };
        // every light evaluated: nothing skipped, nothing changed
        assert_eq!(all.lights_per_point, 256.0);
        assert_eq!((all.skipped_levels, all.change_levels), (0.0, 0.0));
        // the proven bound: its cull distance is beyond the floor's diagonal (about 30.5),
        // so it skips nothing here, which is the honest answer for a falloff that never
        // reaches zero
        assert!(bound.cull_distance.unwrap() > 30.5, "{bound:?}");
        assert_eq!(bound.lights_per_point, 256.0);
        assert!(bound.skipped_levels <= 0.5, "{bound:?}");
        // the nominal range skips visible light (more than one level somewhere)
        assert!(nominal.skipped_levels > 1.0, "{nominal:?}");
        // the window: culling beyond the range skips exactly nothing
        assert_eq!(window.skipped_levels, 0.0);
        assert_eq!(window.lights_per_point, nominal.lights_per_point);
        assert!(window.change_levels > 1.0, "the window at 7 changes the look: {window:?}");
        // the faithful window: within one level of LearnOpenGL and still exact, but the 256
        // tails add up, so its range is several times 7 and it keeps many more lights
        assert_eq!(faithful.skipped_levels, 0.0);
        assert!(faithful.change_levels <= 1.0, "{faithful:?}");
        assert!(faithful.cull_distance.unwrap() > 2.0 * NOMINAL_RANGE, "{faithful:?}");
        assert!(faithful.lights_per_point > window.lights_per_point, "{faithful:?}");
        // the numbers the speed chapter quotes in its prose
        assert!(bound.cull_distance.unwrap() > 300.0, "'only beyond about 300 units': {bound:?}");
        assert!((70.0..80.0).contains(&nominal.lights_per_point), "'about 75 of the 256': {nominal:?}");
        assert!((10.0..15.0).contains(&nominal.skipped_levels), "'a dozen levels': {nominal:?}");
        assert!((25.0..35.0).contains(&window.change_levels), "'up to 30 levels': {window:?}");
        assert_eq!(faithful.cull_distance, Some(30.0), "'the smallest range ... is 30'");
        assert_eq!(faithful.lights_per_point, 256.0, "'at 30 nothing on this floor can be skipped'");
    }
}
