//! Chapter 2, Basic lighting: ambient, diffuse and specular at sample fragments.
//!
//! Run: `cargo run --example basic_lighting [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::basic_lighting::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{basic_lighting, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("basic_lighting: {message}");
            std::process::exit(2);
        }
    };
    let tables = basic_lighting::tables();
    print!("{}", render(&tables, format));
}
