//! The speed-against-accuracy harness in quick mode: structure and invariants of
//! the measured errors (never timings: those belong to benchmarks).

use lightlab::figures::book_data::BookData;
use std::sync::OnceLock;

use lightlab::study::speed::{
    self, dominates, from_csv, pareto, rsqrt_newton, run_study, to_csv, Machine, PowMethod, Row, StudyOptions,
};

/// One quick run shared by every test (the study is deterministic except for timings).
fn rows() -> &'static Vec<Row> {
    static ROWS: OnceLock<Vec<Row>> = OnceLock::new();
    ROWS.get_or_init(|| run_study(&StudyOptions::quick(), &mut |_| {}))
}

fn row(scene: &str, method: &str) -> &'static Row {
    rows()
        .iter()
        .find(|r| r.scene == scene && r.method == method)
        .unwrap_or_else(|| panic!("no row {scene} / {method}"))
}

#[test]
fn every_scene_has_rows_with_sane_numbers() {
    for scene in speed::SCENES {
        let n = rows().iter().filter(|r| r.scene == scene).count();
        assert!(n >= 3, "{scene}: {n} rows");
    }
    for r in rows() {
        assert!(r.fragments > 0, "{}: no fragments", r.method);
        assert!(r.error.pixels > 0, "{}: no pixels compared", r.method);
        let t = r.timing;
        assert!(t.ms_min > 0.0 && t.ms_min <= t.ms_median && t.ms_median <= t.ms_max, "{}: {t:?}", r.method);
        let e = r.error;
        assert!(e.mean_levels >= 0.0 && e.mean_levels <= e.max_levels, "{}: {e:?}", r.method);
        assert!((0.0..=1.0).contains(&e.over_one), "{}: {e:?}", r.method);
        assert!(e.flip.is_finite() && e.flip >= 0.0, "{}: {e:?}", r.method);
    }
}

#[test]
fn phong_and_gouraud_error_fall_with_tessellation() {
    for prefix in ["Phong", "Gouraud"] {
        let errs: Vec<f64> = StudyOptions::quick()
            .tessellations
            .iter()
            .map(|s| row(speed::SPHERE, &format!("{prefix} {s}×{}", 2 * s)).error.mean_levels)
            .collect();
        for w in errs.windows(2) {
            assert!(w[1] < w[0], "{prefix}: mean error rose with tessellation: {errs:?}");
        }
    }
}

#[test]
fn phong_beats_gouraud_at_every_tessellation() {
    for s in StudyOptions::quick().tessellations {
        let size = format!("{s}×{}", 2 * s);
        let (p, g) = (row(speed::SPHERE, &format!("Phong {size}")), row(speed::SPHERE, &format!("Gouraud {size}")));
        assert!(p.error.mean_levels < g.error.mean_levels, "{size}: Phong {:?} Gouraud {:?}", p.error, g.error);
    }
}

#[test]
fn f64_is_at_least_as_accurate_as_f32() {
    let f64_row = row(speed::GBUFFER, "f64 shading");
    let f32_row = row(speed::GBUFFER, "powf (scalar f32)");
    assert!(f64_row.error.max_levels <= f32_row.error.max_levels, "{:?} vs {:?}", f64_row.error, f32_row.error);
    assert!(f64_row.error.mean_levels <= f32_row.error.mean_levels);
}

#[test]
fn a_bigger_table_is_more_accurate() {
    let (small, big) = (row(speed::GBUFFER, "LUT 256"), row(speed::GBUFFER, "LUT 1024"));
    assert!(small.error.max_levels >= big.error.max_levels, "{:?} vs {:?}", small.error, big.error);
    assert!(small.error.mean_levels >= big.error.mean_levels);
}

#[test]
fn exact_inputs_leave_only_rounding_for_exact_methods() {
    // exact-input shading in f32 (powf, exact normalize) differs from the f64 reference
    // by rounding only: far below one 8-bit level (measured ~0.002 levels; 0.05 leaves room
    // for other builds' fused multiply-adds)
    for m in ["powf (scalar f32)", "Scene::shade (scalar core)", "16-lane kernel, Phong", "f64 shading"] {
        let e = row(speed::GBUFFER, m).error;
        assert!(e.max_levels < 0.05, "{m}: {e:?}");
    }
    // Schlick's rational is a different curve: many levels off on this highlight
    assert!(row(speed::GBUFFER, "Schlick x/(n−nx+x)").error.max_levels > 5.0);
}

#[test]
fn culling_changes_no_pixel_by_more_than_half_a_level() {
    // culling::threshold_for keeps the total skipped light within half a level
    // (plus the scene's f32 rounding against the reference, < 0.05 levels as above)
    let (off, on) = (row(speed::FLOOR, "culling off (scalar)"), row(speed::FLOOR, "culling on (scalar)"));
    assert!(on.error.max_levels <= off.error.max_levels + 0.5 + 0.05, "{:?} vs {:?}", on.error, off.error);
}

#[test]
fn pareto_front_is_non_dominated_and_dominates_the_rest() {
    let all = rows();
    let front = pareto(all);
    for (r, on) in all.iter().zip(&front) {
        let dominated = all.iter().any(|q| dominates(q, r));
        assert_eq!(*on, !dominated, "{}", r.method);
    }
    for scene in speed::SCENES {
        assert!(all.iter().zip(&front).any(|(r, f)| *f && r.scene == scene), "{scene}: empty front");
        // the cheapest row of a scene is always on its front
        let cheapest = all
            .iter()
            .zip(&front)
            .filter(|(r, _)| r.scene == scene)
            .min_by(|a, b| a.0.timing.ms_median.total_cmp(&b.0.timing.ms_median))
            .unwrap();
        assert!(*cheapest.1, "{scene}: cheapest {} not on the front", cheapest.0.method);
    }
}

#[test]
fn csv_round_trips() {
    let machine = Machine { cpu: "Test CPU, 2 GHz".into(), cores: 2, isa: "Avx2".into(), frame: "160×120".into() };
    let text = to_csv(&machine, rows()).unwrap();
    let (m2, rows2) = from_csv(&text).unwrap();
    assert_eq!(m2, machine);
    assert_eq!(rows2.len(), rows().len());
    // ns/fragment is derived (recomputed from the rounded median on writing), so the
    // fixed point is reached after one round trip: parsing again gives the same rows
    assert_eq!(from_csv(&to_csv(&m2, &rows2).unwrap()).unwrap().1, rows2, "parse and write are not a fixed point");
    for (a, b) in rows().iter().zip(&rows2) {
        assert_eq!((&a.scene, &a.group, &a.method, a.fragments), (&b.scene, &b.group, &b.method, b.fragments));
        // 5 significant digits in the file
        assert!((a.error.mean_levels - b.error.mean_levels).abs() <= 1e-4 * a.error.mean_levels.max(1e-30));
    }
}

#[test]
fn bad_csv_is_an_error_naming_the_line() {
    assert!(from_csv("").unwrap_err().to_string().contains("header"));
    let e = from_csv(&format!("{}\na,b,c\n", speed::CSV_HEADER)).unwrap_err().to_string();
    assert!(e.contains("line 2"), "{e}");
    let bad_num = format!("{}\ns,g,m,1,x,1,1,1,1,1,1,1,1\n", speed::CSV_HEADER);
    assert!(from_csv(&bad_num).unwrap_err().to_string().contains("field 5"));
    // Line numbers count the machine's `#` lines.
    let e = from_csv(&format!("# cpu: x\n# cores: 2\n{}\ns,g,m\n", speed::CSV_HEADER)).unwrap_err().to_string();
    assert!(e.contains("line 4"), "{e}");
    let e = from_csv("# cores: two\n").unwrap_err().to_string();
    assert!(e.contains("line 1") && e.contains("two"), "{e}");
}

#[test]
fn committed_csvs_parse_and_cover_the_methods() {
    for scene in speed::SCENES {
        let (m, rows) = lightlab::figures::study_charts::scene_data(&BookData::in_repository(), scene).unwrap();
        assert!(!m.cpu.is_empty() && m.cores > 0, "{scene}: {m:?}");
        assert!(rows.iter().all(|r| r.scene == scene));
        let quick: Vec<&str> = self::rows().iter().filter(|r| r.scene == scene).map(|r| r.group.as_str()).collect();
        for g in quick {
            assert!(rows.iter().any(|r| r.group == g), "{scene}: committed CSV lacks group {g}");
        }
    }
}

#[test]
fn pow_approximations_agree_where_they_should() {
    let s = 32.0;
    for x in [0.0f32, 0.25, 0.5, 0.9, 0.99, 1.0] {
        let exact = x.powf(s);
        // a table interpolates exactly at its entries and at the ends
        let lut = PowMethod::lut(1024, s).eval(x, s);
        assert!((lut - exact).abs() < 2e-3, "LUT at {x}: {lut} vs {exact}");
        // Schlick meets x^s at 0 and 1 only
        let schlick = PowMethod::Schlick.eval(x, s);
        if x == 0.0 || x == 1.0 {
            assert_eq!(schlick, exact);
        }
    }
    assert_eq!(PowMethod::Powf.eval(-0.5, 2.0), 0.0, "a negative base is clamped, not squared");
    assert_eq!(PowMethod::lut(1, s).eval(2.0, s), 1.0, "a degenerate table still answers");
    // rsqrt + one Newton step: relative error below 2e-3 (Lomont 2003 reports 1.75e-3)
    for x in [1e-6f32, 0.3, 1.0, 2.0, 1e6] {
        let rel = (rsqrt_newton(x) * x.sqrt() - 1.0).abs();
        assert!(rel < 2e-3, "x = {x}: {rel}");
    }
    assert_eq!(rsqrt_newton(0.0), 0.0);
    assert_eq!(rsqrt_newton(f32::NAN), 0.0);
}
