//! Chapter 5, Light casters: attenuation for the 12 range rows, against power/d².
//!
//! Run: `cargo run --release --example attenuation [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::attenuation::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{attenuation, render, Format};

fn main() {
    // ANCHOR: main
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("attenuation: {message}");
            std::process::exit(2);
        }
    };
    let tables = attenuation::tables();
    print!("{}", render(&tables, format));
    // ANCHOR_END: main
}
