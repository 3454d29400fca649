//! Chapter 4, Lighting maps: sampled maps, nearest against bilinear.
//!
//! Run: `cargo run --release --example lighting_maps [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::lighting_maps::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{lighting_maps, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("lighting_maps: {message}");
            std::process::exit(2);
        }
    };
    let tables = lighting_maps::tables();
    print!("{}", render(&tables, format));
}
