//! LearnOpenGL "Light casters": directional light, point light, attenuation and the
//! range table, French (000) and Ukrainian (003).

use glam::{Mat4, Vec3};

use super::listings::{struct_fields, FR_POINT_STRUCT, UK_POINT_STRUCT};
use super::{cited, Entry};
use crate::casters::{Attenuation as Att32, RANGE_TABLE};
use crate::reference::casters::Attenuation;

/// The range table as both texts print it (000 l.970-981, 003 l.1455-1467), one row per line.
pub const PRINTED_RANGE_ROWS: [&str; 12] = [
    "7 1.0 0.7 1.8",
    "13 1.0 0.35 0.44",
    "20 1.0 0.22 0.20",
    "32 1.0 0.14 0.07",
    "50 1.0 0.09 0.032",
    "65 1.0 0.07 0.017",
    "100 1.0 0.045 0.0075",
    "160 1.0 0.027 0.0028",
    "200 1.0 0.022 0.0019",
    "325 1.0 0.014 0.0007",
    "600 1.0 0.007 0.0002",
    "3250 1.0 0.0014 0.000007",
];

/// The relative drop of the attenuation per unit distance, `−F′(d)/F(d)`, by central
/// differences on the `f64` reference (step `1e-4·max(1, d)`).
pub fn relative_drop(a: &Attenuation, d: f64) -> f64 {
    let h = 1e-4 * d.max(1.0);
    -(a.at(d + h) - a.at(d - h)) / (2.0 * h) / a.at(d)
}

/// The printed garbled formula of 003 l.1410, `Φ = (1/d²)(Kc + Kl·d + Kq·d²)`, evaluated as printed.
pub fn garbled_attenuation(a: &Attenuation, d: f64) -> f64 {
    (a.constant + a.linear * d + a.quadratic * d * d) / (d * d)
}

pub(super) fn directional() -> Vec<Entry> {
    let scene = crate::scene::Scene::learnopengl_default();
    let dir = scene.dir_light.map_or(Vec3::NAN, |l| l.direction);
    let moved = Mat4::from_translation(Vec3::new(3.0, -2.0, 5.0));
    let direction = glam::Vec4::new(-0.2, -1.0, -0.3, 0.0);
    let position = glam::Vec4::new(1.2, 1.0, 2.0, 1.0);
    vec![
        cited("directional-points-down", &[(0, 897, 900), (3, 1355, 1358)])
            .says(
                "the directional light (−0.2, −1, −0.3) points down, from the light",
                "lightingShader.setVec3(\"light.direction\", -0.2f, -1.0f, -0.3f);",
            )
            .holds(
                dir == Vec3::new(-0.2, -1.0, -0.3) && dir.y < 0.0,
                format!("Scene::learnopengl_default() direction {:?}: y < 0", dir.to_array()),
                "",
            ),
        cited("dir-vec4-fr", &[(0, 905, 905)])
            .says("x of the same direction written as a vec4 (−0.2 on l.900)", "0.2")
            .number(
                dir.x as f64,
                "the minus signs were lost: vec4(0.2f, 1.0f, 0.3f, 0.0f) points the sun upward; the Ukrainian text \
                 keeps them",
            ),
        cited("dir-vec4-uk", &[(3, 1363, 1363)])
            .says("x of the same direction written as a vec4 (−0.2 on l.1358)", "vec4(-θ·2f, -1·θf, -θ·3f, θ·θf)")
            .holds(
                "vec4(-θ·2f, -1·θf, -θ·3f, θ·θf)".matches('-').count() == 3,
                format!("(−0.2, −1.0, −0.3, 0.0): all three signs kept; x = {}", dir.x),
                "the digits suffer the 0 → θ typesetting (zero-digit-uk) but the vector is right",
            ),
        cited("w-tells-direction-from-position", &[(0, 903, 905), (3, 1361, 1363)])
            .says(
                "w = 0: a direction translations leave alone; w = 1: a position they move",
                "il est important d'initialiser la composante w à la valeur 1.0 … w à 0.0",
            )
            .holds(
                moved * direction == direction
                    && moved * position != position
                    && crate::glsl::homogeneous_kind(direction.w, 1e-6)
                        == Some(crate::glsl::HomogeneousKind::Direction),
                "translate·(d, 0) = (d, 0); translate·(p, 1) ≠ (p, 1)".into(),
                "glsl::homogeneous_kind",
            ),
        cited("ten-containers", &[(0, 883, 886), (0, 929, 929), (3, 1315, 1320), (3, 1398, 1398)])
            .says("containers in the scene", "10")
            .number(crate::raster::presets::CUBE_POSITIONS.len() as f64, "raster::presets::CUBE_POSITIONS"),
    ]
}

pub(super) fn attenuation() -> Vec<Entry> {
    let fifty = Attenuation::from_f32(&RANGE_TABLE[4].attenuation);
    let d = 50.0;
    let k = fifty.linear / fifty.quadratic;
    let drop_at_cross = relative_drop(&fifty, k);
    // The peak of −F′/F: d* solves 2Kq²d² + 2KlKq·d − (2KqKc − Kl²) = 0 (set the derivative of
    // (Kl + 2Kq d)/(Kc + Kl d + Kq d²) to zero).
    let (a2, a1, a0) = (
        2.0 * fifty.quadratic * fifty.quadratic,
        2.0 * fifty.linear * fifty.quadratic,
        -(2.0 * fifty.quadratic * fifty.constant - fifty.linear * fifty.linear),
    );
    let peak = (-a1 + (a1 * a1 - 4.0 * a2 * a0).sqrt()) / (2.0 * a2);
    let drop_10 = relative_drop(&fifty, 10.0);
    let drop_50 = relative_drop(&fifty, 50.0);
    let garbled = |x: f64| garbled_attenuation(&fifty, x);
    let uk_fields = struct_fields(UK_POINT_STRUCT);
    let new_fields = struct_fields(FR_POINT_STRUCT)
        .into_iter()
        .filter(|f| ["constant", "linear", "quadratic"].contains(&f.as_str()));
    let light_pos = crate::phong::BasicLighting::learnopengl().light_pos;
    let farthest =
        crate::raster::presets::CUBE_POSITIONS.iter().map(|p| p.distance(light_pos) as f64).fold(0.0, f64::max);
    vec![
        cited("attenuation-formula-fr", &[(0, 937, 937)]).says("F_att = 1 / (Kc + Kl·d + Kq·d²), as typeset", "F_att = 1.0 / (K_c + K_l * d + K_q * d^2)").holds((fifty.at(d) - 1.0 / (1.0 + 0.09 * d + 0.032 * d * d)).abs() < 1e-8, format!("reference Attenuation::at(50) = {:.6} with (1, 0.09, 0.032)", fifty.at(d)), "the printed fraction and lightlab agree"),
        cited("attenuation-code", &[(0, 1014, 1016), (0, 1305, 1307), (3, 1553, 1561), (3, 2056, 2064)]).says("the shaders compute 1 / (constant + linear·d + quadratic·d²)", "float attenuation = 1.0 / (light.constant + light.linear * distance + light.quadratic * (distance * distance));").holds((crate::casters::Attenuation::LEARNOPENGL.at(50.0) as f64 - fifty.at(d)).abs() < 1e-6, format!(
                "casters::Attenuation::at(50) = {:.6} (f32) against the f64 reference {:.6}",
                crate::casters::Attenuation::LEARNOPENGL.at(50.0),
                fifty.at(d)
            ), "the same line in both texts, in the point-light and multiple-lights chapters"),
        cited("attenuation-formula-uk", &[(3, 1408, 1410)]).says("attenuation at d = 50 with (1, 0.09, 0.032), printed formula against the real one", "Φ = (1/d²)(K_v + K_l·d + K_a·d²)").number(fifty.at(d), &format!(
                "the fraction 1/(…) was typeset as a product (1/d²)(…): Φ = Kc/d² + Kl/d + Kq falls toward Kq = {} \
                 from above ({:.4} at d = 50, {:.4} at d = 1000) and exceeds 1 near the light ({:.3} at d = 1), \
                 where the real factor is {:.4} at d = 50",
                fifty.quadratic as f32,
                garbled(50.0),
                garbled(1000.0),
                garbled(1.0),
                fifty.at(d)
            ))
        .with_published_value(garbled(d))
        .into_text_erratum(),
        cited("denominator-at-least-1-fr", &[(0, 945, 945)]).says("with Kc = 1 the denominator never drops below 1", "son rôle est d'assurer que le dénominateur est toujours supérieur à 1").holds(1.0 / fifty.at(0.0) > 1.0, format!("Kc + Kl·d + Kq·d² = {} at d = 0: at least 1, equal at the light", 1.0 / fifty.at(0.0)), "\"toujours supérieur à 1\" (always greater than 1) fails at d = 0; the original and the Ukrainian \
                                                                                                                                                                                                                                                                                                                                 say \"never smaller than 1\""),
        cited("denominator-at-least-1-uk", &[(3, 1436, 1436)]).says("with Kc = 1 the denominator never drops below 1", "знаменник ніколи не стає меншим за 1").holds((0..=1000).all(|i| 1.0 / fifty.at(i as f64 * 0.1) >= 1.0), "≥ 1 on d ∈ [0, 100]".into(), ""),
        cited("coefficient-symbols-fr", &[(0, 955, 955)]).says("the quadratic coefficient is K_q", "K_g * d^2").holds("K_g * d^2".contains("K_q"), "K_q (the code calls it quadratic)".into(), "typo: K_g for K_q"),
        cited("coefficient-symbols-uk", &[(3, 1410, 1434), (3, 1470, 1488)]).says("the coefficients are K_c, K_l, K_q", "K_v, K_a; Кв, Клі, К☞; Кв, Кл, Кр").holds("K_v, K_a; Кв, Клі, К☞; Кв, Кл, Кр".contains("K_c"), "K_c, K_l, K_q".into(), "the subscripts were translated or garbled: c became v or в, q became a, р or ☞"),
        cited("quadratic-overtakes-linear", &[(0, 957, 957), (3, 1438, 1438)]).says("the quadratic term is smaller than the linear one at short range and larger further out", "Ce terme est moins significatif que le terme linéaire quand la distance est faible").holds(fifty.quadratic * (0.5 * k).powi(2) < fifty.linear * 0.5 * k
                && fifty.quadratic * (2.0 * k).powi(2) > fifty.linear * 2.0 * k, format!("Kq·d² = Kl·d at d = Kl/Kq = {k:.4} for the distance-50 row"), ""),
        cited("falls-faster-far-away", &[(0, 959, 959), (3, 1440, 1440)]).says("once the quadratic term dominates, the light decreases a lot faster", "la lumière diminue linéairement pour des distances faibles, puis beaucoup plus vite").holds(drop_10 > drop_at_cross, format!(
                "relative drop −F′/F: {drop_at_cross:.3} per unit at the crossover d = {k:.2}, peak {:.3} at \
                 d = {peak:.2}, then {drop_10:.3} at d = 10 and {drop_50:.4} at d = 50",
                relative_drop(&fifty, peak)
            ), "past the crossover the light falls more slowly, as the text itself says a few lines earlier \
                (000 l.933, 003 l.1404) and the next sentence of 003 l.1440; the English original has the same slip"),
        cited("attenuation-tends-to-zero", &[(0, 963, 963), (3, 1444, 1444)]).says("high near the light, quickly lower, slowly toward 0 (about 0 at distance 100)", "elle diminue rapidement avec la distance pour tendre lentement vers 0").holds(fifty.at(0.0) == 1.0 && fifty.at(100.0) < 0.01, format!("F(0) = 1, F(10) = {:.3}, F(100) = {:.4}", fifty.at(10.0), fifty.at(100.0)), "distance-50 coefficients"),
        cited("attenuation-three-terms", &[(0, 987, 998), (3, 1492, 1523)]).says("new values in the Light struct", "3").number(new_fields.count() as f64, "constant, linear, quadratic in the printed struct"),
        cited("distance-50-coefficients", &[(0, 1001, 1006), (3, 1530, 1541)]).says("covering distance 50 takes the table's row 50", "light.constant 1.0f; light.linear 0.09f; light.quadratic 0.032f").holds(RANGE_TABLE[4].range == 50.0 && RANGE_TABLE[4].attenuation == Att32::LEARNOPENGL, format!("RANGE_TABLE row {} = Attenuation::LEARNOPENGL", RANGE_TABLE[4].range), ""),
        cited("light-struct-semicolon-fr", &[(0, 990, 998)]).says("the Light struct is closed with };", "… float quadratic; };").holds(FR_POINT_STRUCT.trim_end().ends_with("};"), "struct declarations end with a semicolon in GLSL".into(), "compiles (tests/gl_errata.rs)"),
        cited("light-struct-semicolon-uk", &[(3, 1495, 1527)]).says("the Light struct is closed with };", "… float quadratic; }").holds(UK_POINT_STRUCT.trim_end().ends_with("};"), format!("the struct has {} fields and no closing semicolon", uk_fields.len()), "as printed the listing does not compile: llvmpipe reports a syntax error (tests/gl_errata.rs)"),
        cited("back-containers-fr", &[(0, 1036, 1036)]).says("the containers at the back are quite dark", "Les conteneurs du fond sont assez sombres").holds(fifty.at(farthest) < 0.2, format!("farthest container {farthest:.2} from the light: F = {:.3}", fifty.at(farthest)), "light at (1.2, 1, 2), distance-50 coefficients"),
        cited("back-containers-uk", &[(3, 1584, 1584)]).says("the containers at the back are not lit at all", "Контейнери в задній частині взагалі не освітлені").holds(fifty.at(farthest) == 0.0, format!("farthest container {farthest:.2} from the light: F = {:.3}, dim but lit", fifty.at(farthest)), "the attenuation never reaches 0; the French says \"assez sombres\" (quite dark)"),
    ]
}

pub(super) fn range_table() -> Vec<Entry> {
    let mut out = Vec::new();
    let places: &[(u8, u32, u32)] = &[(0, 969, 981), (3, 1450, 1467)];
    let parsed: Vec<Vec<f64>> = PRINTED_RANGE_ROWS
        .iter()
        .map(|r| r.split_whitespace().map(|x| x.parse().unwrap_or(f64::NAN)).collect())
        .collect();
    let left_at_range: Vec<f64> =
        RANGE_TABLE.iter().map(|r| Attenuation::from_f32(&r.attenuation).at(r.range as f64)).collect();
    let (lo, hi) = left_at_range.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &f| (lo.min(f), hi.max(f)));
    let range_note = format!(
        "every row ends at {:.1}–{:.1} % of the light (1/{:.0} to 1/{:.0}): read as the row's coverage, it agrees \
         when F(d) rounds to 1 %",
        100.0 * lo,
        100.0 * hi,
        1.0 / hi,
        1.0 / lo
    );
    for (i, (row, printed)) in RANGE_TABLE.iter().zip(PRINTED_RANGE_ROWS).enumerate() {
        let a = Attenuation::from_f32(&row.attenuation);
        let d = row.range as f64;
        let left = a.at(d);
        let fr_line = 970 + i as u32;
        // The Ukrainian table has a blank line before its last row.
        let uk_line = if i == 11 { 1467 } else { 1455 + i as u32 };
        out.push(
            cited(&format!("range-{}", row.range), &[(0, fr_line, fr_line), (3, uk_line, uk_line)])
                .says(&format!("light left at the covered distance {}", row.range), &printed.replace(' ', " | "))
                .holds(
                    (0.005..0.015).contains(&left),
                    format!("F({}) = {:.4} = 1/{:.0}", row.range, left, 1.0 / left),
                    &range_note,
                ),
        );
    }
    let same = parsed.iter().zip(RANGE_TABLE.iter()).all(|(p, r)| {
        p.len() == 4
            && p[0] == r.range as f64
            && p[1] == r.attenuation.constant as f64
            // f32 storage: half an ulp is 6e-8 relative.
            && (p[2] - r.attenuation.linear as f64).abs() <= 1e-7 * p[2]
            && (p[3] - r.attenuation.quadratic as f64).abs() <= 1e-7 * p[3]
    });
    out.push(
        cited("range-table-printed", places)
            .says(
                "the 12 rows, the same in both texts and in casters::RANGE_TABLE",
                "7 | 1.0 | 0.7 | 1.8 … 3250 | 1.0 | 0.0014 | 0.000007",
            )
            .holds(
                same,
                format!("{} rows parsed, equal to RANGE_TABLE", parsed.len()),
                "the Ukrainian prints the last row outside the bold table (l.1467)",
            ),
    );
    out.push(
        cited("range-constant-1", &[(0, 983, 983), (3, 1470, 1476)])
            .says("Kc = 1.0 in every row", "Le terme constant est fixé à 1.0 dans tous les cas")
            .holds(RANGE_TABLE.iter().all(|r| r.attenuation.constant == 1.0), "12 of 12 rows".into(), ""),
    );
    let decreasing = RANGE_TABLE.windows(2).all(|w| {
        w[1].attenuation.linear < w[0].attenuation.linear && w[1].attenuation.quadratic < w[0].attenuation.quadratic
    });
    out.push(
        cited("range-coefficients-shrink", &[(0, 983, 983), (3, 1482, 1488)])
            .says(
                "longer ranges take smaller Kl and Kq",
                "Le terme linéaire K_l est assez petit pour couvrir de grandes distances",
            )
            .holds(decreasing, "Kl and Kq strictly decrease down the table".into(), ""),
    );
    let kq_smaller_far =
        RANGE_TABLE.iter().filter(|r| r.range >= 20.0).all(|r| r.attenuation.quadratic < r.attenuation.linear);
    let exceptions: Vec<String> = RANGE_TABLE
        .iter()
        .filter(|r| r.attenuation.quadratic >= r.attenuation.linear)
        .map(|r| format!("{}", r.range))
        .collect();
    out.push(
        cited("range-quadratic-smaller", &[(0, 983, 983), (3, 1482, 1488)])
            .says(
                "for large distances the quadratic coefficient is even smaller than the linear one",
                "et le terme quadratique est encore plus faible",
            )
            .holds(
                kq_smaller_far,
                format!("Kq < Kl from distance 20 on; not at {}", exceptions.join(" and ")),
                "the sentence speaks of lights that cover large distances",
            ),
    );
    out
}
