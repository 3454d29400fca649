//! The book's charts, each computed here from the formula it shows.

use super::chart::{LineChart, Series};
use crate::book::Artifact;

/// The charts this module contributes to the book (paths under `book/src/generated/`).
pub fn artifacts() -> Vec<Artifact> {
    vec![Artifact { path: "charts/specular-falloff.png", make: specular_falloff_png }]
}

/// Shininess exponents drawn in the specular falloff chart (LearnOpenGL, Basic
/// Lighting, shows 2 to 256).
pub const SPECULAR_FALLOFF_SHININESS: [f64; 5] = [2.0, 8.0, 32.0, 128.0, 256.0];

/// `spec = pow(cos(alpha), shininess)` for `alpha` from 0 to 90 degrees in steps of
/// 0.25 degree, one line per shininess in [`SPECULAR_FALLOFF_SHININESS`].
///
/// ```text
/// spec(alpha) = max(cos alpha, 0)^shininess,   alpha = angle(reflect_dir, view_dir)
/// ```
/// LearnOpenGL, Basic Lighting, "Specular lighting" (the Phong specular term).
pub fn specular_falloff_png() -> Result<Vec<u8>, String> {
    // 0.25 degree steps resolve the s = 256 peak (half width about 4 degrees).
    let alphas: Vec<f64> = (0..=360).map(|i| f64::from(i) * 0.25).collect();
    let mut chart =
        LineChart::new("angle between R and V, α (degrees)", "pow(cos α, s)").x_range(0.0, 90.0).y_range(0.0, 1.0);
    for s in SPECULAR_FALLOFF_SHININESS {
        chart = chart.series(Series::from_fn(&format!("s = {s}"), &alphas, |a| a.to_radians().cos().max(0.0).powf(s)));
    }
    chart.to_png()
}
