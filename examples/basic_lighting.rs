//! Chapter 2, Basic lighting: ambient, diffuse and specular at sample fragments.
//!
//! Run: `cargo run --release --example basic_lighting [-- --format text|markdown|csv]`.
//! Change the chapter's numbers without editing code, for example
//! `-- --light-pos 2,1,0 --shininess 64 --ambient 0.2`; `-- --help` lists them.
//! The tables come from [`lightlab::tables::basic_lighting::tables_for`], the
//! function the snapshot tests and the book call with the chapter's values.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::phong::BasicLighting;
use lightlab::table::render;
use lightlab::tables::basic_lighting;

const OPTIONS: [Opt; 7] = [
    Opt { name: "light-pos", value: "X,Y,Z", help: "lightPos (default 1.2,1,2)" },
    Opt { name: "view-pos", value: "X,Y,Z", help: "viewPos, the eye (default 0,0,3)" },
    Opt { name: "light-color", value: "R,G,B", help: "lightColor (default 1,1,1)" },
    Opt { name: "object-color", value: "R,G,B", help: "objectColor (default coral 1,0.5,0.31)" },
    Opt { name: "ambient", value: "S", help: "ambientStrength (default 0.1)" },
    Opt { name: "specular", value: "S", help: "specularStrength (default 0.5)" },
    Opt {
        name: "shininess",
        value: "S",
        help: "the exponent in pow(max(dot(viewDir, reflectDir), 0.0), 32) (default 32)",
    },
];

fn main() {
    // ANCHOR: main
    let args = Args::from_env("basic_lighting", &OPTIONS);
    let chapter = BasicLighting::learnopengl();
    let scene = (|| -> Result<BasicLighting, String> {
        Ok(BasicLighting {
            light_pos: args.vec3("light-pos", chapter.light_pos)?,
            view_pos: args.vec3("view-pos", chapter.view_pos)?,
            light_color: args.vec3("light-color", chapter.light_color)?,
            object_color: args.vec3("object-color", chapter.object_color)?,
            ambient_strength: args.number_at_least("ambient", chapter.ambient_strength, 0.0)?,
            specular_strength: args.number_at_least("specular", chapter.specular_strength, 0.0)?,
            shininess: args.number_at_least("shininess", chapter.shininess, 0.0)?,
        })
    })()
    .unwrap_or_else(|message| {
        eprintln!("basic_lighting: {message}");
        std::process::exit(2);
    });
    let tables = basic_lighting::tables_for(&scene);
    print!("{}", render(&tables, args.format));
    // ANCHOR_END: main
}
