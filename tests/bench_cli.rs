//! `lightlab bench` refuses counts outside its documented limits (usage error, exit 2) before
//! allocating or timing anything.
#![cfg(feature = "book")]

use std::process::Command;

fn bench(args: &[&str]) -> (Option<i32>, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab")).arg("bench").args(args).output().expect("run lightlab");
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[test]
fn huge_or_zero_counts_are_usage_errors() {
    for (flag, value) in
        [("--runs", "18446744073709551615"), ("--runs", "0"), ("--frames", "100001"), ("--frames", "0")]
    {
        let (code, stderr) = bench(&["quad-single", flag, value]);
        assert_eq!(code, Some(2), "{flag} {value}: exit code; stderr: {stderr}");
        assert!(stderr.contains(flag), "{flag} {value}: the error names the flag; stderr: {stderr}");
    }
}

#[test]
fn csv_without_roofline_or_scaling_is_a_usage_error() {
    let (code, stderr) = bench(&["quad-single", "--csv", "/nonexistent/x.csv"]);
    assert_eq!(code, Some(2), "stderr: {stderr}");
    assert!(stderr.contains("--csv"), "the error names the flag; stderr: {stderr}");
}

#[test]
fn roofline_writes_a_csv_that_reads_back_with_one_row_per_scene() {
    let dir = crate::common::temp_dir("roofline", "csv");
    let csv = dir.join("roofline.csv");
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .args(["bench", "--roofline", "quad-single", "floor-lights256", "--runs", "1", "--frames", "1", "--csv"])
        .arg(&csv)
        .output()
        .expect("run lightlab");
    assert_eq!(out.status.code(), Some(0), "stderr: {}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.matches("bound=").count(), 2, "one roofline line per scene: {stdout}");
    let text = std::fs::read_to_string(&csv).expect("the CSV was written");
    let rows: Vec<lightlab::study::bench::roofline::RooflineRow> =
        lightlab::study::bench::roofline::from_csv(&text).expect("it parses");
    let scenes: Vec<&str> = rows.iter().map(|r| r.scene.as_str()).collect();
    assert_eq!(scenes, ["quad-single", "floor-lights256"]);
    for r in &rows {
        assert!(r.peak_gflops > 0.0 && r.store_gbs > 0.0 && r.ms > 0.0, "{r:?}");
        assert!(r.flops > 0.0 && r.bytes > 0.0, "{r:?}");
    }
    // 256 lights per fragment against one: the floor does far more work per fragment
    // (about 78 operations a light against quad-single's 154 for its light and
    // interpolation, so about 130 times); 50 leaves the per-fragment terms counted once
    // room, and any count that dropped the lights would fall far below it
    let per_fragment = |r: &lightlab::study::bench::roofline::RooflineRow| r.flops / r.fragments as f64;
    assert!(per_fragment(&rows[1]) > 50.0 * per_fragment(&rows[0]), "{rows:?}");
    // and so more operations per framebuffer byte
    assert!(rows[1].intensity() > rows[0].intensity(), "{rows:?}");
}
