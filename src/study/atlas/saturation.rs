//! Many lights that saturate (case 12): per-channel clamping shifts the hue; scaling by the largest channel keeps it.
//!
//! Part of the failure atlas; see [`super`] for the symbols and the case list.

use glam::Vec3;

use super::super::{linspace, Curve, Figure};

// ---------------------------------------------------------------- case 12

/// How an unclamped color is brought into [0, 1] for output (case 12).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClampStrategy {
    /// `clamp(c, 0, 1)` per channel: what an RGBA8 framebuffer does.
    PerChannel,
    /// Negative channels to 0, then divide by the largest channel if it exceeds 1.
    /// Keeps the ratios between channels, so the hue.
    ScaleByMax,
}

impl ClampStrategy {
    /// Apply the strategy. NaN channels become 0 first.
    ///
    /// ```text
    /// PerChannel: min(max(c, 0), 1)
    /// ScaleByMax: c' = max(c, 0); c' / max(1, max(c'))
    /// ```
    pub fn apply(self, c: Vec3) -> Vec3 {
        let c = Vec3::new(saturate_low(c.x), saturate_low(c.y), saturate_low(c.z));
        match self {
            ClampStrategy::PerChannel => c.min(Vec3::ONE),
            ClampStrategy::ScaleByMax => c / c.max_element().max(1.0),
        }
    }
}

fn saturate_low(x: f32) -> f32 {
    x.max(0.0)
}

/// The HSV hue of a non-negative color, degrees in [0, 360); `None` for a
/// grey (no hue) or non-finite color.
///
/// ```text
/// max = R: 60·((G − B)/(max − min) mod 6);  max = G: 60·((B − R)/(max − min) + 2);
/// max = B: 60·((R − G)/(max − min) + 4)
/// ```
pub fn hue_deg(c: Vec3) -> Option<f32> {
    let (max, min) = (c.max_element(), c.min_element());
    let chroma = max - min;
    if !(chroma > 0.0 && c.is_finite()) {
        return None;
    }
    let h = if max == c.x {
        ((c.y - c.z) / chroma).rem_euclid(6.0)
    } else if max == c.y {
        (c.z - c.x) / chroma + 2.0
    } else {
        (c.x - c.y) / chroma + 4.0
    };
    Some(60.0 * h)
}

/// The circular difference of two hues in degrees, in [0, 180]; `None` if
/// either color is grey.
pub fn hue_shift_deg(a: Vec3, b: Vec3) -> Option<f32> {
    let d = (hue_deg(a)? - hue_deg(b)?).rem_euclid(360.0);
    Some(d.min(360.0 - d))
}

/// Case 12: the hue shift of `lights` equal contributions `each` after `strategy`.
///
/// ```text
/// shift = hue_shift(strategy(lights · each), each)
/// ```
///
/// 0 when the sum stays below 1; `None` for a grey `each`.
pub fn case12_hue_shift(lights: u32, each: Vec3, strategy: ClampStrategy) -> Option<f32> {
    hue_shift_deg(strategy.apply(lights as f32 * each), each)
}

/// Case 12's contribution per light: coral lit at 0.3 (`0.3 · (1, 0.5, 0.31)`).
pub fn case12_contribution() -> Vec3 {
    0.3 * crate::color::CORAL
}

/// Case 12 figure: hue shift against the number of lights, both strategies.
pub fn case12_figure() -> Figure {
    let series = [ClampStrategy::PerChannel, ClampStrategy::ScaleByMax]
        .into_iter()
        .map(|st| {
            Curve::from_fn(format!("{st:?}"), linspace(1.0, 16.0, 15), move |n| {
                case12_hue_shift(n as u32, case12_contribution(), st).unwrap_or(f32::NAN)
            })
        })
        .collect();
    Figure::new("Hue shift of coral under N lights of 0.3", "lights", "hue shift (°)", series)
}

pub(super) fn case12_measure() -> (String, String) {
    let s = |n, st| case12_hue_shift(n, case12_contribution(), st).unwrap_or(f32::NAN);
    (
        format!(
            "coral × 0.3 per light: hue shift {:.1}° at 4 lights, {:.1}° at 8 (toward yellow)",
            s(4, ClampStrategy::PerChannel),
            s(8, ClampStrategy::PerChannel)
        ),
        format!("scale by max: {:.1e}° at 8 lights", s(8, ClampStrategy::ScaleByMax)),
    )
}
