//! Chapter 3, Materials: the 24 classic materials and their shaded color.
//!
//! Run: `cargo run --release --example materials [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::materials::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{materials, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("materials: {message}");
            std::process::exit(2);
        }
    };
    let tables = materials::tables();
    print!("{}", render(&tables, format));
}
