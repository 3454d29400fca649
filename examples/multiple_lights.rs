//! Chapter 6, Multiple lights: every light's terms at sample fragments, in the chapter's
//! scene and its four atmospheres.
//!
//! Run: `cargo run --release --example multiple_lights [-- --format text|markdown|csv]`.
//! Without editing code, show one atmosphere and a fragment of your own, for example
//! `-- --atmosphere desert --frag-pos 0,0.5,0 --normal 0,1,0`; `-- --help` lists the options.
//! The tables come from [`lightlab::tables::multiple_lights::tables_for`], the function the
//! snapshot tests and the book call with every atmosphere and the chapter's fragments.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use glam::Vec3;
use lightlab::scene::Atmosphere;
use lightlab::table::render;
use lightlab::tables::{multiple_lights, Fragment};

const OPTIONS: [Opt; 3] = [
    Opt {
        name: "atmosphere",
        value: "NAME",
        help: "only this atmosphere after the default scene: desert, factory, horror, biochemical-lab",
    },
    Opt { name: "frag-pos", value: "X,Y,Z", help: "FragPos of an extra fragment, \"yours\" (needs --normal)" },
    Opt { name: "normal", value: "X,Y,Z", help: "Normal of that fragment (needs --frag-pos)" },
];

fn main() {
    let args = Args::from_env("multiple_lights", &OPTIONS);
    let chosen = (|| -> Result<_, String> {
        let names = Atmosphere::ALL.map(Atmosphere::name);
        let only = args.choice("atmosphere", &names)?.map(|k| Atmosphere::ALL[k]);
        let yours = match (args.has("frag-pos"), args.has("normal")) {
            (false, false) => None,
            (true, true) => Some(Fragment {
                name: "yours",
                frag_pos: args.vec3("frag-pos", Vec3::ZERO)?,
                normal: args.vec3("normal", Vec3::Z)?,
            }),
            _ => return Err("--frag-pos and --normal go together: give both".to_string()),
        };
        Ok((only, yours))
    })();
    let (only, yours) = chosen.unwrap_or_else(|message| {
        eprintln!("multiple_lights: {message}");
        std::process::exit(2);
    });
    print!("{}", render(&multiple_lights::tables_for(only, yours), args.format));
}
