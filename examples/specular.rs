//! Specular lobes: pow(cos α, s), Phong against Blinn-Phong, matching exponents, half-widths.
//!
//! Run: `cargo run --release --example specular [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::specular::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{render, specular, Format};

fn main() {
    // ANCHOR: main
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("specular: {message}");
            std::process::exit(2);
        }
    };
    let tables = specular::tables();
    print!("{}", render(&tables, format));
    // ANCHOR_END: main
}
