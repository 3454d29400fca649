//! Every checkable claim the four tutorials print, checked: coverage per text, the French
//! and Ukrainian texts side by side, then the full table with the errata first.
//!
//! Run: `cargo run --example errata [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::errata::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::table::{render, Format};
use lightlab::tables::errata;

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("errata: {message}");
            std::process::exit(2);
        }
    };
    let tables = errata::tables();
    print!("{}", render(&tables, format));
}
