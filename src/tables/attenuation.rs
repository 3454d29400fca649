//! Chapter 5, Light casters: attenuation for each row of the range table.
//!
//! Source: LearnOpenGL, Light casters, "Choosing the right values" (the Ogre3D
//! wiki's table); opengl-tutorial 8 for `LightPower / d²`.

use crate::casters::{inverse_square_falloff, Attenuation, RANGE_TABLE};
use crate::table::{constant, num32, Table};

/// opengl-tutorial 8's `LightPower`.
pub const TUTORIAL_POWER: f32 = 50.0;

/// The chapter's tables: the range rows, then a distance sweep.
pub fn tables() -> Vec<Table> {
    tables_for(None)
}

/// The range table's cells that every row has: `Kc`, `Kl`, `Kq` as written, then
/// `F(1)`, `F(5)`, `F(10)` with 4 decimals.
fn coefficient_cells(a: &Attenuation) -> [String; 6] {
    [
        constant(a.constant),
        constant(a.linear),
        constant(a.quadratic),
        num32(a.at(1.0), 4),
        num32(a.at(5.0), 4),
        num32(a.at(10.0), 4),
    ]
}

/// The distances where `F` falls to 5/256 and to 1/256.
fn distance_cells(a: &Attenuation) -> [String; 2] {
    [distance_cell(a.distance_for(5.0 / 256.0)), distance_cell(a.distance_for(1.0 / 256.0))]
}

/// The same tables, with `yours` (your own constant, linear and quadratic
/// terms) as a last range row and a last sweep column.
pub fn tables_for(yours: Option<Attenuation>) -> Vec<Table> {
    let mut range = range_table();
    if let Some(a) = yours {
        let mut row = vec!["yours".to_string()];
        row.extend(coefficient_cells(&a));
        row.extend(["—".to_string(), "—".to_string()]);
        row.extend(distance_cells(&a));
        row.push("—".to_string());
        range.push(row);
    }
    let mut sweep = sweep_table();
    if let Some(a) = yours {
        sweep.note.push_str(&format!(
            " Last column: yours, F(d) = 1/({} + {}·d + {}·d²).",
            constant(a.constant),
            constant(a.linear),
            constant(a.quadratic)
        ));
        sweep.headers.push("F yours".to_string());
        for row in &mut sweep.rows {
            let d: f32 = row[0].parse().unwrap_or(f32::NAN);
            row.push(num32(a.at(d), 4));
        }
    }
    vec![range, sweep]
}

fn distance_cell(d: Option<f32>) -> String {
    d.map_or("—".to_string(), |d| num32(d, 2))
}

fn range_table() -> Table {
    let mut t = Table::new(
        "Attenuation 1/(Kc + Kl·d + Kq·d²) for each range row",
        "F(d) at d = 1, 5, 10, range/2 and range (distances in world units). F(range) shows each row's \
         design rule: about 1/80 at its range. d(5/256), d(1/256): where F falls to what an 8-bit channel shows as 5 and 1 step. Last column: \
         opengl-tutorial 8's LightPower/d² with power 50 at the same range, for comparison.",
        &[
            "range", "Kc", "Kl", "Kq", "F(1)", "F(5)", "F(10)", "F(range/2)", "F(range)", "d(5/256)", "d(1/256)",
            "50/range²",
        ],
    );
    for row in &RANGE_TABLE {
        let a = row.attenuation;
        let mut cells = vec![format!("{}", row.range)];
        cells.extend(coefficient_cells(&a));
        cells.extend([num32(a.at(row.range / 2.0), 4), num32(a.at(row.range), 5)]);
        cells.extend(distance_cells(&a));
        cells.push(num32(inverse_square_falloff(TUTORIAL_POWER, row.range), 6));
        t.push(cells);
    }
    t
}

fn sweep_table() -> Table {
    let rows: [(f32, Attenuation); 3] =
        [(7.0, RANGE_TABLE[0].attenuation), (50.0, RANGE_TABLE[4].attenuation), (3250.0, RANGE_TABLE[11].attenuation)];
    let mut t = Table::new(
        "Attenuation against inverse-square by distance",
        format!(
            "LearnOpenGL's F(d) for three range rows beside opengl-tutorial 8's LightPower/d² (power 50) and the \
             bare 1/d². The polynomial starts at 1/Kc = 1 and stays finite at d = 0; power/d² exceeds 1 closer \
             than √50 = {} and is infinite at the light.",
            num32(TUTORIAL_POWER.sqrt(), 2)
        ),
        &["d", "F range 7", "F range 50", "F range 3250", "50/d²", "1/d²"],
    );
    for d in [0.0f32, 0.5, 1.0, 2.0, 3.0, 5.0, 7.0, 10.0, 20.0, 50.0, 100.0] {
        let mut row = vec![format!("{d}")];
        row.extend(rows.iter().map(|(_, a)| num32(a.at(d), 4)));
        row.push(num32(inverse_square_falloff(TUTORIAL_POWER, d), 4));
        row.push(num32(inverse_square_falloff(1.0, d), 4));
        t.push(row);
    }
    t
}
