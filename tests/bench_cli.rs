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
