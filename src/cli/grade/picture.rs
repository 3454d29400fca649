//! The feedback picture: the student's shader and the reference on the chapter's scene,
//! side by side, with a difference heat map, all three drawn on llvmpipe.
//!
//! The scene is DESIGN.md's `quad-single`, a full-screen quad whose fragments carry
//! `FragPos = (x·4/3, y, 0)` and `Normal = (x/2, y/2, 1)` (x, y in NDC), with Basic
//! lighting's constants where the model has them (`lightPos` (1.2, 1, 2), `viewPos`
//! (0, 0, 3), white light, coral object, ambient 0.1, specular 0.5, shininess 32). The
//! model's other inputs keep the value of one generated case, the same in every pixel.
//! Both shaders run through the check's own batches (the student's as
//! [`crate::checker::check::CompiledShader::run`], the reference as the exercise's function
//! file, [`crate::checker::diagnose::run_functions`]), so the picture shows exactly what the
//! check compared. Models without `FragPos` and `Normal` inputs, a function file, or with
//! a vertex shader handed in get no picture.
//!
//! A spot-light model ([`Scene::Spot`]: its layout has `light.cutOff`) would leave the
//! quad dark under a spot aimed at random: its picture is Light casters' flashlight
//! instead, the spot at the camera (0, 0, 3) aimed down -z, cut-offs 12.5° and 17.5°,
//! LearnOpenGL's attenuation (1, 0.09, 0.032) and light strengths (0.1, 0.8, 1), so the
//! spot's disc and soft edge fall on the quad (its radius at z = 0 is 3·tan 17.5° ≈ 0.95).

use std::path::Path;

use glam::Vec3;

use crate::checker::check::{self, Mapping};
use crate::exercises::{Check, Exercise};
use crate::gl::GlContext;
use crate::oracle::cases::{Group, Slot};

/// Width and height of each of the three panels, in pixels.
pub const PANEL: (u32, u32) = (160, 120);

/// The largest difference the heat map shows at full brightness: 0.25 in any channel is a
/// mistake anyone sees; the bounds the check accepts are below 10⁻⁴, so black is "agrees".
pub const HEAT_FULL_SCALE: f32 = 0.25;

/// Basic lighting's constants (DESIGN.md, quad-single), by the tutorial's names.
const CHAPTER: &[(&str, [f32; 3])] = &[
    ("lightPos", [1.2, 1.0, 2.0]),
    ("viewPos", [0.0, 0.0, 3.0]),
    ("lightColor", [1.0, 1.0, 1.0]),
    ("objectColor", [1.0, 0.5, 0.31]),
    ("ambientStrength", [0.1; 3]),
    ("specularStrength", [0.5; 3]),
    ("shininess", [32.0; 3]),
];

/// Light casters' flashlight (LearnOpenGL, Light casters, "Spotlight" and "Smooth/soft
/// edges": the spot at the camera, `cutOff = cos(12.5°)`, `outerCutOff = cos(17.5°)`,
/// attenuation (1, 0.09, 0.032), ambient 0.1, diffuse 0.8, specular 1).
const FLASHLIGHT: &[(&str, [f32; 3])] = &[
    ("viewPos", [0.0, 0.0, 3.0]),
    ("light.position", [0.0, 0.0, 3.0]),
    ("light.direction", [0.0, 0.0, -1.0]),
    ("light.cutOff", [crate::gl::layout::SPOT_CUT_OFFS.0; 3]),
    ("light.outerCutOff", [crate::gl::layout::SPOT_CUT_OFFS.1; 3]),
    ("light.constant", [1.0; 3]),
    ("light.linear", [0.09; 3]),
    ("light.quadratic", [0.032; 3]),
    ("light.ambient", [0.1; 3]),
    ("light.diffuse", [0.8; 3]),
    ("light.specular", [1.0; 3]),
    ("material.shininess", [32.0; 3]),
];

/// The scene a picture is drawn on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scene {
    /// Basic lighting's: the quad lit from (1.2, 1, 2).
    Basic,
    /// Light casters' flashlight: a spot at the camera aimed at the quad.
    Spot,
}

/// The scene of `exercise`'s picture: [`Scene::Spot`] when its model has a spot's cut-off.
pub fn scene_of(exercise: &Exercise) -> Scene {
    let spot = exercise.model().is_some_and(|m| m.layout().find("light.cutOff").is_some());
    if spot {
        Scene::Spot
    } else {
        Scene::Basic
    }
}

fn write(row: &mut [[f32; 4]], input: usize, offset: usize, values: &[f32]) {
    for (i, &x) in values.iter().enumerate() {
        if let Some(slot) = row.get_mut(input + (offset + i) / 4) {
            slot[(offset + i) % 4] = x;
        }
    }
}

fn heat(d: f32) -> [u8; 3] {
    // Black, red, yellow, white as the difference grows to HEAT_FULL_SCALE.
    let t = (d / HEAT_FULL_SCALE).clamp(0.0, 1.0) * 3.0;
    let c = |x: f32| (x.clamp(0.0, 1.0) * 255.0).round() as u8;
    [c(t), c(t - 1.0), c(t - 2.0)]
}

fn to8(x: f32) -> u8 {
    if x.is_finite() {
        (x.clamp(0.0, 1.0) * 255.0).round() as u8
    } else {
        255
    }
}

// String error: the caller prints it as a note; the verdict stands without a picture.
/// Renders the picture for `answer` (a fragment shader) of `exercise`, with `extra`
/// merged over the exercise's mapping, and writes it as a PNG to `path`.
pub fn render(
    ctx: &GlContext,
    exercise: &Exercise,
    answer: &str,
    extra: &Mapping,
    seed: u64,
    path: &Path,
) -> Result<(), String> {
    let (model_name, mapping_toml) = match exercise.check {
        Check::Shader { model, mapping } | Check::Variant { model, mapping, .. } => (model, mapping),
        _ => return Err("not a shader exercise".into()),
    };
    let functions = exercise.functions().ok_or("the model has no function file to draw the reference with")?;
    let mut mapping = if mapping_toml.is_empty() {
        Mapping::default()
    } else {
        check::parse_mapping(mapping_toml).map_err(|e| e.to_string())?
    };
    mapping.names.extend(extra.names.iter().map(|(k, v)| (k.clone(), v.clone())));
    mapping.values.extend(extra.values.iter().map(|(k, v)| (k.clone(), *v)));
    let shader = check::compile_shader(ctx, answer, model_name, &mapping).map_err(|e| e.to_string())?;
    let model = shader.model();
    let layout = model.layout;
    let slot = |name: &str| match layout.find(name).map(|q| q.slot) {
        Some(Slot::Case { input, offset }) => Some((input, offset)),
        _ => None,
    };
    let (Some(frag_pos), Some(normal)) = (slot("FragPos"), slot("Normal")) else {
        return Err(format!("model {model_name} has no FragPos and Normal inputs to draw the scene with"));
    };
    let first = shader.generate(1, seed).map_err(|e| e.to_string())?.into_iter().next().ok_or("no case")?;
    let base = first.rows.first().cloned().ok_or("no case")?;
    let (w, h) = PANEL;
    let mut rows = Vec::with_capacity((w * h) as usize);
    for py in 0..h {
        for px in 0..w {
            // Pixel centres in NDC, y up.
            let x = (px as f32 + 0.5) / w as f32 * 2.0 - 1.0;
            let y = 1.0 - (py as f32 + 0.5) / h as f32 * 2.0;
            let mut row = base.clone();
            let constants = match scene_of(exercise) {
                Scene::Basic => CHAPTER,
                Scene::Spot => FLASHLIGHT,
            };
            for &(name, value) in constants {
                if let (Some((input, offset)), Some(q)) = (slot(name), layout.find(name)) {
                    write(&mut row, input, offset, &value[..q.components.min(3)]);
                }
            }
            write(&mut row, frag_pos.0, frag_pos.1, &Vec3::new(x * 4.0 / 3.0, y, 0.0).to_array());
            write(&mut row, normal.0, normal.1, &Vec3::new(x / 2.0, y / 2.0, 1.0).to_array());
            rows.push(row);
        }
    }
    let groups = vec![Group { uniforms: first.uniforms.clone(), scene: first.scene.clone(), rows }];
    let student = shader.run(&groups).map_err(|e| e.to_string())?;
    let reference =
        crate::checker::diagnose::run_functions(ctx, model, &functions, &groups).map_err(|e| e.to_string())?;
    let mut img = image::RgbImage::new(3 * w + 8, h);
    for (k, (s, r)) in student[0].iter().zip(&reference[0]).enumerate() {
        let (px, py) = (k as u32 % w, k as u32 / w);
        img.put_pixel(px, py, image::Rgb([to8(s[0]), to8(s[1]), to8(s[2])]));
        img.put_pixel(w + 4 + px, py, image::Rgb([to8(r[0]), to8(r[1]), to8(r[2])]));
        let d =
            (0..3).map(|c| (s[c] - r[c]).abs()).fold(0.0f32, |m, x| if x.is_nan() { f32::INFINITY } else { m.max(x) });
        img.put_pixel(2 * w + 8 + px, py, image::Rgb(heat(d)));
    }
    let mut png = Vec::new();
    image::DynamicImage::ImageRgb8(img)
        .write_to(&mut std::io::Cursor::new(&mut png), image::ImageFormat::Png)
        .map_err(|e| e.to_string())?;
    crate::outfile::write_atomically(path, png).map_err(|e| e.to_string())
}
