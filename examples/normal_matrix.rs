//! Normals: the angle error of a normal sent through the model matrix, and the
//! inverse-transpose normal matrix against the cofactor form.
//!
//! Run: `cargo run --release --example normal_matrix [-- --format text|markdown|csv]`.
//! Try a model matrix of your own without editing code, for example
//! `-- --scale 1,0.1,1 --normal 0,1,1`; `-- --help` lists the options.
//! The tables come from [`lightlab::tables::normal_matrix::tables_for`], the function the
//! snapshot tests and the book call with the chapter's models and n = (1, 1, 1).

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use glam::Vec3;
use lightlab::table::render;
use lightlab::tables::normal_matrix;

const OPTIONS: [Opt; 2] = [
    Opt { name: "scale", value: "X,Y,Z", help: "an extra model matrix scale(x, y, z), the last row \"yours\"" },
    Opt { name: "normal", value: "X,Y,Z", help: "the normal of the second table (default 1,1,1; not zero)" },
];

fn main() {
    let args = Args::from_env("normal_matrix", &OPTIONS);
    let chosen = (|| -> Result<_, String> {
        let scale = if args.has("scale") { Some(args.vec3("scale", Vec3::ONE)?) } else { None };
        let normal = args.vec3("normal", Vec3::ONE)?;
        if normal == Vec3::ZERO {
            return Err("--normal: a zero vector has no direction; give a non-zero normal like 1,1,1".to_string());
        }
        Ok((scale, normal))
    })();
    let (scale, normal) = chosen.unwrap_or_else(|message| {
        eprintln!("normal_matrix: {message}");
        std::process::exit(2);
    });
    print!("{}", render(&normal_matrix::tables_for(scale, normal), args.format));
}
