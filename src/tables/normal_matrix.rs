//! Normals: what goes wrong when a normal goes through the model matrix, and
//! inverse-transpose against cofactor.
//!
//! Source: LearnOpenGL, Basic lighting ("One last thing": the normal matrix).

use glam::{Mat3, Vec3};

use crate::normals::{
    condition_number, model_matrix_normal_error_deg, normal_matrix_cofactor, normal_matrix_inverse_transpose,
    transform_normal,
};
use crate::table::{constant3, num32, vec3, Table};

/// The model matrices of the tables (upper-left 3×3), with their names.
pub fn models() -> Vec<(&'static str, Mat3)> {
    vec![
        (
            "rotation 50° about (1, 0.3, 0.5)",
            Mat3::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50f32.to_radians()),
        ),
        ("uniform scale 2", Mat3::from_diagonal(Vec3::splat(2.0))),
        ("scale (2, 1, 1)", Mat3::from_diagonal(Vec3::new(2.0, 1.0, 1.0))),
        ("scale (1, 0.2, 1)", Mat3::from_diagonal(Vec3::new(1.0, 0.2, 1.0))),
        ("shear x += y", Mat3::from_cols(Vec3::X, Vec3::new(1.0, 1.0, 0.0), Vec3::Z)),
        ("scale (1, 1, 1e-3)", Mat3::from_diagonal(Vec3::new(1.0, 1.0, 1e-3))),
        ("scale (1, 1, 1e-6)", Mat3::from_diagonal(Vec3::new(1.0, 1.0, 1e-6))),
        ("scale (1, 1, 1e-20)", Mat3::from_diagonal(Vec3::new(1.0, 1.0, 1e-20))),
        ("scale (1, 1, 0) (singular)", Mat3::from_diagonal(Vec3::new(1.0, 1.0, 0.0))),
    ]
}

/// The sample normals (unit length).
fn normals() -> [(&'static str, Vec3); 3] {
    [("(1,1,0)/√2", Vec3::new(1.0, 1.0, 0.0).normalize()), ("(1,1,1)/√3", Vec3::ONE.normalize()), ("(0,1,0)", Vec3::Y)]
}

/// The chapter's tables: the model-matrix error, then inverse-transpose vs cofactor.
pub fn tables() -> Vec<Table> {
    tables_for(None, Vec3::ONE)
}

/// The same tables with a scale of your own (`yours`, a model `scale(x, y, z)` after the
/// chapter's) and the normal of the second table (`(1, 1, 1)` in the chapter; normalized
/// here). A normal with no direction (zero, or too long to normalize) falls back to the
/// chapter's; the title prints the normal used.
pub fn tables_for(scale: Option<Vec3>, normal: Vec3) -> Vec<Table> {
    let mut models: Vec<(String, Mat3)> = models().into_iter().map(|(name, m)| (name.to_string(), m)).collect();
    models.extend(scale.map(|s| (format!("yours: scale {}", constant3(s)), Mat3::from_diagonal(s))));
    let normal = if normal.normalize_or_zero() == Vec3::ZERO { Vec3::ONE } else { normal };
    vec![error_table(&models), inverse_vs_cofactor_table(&models, normal)]
}

fn error_table(models: &[(String, Mat3)]) -> Table {
    let mut headers = vec!["model (mat3)".to_string(), "det M".to_string()];
    headers.extend(normals().iter().map(|(name, _)| format!("error n={name} (deg)")));
    let mut t = Table {
        title: "Angle error of a normal sent through the model matrix".into(),
        note: "Error = angle between normalize(M n) (the bug) and normalize(M^(−T) n) (the normal matrix), degrees. \
               Zero for rotations and uniform scale; grows towards 90° as a scale goes to 0. \"—\": no direction \
               survives (the singular M maps this normal to zero)."
            .into(),
        headers,
        rows: Vec::new(),
    };
    for (name, m) in models {
        let m = *m;
        let mut row = vec![name.clone(), scientific(m.determinant())];
        row.extend(
            normals()
                .iter()
                .map(|&(_, n)| model_matrix_normal_error_deg(m, n).map_or("—".to_string(), |e| num32(e, 3))),
        );
        t.push(row);
    }
    t
}

fn inverse_vs_cofactor_table(models: &[(String, Mat3)], normal: Vec3) -> Table {
    let n = normal.normalize();
    let title = if normal == Vec3::ONE {
        "Inverse-transpose against cofactor, n = (1,1,1)/√3".to_string()
    } else {
        format!("Inverse-transpose against cofactor, n = normalize{}", constant3(normal))
    };
    let mut t = Table::new(
        title,
        "Both normal matrices should give the same direction; the cofactor form needs no division and still gives \
         one for a singular M. κ_F = ‖M‖_F · ‖M^(−1)‖_F, the Frobenius condition number (inf when singular). \
         Angle between the two results in degrees (f32, atan2 form). At scale 1e-20 the \
         inverse-transpose is finite but the transformed normal's squared length overflows f32, so it cannot be \
         normalized; the cofactor form avoids the 1/det.",
        &["model (mat3)", "κ_F", "inverse-transpose n'", "cofactor n'", "angle between (deg)"],
    );
    for (name, m) in models {
        let m = *m;
        let cofactor = transform_normal(normal_matrix_cofactor(m), n);
        let inverse = normal_matrix_inverse_transpose(m).map(|it| transform_normal(it, n));
        let inverse_cell = match inverse {
            None => "singular".to_string(),
            Some(i) if i == Vec3::ZERO => "overflow: |n'|² > f32::MAX".to_string(),
            Some(i) => vec3(i, 4),
        };
        let angle = match inverse {
            Some(i) if i != Vec3::ZERO => num32(angle_deg(i, cofactor), 4),
            _ => "—".to_string(),
        };
        t.push(vec![name.clone(), scientific(condition_number(m)), inverse_cell, vec3(cofactor, 4), angle]);
    }
    t
}

/// Determinants and condition numbers span 1e-20 … 1e20: scientific notation.
fn scientific(k: f32) -> String {
    if k.is_finite() {
        format!("{k:.3e}")
    } else {
        "inf".to_string()
    }
}

/// The angle between two unit vectors in degrees, as atan2(|a × b|, a · b),
/// which stays accurate near 0 where acos(a · b) loses digits in f32.
fn angle_deg(a: Vec3, b: Vec3) -> f32 {
    a.cross(b).length().atan2(a.dot(b)).to_degrees()
}
