//! Every worked table: an insta snapshot of its text rendering, the same cells
//! in every format, the examples' output, and the key numbers asserted.

use lightlab::table::{render, Format, Table};
use lightlab::tables;

fn chapters() -> Vec<(&'static str, Vec<Table>)> {
    tables::chapters().into_iter().map(|(name, f)| (name, f())).collect()
}

#[test]
fn chapter_list_matches_the_examples() {
    let names: Vec<_> = tables::chapters().into_iter().map(|(name, _)| name).collect();
    for name in &names {
        let path = format!("{}/examples/{name}.rs", env!("CARGO_MANIFEST_DIR"));
        let source = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        // `tables_for(..)` takes the chapter's numbers from the command line; `tables()` is it with the chapter's values
        let prints = source.contains(&format!("{name}::tables()")) || source.contains(&format!("{name}::tables_for("));
        assert!(prints, "{path} does not print {name}::tables() or {name}::tables_for(..)");
    }
    assert_eq!(names.len(), 11);
}

#[test]
fn every_table_matches_its_snapshot() {
    for (chapter, tables) in chapters() {
        for (i, table) in tables.iter().enumerate() {
            insta::assert_snapshot!(format!("{chapter}_{i}"), table.to_text());
        }
    }
}

#[test]
fn every_table_is_well_formed_and_deterministic() {
    for (chapter, tables) in chapters() {
        assert!(!tables.is_empty(), "{chapter}: no tables");
        for t in &tables {
            assert!(!t.rows.is_empty(), "{chapter}: table {:?} has no rows", t.title);
            for row in &t.rows {
                assert_eq!(row.len(), t.headers.len(), "{chapter}: {:?} row {row:?}", t.title);
                for cell in row {
                    assert!(!cell.contains("NaN"), "{chapter}: {:?} has a NaN cell in {row:?}", t.title);
                    assert!(
                        !cell.starts_with("-0.0") || !cell.trim_start_matches(['-', '0', '.']).is_empty(),
                        "{cell}"
                    );
                }
            }
            // Markdown: title, note, header, rule, one line per row.
            let md = t.to_markdown();
            assert_eq!(md.lines().filter(|l| l.starts_with('|')).count(), t.rows.len() + 2, "{chapter}: {md}");
            // CSV: title comment, header, one line per row (no cell has a newline).
            assert_eq!(t.to_csv().lines().count(), t.rows.len() + 2, "{chapter}: {:?}", t.title);
        }
        let again: Vec<_> = chapters().into_iter().find(|(c, _)| *c == chapter).map(|(_, t)| t).unwrap_or_default();
        assert_eq!(render(&tables, Format::Text), render(&again, Format::Text), "{chapter}: not deterministic");
    }
}

/// The example binaries print exactly the library's rendering. `cargo test`
/// builds the examples next to the test binary; `cargo test --test suite tables::`
/// alone does not (they may be missing or stale), and then this test says so
/// and skips them. An example older than the newest build of the library
/// (`target/<profile>/deps/liblightlab-*.rlib`) counts as stale.
#[test]
fn examples_print_the_library_tables() {
    let Some(dir) = std::env::current_exe().ok().and_then(|p| Some(p.parent()?.parent()?.join("examples"))) else {
        return;
    };
    let modified = |p: &std::path::Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    let library = dir.parent().and_then(|d| std::fs::read_dir(d.join("deps")).ok()).and_then(|entries| {
        entries
            .filter_map(Result::ok)
            .map(|e| e.path())
            .filter(|p| {
                p.file_name()
                    .and_then(|n| n.to_str())
                    .is_some_and(|n| n.starts_with("liblightlab-") && n.ends_with(".rlib"))
            })
            .filter_map(|p| modified(&p))
            .max()
    });
    let mut ran = 0;
    for (chapter, tables) in chapters() {
        let exe = dir.join(format!("{chapter}{}", std::env::consts::EXE_SUFFIX));
        let fresh = match (modified(&exe), library) {
            (Some(example), Some(library)) => example >= library,
            _ => false,
        };
        if !fresh {
            eprintln!("example {} missing or stale; run `cargo test` (all targets) to check it", exe.display());
            continue;
        }
        for (flag, format) in [("text", Format::Text), ("markdown", Format::Markdown), ("csv", Format::Csv)] {
            let out = std::process::Command::new(&exe).args(["--format", flag]).output().expect("example runs");
            assert!(out.status.success(), "{chapter} --format {flag}: {}", String::from_utf8_lossy(&out.stderr));
            assert_eq!(String::from_utf8_lossy(&out.stdout), render(&tables, format), "{chapter} --format {flag}");
        }
        let bad = std::process::Command::new(&exe).args(["--format", "pdf"]).output().expect("example runs");
        assert_eq!(bad.status.code(), Some(2), "{chapter}: a bad --format is a usage error");
        ran += 1;
    }
    eprintln!("checked {ran} example binaries");
}

fn cell(t: &Table, row: usize, header: &str) -> f64 {
    let col = t.headers.iter().position(|h| h == header).unwrap_or_else(|| panic!("no column {header:?}"));
    t.rows[row][col].parse().unwrap_or_else(|_| panic!("{:?} row {row} {header:?} = {:?}", t.title, t.rows[row][col]))
}

/// Research notes §1.1.b: I from the exact cosines of the printed degrees
/// (f64): 0.5378114857, 0.9137894934, 1.7341792660, 0.1134237166,
/// −2.0235549494, 0.5407168192. Tolerance 1e-4: the f32 cosines carry
/// ~6e-8 absolute error, divided by ε ≥ 0.0226 that is ≤ 3e-6; 1e-4 is the
/// table's printed precision.
#[test]
fn spotlight_recomputed_intensities() {
    let expected = [0.5378114857, 0.9137894934, 1.7341792660, 0.1134237166, -2.0235549494, 0.5407168192];
    for (row, want) in tables::spotlight::WORKED_TABLE.iter().zip(expected) {
        let got = f64::from(row.recomputed().intensity);
        assert!((got - want).abs() < 1e-4, "expected {want}, got {got}, diff {}", got - want);
    }
    let t = &tables::spotlight::tables()[0];
    assert_eq!(t.rows[5][tables_col(t, "φ pub")], "0.9978");
    assert_eq!(t.rows[5][tables_col(t, "φ rec")], "0.9763");
    assert_eq!(t.rows[5][tables_col(t, "I rec")], "0.5407");
    assert_eq!(t.rows[5][tables_col(t, "I pub")], "0.29");
    // The slip: 0.9978 is cos(12.5 rad), printed to 4 decimals.
    assert_eq!(format!("{:.4}", 12.5f64.cos()), "0.9978");
}

fn tables_col(t: &Table, header: &str) -> usize {
    t.headers.iter().position(|h| h == header).unwrap_or_else(|| panic!("no column {header:?}"))
}

#[test]
fn spotlight_hard_edge_and_soft_edges() {
    let t = &tables::spotlight::tables()[2];
    let row = |angle: &str| t.rows.iter().position(|r| r[0] == angle).expect(angle);
    // Strict `>`: at exactly the cut-off angle the hard spot is off.
    assert_eq!(cell(t, row("12.5"), "hard 12.5°"), 0.0);
    assert_eq!(cell(t, row("12"), "hard 12.5°"), 1.0);
    // Soft 12.5/17.5 at 15° is the worked table's row 6 (0.5407); 12.5/15 is 0 there.
    assert_eq!(cell(t, row("15"), "soft 12.5°/17.5°"), 0.5407);
    assert_eq!(cell(t, row("15"), "soft 12.5°/15°"), 0.0);
}

/// Research notes §1.1.a: F at the row's own range, f64. Tolerance 1e-5:
/// the cell is printed with 5 decimals.
#[test]
fn attenuation_at_range() {
    let t = &tables::attenuation::tables()[0];
    let expected = [
        0.0106269926,
        0.0125140783,
        0.0117096019,
        0.0129600829,
        0.0116959064,
        0.0129240711,
        0.0124223602,
        0.0129870130,
        0.0122850123,
        0.0125805944,
        0.0129533679,
        0.0125805944,
    ];
    for (i, want) in expected.iter().enumerate() {
        let got = cell(t, i, "F(range)");
        assert!((got - want).abs() <= 0.5e-5 + 1e-9, "row {i}: expected {want}, got {got}");
    }
    // Range 50 row at d = 1, 5, 10 (§1.1.a: 0.8912655971, 0.4444444444, 0.1960784314), 4 decimals.
    assert_eq!((cell(t, 4, "F(1)"), cell(t, 4, "F(5)"), cell(t, 4, "F(10)")), (0.8913, 0.4444, 0.1961));
}

#[test]
fn colors_olive_published_and_exact() {
    let t = &tables::colors::tables()[0];
    let olive = t.rows.iter().find(|r| r[0] == "olive").expect("olive row");
    assert_eq!(olive[2], "(0.33, 0.21, 0.06)");
    assert_eq!(olive[3], "(0.3300, 0.2100, 0.0558)");
}

#[test]
fn specular_matching_exponent_tends_to_four() {
    let t = &tables::specular::tables()[2];
    let ratios: Vec<f64> = (0..t.rows.len()).map(|i| cell(t, i, "ratio")).collect();
    assert!(ratios.windows(2).all(|w| w[1] < w[0]), "ratio not decreasing: {ratios:?}");
    // s = 256: 4.003 printed; the limit is 4 from above.
    assert!(ratios[ratios.len() - 1] > 4.0 && ratios[ratios.len() - 1] < 4.01, "{ratios:?}");
    // Half-width of s = 32: acos(2^(-1/32)) = 11.88° (f64: 11.8840°), 2 decimals.
    assert_eq!(cell(t, 4, "Phong half-width (deg)"), 11.88);
}

/// Scale (1, 0.2, 1) and n = (1,1,0)/√2: M n ∝ (1, 0.2, 0) and M^(−T) n ∝ (1, 5, 0),
/// angle = atan(5) − atan(0.2) = 67.380°, printed with 3 decimals.
#[test]
fn normal_matrix_errors() {
    let t = &tables::normal_matrix::tables()[0];
    let row = t.rows.iter().position(|r| r[0] == "scale (1, 0.2, 1)").expect("row");
    let want = (5f64.atan() - 0.2f64.atan()).to_degrees();
    assert!((cell(t, row, "error n=(1,1,0)/√2 (deg)") - want).abs() < 1e-3, "{want}");
    assert_eq!(cell(t, 0, "error n=(1,1,1)/√3 (deg)"), 0.0, "rotation: no error");
    let cof = &tables::normal_matrix::tables()[1];
    let singular = cof.rows.iter().find(|r| r[0].contains("singular")).expect("singular row");
    assert_eq!(singular[2], "singular");
    assert_eq!(singular[3], "(0.0000, 0.0000, 1.0000)");
}

#[test]
fn materials_table_has_all_24_rows() {
    let t = tables::materials::tables();
    assert_eq!(t[0].rows.len(), 24);
    assert_eq!(t[1].rows.len(), 24);
    assert_eq!(t[0].rows[0][0], "emerald");
    assert_eq!(cell(&t[0], 0, "× 128"), 76.8);
}

#[test]
fn multiple_lights_has_default_and_four_atmospheres() {
    let t = tables::multiple_lights::tables();
    assert_eq!(t.len(), 5);
    for (table, name) in t.iter().skip(1).zip(["desert", "factory", "horror", "biochemical-lab"]) {
        assert!(table.title.contains(name), "{}", table.title);
    }
    // 4 fragments × (dir + 4 points + spot + sum + clamped).
    assert_eq!(t[0].rows.len(), 4 * 8);
}

#[test]
fn errata_discrepancies_come_first() {
    let entries = lightlab::errata::discrepancies_first();
    assert_eq!(entries.len(), lightlab::errata::entries().len());
    let first_agreeing = entries.iter().position(|e| e.agrees).unwrap_or(entries.len());
    assert!(entries[first_agreeing..].iter().all(|e| e.agrees), "a discrepancy after an agreeing entry");
    assert!(first_agreeing > 0, "no discrepancy listed");
    // The full table comes after the coverage and the French/Ukrainian tables.
    let t = &tables::errata::tables()[2];
    assert_eq!(t.rows.len(), entries.len());
    assert_eq!(t.rows[0][5], "DISCREPANCY");
}

#[test]
fn lighting_maps_filters_differ_on_an_edge() {
    let t = &tables::lighting_maps::tables()[0];
    let edge: Vec<_> = t.rows.iter().filter(|r| r[0] == "frame/wood edge").collect();
    assert_eq!(edge.len(), 2);
    assert_ne!(edge[0][4], edge[1][4], "nearest and bilinear should differ on the frame/wood edge");
}
