//! Chapter 1, Colors: coral under white, green, olive and other lights.
//!
//! Run: `cargo run --example colors [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::colors::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{colors, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("colors: {message}");
            std::process::exit(2);
        }
    };
    let tables = colors::tables();
    print!("{}", render(&tables, format));
}
