//! Chapter 4, Lighting maps: the container's diffuse, specular and emission maps
//! sampled at a few UVs, nearest against bilinear.
//!
//! Run: `cargo run --release --example lighting_maps [-- --format text|markdown|csv]`.
//! Sample a point of your own without editing code: `-- --uv 0.3,0.6`; `-- --help` lists
//! the options. The tables come from [`lightlab::tables::lighting_maps::tables_for`], the
//! function the snapshot tests and the book call with the chapter's samples only.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::table::render;
use lightlab::tables::lighting_maps;

const OPTIONS: [Opt; 1] =
    [Opt { name: "uv", value: "U,V", help: "TexCoords of an extra sample, the last rows (e.g. 0.3,0.6)" }];

fn main() {
    let args = Args::from_env("lighting_maps", &OPTIONS);
    let uv = args.vec2("uv", "0.3,0.6").unwrap_or_else(|message| {
        eprintln!("lighting_maps: {message}");
        std::process::exit(2);
    });
    print!("{}", render(&lighting_maps::tables_for(uv), args.format));
}
