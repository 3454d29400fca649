//! The oracle table the book shows (`book/data/oracle.md`) is the output of
//! `lightlab oracle --format markdown` on this machine: rerun it and compare.
//!
//! The report is deterministic (fixed seed, one llvmpipe), so any difference means
//! a formula, a shader or a bound changed. Regenerate with
//! `cargo run --release -- oracle --format markdown > book/data/oracle.md`.
#![cfg(feature = "gl")]

use crate::gl_common;

use lightlab::oracle::report_markdown;

#[test]
fn book_oracle_table_is_the_current_output() {
    let Some(_ctx) = gl_common::context_or_skip() else { return };
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/book/data/oracle.md");
    let committed = std::fs::read_to_string(path).expect("book/data/oracle.md is committed");
    let fresh = report_markdown(100_000).expect("the oracle runs where a context exists");
    let first_line = |s: &str| s.lines().next().unwrap_or("").to_string();
    // The first line names the renderer and Mesa version; another llvmpipe build may
    // round differently, so the numbers are only compared on the one that made them.
    if first_line(&fresh) != first_line(&committed) {
        println!(
            "skipped: book/data/oracle.md was made on {:?}, this is {:?}",
            first_line(&committed),
            first_line(&fresh)
        );
        return;
    }
    assert!(
        fresh == committed,
        "book/data/oracle.md differs from a fresh run; regenerate it with \
         `cargo run --release -- oracle --format markdown > book/data/oracle.md`"
    );
}
