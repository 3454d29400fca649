//! `lightlab render`: draw a preset or a scene file to a PNG.

use std::path::PathBuf;

use crate::raster::framebuffer::Framebuffer;
use crate::raster::presets::{names, preset_desc};
use crate::raster::scene_desc::SceneDesc;
use crate::raster::shade::ShadingMode;

/// Where `render --help` sends a reader for the scene-file format.
pub const SCENE_FILE_HELP: &str = "Scene files: every key, its default and an example are in the book's appendix \
\"Scene files\" (book/src/appendix-scene-files.md). Start from a preset: \
lightlab render --preset coral-cube --dump-scene > my.toml";

/// Arguments of `lightlab render`.
#[derive(clap::Args, Debug, Clone)]
#[command(after_help = SCENE_FILE_HELP)]
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
    /// Write the preset (or scene file) as a scene file instead of rendering:
    /// to -o FILE.toml, or to standard output. It renders the same image.
    #[arg(long)]
    pub dump_scene: bool,
}

// String error: a one-line message naming the bad part of --size; boxed by the caller's `?`.
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

/// The scene a preset or scene file describes, with `--shading` applied.
pub fn scene_desc(args: &RenderArgs) -> Result<SceneDesc, Box<dyn std::error::Error>> {
    let mut desc = match (&args.preset, &args.scene) {
        (Some(name), _) => preset_desc(name)
            .ok_or_else(|| format!("--preset: unknown preset {name:?}; known: {}", names().join(", ")))?,
        (None, Some(path)) => {
            let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
            crate::raster::scene_file::parse_desc(&text).map_err(|e| format!("{}: {e}", path.display()))?
        }
        (None, None) => return Err("give --preset NAME or --scene FILE.toml".into()),
    };
    if let Some(s) = &args.shading {
        desc.shading = ShadingMode::from_name(s).ok_or_else(|| format!("--shading: unknown mode {s:?}"))?;
    }
    Ok(desc)
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
    let desc = scene_desc(args)?;
    if args.dump_scene {
        let source = match (&args.preset, &args.scene) {
            (Some(name), _) => format!("--preset {name}"),
            (None, Some(path)) => format!("--scene {}", path.display()),
            (None, None) => String::new(),
        };
        let header = format!(
            "Written by `lightlab render {source} --dump-scene`; renders the same image.\n\
             Every key is described in the book's appendix \"Scene files\"."
        );
        let text = desc.to_toml(&header);
        match &args.output {
            Some(path) => crate::outfile::write_atomically(path, text.as_bytes())?,
            None => super::output::print(text)?,
        }
        return Ok(());
    }
    let output = args.output.as_ref().ok_or("-o/--output: required")?;
    // Before the work: an unwritable -o is refused before the scene is built and drawn.
    crate::outfile::check_writable(output)?;
    let world = desc.to_world(aspect)?;
    let mut fb = Framebuffer::new(width, height)?;
    world.render(&mut fb);
    fb.save_png(output, args.srgb)?;
    Ok(())
}
