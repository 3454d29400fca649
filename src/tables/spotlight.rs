//! Chapter 5, Light casters, spotlight: the worked table, by angle, and hard against soft edges.
//!
//! Source: LearnOpenGL, Light casters, "Smooth/Soft edges" (the table of θ,
//! φ, γ, ε and I, printed identically in both translations).

use crate::casters::{hard_spot, spot_intensity};
use crate::table::{num32, Table};

/// One printed row of the chapter's table: the cosines and results as
/// printed, and the angles (degrees) they stand for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WorkedRow {
    /// θ as printed (cosine).
    pub theta: f32,
    /// θ in degrees.
    pub theta_deg: f32,
    /// φ (inner cut-off) as printed.
    pub phi: f32,
    /// φ in degrees.
    pub phi_deg: f32,
    /// γ (outer cut-off) as printed.
    pub gamma: f32,
    /// γ in degrees.
    pub gamma_deg: f32,
    /// ε = φ − γ as printed.
    pub epsilon: f32,
    /// I = (θ − γ)/ε as printed.
    pub intensity: f32,
}

/// A row from `[cosine, degrees]` pairs for θ, φ, γ, then ε and I.
const fn worked(theta: [f32; 2], phi: [f32; 2], gamma: [f32; 2], epsilon: f32, intensity: f32) -> WorkedRow {
    WorkedRow {
        theta: theta[0],
        theta_deg: theta[1],
        phi: phi[0],
        phi_deg: phi[1],
        gamma: gamma[0],
        gamma_deg: gamma[1],
        epsilon,
        intensity,
    }
}

/// The chapter's six rows as printed.
///
/// Row 6 prints φ = 0.9978, which is cos(12.5 *radians*); cos(12.5°) = 0.9763.
/// Its ε = 0.0448 and I = 0.29 follow from that slip (research notes §1.1.b, erratum E2).
pub const WORKED_TABLE: [WorkedRow; 6] = [
    worked([0.87, 30.0], [0.91, 25.0], [0.82, 35.0], 0.09, 0.56),
    worked([0.9, 26.0], [0.91, 25.0], [0.82, 35.0], 0.09, 0.89),
    worked([0.97, 14.0], [0.91, 25.0], [0.82, 35.0], 0.09, 1.67),
    worked([0.83, 34.0], [0.91, 25.0], [0.82, 35.0], 0.09, 0.11),
    worked([0.64, 50.0], [0.91, 25.0], [0.82, 35.0], 0.09, -2.0),
    worked([0.966, 15.0], [0.9978, 12.5], [0.953, 17.5], 0.0448, 0.29),
];

/// The recomputed row: exact cosines of the printed degrees (f32).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Recomputed {
    /// cos(θ°).
    pub theta: f32,
    /// cos(φ°).
    pub phi: f32,
    /// cos(γ°).
    pub gamma: f32,
    /// φ − γ.
    pub epsilon: f32,
    /// (θ − γ)/ε, unclamped.
    pub intensity: f32,
    /// The shader's clamped intensity, [`spot_intensity`].
    pub clamped: f32,
}

impl WorkedRow {
    /// Recompute the row from its angles in degrees.
    pub fn recomputed(&self) -> Recomputed {
        let cos = |deg: f32| deg.to_radians().cos();
        let (theta, phi, gamma) = (cos(self.theta_deg), cos(self.phi_deg), cos(self.gamma_deg));
        let epsilon = phi - gamma;
        Recomputed {
            theta,
            phi,
            gamma,
            epsilon,
            intensity: (theta - gamma) / epsilon,
            clamped: spot_intensity(theta, phi, gamma),
        }
    }
}

/// The chapter's tables: published against recomputed, by angle, hard against soft.
pub fn tables() -> Vec<Table> {
    tables_for(12.5, 17.5)
}

/// The same tables with your own cut-offs (degrees, `light.cutOff` and
/// `light.outerCutOff` before the cosine) in the hard-against-soft table; the
/// worked table stays the chapter's. The caller checks 0 ≤ inner ≤ outer ≤ 90
/// ([`crate::casters::SpotLight::new`] names the field); other values give a
/// table of the formula's results as they are.
pub fn tables_for(cut_off_deg: f32, outer_cut_off_deg: f32) -> Vec<Table> {
    vec![worked_table(), by_angle_table(), edge_table(cut_off_deg, outer_cut_off_deg)]
}

fn worked_table() -> Table {
    let phi_rad = 12.5f32.cos();
    let mut t = Table::new(
        "Spotlight worked table: published against recomputed",
        format!(
            "θ, φ, γ are cosines; ε = φ − γ, I = (θ − γ)/ε. \"pub\" is the chapter's table, \"rec\" uses the exact \
             cosines of the angles the rows stand for. Rows 1–5 are consistent with their own two-decimal cosines; \
             their I differs from the exact one in the second decimal only because the cosines were rounded. Row 6 \
             prints φ = 0.9978, which is cos(12.5 radians) = {}, not cos(12.5°) = {}; its ε and I follow from that \
             slip. The shader then clamps I to [0, 1].",
            num32(phi_rad, 4),
            num32(12.5f32.to_radians().cos(), 4)
        ),
        &[
            "row",
            "θ pub",
            "θ rec",
            "φ pub",
            "φ rec",
            "γ pub",
            "γ rec",
            "ε pub",
            "ε rec",
            "I pub",
            "I rec",
            "clamp(I rec)",
        ],
    );
    for (i, row) in WORKED_TABLE.iter().enumerate() {
        let r = row.recomputed();
        t.push(vec![
            format!("{}", i + 1),
            format!("{:?}", row.theta),
            num32(r.theta, 4),
            format!("{:?}", row.phi),
            num32(r.phi, 4),
            format!("{:?}", row.gamma),
            num32(r.gamma, 4),
            format!("{:?}", row.epsilon),
            num32(r.epsilon, 4),
            format!("{:?}", row.intensity),
            num32(r.intensity, 4),
            num32(r.clamped, 4),
        ]);
    }
    t
}

fn by_angle_table() -> Table {
    let mut t = Table::new(
        "Spotlight worked table by angle",
        "The same rows by their angles from the cone axis, in degrees: inside the inner cone (θ° < φ°) the \
         intensity is 1, outside the outer cone (θ° > γ°) it is 0, in between it ramps down. I computed from the \
         exact cosines.",
        &["row", "θ (deg)", "φ inner (deg)", "γ outer (deg)", "where", "I", "clamp(I)"],
    );
    for (i, row) in WORKED_TABLE.iter().enumerate() {
        let r = row.recomputed();
        let place = if row.theta_deg < row.phi_deg {
            "inner cone"
        } else if row.theta_deg > row.gamma_deg {
            "outside"
        } else {
            "soft edge"
        };
        t.push(vec![
            format!("{}", i + 1),
            format!("{}", row.theta_deg),
            format!("{}", row.phi_deg),
            format!("{}", row.gamma_deg),
            place.to_string(),
            num32(r.intensity, 4),
            num32(r.clamped, 4),
        ]);
    }
    t
}

fn edge_table(inner: f32, outer: f32) -> Table {
    let cos = |deg: f32| deg.to_radians().cos();
    let chapter = inner == 12.5 && outer == 17.5;
    let which = if chapter { "the Light casters cut-offs".to_string() } else { "your cut-offs".to_string() };
    let mut t = Table::new(
        "Hard cut-off against soft edge",
        format!(
            "Angle from the cone axis in degrees. Hard: the first spot shader, theta > cos({inner}°) ? 1 : 0 (at exactly \
             {inner}° theta equals the cut-off and the strict > gives 0). Soft: clamp((θ − γ)/ε, 0, 1) with {which} \
             {inner}°/{outer}° and the Multiple lights cut-offs 12.5°/15°."
        ),
        &["angle (deg)", "θ = cos", &format!("hard {inner}°"), &format!("soft {inner}°/{outer}°"), "soft 12.5°/15°"],
    );
    let mut angles = vec![0.0f32, 5.0, 10.0, 12.0, 12.5, 13.0, 14.0, 15.0, 16.0, 17.0, 17.5, 18.0, 20.0];
    // your cut-offs and a little beyond the outer one are rows too
    for a in [inner, outer, outer + 2.5] {
        if !angles.contains(&a) && a.is_finite() {
            angles.push(a);
        }
    }
    angles.sort_by(f32::total_cmp);
    for a in angles {
        let theta = cos(a);
        t.push(vec![
            format!("{a}"),
            num32(theta, 4),
            num32(hard_spot(theta, cos(inner)), 0),
            num32(spot_intensity(theta, cos(inner), cos(outer)), 4),
            num32(spot_intensity(theta, cos(12.5), cos(15.0)), 4),
        ]);
    }
    t
}
