//! Chapter 6, Multiple lights: per-light terms in the default scene and the four atmospheres.
//!
//! Run: `cargo run --release --example multiple_lights [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::multiple_lights::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{multiple_lights, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("multiple_lights: {message}");
            std::process::exit(2);
        }
    };
    let tables = multiple_lights::tables();
    print!("{}", render(&tables, format));
}
