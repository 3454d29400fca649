//! LearnOpenGL "Light casters", spotlight, flashlight and soft edges, French (000) and
//! Ukrainian (003): the cone test, the intensity formula and its worked table.

use glam::Vec3;

use super::listings::{light_members_used, struct_fields, FR_SPOT_STRUCT, FR_SPOT_TEST, UK_SPOT_TEST};
use super::{cited, Entry};
use crate::reference::casters::{hard_spot, spot_intensity};

/// One row of the spotlight worked table: angles in degrees and the printed cosines and I.
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
    /// The row's lines: French table, Ukrainian table.
    lines: [(u32, u32); 2],
}

const fn row(id: &'static str, degrees: [f64; 3], printed: [&'static str; 5], lines: [(u32, u32); 2]) -> SpotRow {
    SpotRow {
        id,
        theta_deg: degrees[0],
        theta: printed[0],
        phi_deg: degrees[1],
        phi: printed[1],
        gamma_deg: degrees[2],
        gamma: printed[2],
        epsilon: printed[3],
        intensity: printed[4],
        lines,
    }
}

/// The worked table of Light casters, "Smooth/Soft edges", as printed (000 l.1122-1149,
/// 003 l.1737-1743).
const SPOT_ROWS: [SpotRow; 6] = [
    row("row1", [30.0, 25.0, 35.0], ["0.87", "0.91", "0.82", "0.09", "0.56"], [(1124, 1129), (1738, 1738)]),
    row("row2", [26.0, 25.0, 35.0], ["0.9", "0.91", "0.82", "0.09", "0.89"], [(1130, 1133), (1739, 1739)]),
    row("row3", [14.0, 25.0, 35.0], ["0.97", "0.91", "0.82", "0.09", "1.67"], [(1134, 1137), (1740, 1740)]),
    row("row4", [34.0, 25.0, 35.0], ["0.83", "0.91", "0.82", "0.09", "0.11"], [(1138, 1141), (1741, 1741)]),
    row("row5", [50.0, 25.0, 35.0], ["0.64", "0.91", "0.82", "0.09", "-2.0"], [(1142, 1145), (1742, 1742)]),
    row("row6", [15.0, 12.5, 17.5], ["0.966", "0.9978", "0.953", "0.0448", "0.29"], [(1146, 1149), (1743, 1743)]),
];

fn cos_deg(deg: f64) -> f64 {
    deg.to_radians().cos()
}

/// The unclamped ratio the table prints, `I = (θ − γ) / ε`.
pub fn unclamped_intensity(theta: f64, cut_off: f64, outer_cut_off: f64) -> f64 {
    (theta - outer_cut_off) / (cut_off - outer_cut_off)
}

fn parse(s: &str) -> f64 {
    s.parse().unwrap_or(f64::NAN)
}

pub(super) fn table_rows() -> Vec<Entry> {
    let mut out = Vec::new();
    for r in &SPOT_ROWS {
        let (theta, phi, gamma) = (cos_deg(r.theta_deg), cos_deg(r.phi_deg), cos_deg(r.gamma_deg));
        let src = [(0, r.lines[0].0, r.lines[0].1), (3, r.lines[1].0, r.lines[1].1)];
        let id = |q: &str| format!("spot-{}-{q}", r.id);
        let is_row6 = r.id == "row6";
        let from_printed = unclamped_intensity(parse(r.theta), parse(r.phi), parse(r.gamma));
        out.push(
            cited(&id("theta"), &src)
                .says(&format!("θ = cos {}°", r.theta_deg), r.theta)
                .number(theta, "cos of the printed degrees"),
        );
        out.push(cited(&id("phi"), &src).says(&format!("φ = cos {}° (inner cut-off)", r.phi_deg), r.phi).number(
            phi,
            &if is_row6 {
                format!(
                    "0.9978 is cos(12.5 radians) = {:.4}; cos(12.5°) = {phi:.4} (003 l.1709 itself says 0.976)",
                    12.5f64.cos()
                )
            } else {
                "cos of the printed degrees".to_string()
            },
        ));
        out.push(cited(&id("gamma"), &src).says(&format!("γ = cos {}° (outer cut-off)", r.gamma_deg), r.gamma).number(
            gamma,
            &if is_row6 {
                format!("cos 17.5° = {gamma:.5} was cut to 0.953, not rounded to 0.954")
            } else {
                "cos of the printed degrees".to_string()
            },
        ));
        out.push(cited(&id("epsilon"), &src).says("ε = φ − γ", r.epsilon).number(
            phi - gamma,
            if is_row6 {
                "follows from the wrong φ = cos(12.5 rad): twice the right ε"
            } else {
                "from exact cosines"
            },
        ));
        let intensity = cited(&id("intensity"), &src).says("I = (θ − γ) / ε, before clamping", r.intensity).number(
            unclamped_intensity(theta, phi, gamma),
            &if is_row6 {
                format!(
                    "(0.966 − 0.953) / 0.0448 = {from_printed:.2} follows the wrong φ; with cos(12.5°) I = {:.2}",
                    unclamped_intensity(theta, phi, gamma)
                )
            } else {
                format!(
                    "the row's own 2-decimal cosines give ({} − {}) / {} = {from_printed:.3}; divided by a small ε, a \
                     0.005 rounding in θ moves I by {:.2}",
                    r.theta,
                    r.gamma,
                    r.epsilon,
                    0.005 / (phi - gamma)
                )
            },
        );
        // Rows 1–5 are what their own rounded cosines give; row 6's inputs are wrong, not rounded.
        out.push(if is_row6 { intensity } else { intensity.or_rounding_from(from_printed) });
    }
    out
}

/// Whether a listing assigns to `color` (a statement starting `color =`).
fn assigns_color(listing: &str) -> bool {
    listing.lines().any(|l| l.trim_start().starts_with("color ="))
}

pub(super) fn cone() -> Vec<Entry> {
    let fr_fields = struct_fields(FR_SPOT_STRUCT);
    let cutoff_ok = |test: &str| {
        light_members_used(test).iter().filter(|m| m.eq_ignore_ascii_case("cutoff")).all(|m| fr_fields.contains(m))
    };
    let spot = crate::casters::SpotLight::new(
        Vec3::ZERO,
        Vec3::NEG_Z,
        12.5,
        17.5,
        crate::casters::Attenuation::LEARNOPENGL,
        crate::material::LightProps::white(),
    );
    let on_axis = spot.as_ref().map_or(f32::NAN, |s| s.theta(Vec3::Z));
    let c125 = cos_deg(12.5);
    let falls = (0..90).all(|d| cos_deg(d as f64 + 1.0) < cos_deg(d as f64));
    let row3 = &SPOT_ROWS[2];
    let row5 = &SPOT_ROWS[4];
    let unclamped = |r: &SpotRow| unclamped_intensity(cos_deg(r.theta_deg), cos_deg(r.phi_deg), cos_deg(r.gamma_deg));
    let code_matches = SPOT_ROWS.iter().all(|r| {
        let (t, p, g) = (cos_deg(r.theta_deg), cos_deg(r.phi_deg), cos_deg(r.gamma_deg));
        (spot_intensity(t, p, g) - unclamped_intensity(t, p, g).clamp(0.0, 1.0)).abs() < 1e-12
    });
    let row1 = &SPOT_ROWS[0];
    let as_typeset = parse(row1.theta) - parse(row1.gamma) / parse(row1.epsilon);
    vec![
        cited("spot-theta-below-phi", &[(0, 1051, 1051), (3, 1607, 1609)]).says("a fragment is lit when its angle θ is below the cut-off angle Φ", "θ doit être inférieur à Φ pour que le fragment soit éclairé").holds(hard_spot(cos_deg(10.0), c125) == 1.0 && hard_spot(cos_deg(15.0), c125) == 0.0, "10° < 12.5° lit, 15° > 12.5° dark (comparing cosines with >)".into(), "reference::casters::hard_spot"),
        cited("cutoff-12.5", &[(0, 1075, 1075), (3, 1658, 1658), (3, 1709, 1709)]).says("cos(12.5°), the flashlight's cut-off", "0.976").number(c125, "glm::cos(glm::radians(12.5f)) in both listings; contradicts the table's 0.9978 (spot-row6-phi)"),
        cited("cosine-decreasing", &[(0, 1094, 1098), (3, 1705, 1709)]).says("between 0° and 90° the cosine decreases, hence > in the test", "Entre 0° et 90°, la fonction cosinus est décroissante").holds(falls, "cos strictly decreasing over 0°…90° in 1° steps".into(), ""),
        cited("spot-cutoff-name-fr", &[(0, 1065, 1065), (0, 1084, 1084)]).says("the test reads the struct's cut-off field", "if(theta > light.cutoff)").holds(cutoff_ok(FR_SPOT_TEST), format!("the struct (l.1062-1067) declares {}: GLSL names are case-sensitive", fr_fields.join(", ")), "light.cutoff is not a field (cutOff is): the listing does not compile (tests/gl_errata.rs); the \
                                                                                                                                                                                                                                                                                              Ukrainian text writes light.cutOff"),
        cited("spot-cutoff-name-uk", &[(3, 1636, 1636), (3, 1680, 1680)]).says("the test reads the struct's cut-off field", "if(theta > light.cutOff)").holds(cutoff_ok(UK_SPOT_TEST), "light.cutOff, as declared".into(), "compiles (tests/gl_errata.rs)"),
        cited("spot-else-writes-color", &[(0, 1088, 1089), (3, 1696, 1700)]).says("outside the cone the fragment gets the ambient light", "else color = vec4(light.ambient * vec3(texture(material.diffuse, TexCoords)), 1.0);").holds(!assigns_color(FR_SPOT_TEST) && !assigns_color(UK_SPOT_TEST), "the chapter's fragment shaders write out vec4 FragColor (000 l.164, 003 l.181)".into(), "color is declared nowhere in the chapter's shaders: as part of them the listing does not compile \
                                                                                                                                                                                                                                                                                                                                                                                               (tests/gl_errata.rs); the English original has the same line"),
        cited("spot-vectors-toward-light", &[(0, 1092, 1092), (3, 1703, 1703)]).says("lightDir and −direction both point toward the light", "les deux vecteurs doivent pointer vers la source").holds((on_axis - 1.0).abs() < 1e-6, format!("a fragment on the axis has θ = {on_axis}"), "casters::SpotLight::theta"),
        cited("epsilon-definition-fr", &[(0, 1118, 1118)]).says("ε is the cosine difference between the inner (φ) and outer (γ) cones", "Où θ est le cosinus entre le cône interne (ϕ) et le cône externe (γ) (ε = ϕ − γ)").holds("Où θ est le cosinus entre".contains('ε'), "ε = φ − γ".into(), "the sentence names θ where the original names ε (the Ukrainian l.1731 has ε)"),
        cited("epsilon-definition-uk", &[(3, 1731, 1731)]).says("ε is the cosine difference between the inner (φ) and outer (γ) cones", "ε (епсилон) - це різниця косинусів між внутрішніми (φ) і зовнішній конус (γ)").holds("ε (епсилон) - це різниця косинусів".contains('ε'), "ε = φ − γ".into(), ""),
        cited("spot-table-precedence", &[(0, 1124, 1149), (3, 1738, 1743)]).says("row 1's I as typeset, θ − γ / ε without parentheses", "0.87 - 0.82 / 0.09 = 0.56").number(unclamped_intensity(parse(row1.theta), parse(row1.phi), parse(row1.gamma)), &format!(
                "by precedence 0.87 − 0.82 / 0.09 = {as_typeset:.2}; the printed 0.56 is (0.87 − 0.82) / 0.09, the \
                 formula of l.1116 and the code's (theta − outerCutOff) / epsilon; every row is typeset so"
            ))
        .with_published_value(as_typeset)
        .into_text_erratum(),
        cited("intensity-leaves-0-1", &[(0, 1153, 1153), (3, 1751, 1751)]).says("unclamped, I is negative outside the outer cone and above 1 inside the inner one", "une intensité qui devient négative en dehors du cône extérieur et plus grande que 1 dans le cône interne").holds(unclamped(row5) < 0.0 && unclamped(row3) > 1.0, format!("I = {:.3} at 50°, {:.3} at 14°", unclamped(row5), unclamped(row3)), ""),
        cited("intensity-code-matches-formula", &[(0, 1156, 1158), (3, 1754, 1762)]).says("the code computes clamp((θ − γ) / ε, 0, 1)", "float intensity = clamp((theta - light.outerCutOff) / epsilon, 0.0, 1.0);").holds(code_matches, "reference spot_intensity equals the clamped formula at the table's six rows".into(), "parenthesized, unlike the table"),
        cited("soft-edge-angles", &[(0, 1146, 1146), (0, 1165, 1165), (3, 1743, 1743), (3, 1787, 1787)]).says("the soft-edged flashlight uses 12.5° inside and 17.5° outside, as the table's last row", "un angle interne de 12,5° et un angle externe de 17,5°").holds(SPOT_ROWS[5].phi_deg == 12.5 && SPOT_ROWS[5].gamma_deg == 17.5 && spot.is_ok(), "SpotLight::new(…, 12.5, 17.5, …) is a valid light".into(), ""),
    ]
}
