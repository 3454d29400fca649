//! Specular lobes: pow(cos α, s), Phong against Blinn-Phong, matching exponents, half-widths.
//!
//! Run: `cargo run --release --example specular [-- --format text|markdown|csv]`.
//! Try your own exponent without editing code: `-- --shininess 64`; `-- --help`
//! lists the options. The tables come from
//! [`lightlab::tables::specular::tables_for`], the function the snapshot tests
//! and the book call with the chapter's 32.

#[path = "common/args.rs"]
mod args;

use args::{Args, Opt};
use lightlab::table::render;
use lightlab::tables::specular;

const OPTIONS: [Opt; 1] =
    [Opt { name: "shininess", value: "S", help: "the exponent for Phong against Blinn-Phong (default 32)" }];

fn main() {
    let args = Args::from_env("specular", &OPTIONS);
    let shininess = args.number_at_least("shininess", 32.0, 0.0).unwrap_or_else(|message| {
        eprintln!("specular: {message}");
        std::process::exit(2);
    });
    let tables = specular::tables_for(shininess);
    print!("{}", render(&tables, args.format));
}
