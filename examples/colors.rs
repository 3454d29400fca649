//! Chapter 1, Colors: coral under white, green, olive and other lights.
//!
//! Run: `cargo run --release --example colors [-- --format text|markdown|csv]`.
//! Try your own colours without editing code: `-- --light-color 0.5,0.8,1
//! --object-color 0.2,0.6,0.9`; `-- --help` lists the options.
//! The table comes from [`lightlab::tables::colors::tables_for`], the function
//! the snapshot tests and the book call with the chapter's coral.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::color::CORAL;
use lightlab::table::render;
use lightlab::tables::colors;

const OPTIONS: [Opt; 2] = [
    Opt { name: "light-color", value: "R,G,B", help: "lightColor: adds a row \"yours\" under this light" },
    Opt { name: "object-color", value: "R,G,B", help: "toyColor, the object (default coral 1,0.5,0.31)" },
];

fn main() {
    // ANCHOR: main
    let args = Args::from_env("colors", &OPTIONS);
    let parsed = (|| -> Result<_, String> {
        let object = args.vec3("object-color", CORAL)?;
        let light = match args.has("light-color") {
            true => Some(args.vec3("light-color", glam::Vec3::ONE)?),
            false => None,
        };
        Ok((object, light))
    })();
    let (object, light) = parsed.unwrap_or_else(|message| {
        eprintln!("colors: {message}");
        std::process::exit(2);
    });
    let tables = colors::tables_for(object, light);
    print!("{}", render(&tables, args.format));
    // ANCHOR_END: main
}
