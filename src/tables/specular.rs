//! Chapter 2, specular lobes: `pow(cos α, s)`, Phong against Blinn-Phong, matching exponents.
//!
//! Sources: LearnOpenGL, Basic lighting (shininess 2 … 256 figure) and
//! Advanced lighting (Blinn-Phong, "2 to 4 times" the Phong exponent).

use glam::Vec3;

use crate::glsl::pow_or_zero;
use crate::phong::{
    blinn_exponent_matching_half_width, blinn_exponent_rule_of_thumb, blinn_specular_factor, lobe_half_width_deg,
    phong_specular_factor,
};
use crate::table::{num32, Table};

/// The exponents of the chapter's figure.
pub const EXPONENTS: [f32; 8] = [2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0];

/// The angles of the lobe table, in degrees.
pub const ANGLES_DEG: [f32; 10] = [0.0, 5.0, 10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 75.0, 90.0];

/// The chapter's tables: the lobe, Phong vs Blinn, matching exponents and half-widths.
pub fn tables() -> Vec<Table> {
    tables_for(32.0)
}

/// The same tables for your own `shininess`: Phong against Blinn-Phong at that
/// exponent, and a row for it in the lobe and matching tables when it is not
/// one of the figure's [`EXPONENTS`]. The caller checks `shininess ≥ 0`.
pub fn tables_for(shininess: f32) -> Vec<Table> {
    let mut exponents = EXPONENTS.to_vec();
    if !exponents.contains(&shininess) {
        exponents.push(shininess);
        exponents.sort_by(f32::total_cmp);
    }
    vec![lobe_table(&exponents), phong_vs_blinn_table(shininess), matching_table(&exponents)]
}

fn lobe_table(exponents: &[f32]) -> Table {
    let mut headers = vec!["s".to_string()];
    headers.extend(ANGLES_DEG.iter().map(|a| format!("α={a}°")));
    let mut t = Table {
        title: "Specular lobe pow(cos α, s)".into(),
        note: "α is the angle between view_dir and reflect_dir (degrees); cos α is clamped at 0 first. \
               Higher s: smaller, sharper highlight."
            .into(),
        headers,
        rows: Vec::new(),
    };
    for &s in exponents {
        let mut row = vec![format!("{s}")];
        row.extend(ANGLES_DEG.iter().map(|a| num32(pow_or_zero(a.to_radians().cos().max(0.0), s), 4)));
        t.push(row);
    }
    t
}

/// Light straight above (`light_dir = n`), so `reflect_dir = n`, and the eye
/// tilted by α: Phong sees `cos α`, Blinn-Phong `n · halfway = cos(α/2)`.
fn phong_vs_blinn_table(s: f32) -> Table {
    let matching = blinn_exponent_matching_half_width(s).unwrap_or(f32::NAN);
    let four = blinn_exponent_rule_of_thumb(s);
    let mut t = Table::new(
        format!("Phong against Blinn-Phong at the same angles (s = {s})"),
        format!(
            "Light along the normal, eye tilted by α (degrees) in one plane, through phong_specular_factor and \
             blinn_specular_factor. Blinn-Phong with the same s is much wider; 4s (rule of thumb) or the \
             half-width-matching exponent {} brings it back.",
            num32(matching, 1)
        ),
        &[
            "α (deg)",
            &format!("Phong s={s}"),
            &format!("Blinn s={s}"),
            &format!("Blinn s={four} (4×)"),
            "Blinn s=matching",
        ],
    );
    let n = Vec3::Z;
    for a in ANGLES_DEG {
        let (sin, cos) = a.to_radians().sin_cos();
        let view_dir = Vec3::new(sin, 0.0, cos);
        t.push(vec![
            format!("{a}"),
            num32(phong_specular_factor(n, n, view_dir, s), 4),
            num32(blinn_specular_factor(n, n, view_dir, s), 4),
            num32(blinn_specular_factor(n, n, view_dir, four), 4),
            num32(blinn_specular_factor(n, n, view_dir, matching), 4),
        ]);
    }
    t
}

fn matching_table(exponents: &[f32]) -> Table {
    let mut t = Table::new(
        "Lobe half-width and the matching Blinn exponent",
        "Half-width: the angle α (degrees) where the lobe falls to 1/2, acos(2^(−1/s)) for Phong; Blinn-Phong with \
         the same s has twice the in-plane angle. Matching Blinn exponent: same half-width, ln(1/2)/ln(cos(α½/2)); \
         the ratio tends to 4 as s grows.",
        &[
            "Phong s",
            "Phong half-width (deg)",
            "Blinn same s half-width (deg)",
            "rule of thumb 4s",
            "matching Blinn s",
            "ratio",
        ],
    );
    for &s in exponents {
        let half = lobe_half_width_deg(s).unwrap_or(f32::NAN);
        let blinn_same_s = 2.0 * half;
        let matching = blinn_exponent_matching_half_width(s).unwrap_or(f32::NAN);
        t.push(vec![
            format!("{s}"),
            num32(half, 2),
            num32(blinn_same_s, 2),
            format!("{}", blinn_exponent_rule_of_thumb(s)),
            num32(matching, 2),
            num32(matching / s, 3),
        ]);
    }
    t
}
