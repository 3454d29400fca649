//! The published-number table: the agreement rule and the errata it finds.

use lightlab::errata::{agrees_to_printed_precision, discrepancies_first, entries};

fn find(id: &str) -> lightlab::errata::Entry {
    entries().into_iter().find(|e| e.id == id).unwrap_or_else(|| panic!("no errata entry {id}"))
}

#[test]
fn agreement_is_to_printed_precision() {
    // 0.0558 rounds to 0.06 at two decimals; 0.5378 does not round to 0.56.
    assert!(agrees_to_printed_precision("0.06", 0.0558));
    assert!(!agrees_to_printed_precision("0.56", 0.5378));
    assert!(agrees_to_printed_precision("32", 32.4));
    assert!(!agrees_to_printed_precision("32", 32.6));
    assert!(!agrees_to_printed_precision("(1/d²)", 0.0));
}

#[test]
fn spot_row6_uses_cos_of_radians() {
    let phi = find("spot-row6-phi");
    assert!(!phi.agrees, "0.9978 should be flagged");
    // The printed 0.9978 is cos(12.5 rad) to four decimals: this is the cause the note names.
    assert!(agrees_to_printed_precision(phi.published, 12.5f64.cos()));
    // Recomputed in f64 here, independently of the library's f32 path. Tolerance:
    // ε = cos12.5° − cos17.5° = 0.0226 loses ~5 bits to cancellation, so the f32
    // quotient carries ~1e-5 relative error; 1e-4 absolute leaves a 10x margin.
    let c = |d: f64| d.to_radians().cos();
    let expected = (c(15.0) - c(17.5)) / (c(12.5) - c(17.5));
    let got = find("spot-row6-intensity").recomputed;
    assert!((got - expected).abs() < 1e-4, "expected {expected}, got {got}, diff {}", got - expected);
    assert!((expected - 0.5407).abs() < 1e-4);
}

#[test]
fn spot_rows_1_to_5_differ_only_by_rounding() {
    let c = |d: f64| d.to_radians().cos();
    for (row, theta_deg, printed) in
        [(1, 30.0, 0.56), (2, 26.0, 0.89), (3, 14.0, 1.67), (4, 34.0, 0.11), (5, 50.0, -2.0)]
    {
        let e = find(&format!("spot-row{row}-intensity"));
        let exact = (c(theta_deg) - c(35.0)) / (c(25.0) - c(35.0));
        // f32 cosines differ from f64 by ~1 ulp (6e-8); divided by ε = 0.087 that is < 1e-6.
        assert!((e.recomputed - exact).abs() < 1e-5, "row {row}: expected {exact}, got {}", e.recomputed);
        // The printed I is what the printed 2-decimal cosines give: (θ − 0.82) / 0.09.
        let theta_printed = find(&format!("spot-row{row}-theta")).published_value.unwrap();
        let from_printed = (theta_printed - 0.82) / 0.09;
        assert!(agrees_to_printed_precision(e.published, from_printed), "row {row}: {from_printed} vs {printed}");
        // Row 4 (0.1134 → 0.11) and row 5 (−2.024 → −2.0, one decimal) still round to the
        // printed value; rows 1–3 show the rounding error of the 2-decimal cosines.
        assert_eq!(e.agrees, row == 4 || row == 5, "row {row}: exact {exact} against printed {printed}");
    }
}

#[test]
fn olive_blue_is_rounded_not_wrong() {
    let e = find("color-olive-b");
    assert!(e.agrees);
    assert!((e.recomputed - 0.18 * 0.31).abs() < 1e-7, "f32 product 0.18*0.31 within an ulp");
}

#[test]
fn every_entry_is_finite_and_explained_and_discrepancies_come_first() {
    let all = discrepancies_first();
    assert!(all.len() >= 40);
    let first_agreeing = all.iter().position(|e| e.agrees).unwrap_or(all.len());
    assert!(all[first_agreeing..].iter().all(|e| e.agrees));
    assert!(first_agreeing >= 5, "expected the known errata to be found, got {first_agreeing}");
    for e in &all {
        assert!(e.recomputed.is_finite(), "{}: recomputed {}", e.id, e.recomputed);
        assert!(!e.note.is_empty() && !e.source.is_empty(), "{}", e.id);
    }
    let ids: std::collections::BTreeSet<_> = all.iter().map(|e| e.id.clone()).collect();
    assert_eq!(ids.len(), all.len(), "ids are unique");
}
