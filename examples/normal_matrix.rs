//! Normals: the model-matrix error, inverse-transpose against cofactor.
//!
//! Run: `cargo run --release --example normal_matrix [-- --format text|markdown|csv]`.
//! The tables come from [`lightlab::tables::normal_matrix::tables`], the same function
//! the snapshot tests and the book use.

use lightlab::tables::{normal_matrix, render, Format};

fn main() {
    let format = match Format::from_args(std::env::args().skip(1)) {
        Ok(format) => format,
        Err(message) => {
            eprintln!("normal_matrix: {message}");
            std::process::exit(2);
        }
    };
    let tables = normal_matrix::tables();
    print!("{}", render(&tables, format));
}
