//! Chapter 5, Light casters: attenuation for each row of the range table.
//!
//! Run: `cargo run --release --example attenuation [-- --format text|markdown|csv]`.
//! Add your own terms without editing code: `-- --attenuation 1,0.14,0.07`
//! (constant, linear, quadratic); `-- --help` lists the options.
//! The tables come from [`lightlab::tables::attenuation::tables_for`], the
//! function the snapshot tests and the book call without a row of yours.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::casters::Attenuation;
use lightlab::table::render;
use lightlab::tables::attenuation;

const OPTIONS: [Opt; 1] = [Opt {
    name: "attenuation",
    value: "KC,KL,KQ",
    help: "constant, linear and quadratic terms of your own (a last row and column)",
}];

fn main() {
    let args = Args::from_env("attenuation", &OPTIONS);
    let yours = (|| -> Result<Option<Attenuation>, String> {
        if !args.has("attenuation") {
            return Ok(None);
        }
        let k = args.vec3("attenuation", glam::Vec3::new(1.0, 0.09, 0.032))?;
        Attenuation::new(k.x, k.y, k.z).map(Some).map_err(|e| format!("--attenuation: {e}"))
    })();
    let yours = yours.unwrap_or_else(|message| {
        eprintln!("attenuation: {message}");
        std::process::exit(2);
    });
    let tables = attenuation::tables_for(yours);
    print!("{}", render(&tables, args.format));
}
