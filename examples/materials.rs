//! Chapter 3, Materials: the 24 classic materials and their shaded color.
//!
//! Run: `cargo run --release --example materials [-- --format text|markdown|csv]`.
//! Change the light without editing code, for example
//! `-- --light-pos 2,1,0 --light-diffuse 0.5,0.5,0.5`; `-- --help` lists the options.
//! The tables come from [`lightlab::tables::materials::tables_for`], the function the
//! snapshot tests and the book call with the exercise's white light.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::material::LightProps;
use lightlab::table::render;
use lightlab::tables::materials;

const OPTIONS: [Opt; 4] = [
    Opt { name: "light-pos", value: "X,Y,Z", help: "light.position (default 1.2,1,2)" },
    Opt { name: "light-ambient", value: "R,G,B", help: "light.ambient (default 1,1,1)" },
    Opt { name: "light-diffuse", value: "R,G,B", help: "light.diffuse (default 1,1,1)" },
    Opt { name: "light-specular", value: "R,G,B", help: "light.specular (default 1,1,1)" },
];

fn main() {
    let args = Args::from_env("materials", &OPTIONS);
    let white = LightProps::white();
    let chosen = (|| -> Result<_, String> {
        let light = LightProps {
            ambient: args.vec3("light-ambient", white.ambient)?,
            diffuse: args.vec3("light-diffuse", white.diffuse)?,
            specular: args.vec3("light-specular", white.specular)?,
        };
        Ok((args.vec3("light-pos", materials::REFERENCE_LIGHT_POS)?, light))
    })();
    let (light_pos, light) = chosen.unwrap_or_else(|message| {
        eprintln!("materials: {message}");
        std::process::exit(2);
    });
    print!("{}", render(&materials::tables_for(light_pos, &light), args.format));
}
