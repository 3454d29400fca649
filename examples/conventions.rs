//! LearnOpenGL, opengl-tutorial 8 and ogldev 19 on the same fragments, with the causes.
//!
//! Run: `cargo run --release --example conventions [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::conventions::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{conventions, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("conventions: {message}");
            std::process::exit(2);
        }
    };
    let tables = conventions::tables();
    print!("{}", render(&tables, format));
}
