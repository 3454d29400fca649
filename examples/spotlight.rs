//! Chapter 5, Light casters: the spotlight's worked table, published against recomputed.
//!
//! Run: `cargo run --release --example spotlight [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::spotlight::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{render, spotlight, Format};

fn main() {
    // ANCHOR: main
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("spotlight: {message}");
            std::process::exit(2);
        }
    };
    let tables = spotlight::tables();
    print!("{}", render(&tables, format));
    // ANCHOR_END: main
}
