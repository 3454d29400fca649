//! Every number the tutorials print, recomputed with the `f64` reference
//! ([`crate::reference`]) where a formula is involved: one table of
//! "published value | source | recomputed | note", used by the tests, the
//! `errata` example and the book's errata chapter.
//!
//! A published number *agrees* when it equals the recomputed value to the
//! precision it is printed with: `|published − recomputed| ≤ ½ · 10^(−decimals)`,
//! where `decimals` counts the digits after the point in the printed text
//! (so `0.06` agrees with 0.0558, which rounds to it, but `0.56` does not
//! agree with 0.5378). Everything else is an erratum, and its note names the cause.
//!
//! Seeds: `000` LearnOpenGL "Lighting" (French), `001` opengl-tutorial 8,
//! `002` ogldev 19, `003` the Ukrainian lecture and lab. Line numbers refer to
//! the seed files in `shared/seeds/`.

use glam::{DVec3, Vec3};

use crate::casters::RANGE_TABLE;

use crate::reference::color::modulate;

/// The coral of the Colors chapter as the text prints it, `(1.0, 0.5, 0.31)`, in `f64`.
const CORAL: DVec3 = DVec3::new(1.0, 0.5, 0.31);

/// One printed number and its recomputation.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// Short stable identifier, e.g. `spot-row6-phi`.
    pub id: String,
    /// Where it is printed: seed, chapter and line.
    pub source: &'static str,
    /// What the number is.
    pub quantity: &'static str,
    /// The number as printed.
    pub published: &'static str,
    /// The printed number parsed, when it is a plain number.
    pub published_value: Option<f64>,
    /// lightlab's value, computed by the library at the time the table is built.
    pub recomputed: f64,
    /// Whether the published number agrees to its printed precision.
    pub agrees: bool,
    /// The cause of a disagreement, or how the recomputation was done.
    pub note: &'static str,
}

/// Whether `published` (as printed) equals `value` to the printed precision.
///
/// ```text
/// |published − value| ≤ ½ · 10^(−decimals)   (+ 1e-12 for the binary representation)
/// ```
///
/// `false` when `published` is not a plain decimal number.
// ANCHOR: agrees_to_printed_precision
pub fn agrees_to_printed_precision(published: &str, value: f64) -> bool {
    let Ok(p) = published.trim().parse::<f64>() else {
        return false;
    };
    let decimals = published.trim().split_once('.').map_or(0, |(_, frac)| frac.len()) as i32;
    (p - value).abs() <= 0.5 * 10f64.powi(-decimals) + 1e-12
}
// ANCHOR_END: agrees_to_printed_precision

fn entry(
    id: impl Into<String>,
    source: &'static str,
    quantity: &'static str,
    published: &'static str,
    recomputed: f64,
    note: &'static str,
) -> Entry {
    Entry {
        id: id.into(),
        source,
        quantity,
        published,
        published_value: published.trim().parse().ok(),
        recomputed,
        agrees: agrees_to_printed_precision(published, recomputed),
        note,
    }
}

fn cos_deg(deg: f64) -> f64 {
    deg.to_radians().cos()
}

/// The color products of the Colors chapter.
fn color_entries() -> Vec<Entry> {
    let src = "000 Colors l.100-116; 003 l.44-80";
    let white = modulate(DVec3::ONE, CORAL);
    let green = modulate(DVec3::new(0.0, 1.0, 0.0), CORAL);
    let olive = modulate(DVec3::new(0.33, 0.42, 0.18), CORAL);
    vec![
        entry("color-white-r", src, "white × coral, red", "1.0", white.x, "exact"),
        entry("color-white-g", src, "white × coral, green", "0.5", white.y, "exact"),
        entry("color-white-b", src, "white × coral, blue", "0.31", white.z, "exact"),
        entry("color-green-r", src, "green × coral, red", "0.0", green.x, "exact"),
        entry("color-green-g", src, "green × coral, green", "0.5", green.y, "exact"),
        entry("color-green-b", src, "green × coral, blue", "0.0", green.z, "exact"),
        entry("color-olive-r", src, "(0.33, 0.42, 0.18) × coral, red", "0.33", olive.x, "exact"),
        entry("color-olive-g", src, "(0.33, 0.42, 0.18) × coral, green", "0.21", olive.y, "exact"),
        entry(
            "color-olive-b",
            src,
            "(0.33, 0.42, 0.18) × coral, blue",
            "0.06",
            olive.z,
            "0.18 × 0.31 = 0.0558, printed rounded to two decimals",
        ),
    ]
}

/// One row of the spotlight worked table: θ in degrees, printed cosines and I.
struct SpotRow {
    id: &'static str,
    theta_deg: f64,
    theta: &'static str,
    phi_deg: f64,
    phi: &'static str,
    gamma_deg: f64,
    gamma: &'static str,
    epsilon: &'static str,
    intensity: &'static str,
}

/// The worked table of Light casters, "Smooth/Soft edges" (000 l.1118-1149,
/// 003 l.1736-1743), as printed.
const SPOT_ROWS: [SpotRow; 6] = [
    SpotRow {
        id: "row1",
        theta_deg: 30.0,
        theta: "0.87",
        phi_deg: 25.0,
        phi: "0.91",
        gamma_deg: 35.0,
        gamma: "0.82",
        epsilon: "0.09",
        intensity: "0.56",
    },
    SpotRow {
        id: "row2",
        theta_deg: 26.0,
        theta: "0.9",
        phi_deg: 25.0,
        phi: "0.91",
        gamma_deg: 35.0,
        gamma: "0.82",
        epsilon: "0.09",
        intensity: "0.89",
    },
    SpotRow {
        id: "row3",
        theta_deg: 14.0,
        theta: "0.97",
        phi_deg: 25.0,
        phi: "0.91",
        gamma_deg: 35.0,
        gamma: "0.82",
        epsilon: "0.09",
        intensity: "1.67",
    },
    SpotRow {
        id: "row4",
        theta_deg: 34.0,
        theta: "0.83",
        phi_deg: 25.0,
        phi: "0.91",
        gamma_deg: 35.0,
        gamma: "0.82",
        epsilon: "0.09",
        intensity: "0.11",
    },
    SpotRow {
        id: "row5",
        theta_deg: 50.0,
        theta: "0.64",
        phi_deg: 25.0,
        phi: "0.91",
        gamma_deg: 35.0,
        gamma: "0.82",
        epsilon: "0.09",
        intensity: "-2.0",
    },
    SpotRow {
        id: "row6",
        theta_deg: 15.0,
        theta: "0.966",
        phi_deg: 12.5,
        phi: "0.9978",
        gamma_deg: 17.5,
        gamma: "0.953",
        epsilon: "0.0448",
        intensity: "0.29",
    },
];

/// The unclamped ratio the table prints, `I = (θ − γ) / ε`.
fn unclamped_intensity(theta: f64, cut_off: f64, outer_cut_off: f64) -> f64 {
    (theta - outer_cut_off) / (cut_off - outer_cut_off)
}

fn spot_entries() -> Vec<Entry> {
    let src = "000 Light casters l.1118-1149; 003 l.1736-1743";
    let mut out = Vec::new();
    for r in &SPOT_ROWS {
        let (theta, phi, gamma) = (cos_deg(r.theta_deg), cos_deg(r.phi_deg), cos_deg(r.gamma_deg));
        let id = |q: &str| format!("spot-{}-{q}", r.id);
        let is_row6 = r.id == "row6";
        out.push(entry(
            id("theta"),
            src,
            "θ = cos of the fragment angle",
            r.theta,
            theta,
            "cos of the printed degrees",
        ));
        out.push(entry(
            id("phi"),
            src,
            "φ = cos of the inner cut-off",
            r.phi,
            phi,
            if is_row6 {
                "0.9978 is cos(12.5 radians); cos(12.5°) = 0.9763 (the chapter itself says 0.976)"
            } else {
                "cos of the printed degrees"
            },
        ));
        out.push(entry(
            id("gamma"),
            src,
            "γ = cos of the outer cut-off",
            r.gamma,
            gamma,
            if is_row6 {
                "cos 17.5° = 0.95372 was truncated to 0.953, not rounded to 0.954"
            } else {
                "cos of the printed degrees"
            },
        ));
        out.push(entry(
            id("epsilon"),
            src,
            "ε = φ − γ",
            r.epsilon,
            phi - gamma,
            if is_row6 { "follows from the wrong φ = cos(12.5 rad)" } else { "from exact cosines" },
        ));
        out.push(entry(
            id("intensity"),
            src,
            "I = (θ − γ) / ε, before clamping",
            r.intensity,
            unclamped_intensity(theta, phi, gamma),
            if is_row6 {
                "the wrong φ halves I; with cos(12.5°) I = 0.54"
            } else {
                "cosines rounded to 2 decimals, then divided by a small ε: a 0.005 error in θ moves I by 0.06"
            },
        ));
    }
    out
}

fn caster_entries() -> Vec<Entry> {
    let fifty = crate::reference::casters::Attenuation::from_f32(&RANGE_TABLE[4].attenuation);
    let d = 50.0f64;
    // 003 l.1408-1410 prints Φ = (1/d²)(Kc + Kl·d + Kq·d²); evaluated here as printed.
    let garbled = (fifty.constant + fifty.linear * d + fifty.quadratic * d * d) / (d * d);
    vec![
        entry(
            "cutoff-12.5",
            "003 Light casters l.1709",
            "cos(12.5°)",
            "0.976",
            cos_deg(12.5),
            "agrees; contradicts the worked table's 0.9978",
        ),
        entry(
            "dir-vec4-x",
            "000 Light casters l.905",
            "x of the directional light as a vec4 (set as -0.2 two paragraphs earlier, l.900)",
            "0.2",
            -0.2,
            "the minus signs were lost: vec4(0.2, 1.0, 0.3, 0.0) points the sun upward; 003 keeps -0.2",
        ),
        Entry {
            published_value: Some(garbled),
            ..entry(
                "attenuation-formula-003",
                "003 Light casters l.1408-1410",
                "attenuation at d = 50 with (1, 0.09, 0.032)",
                "(1/d²)(Kc + Kl·d + Kq·d²)",
                fifty.at(d),
                "the fraction was typeset as a product; the printed formula gives 0.0342 at d = 50 and grows toward Kq",
            )
        },
        entry(
            "light-power-001",
            "001 opengl-tutorial 8 l.169",
            "LightPower (\"for example 60 watts\")",
            "60",
            crate::models::OpenGLTutorial::with_defaults(Vec3::ZERO, Vec3::ONE).light_power as f64,
            "the tutorial's shader uses 50; the text's 60 is an example, so images differ by 60/50 = 1.2 in diffuse and specular",
        ),
    ]
}

fn material_entries() -> Vec<Entry> {
    let cyan = crate::material::classic_material("cyan plastic").map_or(f64::NAN, |m| m.shininess() as f64);
    vec![entry(
        "cyan-plastic-shininess",
        "000 Materials l.675 (exercise), LearnOpenGL materials_exercise1",
        "cyan plastic shininess (table 0.25 × 128)",
        "32",
        cyan,
        "the table's shininess is a fraction of 128",
    )]
}

/// Every entry, in source order (colors, casters, spot table, materials).
pub fn entries() -> Vec<Entry> {
    let mut all = color_entries();
    all.extend(caster_entries());
    all.extend(spot_entries());
    all.extend(material_entries());
    all
}

/// Every entry with the discrepancies first (stable within each group).
pub fn discrepancies_first() -> Vec<Entry> {
    let mut all = entries();
    all.sort_by_key(|e| e.agrees);
    all
}
