//! The benchmark scenes through OpenGL (Mesa llvmpipe here): `lightlab bench --llvmpipe`.
//!
//! Each scene is the one the CPU back end draws ([`crate::raster::presets::bench_scene`]):
//! the same meshes, model, view and projection matrices, lights and material, turned into
//! vertex buffers and uniforms here, and drawn with the tutorials' shaders
//! (`src/gl/shaders/bench/`, the GLSL of `../shared/tools/llvmpipe_bench.py`) into an
//! 800 × 600 RGBA32F target with a depth buffer. Timing follows the script and the CPU
//! bench: one frame to count fragments (alpha > 0 after a transparent clear), three warm-up
//! frames, then `runs` runs of `frames` frames, each run closed by `glFinish`.
//!
//! | scene | program |
//! | --- | --- |
//! | `quad-single` | `quad.vert` + `single.frag` (Basic lighting) |
//! | `quad-multi` | `quad.vert` + the Multiple lights shader |
//! | `quad-multi-ATM` | `quad.vert` + the Multiple lights shader, the atmosphere's uniforms |
//! | `cube-multi`, `sphere4096-multi`, `sphere4096-multi-ATM` | `mesh.vert` + the Multiple lights shader |
//! | `sphere4096-gouraud` | the Multiple lights shader in the vertex stage, colour interpolated |
//! | `floor-lights256` | `mesh.vert` + `many.frag` (256 point lights in a loop) |

use glam::Vec3;
use glow::HasContext;

use super::ColorTarget;
use crate::gl::batch::{apply_uniform, gl_check, program, Uniform};
use crate::gl::layout::scene_uniforms;
use crate::gl::{GlContext, GlError};
use crate::phong::BasicLighting;
use crate::raster::pipeline::{Geometry, World};
use crate::raster::presets::{bench_scene, BENCH_SIZE};
use crate::raster::rasterize::CullMode;
use crate::raster::shade::{ShadingMode, Surface};

const MESH_VERT: &str = include_str!("../../gl/shaders/bench/mesh.vert");
const QUAD_VERT: &str = include_str!("../../gl/shaders/bench/quad.vert");
const SINGLE_FRAG: &str = include_str!("../../gl/shaders/bench/single.frag");
const MANY_FRAG: &str = include_str!("../../gl/shaders/bench/many.frag");
const GOURAUD_FRAG: &str = include_str!("../../gl/shaders/bench/gouraud.frag");
const MULTI_FRAG: &str = concat!(
    "#version 330 core\nout vec4 FragColor;\nin vec3 FragPos;\nin vec3 Normal;\n",
    include_str!("../../gl/shaders/bench/multi_lights.glsl"),
    include_str!("../../gl/shaders/bench/multi_main.frag")
);
const GOURAUD_VERT: &str = concat!(
    "#version 330 core\nin vec3 aPos;\nin vec3 aNormal;\nuniform mat4 model, view, projection;\nout vec3 Color;\n",
    include_str!("../../gl/shaders/bench/multi_lights.glsl"),
    include_str!("../../gl/shaders/bench/gouraud_main.vert")
);

/// Point lights the Multiple lights shader has (`NR_POINT_LIGHTS`); a scene with more is
/// drawn with `many.frag`.
const MULTI_POINT_LIGHTS: usize = 4;

/// One scene's GL measurement.
#[derive(Clone, Debug, PartialEq)]
pub struct GlBenchRun {
    /// Covered pixels of one frame (alpha > 0).
    pub fragments: usize,
    /// Milliseconds per frame of each run.
    pub runs_ms: Vec<f64>,
    /// The renderer string (`llvmpipe (LLVM …)`).
    pub renderer: String,
    /// The first frame, linear RGBA floats, 800 × 600, bottom row first (as GL reads).
    pub rgba: Vec<f32>,
}

/// What one scene draws: its program's sources, vertex data and uniforms.
struct Draw {
    vertex: &'static str,
    fragment: &'static str,
    /// Interleaved `aPos, aNormal` (6 floats a vertex), or the quad's `p` (2 floats).
    vertices: Vec<f32>,
    /// Triangle indices (meshes), empty for the quad's strip.
    indices: Vec<u32>,
    uniforms: Vec<(String, Uniform)>,
    cull_back: bool,
    depth_test: bool,
}

/// The draw of benchmark scene `name`, from the CPU back end's description of it.
fn draw_for(name: &str) -> Result<Draw, GlError> {
    let unknown = || GlError::Input { field: "scene".into(), reason: format!("unknown benchmark scene {name:?}") };
    let world: World = bench_scene(name).ok_or_else(unknown)?;
    draw_of(&world, name == "quad-single")
}

/// The draw of `world`'s first object with its lights (`single`: the Basic lighting shader
/// of quad-single instead of the Multiple lights one).
fn draw_of(world: &World, single: bool) -> Result<Draw, GlError> {
    let object = world
        .objects
        .first()
        .ok_or_else(|| GlError::Input { field: "scene".into(), reason: "a world with no object".into() })?;
    let v3 = |x: Vec3| Uniform::Vec3(x.to_array());
    let mut uniforms: Vec<(String, Uniform)> = vec![("viewPos".into(), v3(world.camera.eye))];
    if let Surface::Material(m) = &object.surface {
        uniforms.push(("material.diffuse".into(), v3(m.diffuse)));
        uniforms.push(("material.specular".into(), v3(m.specular)));
        uniforms.push(("material.shininess".into(), Uniform::Float(m.shininess)));
    }
    let lights = &world.lights;
    let many = lights.point_lights.len() > MULTI_POINT_LIGHTS;
    if single {
        // the CPU scene is built from the chapter's BasicLighting: the shader takes its uniforms
        let b = BasicLighting::learnopengl();
        uniforms = vec![
            ("lightPos".into(), v3(b.light_pos)),
            ("viewPos".into(), v3(b.view_pos)),
            ("lightColor".into(), v3(b.light_color)),
            ("objectColor".into(), v3(b.object_color)),
        ];
    } else if many {
        for (k, l) in lights.point_lights.iter().enumerate() {
            uniforms.push((format!("lightPositions[{k}]"), v3(l.position)));
            // many.frag scales one colour by 0.05, 0.8 and 1: the specular intensity is it
            uniforms.push((format!("lightColors[{k}]"), v3(l.props.specular)));
        }
    } else {
        uniforms.extend(scene_uniforms(lights));
    }
    let (vertex, fragment, vertices, indices) = match &object.geometry {
        Geometry::NdcQuad => {
            let fragment = if single { SINGLE_FRAG } else { MULTI_FRAG };
            (QUAD_VERT, fragment, vec![-1.0, -1.0, 1.0, -1.0, -1.0, 1.0, 1.0, 1.0], Vec::new())
        }
        Geometry::Mesh(mesh) => {
            uniforms.push(("model".into(), Uniform::Mat4(object.model.to_cols_array())));
            uniforms.push(("view".into(), Uniform::Mat4(world.camera.view.to_cols_array())));
            uniforms.push(("projection".into(), Uniform::Mat4(world.camera.projection.to_cols_array())));
            let vertices = mesh.positions.iter().zip(&mesh.normals).flat_map(|(p, n)| [p.x, p.y, p.z, n.x, n.y, n.z]);
            let indices = mesh.triangles.iter().flatten().copied().collect();
            let (vertex, fragment) = match (world.shading, many) {
                (ShadingMode::Gouraud, _) => (GOURAUD_VERT, GOURAUD_FRAG),
                (_, true) => (MESH_VERT, MANY_FRAG),
                _ => (MESH_VERT, MULTI_FRAG),
            };
            (vertex, fragment, vertices.collect(), indices)
        }
    };
    Ok(Draw {
        vertex,
        fragment,
        vertices,
        indices,
        uniforms,
        cull_back: object.cull == CullMode::Back,
        depth_test: world.depth_test,
    })
}

/// Draws benchmark scene `name` on `ctx` and times it (see the module docs).
///
/// Errors: [`GlError::Input`] for an unknown scene; [`GlError::Compile`]/[`GlError::Link`]
/// if the driver rejects a shader; [`GlError::Gl`] or [`GlError::Framebuffer`] if a GL
/// object cannot be made.
pub fn run_scene(ctx: &GlContext, name: &str, runs: usize, frames: usize) -> Result<GlBenchRun, GlError> {
    run_draw(ctx, draw_for(name)?, ColorTarget::Float, runs, frames)
}

/// [`run_scene`] with a `target` colour renderbuffer: `GL_RGBA32F` or `GL_RGBA8` (read
/// back as floats, `k/255`).
pub fn run_scene_in(
    ctx: &GlContext,
    name: &str,
    target: ColorTarget,
    runs: usize,
    frames: usize,
) -> Result<GlBenchRun, GlError> {
    run_draw(ctx, draw_for(name)?, target, runs, frames)
}

/// Draws `world` (its first object, with the Multiple lights shaders, or the 256-light one
/// for more than four point lights) on `ctx` and times it, as [`run_scene`]: for scenes
/// that are not named benchmark scenes, such as the triangle-size sweep's spheres.
pub fn run_world(ctx: &GlContext, world: &World, runs: usize, frames: usize) -> Result<GlBenchRun, GlError> {
    run_draw(ctx, draw_of(world, false)?, ColorTarget::Float, runs, frames)
}

/// [`run_world`] with a `target` colour renderbuffer, as [`run_scene_in`].
pub fn run_world_in(
    ctx: &GlContext,
    world: &World,
    target: ColorTarget,
    runs: usize,
    frames: usize,
) -> Result<GlBenchRun, GlError> {
    run_draw(ctx, draw_of(world, false)?, target, runs, frames)
}

fn run_draw(
    ctx: &GlContext,
    draw: Draw,
    target: ColorTarget,
    runs: usize,
    frames: usize,
) -> Result<GlBenchRun, GlError> {
    let gl = ctx.gl();
    let (w, h) = (BENCH_SIZE.0 as i32, BENCH_SIZE.1 as i32);
    let program = program(gl, draw.vertex, draw.fragment, draw.fragment)?;
    // SAFETY: GL calls on the current context with objects created here and deleted below.
    unsafe {
        gl.use_program(Some(program));
        for (uniform, value) in &draw.uniforms {
            let Some(loc) = gl.get_uniform_location(program, uniform) else { continue }; // optimized away
            apply_uniform(gl, &loc, value);
        }
        let vao = gl.create_vertex_array().map_err(made("glGenVertexArrays"))?;
        gl.bind_vertex_array(Some(vao));
        let vbo = gl.create_buffer().map_err(made("glGenBuffers"))?;
        gl.bind_buffer(glow::ARRAY_BUFFER, Some(vbo));
        gl.buffer_data_u8_slice(glow::ARRAY_BUFFER, bytes_of(&draw.vertices), glow::STATIC_DRAW);
        let mesh = !draw.indices.is_empty();
        let attributes: &[(&str, i32, i32)] = if mesh { &[("aPos", 3, 0), ("aNormal", 3, 3)] } else { &[("p", 2, 0)] };
        let stride = if mesh { 6 * 4 } else { 2 * 4 };
        for &(attribute, size, offset) in attributes {
            if let Some(loc) = gl.get_attrib_location(program, attribute) {
                gl.enable_vertex_attrib_array(loc);
                gl.vertex_attrib_pointer_f32(loc, size, glow::FLOAT, false, stride, offset * 4);
            }
        }
        let ibo = if mesh {
            let ibo = gl.create_buffer().map_err(made("glGenBuffers"))?;
            gl.bind_buffer(glow::ELEMENT_ARRAY_BUFFER, Some(ibo));
            let bytes = std::slice::from_raw_parts(draw.indices.as_ptr().cast::<u8>(), draw.indices.len() * 4);
            gl.buffer_data_u8_slice(glow::ELEMENT_ARRAY_BUFFER, bytes, glow::STATIC_DRAW);
            Some(ibo)
        } else {
            None
        };
        let fbo = gl.create_framebuffer().map_err(made("glGenFramebuffers"))?;
        gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
        let color = gl.create_renderbuffer().map_err(made("glGenRenderbuffers"))?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(color));
        let format = match target {
            ColorTarget::Float => glow::RGBA32F,
            ColorTarget::Rgba8 => glow::RGBA8,
        };
        gl.renderbuffer_storage(glow::RENDERBUFFER, format, w, h);
        gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::COLOR_ATTACHMENT0, glow::RENDERBUFFER, Some(color));
        let depth = gl.create_renderbuffer().map_err(made("glGenRenderbuffers"))?;
        gl.bind_renderbuffer(glow::RENDERBUFFER, Some(depth));
        gl.renderbuffer_storage(glow::RENDERBUFFER, glow::DEPTH_COMPONENT24, w, h);
        gl.framebuffer_renderbuffer(glow::FRAMEBUFFER, glow::DEPTH_ATTACHMENT, glow::RENDERBUFFER, Some(depth));
        let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
        let result = if status != glow::FRAMEBUFFER_COMPLETE {
            Err(GlError::Framebuffer { status })
        } else {
            gl.viewport(0, 0, w, h);
            gl.disable(glow::BLEND);
            if draw.depth_test {
                gl.enable(glow::DEPTH_TEST)
            } else {
                gl.disable(glow::DEPTH_TEST)
            }
            if draw.cull_back {
                gl.enable(glow::CULL_FACE)
            } else {
                gl.disable(glow::CULL_FACE)
            }
            gl.cull_face(glow::BACK);
            gl.clear_color(0.0, 0.0, 0.0, 0.0);
            gl.clear_depth_f32(1.0);
            let count = draw.indices.len() as i32;
            let frame = || {
                gl.clear(glow::COLOR_BUFFER_BIT | glow::DEPTH_BUFFER_BIT);
                if mesh {
                    gl.draw_elements(glow::TRIANGLES, count, glow::UNSIGNED_INT, 0);
                } else {
                    gl.draw_arrays(glow::TRIANGLE_STRIP, 0, 4);
                }
            };
            time_frames(gl, w, h, runs, frames, frame).map(|(rgba, runs_ms)| GlBenchRun {
                fragments: rgba.chunks_exact(4).filter(|p| p[3] > 0.0).count(),
                runs_ms,
                renderer: ctx.info().renderer.clone(),
                rgba,
            })
        };
        gl.bind_framebuffer(glow::FRAMEBUFFER, None);
        gl.delete_framebuffer(fbo);
        gl.delete_renderbuffer(color);
        gl.delete_renderbuffer(depth);
        gl.delete_buffer(vbo);
        if let Some(ibo) = ibo {
            gl.delete_buffer(ibo);
        }
        gl.delete_vertex_array(vao);
        gl.delete_program(program);
        result
    }
}

/// One frame read back, three warm-up frames, then `runs` runs of `frames` frames: `(the
/// first frame's RGBA, ms per frame of each run)`.
///
/// # Safety
/// A current GL context with the scene's program, buffers and framebuffer bound.
unsafe fn time_frames(
    gl: &glow::Context,
    w: i32,
    h: i32,
    runs: usize,
    frames: usize,
    frame: impl Fn(),
) -> Result<(Vec<f32>, Vec<f64>), GlError> {
    // SAFETY: as the caller guarantees.
    unsafe {
        frame();
        gl.finish();
        gl_check(gl, "glDrawElements")?;
        let mut rgba = vec![0.0f32; (w * h * 4) as usize];
        let bytes = std::slice::from_raw_parts_mut(rgba.as_mut_ptr().cast::<u8>(), rgba.len() * 4);
        gl.read_pixels(0, 0, w, h, glow::RGBA, glow::FLOAT, glow::PixelPackData::Slice(Some(bytes)));
        gl_check(gl, "glReadPixels")?;
        for _ in 0..3 {
            frame();
        }
        gl.finish();
        // each run ends with glFinish inside its timed span, as the script's
        let runs_ms = crate::timing::time_runs(runs, frames, &frame, || gl.finish());
        Ok((rgba, runs_ms))
    }
}

/// The error of a GL object that could not be made by `call`.
fn made(call: &'static str) -> impl Fn(String) -> GlError {
    move |detail| GlError::Gl { call: call.into(), detail }
}

/// `f32`s as bytes for a buffer upload.
fn bytes_of(v: &[f32]) -> &[u8] {
    // SAFETY: f32 has no padding and u8 alignment 1; the length is exact.
    unsafe { std::slice::from_raw_parts(v.as_ptr().cast::<u8>(), std::mem::size_of_val(v)) }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_scene_has_a_draw_with_its_programs_inputs() {
        for name in crate::raster::presets::all_bench_scenes() {
            let name = name.as_str();
            let d = draw_for(name).unwrap();
            assert!(!d.vertices.is_empty(), "{name}");
            let has = |u: &str| d.uniforms.iter().any(|(n, _)| n == u);
            assert!(has("viewPos"), "{name}");
            if d.fragment == MANY_FRAG {
                assert!(has("lightPositions[255]") && has("lightColors[255]"), "{name}");
            }
            if d.fragment == MULTI_FRAG || d.vertex == GOURAUD_VERT {
                assert!(has("pointLights[3].quadratic") && has("spotLight.outerCutOff"), "{name}");
            }
        }
        assert!(draw_for("no-such-scene").is_err());
    }

    /// `many.frag` bakes the floor lights' intensities (0.05, 0.8, 1 times the colour) and
    /// attenuation (1, 0.7, 1.8): they must be the CPU scene's.
    #[test]
    fn the_floor_shaders_constants_are_the_scenes() {
        let scene = crate::raster::presets::floor_lights();
        for l in &scene.point_lights {
            let c = l.props.specular;
            assert_eq!(l.props.ambient, 0.05 * c);
            assert_eq!(l.props.diffuse, 0.8 * c);
            let a = l.attenuation;
            assert_eq!((a.constant, a.linear, a.quadratic), (1.0, 0.7, 1.8));
        }
        assert!(MANY_FRAG.contains("const float Kc = 1.0, Kl = 0.7, Kq = 1.8;"));
        assert!(MANY_FRAG.contains("0.05 * lightColors[i]") && MANY_FRAG.contains("0.8 * lightColors[i]"));
    }
}
