//! Every checkable claim of the tutorials with its check, errata first; the coverage of
//! each text; the places where the French and Ukrainian texts differ.
//!
//! Source: [`crate::errata`].

use crate::errata::{coverage, discrepancies_first, french_ukrainian_pairs, seed_name};
use crate::table::Table;

/// The errata tables: coverage per text, French vs Ukrainian, then the full table (errata first).
pub fn tables() -> Vec<Table> {
    let mut t = Table::new(
        "Printed claims, checked",
        "Every checkable claim of the four texts: numbers recomputed by lightlab (f32 core or f64 reference, 6 \
         decimals), statements, counts, formulas as typeset and listings. Errata first: DISCREPANCY (a wrong \
         number), then text (a wrong statement, formula or listing), then rounding (equal at the printed \
         precision, or to what the text's own rounded inputs give), then agrees. The source gives the seed, its \
         lines, and the tutorial's chapter and section; published is the printed excerpt.",
        &["id", "source", "quantity", "published", "recomputed", "verdict", "cause / note"],
    );
    for e in discrepancies_first() {
        t.push(vec![
            e.id.clone(),
            e.source.clone(),
            e.quantity.clone(),
            e.published.replace('\n', " "),
            e.recomputed.cell(),
            e.verdict.label().to_string(),
            e.note.clone(),
        ]);
    }
    let mut c = Table::new(
        "Coverage per text",
        "Claims found in each text and their verdicts; a claim printed in several texts counts in each.",
        &["text", "claims", "agrees", "rounding", "DISCREPANCY", "text errors"],
    );
    for k in coverage() {
        c.push(vec![
            seed_name(k.seed).to_string(),
            k.claims.to_string(),
            k.agrees.to_string(),
            k.rounding.to_string(),
            k.discrepancy.to_string(),
            k.text.to_string(),
        ]);
    }
    let mut d = Table::new(
        "French and Ukrainian texts side by side",
        "The claims the two LearnOpenGL texts print differently: 000 is the French translation, 003 the \
         Ukrainian lecture.",
        &["claim", "000 (French)", "verdict", "003 (Ukrainian)", "verdict"],
    );
    for (_, fr, uk) in french_ukrainian_pairs() {
        d.push(vec![
            fr.quantity.clone(),
            format!(
                "{} — {}",
                fr.cites.iter().map(|c| c.lines()).collect::<Vec<_>>().join(", "),
                fr.published.replace('\n', " ")
            ),
            fr.verdict.label().to_string(),
            format!(
                "{} — {}",
                uk.cites.iter().map(|c| c.lines()).collect::<Vec<_>>().join(", "),
                uk.published.replace('\n', " ")
            ),
            uk.verdict.label().to_string(),
        ]);
    }
    vec![c, d, t]
}
