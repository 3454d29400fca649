// each example uses the parts it needs
#![allow(dead_code)]
//! Command-line arguments shared by the chapter examples: `--format`, `--help`
//! and the chapter's own numbers (`--light-pos 2,1,0`, `--shininess 64`, …).
//!
//! A bad argument is a message naming it (the example prints it and exits 2),
//! never a panic.

use glam::{Vec2, Vec3};
use lightlab::table::Format;

/// The parsed arguments.
pub struct Args {
    /// `--format` (default text).
    pub format: Format,
    values: Vec<(&'static str, String)>,
}

/// One option an example takes: its name without `--`, a value placeholder and a help line.
pub struct Opt {
    pub name: &'static str,
    pub value: &'static str,
    pub help: &'static str,
}

fn usage(program: &str, options: &[Opt]) -> String {
    let mut s = format!("usage: cargo run --release --example {program} -- [--format text|markdown|csv]");
    for o in options {
        s.push_str(&format!(" [--{} {}]", o.name, o.value));
    }
    s.push_str("\n\n  --format text|markdown|csv   how to print the tables (default text)\n");
    for o in options {
        let flag = format!("--{} {}", o.name, o.value);
        s.push_str(&format!("  {flag:<28} {}\n", o.help));
    }
    s
}

impl Args {
    /// Parse `std::env::args()`; on `--help` print the usage and exit 0; on a
    /// bad argument print the message and the usage to stderr and exit 2.
    pub fn from_env(program: &str, options: &[Opt]) -> Args {
        match Args::parse(std::env::args().skip(1), options) {
            Ok(Some(args)) => args,
            Ok(None) => {
                print!("{}", usage(program, options));
                std::process::exit(0);
            }
            Err(message) => {
                eprintln!("{program}: {message}\n\n{}", usage(program, options));
                std::process::exit(2);
            }
        }
    }

    /// Parse arguments (without the program name); `Ok(None)` for `--help`.
    pub fn parse(args: impl IntoIterator<Item = String>, options: &[Opt]) -> Result<Option<Args>, String> {
        let mut out = Args { format: Format::Text, values: Vec::new() };
        let mut args = args.into_iter();
        while let Some(arg) = args.next() {
            if arg == "--help" || arg == "-h" {
                return Ok(None);
            }
            let Some(flag) = arg.strip_prefix("--") else {
                return Err(format!("unexpected argument {arg:?}"));
            };
            let (name, inline) = match flag.split_once('=') {
                Some((n, v)) => (n, Some(v.to_string())),
                None => (flag, None),
            };
            let mut value = || inline.clone().or_else(|| args.next()).ok_or(format!("--{name} needs a value"));
            if name == "format" {
                let v = value()?;
                out.format = Format::from_name(&v)
                    .ok_or_else(|| format!("--format: unknown format {v:?}; expected text, markdown or csv"))?;
                continue;
            }
            let Some(opt) = options.iter().find(|o| o.name == name) else {
                return Err(format!("unknown option --{name}"));
            };
            let v = value()?;
            out.values.retain(|(n, _)| *n != opt.name);
            out.values.push((opt.name, v));
        }
        Ok(Some(out))
    }

    /// Whether `--name` was given.
    pub fn has(&self, name: &str) -> bool {
        self.raw(name).is_some()
    }

    fn raw(&self, name: &str) -> Option<&str> {
        self.values.iter().find(|(n, _)| *n == name).map(|(_, v)| v.as_str())
    }

    /// A finite number given as `--name X`, or `default`.
    pub fn number(&self, name: &str, default: f32) -> Result<f32, String> {
        let Some(v) = self.raw(name) else { return Ok(default) };
        match v.trim().parse::<f32>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => Err(format!("--{name}: expected a finite number like {default}, got {v:?}")),
        }
    }

    /// A finite number at least `min` given as `--name X`, or `default`.
    pub fn number_at_least(&self, name: &str, default: f32, min: f32) -> Result<f32, String> {
        let x = self.number(name, default)?;
        if x < min {
            return Err(format!("--{name}: must be at least {min}, got {x}"));
        }
        Ok(x)
    }

    /// Three finite numbers given as `--name x,y,z`, or `default`.
    pub fn vec3(&self, name: &str, default: Vec3) -> Result<Vec3, String> {
        let example = format!("{},{},{}", default.x, default.y, default.z);
        Ok(self.numbers::<3>(name, "three numbers x,y,z", &example)?.map_or(default, Vec3::from_array))
    }

    /// Two finite numbers given as `--name u,v`, if given.
    pub fn vec2(&self, name: &str, example: &str) -> Result<Option<Vec2>, String> {
        Ok(self.numbers::<2>(name, "two numbers u,v", example)?.map(Vec2::from_array))
    }

    /// `N` comma-separated finite numbers given as `--name a,b,…`, if given; the error
    /// names the option, says `what` was expected and shows `example`.
    fn numbers<const N: usize>(&self, name: &str, what: &str, example: &str) -> Result<Option<[f32; N]>, String> {
        let Some(v) = self.raw(name) else { return Ok(None) };
        let parts: Vec<&str> = v.split(',').map(str::trim).collect();
        let bad = || format!("--{name}: expected {what} like {example}, got {v:?}");
        if parts.len() != N {
            return Err(bad());
        }
        let mut out = [0.0f32; N];
        for (k, p) in parts.iter().enumerate() {
            out[k] = p.parse::<f32>().ok().filter(|x| x.is_finite()).ok_or_else(bad)?;
        }
        Ok(Some(out))
    }

    /// One of `choices` given as `--name X`, if given.
    pub fn choice(&self, name: &str, choices: &[&str]) -> Result<Option<usize>, String> {
        let Some(v) = self.raw(name) else { return Ok(None) };
        choices
            .iter()
            .position(|c| c.eq_ignore_ascii_case(v.trim()))
            .map(Some)
            .ok_or_else(|| format!("--{name}: expected one of {}, got {v:?}", choices.join(", ")))
    }
}
