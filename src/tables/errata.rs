//! Every printed number of the tutorials with its recomputed value, discrepancies first.
//!
//! Source: [`crate::errata::discrepancies_first`].

use super::{num, Table};
use crate::errata::discrepancies_first;

/// The errata table.
pub fn tables() -> Vec<Table> {
    let mut t = Table::new(
        "Printed numbers, recomputed",
        "Every number the seeds print with the value recomputed from its formula in f64 (6 decimals). \
         Discrepancies first, each with its cause; \"agrees\" means equal after the rounding the text uses.",
        &["id", "source", "quantity", "published", "recomputed", "verdict", "cause / note"],
    );
    for e in discrepancies_first() {
        t.push(vec![
            e.id.clone(),
            e.source.to_string(),
            e.quantity.to_string(),
            e.published.to_string(),
            num(e.recomputed, 6),
            if e.agrees { "agrees" } else { "DISCREPANCY" }.to_string(),
            e.note.to_string(),
        ]);
    }
    vec![t]
}
