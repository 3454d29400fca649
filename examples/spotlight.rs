//! Chapter 5, Light casters: the spotlight's worked table, published against recomputed.
//!
//! Run: `cargo run --release --example spotlight [-- --format text|markdown|csv]`.
//! Try your own cone without editing code: `-- --cut-off 10 --outer-cut-off 20`
//! (degrees, as `glm::radians(12.5f)` takes them); `-- --help` lists the options.
//! The tables come from [`lightlab::tables::spotlight::tables_for`], the function
//! the snapshot tests and the book call with the chapter's 12.5° and 17.5°.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::casters::{Attenuation, SpotLight};
use lightlab::material::LightProps;
use lightlab::table::render;
use lightlab::tables::spotlight;

const OPTIONS: [Opt; 2] = [
    Opt { name: "cut-off", value: "DEG", help: "inner cut-off φ in degrees (default 12.5)" },
    Opt { name: "outer-cut-off", value: "DEG", help: "outer cut-off γ in degrees (default 17.5)" },
];

fn main() {
    let args = Args::from_env("spotlight", &OPTIONS);
    let cone = (|| -> Result<(f32, f32), String> {
        let (inner, outer) = (args.number("cut-off", 12.5)?, args.number("outer-cut-off", 17.5)?);
        // the same checks as the library's spot light, naming the option
        let at = glam::Vec3::ZERO;
        SpotLight::new(at, glam::Vec3::NEG_Z, inner, outer, Attenuation::LEARNOPENGL, LightProps::white())
            .map_err(|e| format!("--{}: {}", e.field.replace("_deg", "").replace('_', "-"), e.reason))?;
        Ok((inner, outer))
    })();
    let (inner, outer) = cone.unwrap_or_else(|message| {
        eprintln!("spotlight: {message}");
        std::process::exit(2);
    });
    let tables = spotlight::tables_for(inner, outer);
    print!("{}", render(&tables, args.format));
}
