//! The book's renders from the CPU raster back end ([`crate::raster`]), and the
//! comparison figures with their generated captions.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `world` | a [`World`]: a preset of [`presets`] or a sphere built here |
//! | `panel` | one render, 8-bit RGB, no gamma encoding (the tutorials write linear values) |
//! | `reference`, `test` | the two images of a comparison; FLIP is computed of `test` against `reference` |
//! | `caption` | a Markdown artifact next to a comparison, holding the numbers computed from it |
//!
//! Every image is rendered at book-build time, in a modest size so the whole book
//! builds in seconds. The renders are deterministic: the rasterizer has no randomness and
//! sums in a fixed order. Captions that quote numbers are generated next to the image
//! (`*-caption.md`), so no number in the book is typed by hand.
//!
//! Sources: LearnOpenGL, Lighting chapters (the scenes, via [`presets`]); Gouraud 1971
//! and Phong 1975 (the tessellation comparison); Andersson et al. 2020 (FLIP).

use super::FigureError;
use glam::{DVec3, Mat4, Vec3};
use image::RgbImage;

use super::artifact::Artifact;
use super::compare::{encode_png, labelled_comparison, labelled_grid_in, Comparison};
use crate::i18n::Lang;
use crate::maps::LightingMaps;
use crate::material::{LightProps, Material, CLASSIC_MATERIALS};
use crate::models::ShadingModel;
use crate::phong::BasicLighting;
use crate::raster::camera::Camera;
use crate::raster::clip::ClipVertex;
use crate::raster::framebuffer::Framebuffer;
use crate::raster::kernel::Lanes;
use crate::raster::kernel::Specular;
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::{vertex_stage, ShadedVertex};
use crate::raster::pipeline::{Geometry, Object, World};
use crate::raster::presets;
use crate::raster::rasterize::CullMode;
use crate::raster::rasterize::{DrawCall, FragmentBatch, FragmentShader};
use crate::raster::raycast::{RayObject, RayScene, Shape};
use crate::raster::shade::{ShadingMode, Surface};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Every render and comparison of the book, with the comparisons' captions. Each
/// comparison is rendered once and writes its image and its caption together.
pub fn artifacts() -> Vec<Artifact> {
    let mut all = Vec::new();
    for (name, draw) in SCALABLE {
        for (scale, path) in [(1, format!("renders/{name}.png")), (2, format!("renders/{name}@2x.png"))] {
            all.extend(Artifact::localized(vec![path], move |lang| {
                drawn_once(name, scale, draw)?.png(lang).map(|png| vec![png])
            }));
        }
    }
    all.extend([Artifact::file("renders/gouraud-phong-table.md", || gouraud_phong_table().map(String::into_bytes))]);
    // Each comparison is rendered once: its picture per language, its caption (Markdown,
    // translated with the chapter) in English.
    for (name, compare, caption) in COMPARISONS {
        all.extend(Artifact::localized(vec![format!("renders/{name}-compare.png")], move |lang| {
            with_compared(name, compare, |c| c.png_in(lang)).map(|png| vec![png])
        }));
        all.push(Artifact::file(format!("renders/{name}-compare-caption.md"), move || {
            with_compared(name, compare, |c| Ok(caption(c).into_bytes()))
        }));
    }
    all.extend(Artifact::localized(vec!["renders/floor-falloff.png".to_owned()], |lang| {
        drawn_once("floor-falloff", 1, |_| floor_falloff())?.png(lang).map(|png| vec![png])
    }));
    all
}

/// A render of the book: one image, or panels with labels (drawn in the reader's language
/// by [`Drawn::png`]).
#[derive(Debug, Clone)]
pub enum Drawn {
    /// One image without words.
    Image(RgbImage),
    /// A labelled comparison (its labels redrawn per language by [`Comparison::png_in`]).
    Compared(Box<Comparison>),
    /// Panels with their English labels, in a grid of `cols` columns ([`labelled_grid_in`]).
    Grid {
        /// Each panel and its label.
        panels: Vec<(RgbImage, String)>,
        /// Columns of the grid.
        cols: usize,
    },
}

impl Drawn {
    /// Panels with labels, copied from the borrowed form `labelled_grid` takes.
    pub fn grid(panels: &[(&RgbImage, &str)], cols: usize) -> Result<Drawn, FigureError> {
        Ok(Drawn::Grid { panels: panels.iter().map(|(i, l)| ((*i).clone(), (*l).to_owned())).collect(), cols })
    }

    /// The PNG in `lang`: the labels through [`crate::i18n::tr`].
    pub fn png(&self, lang: Lang) -> Result<Vec<u8>, FigureError> {
        match self {
            Drawn::Image(img) => png_of(img.clone()),
            Drawn::Compared(c) => c.png_in(lang),
            Drawn::Grid { panels, cols } => {
                let borrowed: Vec<(&RgbImage, &str)> = panels.iter().map(|(i, l)| (i, l.as_str())).collect();
                png_of(labelled_grid_in(&borrowed, *cols, lang)?)
            }
        }
    }
}

/// The render `name` at `scale`, drawn once per process and shared by its languages' copies
/// (the render is the cost; the labels are cheap). A failure is kept as its message.
fn drawn_once(
    name: &'static str,
    scale: u32,
    draw: impl FnOnce(u32) -> Result<Drawn, FigureError>,
) -> Result<Arc<Drawn>, FigureError> {
    type Slot = Arc<OnceLock<Result<Arc<Drawn>, String>>>;
    static DRAWN: OnceLock<Mutex<HashMap<(&'static str, u32), Slot>>> = OnceLock::new();
    let slot: Slot = {
        let mut map = DRAWN.get_or_init(Mutex::default).lock().unwrap_or_else(|e| e.into_inner());
        Arc::clone(map.entry((name, scale)).or_default())
    };
    slot.get_or_init(|| draw(scale).map(Arc::new).map_err(|e| e.to_string())).clone().map_err(FigureError::Invalid)
}

/// A render drawn at `scale` times its book size (1 in the pages; 2 for the `@2x` copy
/// beside it, for projectors and print).
type ScalableRender = fn(u32) -> Result<Drawn, FigureError>;

/// The renders the book shows, each written as `renders/NAME.png` and, at twice the size,
/// `renders/NAME@2x.png`. The comparisons are written once: their captions quote numbers
/// measured on the book-size images.
pub const SCALABLE: [(&str, ScalableRender); 12] = [
    ("coral-cube", coral_cube_png),
    ("phong-terms", phong_terms_png),
    ("shininess-sweep", shininess_sweep_png),
    ("gouraud-phong", gouraud_phong_png),
    ("materials-grid", materials_grid_png),
    ("container-maps", container_maps_png),
    ("container-exercises", container_exercises_png),
    ("casters", casters_png),
    ("spot-edges", spot_edges_png),
    ("multiple-lights", multiple_lights_png),
    ("atmospheres", atmospheres_png),
    ("conventions", conventions_png),
];

/// `size` times `scale` (saturating: an absurd scale is refused by the framebuffer's
/// size check, not wrapped).
fn scaled(size: (u32, u32), scale: u32) -> (u32, u32) {
    (size.0.saturating_mul(scale), size.1.saturating_mul(scale))
}

/// A comparison of the book: its name (`renders/<name>-compare.png`), how it is rendered,
/// and the caption that quotes its numbers.
type Compared = (&'static str, fn() -> Result<Comparison, FigureError>, fn(&Comparison) -> String);

/// The book's comparisons.
const COMPARISONS: [Compared; 4] = [
    ("gouraud-phong", gouraud_phong_compare, gouraud_phong_caption),
    ("raster-raycast", raster_raycast_compare, raster_raycast_caption),
    (
        "conventions-tutorial",
        || conventions_compare(ShadingModel::OpenGLTutorial),
        |c| conventions_caption(ShadingModel::OpenGLTutorial, c),
    ),
    (
        "conventions-ogldev",
        || conventions_compare(ShadingModel::Ogldev),
        |c| conventions_caption(ShadingModel::Ogldev, c),
    ),
];

/// The comparison `name`, rendered once per process and shared by its picture's languages
/// and its caption (as [`drawn_once`] for the renders): `use_it` borrows it from the cache.
fn with_compared<T>(
    name: &'static str,
    compare: fn() -> Result<Comparison, FigureError>,
    use_it: impl FnOnce(&Comparison) -> Result<T, FigureError>,
) -> Result<T, FigureError> {
    match &*drawn_once(name, 0, |_| Ok(Drawn::Compared(Box::new(compare()?))))? {
        Drawn::Compared(c) => use_it(c),
        _ => Err(FigureError::Invalid(format!("{name}: not a comparison"))),
    }
}

/// Size of a figure that holds one render, pixels.
pub const SINGLE: (u32, u32) = (480, 360);
/// Size of each panel of a two-column figure, pixels.
const HALF: (u32, u32) = (360, 270);
/// Size of each panel of a three-column figure, pixels.
const THIRD: (u32, u32) = (240, 180);
/// Size of one sphere of the sphere figures, pixels (square).
const SPHERE: (u32, u32) = (240, 240);

/// Shininess exponents of the sweep (LearnOpenGL, Basic lighting, shows 2 to 256).
pub const SHININESS_SWEEP: [f32; 5] = [2.0, 8.0, 32.0, 128.0, 256.0];

/// Sphere tessellations (stacks, slices) of the Gouraud against Phong figure; 32 × 64 is
/// the benchmark's sphere.
pub const TESSELLATIONS: [(u32, u32); 3] = [(8, 16), (16, 32), (32, 64)];

/// The tessellation of the Gouraud against Phong comparison: the middle one, where the
/// highlight is already round under Phong but still faceted under Gouraud.
pub const COMPARE_TESSELLATION: (u32, u32) = (16, 32);

/// Tint of the colored specular map exercise: a brass-like orange (our choice; the
/// tutorial ships an image instead).
pub const SPECULAR_TINT: Vec3 = Vec3::new(1.0, 0.6, 0.2);

/// Render `world` into a `size` framebuffer and return 8-bit RGB (alpha dropped, no
/// sRGB encoding, as the tutorials' shaders write).
///
/// Errors name the size when it is zero or too large.
pub fn render(world: &World, size: (u32, u32)) -> Result<RgbImage, FigureError> {
    let mut fb = Framebuffer::new(size.0, size.1).map_err(|e| format!("render: {e}"))?;
    world.render(&mut fb);
    Ok(rgb_of(&fb))
}

/// The RGB channels of a framebuffer's [`Framebuffer::to_rgba8`] (no sRGB encoding).
fn rgb_of(fb: &Framebuffer) -> RgbImage {
    let rgb: Vec<u8> = fb.to_rgba8(false).chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
    RgbImage::from_raw(fb.width(), fb.height(), rgb).unwrap_or_default()
}

fn png_of(img: RgbImage) -> Result<Vec<u8>, FigureError> {
    encode_png(&img)
}

fn aspect(size: (u32, u32)) -> f32 {
    size.0 as f32 / size.1 as f32
}

/// A preset of [`presets::preset`], or an error naming it.
fn preset(name: &str, size: (u32, u32)) -> Result<World, FigureError> {
    presets::preset(name, aspect(size)).ok_or_else(|| FigureError::Invalid(format!("renders: unknown preset {name:?}")))
}

/// The eye of the close-up figures (coral cube, container): below and left of the cube,
/// where the front face's mirror direction of the lamp (1.2, 1, 2) meets the eye, so the
/// highlight shows as in the tutorials' screenshots.
pub const CLOSE_EYE: Vec3 = Vec3::new(-1.68, -1.12, 4.48);

/// The close-up camera at [`CLOSE_EYE`], aimed between the cube and its lamp.
fn close_camera(size: (u32, u32)) -> Result<Camera, FigureError> {
    Camera::new(CLOSE_EYE, Vec3::new(0.6, 0.5, 1.0), Vec3::Y, 36.0, aspect(size), 0.1, 100.0)
        .map_err(|e| FigureError::Invalid(format!("close camera: {e}")))
}

pub use crate::raster::presets::TIGHT_EYE;

/// The tight camera ([`crate::raster::presets::tight_camera`]) at `size`'s aspect.
fn tight_camera(size: (u32, u32)) -> Result<Camera, FigureError> {
    crate::raster::presets::tight_camera(aspect(size)).map_err(|e| FigureError::Invalid(format!("tight camera: {e}")))
}

/// A preset seen by the close-up camera.
fn close_preset(name: &str, size: (u32, u32)) -> Result<World, FigureError> {
    let mut w = preset(name, size)?;
    w.camera = close_camera(size)?;
    Ok(w)
}

/// A preset rendered at `size`.
pub fn preset_image(name: &str, size: (u32, u32)) -> Result<RgbImage, FigureError> {
    render(&preset(name, size)?, size)
}

/// The coral cube and its lamp (LearnOpenGL, Colors and Basic lighting).
pub fn coral_cube_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled(SINGLE, scale);
    Ok(Drawn::Image(render(&close_preset("coral-cube", size)?, size)?))
}

/// The coral cube with only the ambient, only the diffuse, only the specular term, and
/// their sum, in a 2 × 2 grid: each term alone is the scene with the light's other two
/// intensities set to zero.
pub fn phong_terms_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled(HALF, scale);
    let base = close_preset("coral-cube", size)?;
    let term = |keep: [bool; 3]| -> Result<RgbImage, FigureError> {
        let mut w = base.clone();
        for light in &mut w.lights.point_lights {
            let p = &mut light.props;
            let pick = |v: Vec3, on: bool| if on { v } else { Vec3::ZERO };
            *p = LightProps {
                ambient: pick(p.ambient, keep[0]),
                diffuse: pick(p.diffuse, keep[1]),
                specular: pick(p.specular, keep[2]),
            };
        }
        render(&w, size)
    };
    let (a, d, s, all) =
        (term([true, false, false])?, term([false, true, false])?, term([false, false, true])?, term([true; 3])?);
    Drawn::grid(&[(&a, "ambient"), (&d, "diffuse"), (&s, "specular"), (&all, "ambient + diffuse + specular")], 2)
}

/// A unit sphere at the origin with `material`, tessellated `stacks × slices`, under the
/// Basic lighting lamp (white, at (1.2, 1, 2)), seen from (0, 0, 3) at `size`.
pub fn sphere_world(material: Material, tessellation: (u32, u32), shading: ShadingMode, size: (u32, u32)) -> World {
    let (lights, _) = presets::basic_lighting_scene(&BasicLighting::learnopengl());
    let sphere = Object {
        geometry: Geometry::Mesh(Mesh::uv_sphere(tessellation.0, tessellation.1)),
        model: Mat4::IDENTITY,
        surface: Surface::Material(material),
        cull: CullMode::Back,
    };
    World {
        camera: Camera::learnopengl(aspect(size)),
        clear: lights.clear_color.extend(1.0),
        lights,
        objects: vec![sphere],
        shading,
        depth_test: true,
        range_window: None,
        specialisations: crate::raster::kernel::Specialisations::ALL,
    }
}

/// The Basic lighting material: coral in all three reflectances, with the light's
/// specular strength 0.5 carried by [`presets::basic_lighting_scene`].
fn coral_basic() -> Material {
    presets::basic_lighting_scene(&BasicLighting::learnopengl()).1
}

/// The coral sphere for each shininess of [`SHININESS_SWEEP`], Phong shading.
pub fn shininess_sweep_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled((180, 180), scale);
    let images = SHININESS_SWEEP
        .iter()
        .map(|&s| {
            render(&sphere_world(Material { shininess: s, ..coral_basic() }, (32, 64), ShadingMode::Phong, size), size)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let labels: Vec<String> = SHININESS_SWEEP.iter().map(|s| format!("shininess {s}")).collect();
    let panels: Vec<(&RgbImage, &str)> = images.iter().zip(&labels).map(|(i, l)| (i, l.as_str())).collect();
    Drawn::grid(&panels, panels.len())
}

fn tessellation_label(shading: ShadingMode, (stacks, slices): (u32, u32)) -> String {
    let name = if shading == ShadingMode::Gouraud { "Gouraud" } else { "Phong" };
    format!("{name}, {stacks} × {slices}")
}

/// Gouraud (top row) against Phong (bottom row) on the coral sphere at each of
/// [`TESSELLATIONS`].
pub fn gouraud_phong_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled(SPHERE, scale);
    let mut images = Vec::new();
    let mut labels = Vec::new();
    for shading in [ShadingMode::Gouraud, ShadingMode::Phong] {
        for &t in &TESSELLATIONS {
            images.push(render(&sphere_world(coral_basic(), t, shading, size), size)?);
            labels.push(tessellation_label(shading, t));
        }
    }
    let panels: Vec<(&RgbImage, &str)> = images.iter().zip(&labels).map(|(i, l)| (i, l.as_str())).collect();
    Drawn::grid(&panels, TESSELLATIONS.len())
}

/// Phong (reference) against Gouraud (test) at [`COMPARE_TESSELLATION`], heat map full
/// scale 32 levels.
pub fn gouraud_phong_compare() -> Result<Comparison, FigureError> {
    let t = COMPARE_TESSELLATION;
    let phong = render(&sphere_world(coral_basic(), t, ShadingMode::Phong, SPHERE), SPHERE)?;
    let gouraud = render(&sphere_world(coral_basic(), t, ShadingMode::Gouraud, SPHERE), SPHERE)?;
    labelled_comparison(
        (&phong, &tessellation_label(ShadingMode::Phong, t)),
        (&gouraud, &tessellation_label(ShadingMode::Gouraud, t)),
        32,
    )
}

/// A Markdown table: for each of [`TESSELLATIONS`], the mean FLIP of Gouraud against
/// Phong and the largest and mean difference in 8-bit levels ([`super::compare::diff_stats`]).
///
/// Returns an error if a render or the comparison fails.
pub fn gouraud_phong_table() -> Result<String, FigureError> {
    let mut md = String::from(
        "| tessellation | triangles | mean FLIP | largest difference (levels) | mean difference (levels) |\n\
         | --- | ---: | ---: | ---: | ---: |\n",
    );
    for &(stacks, slices) in &TESSELLATIONS {
        let phong = render(&sphere_world(coral_basic(), (stacks, slices), ShadingMode::Phong, SPHERE), SPHERE)?;
        let gouraud = render(&sphere_world(coral_basic(), (stacks, slices), ShadingMode::Gouraud, SPHERE), SPHERE)?;
        let stats = super::compare::diff_stats(&phong, &gouraud)?;
        let flip = super::compare::flip_mean(&phong, &gouraud)?;
        md.push_str(&format!(
            "| {stacks} × {slices} | {} | {flip:.4} | {} | {:.2} |\n",
            Mesh::uv_sphere(stacks, slices).triangles.len(),
            stats.max_levels,
            stats.mean_levels
        ));
    }
    md.push_str(
        "\n*Gouraud against Phong on the coral sphere, per tessellation, over the whole \
         image; FLIP by NVIDIA's implementation (`nv-flip`, 67 pixels per degree).*\n",
    );
    Ok(md)
}

/// The numbers of a comparison as one Markdown sentence.
fn stats_sentence(c: &Comparison) -> String {
    let s = &c.stats;
    format!(
        "Mean FLIP {:.4} (NVIDIA's FLIP through the `nv-flip` crate, 67 pixels per degree; 0 is \
         indistinguishable, 1 is the largest error). Largest difference {} levels, mean {:.2} levels; \
         {} of {} pixels ({:.1} %) differ by more than one level. The heat map saturates at {} levels.",
        c.flip,
        s.max_levels,
        s.mean_levels,
        s.beyond_one_level,
        s.pixels,
        100.0 * s.beyond_one_level as f64 / s.pixels as f64,
        c.full_scale
    )
}

/// The Gouraud against Phong comparison's caption.
pub fn gouraud_phong_caption(c: &Comparison) -> String {
    let (stacks, slices) = COMPARE_TESSELLATION;
    format!(
        "*The coral sphere at {stacks} × {slices}, Phong (left, the reference) and Gouraud (middle), and the \
         largest channel difference per pixel (right). {}*\n",
        stats_sentence(c)
    )
}

/// Tessellation of the rasterized sphere compared with the ray-cast one: the benchmark's.
pub const RAYCAST_TESSELLATION: (u32, u32) = (32, 64);

/// The rasterized coral sphere (Phong, [`RAYCAST_TESSELLATION`]) against the `f64`
/// ray-cast of the exact sphere with the same camera, lights and material, one ray per
/// pixel centre; heat map full scale 8 levels.
pub fn raster_raycast_compare() -> Result<Comparison, FigureError> {
    let world = sphere_world(coral_basic(), RAYCAST_TESSELLATION, ShadingMode::Phong, SPHERE);
    let raster = render(&world, SPHERE)?;
    let scene = RayScene {
        camera: world.camera,
        lights: world.lights.clone(),
        objects: vec![RayObject { shape: Shape::Sphere { center: DVec3::ZERO, radius: 1.0 }, material: coral_basic() }],
        clear: world.clear,
        specular: Specular::Phong,
    };
    let truth = scene.render(SPHERE.0, SPHERE.1, 1).map_err(|e| format!("ray cast: {e}"))?;
    let truth = rgb_of(&truth.to_framebuffer());
    let (stacks, slices) = RAYCAST_TESSELLATION;
    labelled_comparison((&truth, "f64 ray cast, exact sphere"), (&raster, &format!("raster, {stacks} × {slices}")), 8)
}

/// The raster against ray-cast comparison's caption.
pub fn raster_raycast_caption(c: &Comparison) -> String {
    let (stacks, slices) = RAYCAST_TESSELLATION;
    format!(
        "*The coral sphere ray-cast in `f64` with its exact normal (left, the reference) and rasterized as a \
         {stacks} × {slices} mesh with Phong shading in `f32` (middle); the difference (right) sits on the \
         silhouette, where the polygon and the circle cover different pixels, and in faint bands where the \
         interpolated normal departs from the true one. {}*\n",
        stats_sentence(c)
    )
}

/// One sphere per classic material (24), in 6 columns, each under its name, lit by a
/// full-white light as the Materials exercise requires.
pub fn materials_grid_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled((120, 110), scale);
    let images = CLASSIC_MATERIALS
        .iter()
        .map(|m| {
            let mut w = sphere_world(m.material(), (24, 48), ShadingMode::Phong, size);
            for light in &mut w.lights.point_lights {
                light.props = LightProps::white();
            }
            render(&w, size)
        })
        .collect::<Result<Vec<_>, _>>()?;
    let panels: Vec<(&RgbImage, &str)> =
        images.iter().zip(CLASSIC_MATERIALS.iter()).map(|(i, m)| (i, m.name)).collect();
    Drawn::grid(&panels, 6)
}

/// The container preset with its maps changed by `edit`, at `size`.
fn container_with(size: (u32, u32), tight: bool, edit: impl Fn(&mut LightingMaps)) -> Result<RgbImage, FigureError> {
    let mut w = close_preset("container", size)?;
    if tight {
        w.camera = tight_camera(size)?;
    }
    for o in &mut w.objects {
        if let Surface::Maps(maps, _) = &mut o.surface {
            edit(maps);
        }
    }
    render(&w, size)
}

/// The container with its diffuse map only (specular map black), and with the diffuse
/// and specular maps.
pub fn container_maps_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled(HALF, scale);
    let diffuse = container_with(size, false, |m| {
        m.specular = m.specular.map(|_| Vec3::ZERO);
        m.emission = None;
    })?;
    let both = container_with(size, false, |m| m.emission = None)?;
    Drawn::grid(&[(&diffuse, "diffuse map only"), (&both, "diffuse + specular maps")], 2)
}

/// The Lighting maps exercises: the inverted specular map, a colored specular map
/// ([`SPECULAR_TINT`]) and the emission map.
pub fn container_exercises_png(scale: u32) -> Result<Drawn, FigureError> {
    let colored = crate::maps::container_colored_specular(128, SPECULAR_TINT).map_err(|e| format!("{e:?}"))?;
    let size = scaled(THIRD, scale);
    let inverted = container_with(size, true, |m| {
        m.specular = crate::maps::inverted(&m.specular);
        m.emission = None;
    })?;
    let tinted = container_with(size, true, |m| {
        m.specular = colored.clone();
        m.emission = None;
    })?;
    let emission = container_with(size, true, |_| {})?;
    Drawn::grid(&[(&inverted, "inverted specular"), (&tinted, "colored specular"), (&emission, "emission map")], 3)
}

/// The ten containers under the directional, the point and the spot light.
pub fn casters_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled((320, 240), scale);
    let d = preset_image("casters-directional", size)?;
    let p = preset_image("casters-point", size)?;
    let s = preset_image("casters-spot", size)?;
    Drawn::grid(&[(&d, "directional light"), (&p, "point light"), (&s, "spotlight")], 3)
}

/// The spotlight scene with a hard edge (outer cut-off = inner, 12.5°) and with the
/// chapter's soft edge (12.5° to 17.5°).
pub fn spot_edges_png(scale: u32) -> Result<Drawn, FigureError> {
    let size = scaled(HALF, scale);
    let soft_world = preset("casters-spot", size)?;
    let mut hard_world = soft_world.clone();
    if let Some(spot) = &mut hard_world.lights.spot_light {
        spot.outer_cut_off = spot.cut_off;
    } else {
        return Err(FigureError::Invalid("spot_edges: the casters-spot preset has no spotlight".to_owned()));
    }
    let (hard, soft) = (render(&hard_world, size)?, render(&soft_world, size)?);
    Drawn::grid(&[(&hard, "hard edge: 12.5°"), (&soft, "soft edge: 12.5° to 17.5°")], 2)
}

/// The Multiple lights chapter's default scene.
pub fn multiple_lights_png(scale: u32) -> Result<Drawn, FigureError> {
    Ok(Drawn::Image(preset_image("multiple-lights", scaled(SINGLE, scale))?))
}

/// The four atmospheres of the Multiple lights chapter in a 2 × 2 grid.
pub fn atmospheres_png(scale: u32) -> Result<Drawn, FigureError> {
    let names = ["desert", "factory", "horror", "biochemical-lab"];
    let images = names
        .iter()
        .map(|n| preset_image(&format!("multiple-lights-{n}"), scaled(HALF, scale)))
        .collect::<Result<Vec<_>, _>>()?;
    let labels = ["desert", "factory", "horror", "biochemical lab"];
    let panels: Vec<(&RgbImage, &str)> = images.iter().zip(labels).collect();
    Drawn::grid(&panels, 2)
}

/// A fragment stage that calls `color(world_pos, normal)` for each lane; varyings are
/// world position (0..3) and normal (3..6). It lets the tutorials' per-fragment models
/// of [`crate::models`] run in the rasterizer unchanged.
struct PerFragment<F: Fn(Vec3, Vec3) -> Vec3 + Sync>(F);

impl<F: Fn(Vec3, Vec3) -> Vec3 + Sync> FragmentShader for PerFragment<F> {
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
        let v = &batch.varyings;
        for l in 0..batch.len {
            let c = (self.0)(Vec3::new(v[0][l], v[1][l], v[2][l]), Vec3::new(v[3][l], v[4][l], v[5][l]));
            for (k, channel) in out.iter_mut().enumerate() {
                channel[l] = c[k];
            }
        }
    }
}

/// Vertices of `mesh` under `model` and `camera` with world position and normal as varyings.
fn lit_vertices(mesh: Mesh, model: Mat4, camera: &Camera) -> (Vec<ClipVertex>, Vec<[u32; 3]>) {
    let (verts, triangles) = vertex_stage(&Geometry::Mesh(mesh), model, camera);
    (verts.iter().map(ShadedVertex::lit_clip_vertex).collect(), triangles)
}

/// The coral cube (and its lamp, out of view) under one of the three tutorials' models,
/// from the tight camera, with each model's eye at the camera, at LearnOpenGL's lamp: the
/// conventions chapter's models ([`presets::ConventionsModels`], opengl-tutorial 8 and
/// ogldev 19 through [`presets::ConventionsModels::tutorial`]), each point shaded by the
/// model's scalar `terms`. Blinn-Phong is drawn as LearnOpenGL.
pub fn model_image(model: ShadingModel, size: (u32, u32)) -> Result<RgbImage, FigureError> {
    let camera = tight_camera(size)?;
    let eye = camera.eye;
    let models = presets::ConventionsModels::new(BasicLighting::learnopengl().light_pos, eye);
    let (learn, tutorial) = (models.learnopengl, models.tutorial(model));
    let cube_shader = PerFragment(move |p: Vec3, n: Vec3| match tutorial {
        Some(t) => t.shade(p, n, eye),
        None => learn.terms(p, n).sum(),
    });
    let lamp_shader = PerFragment(|_: Vec3, _: Vec3| Vec3::ONE);
    let (cube_v, cube_t) = lit_vertices(Mesh::learnopengl_cube(), Mat4::IDENTITY, &camera);
    let lamp_model = presets::lamp_model(learn.light_pos);
    let (lamp_v, lamp_t) = lit_vertices(Mesh::learnopengl_cube(), lamp_model, &camera);
    let draw = |vertices, triangles, shader| DrawCall {
        vertices,
        triangles,
        varying_count: 6,
        cull: CullMode::None,
        depth_test: true,
        shader,
    };
    let draws =
        [draw(&cube_v[..], &cube_t[..], &cube_shader as &dyn FragmentShader), draw(&lamp_v, &lamp_t, &lamp_shader)];
    let mut fb = Framebuffer::new(size.0, size.1).map_err(|e| format!("model_image: {e}"))?;
    crate::raster::rasterize::render(&mut fb, Some(Vec3::splat(0.1).extend(1.0)), &draws);
    Ok(rgb_of(&fb))
}

fn model_label(model: ShadingModel) -> &'static str {
    match model {
        ShadingModel::LearnOpenGL | ShadingModel::BlinnPhong => "LearnOpenGL",
        ShadingModel::OpenGLTutorial => "opengl-tutorial 8",
        ShadingModel::Ogldev => "ogldev 19",
    }
}

/// The coral cube under the three tutorials' models, side by side.
pub fn conventions_png(scale: u32) -> Result<Drawn, FigureError> {
    let models = [ShadingModel::LearnOpenGL, ShadingModel::OpenGLTutorial, ShadingModel::Ogldev];
    let images = models.iter().map(|&m| model_image(m, scaled(THIRD, scale))).collect::<Result<Vec<_>, _>>()?;
    let panels: Vec<(&RgbImage, &str)> = images.iter().zip(models).map(|(i, m)| (i, model_label(m))).collect();
    Drawn::grid(&panels, 3)
}

/// LearnOpenGL (reference) against `model` on the coral cube; heat map full scale 64 levels.
pub fn conventions_compare(model: ShadingModel) -> Result<Comparison, FigureError> {
    let reference = model_image(ShadingModel::LearnOpenGL, THIRD)?;
    let test = model_image(model, THIRD)?;
    labelled_comparison((&reference, model_label(ShadingModel::LearnOpenGL)), (&test, model_label(model)), 64)
}

/// The caption of [`conventions_compare`].
pub fn conventions_caption(model: ShadingModel, c: &Comparison) -> String {
    format!(
        "*LearnOpenGL (left, the reference) against {} (middle) on the coral cube, and their difference \
         (right). {}*\n",
        model_label(model),
        stats_sentence(c)
    )
}

/// Full scale of the falloff heat maps, in 8-bit levels.
pub const FALLOFF_HEAT_LEVELS: u8 = 64;

/// `floor-lights256` three ways, and what the window changes: LearnOpenGL's falloff,
/// the range window at the nominal range (culled: the same pixels as unculled) and at
/// the faithful range of `study::window`; below, the heat maps of each against LearnOpenGL's.
pub fn floor_falloff() -> Result<Drawn, FigureError> {
    use crate::raster::kernel::RangeWindow;
    let size = (320, 240);
    let floor = |window: Option<RangeWindow>| -> Result<RgbImage, FigureError> {
        let mut world = presets::bench_scene_at("floor-lights256", aspect(size))
            .ok_or_else(|| FigureError::Invalid("no floor-lights256 scene".into()))?;
        world.range_window = window;
        render(&world, size)
    };
    let nominal = crate::study::window::NOMINAL_RANGE;
    let faithful = crate::study::window::faithful_range()
        .ok_or_else(|| FigureError::Invalid("study::window has no faithful range".into()))?;
    let plain = floor(None)?;
    let near = floor(Some(RangeWindow { range: nominal, cull: false }))?;
    let culled = floor(Some(RangeWindow { range: nominal, cull: true }))?;
    let far = floor(Some(RangeWindow { range: faithful, cull: false }))?;
    let heat_near = super::compare::heat_map(&plain, &near, FALLOFF_HEAT_LEVELS)?;
    let heat_far = super::compare::heat_map(&plain, &far, FALLOFF_HEAT_LEVELS)?;
    let labels = [
        "LearnOpenGL 1/(1 + 0.7d + 1.8d²)".to_owned(),
        format!("times the window at r = {nominal}"),
        format!("times the window at r = {faithful}"),
        format!("window at {nominal}, culled beyond it"),
        format!("difference, r = {nominal} (0 to {FALLOFF_HEAT_LEVELS} levels)"),
        format!("difference, r = {faithful} (0 to {FALLOFF_HEAT_LEVELS} levels)"),
    ];
    let images = [&plain, &near, &far, &culled, &heat_near, &heat_far];
    let panels: Vec<(&RgbImage, &str)> = images.iter().zip(&labels).map(|(i, l)| (*i, l.as_str())).collect();
    Drawn::grid(&panels, 3)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn dimensions(png: &[u8]) -> (u32, u32) {
        let img = image::load_from_memory(png).unwrap();
        (img.width(), img.height())
    }

    #[test]
    fn the_2x_copies_are_twice_the_size() {
        // A single render doubles exactly.
        assert_eq!(dimensions(&coral_cube_png(1).unwrap().png(Lang::En).unwrap()), (480, 360));
        assert_eq!(dimensions(&coral_cube_png(2).unwrap().png(Lang::En).unwrap()), (960, 720));
        // A grid doubles its panels; its labels and gaps keep their pixel size, so the
        // 2× grid is (2w − extra_w) × (2h − extra_h) with the 1× grid's fixed parts.
        let (w1, h1) = dimensions(&phong_terms_png(1).unwrap().png(Lang::En).unwrap());
        let (w2, h2) = dimensions(&phong_terms_png(2).unwrap().png(Lang::En).unwrap());
        let (pw, ph) = HALF;
        assert_eq!((w2 - w1, h2 - h1), (2 * pw, 2 * ph), "two columns and two rows of panels grow by one panel each");
        // every scalable render has a distinct name (the artifact paths)
        let names: std::collections::BTreeSet<&str> = SCALABLE.iter().map(|(n, _)| *n).collect();
        assert_eq!(names.len(), SCALABLE.len());
    }

    #[test]
    fn every_preset_render_is_lit_and_not_blank() {
        // The clear color 0.1 is 26 levels; a pixel above 40 levels is lit geometry.
        // At least 1 % of the pixels must be lit (the smallest scene, the container
        // with its lamp, covers several per cent), or the scene fell out of view.
        for name in ["coral-cube", "container", "casters-point", "multiple-lights"] {
            let img = preset_image(name, (96, 72)).unwrap();
            let lit = img.pixels().filter(|p| p.0.iter().any(|&c| c > 40)).count();
            assert!(lit * 100 > img.pixels().len(), "{name}: {lit} lit pixels");
        }
    }

    #[test]
    fn the_terms_add_up_to_the_sum() {
        // Each channel of the sum equals the sum of the three terms' channels up to the
        // three roundings to 8 bits (at most 1.5 levels) and the clamp at 255.
        let base = preset("coral-cube", (64, 48)).unwrap();
        let with = |a: f32, d: f32, s: f32| {
            let mut w = base.clone();
            let p = &mut w.lights.point_lights[0].props;
            (p.ambient, p.diffuse, p.specular) = (p.ambient * a, p.diffuse * d, p.specular * s);
            w.clear = glam::Vec4::ZERO;
            render(&w, (64, 48)).unwrap()
        };
        let (a, d, s, all) = (with(1.0, 0.0, 0.0), with(0.0, 1.0, 0.0), with(0.0, 0.0, 1.0), with(1.0, 1.0, 1.0));
        for (((pa, pd), ps), pall) in a.pixels().zip(d.pixels()).zip(s.pixels()).zip(all.pixels()) {
            for c in 0..3 {
                let sum = (i32::from(pa.0[c]) + i32::from(pd.0[c]) + i32::from(ps.0[c])).min(255);
                assert!((sum - i32::from(pall.0[c])).abs() <= 2, "terms {sum} vs sum {}", pall.0[c]);
            }
        }
    }

    #[test]
    fn gouraud_differs_from_phong_less_as_the_sphere_gets_finer() {
        let diff = |t| {
            let p = render(&sphere_world(coral_basic(), t, ShadingMode::Phong, (96, 96)), (96, 96)).unwrap();
            let g = render(&sphere_world(coral_basic(), t, ShadingMode::Gouraud, (96, 96)), (96, 96)).unwrap();
            super::super::compare::diff_stats(&p, &g).unwrap().mean_levels
        };
        let (coarse, fine) = (diff((8, 16)), diff((32, 64)));
        assert!(coarse > fine && fine > 0.0, "coarse {coarse}, fine {fine}");
    }

    #[test]
    fn the_learnopengl_model_in_the_fragment_stage_matches_the_kernel() {
        // Two f32 evaluations of the same formula in a different order: they may round to
        // neighbouring 8-bit levels, never further apart (1 level).
        let size = (96, 72);
        let model = model_image(ShadingModel::LearnOpenGL, size).unwrap();
        let mut world = close_preset("coral-cube", size).unwrap();
        world.camera = tight_camera(size).unwrap();
        let kernel = render(&world, size).unwrap();
        let s = super::super::compare::diff_stats(&kernel, &model).unwrap();
        assert!(s.max_levels <= 1, "max {} levels, {} pixels beyond one", s.max_levels, s.beyond_one_level);
    }

    #[test]
    fn the_raster_sphere_is_close_to_the_ray_cast_one() {
        // Mean difference under 1 level: away from the silhouette both shade the same
        // formula, and the silhouette covers a small fraction of the pixels.
        let c = raster_raycast_compare().unwrap();
        assert!(c.stats.mean_levels < 1.0, "mean {}", c.stats.mean_levels);
        assert!(c.flip < 0.05, "flip {}", c.flip);
        assert!(raster_raycast_caption(&c).contains(&format!("{:.4}", c.flip)));
    }
}
