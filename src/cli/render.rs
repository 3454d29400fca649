//! `lightlab render`: draw a preset or a scene file to a PNG.

use std::path::PathBuf;

use crate::raster::framebuffer::Framebuffer;
use crate::raster::presets::{names, preset};
use crate::raster::shade::ShadingMode;

/// Arguments of `lightlab render`.
#[derive(clap::Args, Debug, Clone)]
pub struct RenderArgs {
    /// A preset name (`--list` prints them).
    #[arg(long, conflicts_with = "scene")]
    pub preset: Option<String>,
    /// A scene file (TOML).
    #[arg(long, value_name = "FILE.toml")]
    pub scene: Option<PathBuf>,
    /// Output PNG.
    #[arg(short = 'o', long, value_name = "out.png")]
    pub output: Option<PathBuf>,
    /// Shading mode: flat, gouraud, phong or blinn-phong (default: the scene's).
    #[arg(long, value_parser = ["flat", "gouraud", "phong", "blinn-phong"])]
    pub shading: Option<String>,
    /// Image size, WIDTHxHEIGHT.
    #[arg(long, default_value = "800x600")]
    pub size: String,
    /// Encode to sRGB (default: linear values written as they are, as the tutorials do).
    #[arg(long)]
    pub srgb: bool,
    /// List the presets and exit.
    #[arg(long)]
    pub list: bool,
}

/// Parse `WIDTHxHEIGHT`; the error names the field.
pub fn parse_size(s: &str) -> Result<(u32, u32), String> {
    let (w, h) = s.split_once(['x', 'X']).ok_or_else(|| format!("--size: expected WIDTHxHEIGHT, got {s:?}"))?;
    let parse = |v: &str, field: &str| -> Result<u32, String> {
        match v.trim().parse::<u32>() {
            Ok(n) if (1..=crate::raster::framebuffer::MAX_SIZE).contains(&n) => Ok(n),
            _ => Err(format!(
                "--size: {field} must be an integer in 1..={}, got {v:?}",
                crate::raster::framebuffer::MAX_SIZE
            )),
        }
    };
    Ok((parse(w, "width")?, parse(h, "height")?))
}

/// Run `lightlab render`.
pub fn run(args: &RenderArgs) -> Result<(), Box<dyn std::error::Error>> {
    if args.list {
        let mut out = super::output::stdout();
        for n in names() {
            out.line(n)?;
        }
        out.finish()?;
        return Ok(());
    }
    let (width, height) = parse_size(&args.size)?;
    let aspect = width as f32 / height as f32;
    let mut world = match (&args.preset, &args.scene) {
        (Some(name), _) => preset(name, aspect)
            .ok_or_else(|| format!("--preset: unknown preset {name:?}; known: {}", names().join(", ")))?,
        (None, Some(path)) => crate::raster::scene_file::load(path, aspect)?,
        (None, None) => return Err("give --preset NAME or --scene FILE.toml".into()),
    };
    if let Some(s) = &args.shading {
        world.shading = ShadingMode::from_name(s).ok_or_else(|| format!("--shading: unknown mode {s:?}"))?;
    }
    let output = args.output.as_ref().ok_or("-o/--output: required")?;
    let mut fb = Framebuffer::new(width, height)?;
    world.render(&mut fb);
    fb.save_png(output, args.srgb)?;
    Ok(())
}
