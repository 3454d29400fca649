//! Conventions: LearnOpenGL, opengl-tutorial 8 and ogldev 19 on the same fragments, with
//! the cause of each difference.
//!
//! Run: `cargo run --release --example conventions [-- --format text|markdown|csv]`.
//! Move the light without editing code, for example `-- --light-pos 2,1,0`; `-- --help`
//! lists the options. The tables come from [`lightlab::tables::conventions::tables_for`],
//! the function the snapshot tests and the book call with the chapter's light.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::phong::BasicLighting;
use lightlab::table::render;
use lightlab::tables::conventions;

const OPTIONS: [Opt; 1] =
    [Opt { name: "light-pos", value: "X,Y,Z", help: "the light of all three models (default 1.2,1,2)" }];

fn main() {
    let args = Args::from_env("conventions", &OPTIONS);
    let light_pos = args.vec3("light-pos", BasicLighting::learnopengl().light_pos).unwrap_or_else(|message| {
        eprintln!("conventions: {message}");
        std::process::exit(2);
    });
    print!("{}", render(&conventions::tables_for(light_pos), args.format));
}
