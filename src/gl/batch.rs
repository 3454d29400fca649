//! Evaluate a GLSL function over many cases in one draw call.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `N` | number of cases in one [`Batch::run`] |
//! | `K` | number of inputs per case (`vec4` each), 1 ..= [`MAX_INPUTS`] |
//! | `M` | number of outputs per case (`vec4` each), 1 ..= [`MAX_OUTPUTS`] |
//! | `W` | texture width, `min(N, 4096)` |
//! | `H` | texture rows, `ceil(N / W)` |
//!
//! Case `i` lives at texel `(i % W, i / W)` of K RGBA32F input textures. One full-screen
//! triangle covers the `W x H` viewport; each fragment reads its inputs with
//! `texelFetch(lightlab_input_k, ivec2(gl_FragCoord.xy), 0)` and writes M RGBA32F color
//! attachments, read back as floats. No value is clamped or quantized on the way.
//!
//! # The body
//! The caller's GLSL (version 330 core) must define
//! ```glsl
//! void batch_main(in vec4 inputs[LIGHTLAB_N_INPUTS], out vec4 outputs[LIGHTLAB_N_OUTPUTS]);
//! ```
//! `LIGHTLAB_N_INPUTS` and `LIGHTLAB_N_OUTPUTS` are defined before the body. The body is
//! compiled after `#line 1 1`, so the line numbers in the driver's messages (`0:LINE(COL)`
//! on Mesa, which keeps reporting source string 0) point into the body itself. The generated
//! `main` after the body restarts at `#line 1 2`.

use std::time::{Duration, Instant};

use glow::HasContext;

use super::context::{GlContext, GlError};

/// Widest input texture, in texels. GL 3.3 only guarantees `GL_MAX_TEXTURE_SIZE >= 1024`,
/// so the width is also capped by the driver's limit.
pub const MAX_WIDTH: usize = 4096;
/// Most rows drawn in one draw call; larger batches are split into several draws.
pub const MAX_ROWS_PER_DRAW: usize = 1024;
/// Most inputs per case (GL 3.3 guarantees 16 fragment texture units).
pub const MAX_INPUTS: usize = 16;
/// Most outputs per case (GL 3.3 guarantees 8 draw buffers; the pair check's vertex stage
/// writes up to 7 values and `gl_Position`).
pub const MAX_OUTPUTS: usize = 8;

const VERTEX_SHADER: &str = "#version 330 core
// One triangle covering clip space: (-1,-1), (3,-1), (-1,3).
void main() {
    vec2 p = vec2(float((gl_VertexID & 1) << 2) - 1.0, float((gl_VertexID & 2) << 1) - 1.0);
    gl_Position = vec4(p, 0.0, 1.0);
}
";

/// The results of a run: `outputs[m][i]` is output `m` of case `i`.
pub type Outputs = Vec<Vec<[f32; 4]>>;

/// Where the time of [`Batch::run_timed`] went, summed over its draws.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct BatchTiming {
    /// Creating and filling the input textures (`glTexSubImage2D`).
    pub upload: Duration,
    /// The draw call, up to `glFinish`.
    pub draw: Duration,
    /// Reading the outputs back (`glReadPixels`).
    pub read: Duration,
}

/// A value for [`Batch::set_uniform`]; the variant must match the GLSL type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Uniform {
    /// `int` or `bool`.
    Int(i32),
    /// `float`.
    Float(f32),
    /// `vec3`.
    Vec3([f32; 3]),
    /// `vec4`.
    Vec4([f32; 4]),
    /// `mat4`, column-major.
    Mat4([f32; 16]),
}

/// Sets the uniform at `loc` of the program in use to `value`.
///
/// # Safety
/// A GL context must be current, with the program that owns `loc` in use.
pub(crate) unsafe fn apply_uniform(gl: &glow::Context, loc: &glow::UniformLocation, value: &Uniform) {
    // SAFETY: the caller keeps the context current and the program in use.
    unsafe {
        match value {
            Uniform::Int(v) => gl.uniform_1_i32(Some(loc), *v),
            Uniform::Float(v) => gl.uniform_1_f32(Some(loc), *v),
            Uniform::Vec3(v) => gl.uniform_3_f32(Some(loc), v[0], v[1], v[2]),
            Uniform::Vec4(v) => gl.uniform_4_f32(Some(loc), v[0], v[1], v[2], v[3]),
            Uniform::Mat4(m) => gl.uniform_matrix_4_f32_slice(Some(loc), false, m),
        }
    }
}

/// A compiled program that evaluates one GLSL body over batches of cases.
#[derive(Debug)]
pub struct Batch<'a> {
    ctx: &'a GlContext,
    program: glow::Program,
    vao: glow::VertexArray,
    n_inputs: usize,
    n_outputs: usize,
}

/// Builds the complete fragment shader around `body` (see the module docs). `#extension`
/// lines at the start of `body` go right after `#version`: GLSL allows them only before
/// any code, and the batch's own declarations come before the body.
pub fn fragment_source(body: &str, n_inputs: usize, n_outputs: usize) -> String {
    let mut s = String::from("#version 330 core\n");
    let mut body = body;
    while let Some((line, rest)) = body.split_once('\n') {
        if !line.trim_start().strip_prefix('#').is_some_and(|d| d.trim_start().starts_with("extension")) {
            break;
        }
        s += line;
        s.push('\n');
        body = rest;
    }
    s += &format!("#define LIGHTLAB_N_INPUTS {n_inputs}\n#define LIGHTLAB_N_OUTPUTS {n_outputs}\n");
    for k in 0..n_inputs {
        s += &format!("uniform sampler2D lightlab_input_{k};\n");
    }
    for m in 0..n_outputs {
        s += &format!("layout(location = {m}) out vec4 lightlab_output_{m};\n");
    }
    s += "#line 1 1\n";
    s += body;
    s += "\n#line 1 2\nvoid main() {\n    ivec2 texel = ivec2(gl_FragCoord.xy);\n";
    s += "    vec4 inputs[LIGHTLAB_N_INPUTS];\n    vec4 outputs[LIGHTLAB_N_OUTPUTS];\n";
    for k in 0..n_inputs {
        s += &format!("    inputs[{k}] = texelFetch(lightlab_input_{k}, texel, 0);\n");
    }
    for m in 0..n_outputs {
        s += &format!("    outputs[{m}] = vec4(0.0);\n");
    }
    s += "    batch_main(inputs, outputs);\n";
    for m in 0..n_outputs {
        s += &format!("    lightlab_output_{m} = outputs[{m}];\n");
    }
    s += "}\n";
    s
}

/// Lines of `body` that a Mesa info log points at (`S:LINE(COL): ...`), numbered.
/// Falls back to the whole body, numbered, when the log names no body line.
pub fn log_excerpt(body: &str, log: &str) -> String {
    let lines: Vec<&str> = body.lines().collect();
    let mut wanted: Vec<usize> = log
        .lines()
        .filter_map(|l| {
            // Mesa writes `SOURCE:LINE(COLUMN): error: ...` and keeps SOURCE at 0 even
            // after `#line 1 1`, so only the line number is read.
            let (source, rest) = l.trim_start().split_once(':')?;
            if source.is_empty() || !source.bytes().all(|b| b.is_ascii_digit()) {
                return None;
            }
            let (line, _) = rest.split_once('(')?;
            line.parse::<usize>().ok()
        })
        .filter(|&n| n >= 1 && n <= lines.len())
        .collect();
    wanted.sort_unstable();
    wanted.dedup();
    let numbered = |n: usize| format!("{n:4} | {}", lines[n - 1]);
    if wanted.is_empty() {
        (1..=lines.len()).map(numbered).collect::<Vec<_>>().join("\n")
    } else {
        wanted.into_iter().map(numbered).collect::<Vec<_>>().join("\n")
    }
}

/// `Ok(object)` when its compile or link status is `ok`; otherwise its info log is read,
/// the object deleted, and the log turned into the error by `error`.
fn kept_if<T: Copy>(
    ok: bool,
    object: T,
    log: impl FnOnce(T) -> String,
    delete: impl FnOnce(T),
    error: impl FnOnce(String) -> GlError,
) -> Result<T, GlError> {
    if ok {
        return Ok(object);
    }
    let text = without_trailing_nuls(log(object));
    delete(object);
    Err(error(text))
}

/// An info log without the C string terminators some drivers leave at its end (a box glyph
/// on a terminal or in a page).
fn without_trailing_nuls(log: String) -> String {
    let kept = log.trim_end_matches('\0').len();
    let mut log = log;
    log.truncate(kept);
    log
}

fn compile(
    gl: &glow::Context,
    kind: u32,
    stage: &'static str,
    source: &str,
    body: &str,
) -> Result<glow::Shader, GlError> {
    // SAFETY: GL calls on the current context with owned objects.
    unsafe {
        let shader = gl.create_shader(kind).map_err(|detail| GlError::Gl { call: "glCreateShader".into(), detail })?;
        gl.shader_source(shader, source);
        gl.compile_shader(shader);
        let ok = gl.get_shader_compile_status(shader);
        kept_if(
            ok,
            shader,
            |s| gl.get_shader_info_log(s),
            |s| gl.delete_shader(s),
            |log| GlError::Compile { stage, excerpt: log_excerpt(body, &log), log },
        )
    }
}

/// Compiles a complete fragment shader (with its own `#version` line) without linking it,
/// to check its syntax and types on the real driver. Errors: [`GlError::Compile`] with the
/// info log and the numbered source lines it names.
pub fn compile_fragment(ctx: &GlContext, source: &str) -> Result<(), GlError> {
    let shader = compile(ctx.gl(), glow::FRAGMENT_SHADER, "fragment", source, source).map_err(explained)?;
    // SAFETY: deleting the shader just created on the current context.
    unsafe { ctx.gl().delete_shader(shader) };
    Ok(())
}

/// [`compile_fragment`] for a complete vertex shader.
pub fn compile_vertex(ctx: &GlContext, source: &str) -> Result<(), GlError> {
    let shader = compile(ctx.gl(), glow::VERTEX_SHADER, "vertex", source, source).map_err(explained)?;
    // SAFETY: deleting the shader just created on the current context.
    unsafe { ctx.gl().delete_shader(shader) };
    Ok(())
}

/// The line lightlab adds to Mesa's log of a shader written for a GLSL version it
/// does not read (an English msgid: the checker shows it in the learner's language).
pub const VERSION_NOTE: &str =
    "note: lightlab runs shaders on Mesa llvmpipe, which reads GLSL up to 4.50; the tutorials \
                                write `#version 330 core`, which is enough for every lighting shader";

/// What Mesa's log does not say about a shader written for another GLSL version: the
/// driver here (Mesa llvmpipe, OpenGL 4.5 core) reads GLSL up to 4.50, while editors'
/// templates often write `#version 460`. Other errors pass as they are.
fn explained(e: GlError) -> GlError {
    const VERSION: &str = "is not supported. Supported versions are";
    match e {
        GlError::Compile { stage, excerpt, mut log } if log.contains(VERSION) => {
            log.push_str(VERSION_NOTE);
            log.push('\n');
            GlError::Compile { stage, excerpt, log }
        }
        other => other,
    }
}

/// Compiles and links a vertex + fragment pair as written, so that the driver checks that
/// what the fragment shader reads, the vertex shader writes. Errors: [`GlError::Compile`] for either stage, [`GlError::Link`], [`GlError::Gl`].
pub fn link_pair(ctx: &GlContext, vertex: &str, fragment: &str) -> Result<(), GlError> {
    let program = program(ctx.gl(), vertex, fragment, fragment)?;
    // SAFETY: deleting the program just linked on the current context.
    unsafe { ctx.gl().delete_program(program) };
    Ok(())
}

/// Compiles `vertex` and `fragment` and links them. A fragment error's excerpt numbers the
/// lines of `fragment_body` (the part of the source the user wrote); the vertex shader is
/// deleted when the fragment shader fails.
///
/// Errors: [`GlError::Compile`] for either stage, [`GlError::Link`], [`GlError::Gl`].
pub(crate) fn program(
    gl: &glow::Context,
    vertex: &str,
    fragment: &str,
    fragment_body: &str,
) -> Result<glow::Program, GlError> {
    let vs = compile(gl, glow::VERTEX_SHADER, "vertex", vertex, vertex)?;
    let fs = match compile(gl, glow::FRAGMENT_SHADER, "fragment", fragment, fragment_body) {
        Ok(fs) => fs,
        Err(e) => {
            // SAFETY: deleting the shader created above.
            unsafe { gl.delete_shader(vs) };
            return Err(e);
        }
    };
    link(gl, vs, fs)
}

fn link(gl: &glow::Context, vs: glow::Shader, fs: glow::Shader) -> Result<glow::Program, GlError> {
    // SAFETY: GL calls on the current context with owned objects.
    unsafe {
        let program = gl.create_program().map_err(|detail| GlError::Gl { call: "glCreateProgram".into(), detail })?;
        gl.attach_shader(program, vs);
        gl.attach_shader(program, fs);
        gl.link_program(program);
        gl.detach_shader(program, vs);
        gl.detach_shader(program, fs);
        gl.delete_shader(vs);
        gl.delete_shader(fs);
        let ok = gl.get_program_link_status(program);
        kept_if(ok, program, |p| gl.get_program_info_log(p), |p| gl.delete_program(p), |log| GlError::Link { log })
    }
}

fn check_count(field: &str, n: usize, max: usize) -> Result<(), GlError> {
    if n == 0 || n > max {
        Err(GlError::Input { field: field.into(), reason: format!("{n} is outside 1..={max}") })
    } else {
        Ok(())
    }
}

pub(crate) fn gl_check(gl: &glow::Context, call: &str) -> Result<(), GlError> {
    // SAFETY: error query on the current context.
    let code = unsafe { gl.get_error() };
    if code == glow::NO_ERROR {
        Ok(())
    } else {
        Err(GlError::Gl { call: call.into(), detail: format!("GL error 0x{code:04X}") })
    }
}

/// Views `[f32; 4]` texels as bytes for upload.
fn as_bytes(texels: &[[f32; 4]]) -> &[u8] {
    // SAFETY: [f32; 4] has no padding; u8 has alignment 1; the length is exact.
    unsafe { std::slice::from_raw_parts(texels.as_ptr().cast::<u8>(), std::mem::size_of_val(texels)) }
}

/// Views `[f32; 4]` texels as mutable bytes for read-back (every bit pattern is a valid f32).
fn as_bytes_mut(texels: &mut [[f32; 4]]) -> &mut [u8] {
    let len = std::mem::size_of_val(texels);
    // SAFETY: as in `as_bytes`; any bytes written form valid f32 values.
    unsafe { std::slice::from_raw_parts_mut(texels.as_mut_ptr().cast::<u8>(), len) }
}

impl<'a> Batch<'a> {
    /// Compiles and links `body` (see the module docs for its contract) for `n_inputs`
    /// inputs and `n_outputs` outputs per case.
    ///
    /// Errors: [`GlError::Input`] for counts outside `1..=MAX_INPUTS` / `1..=MAX_OUTPUTS`
    /// (or above the driver's limits), [`GlError::Compile`] with the info log and the body
    /// lines it names, [`GlError::Link`].
    pub fn new(ctx: &'a GlContext, body: &str, n_inputs: usize, n_outputs: usize) -> Result<Batch<'a>, GlError> {
        check_count("n_inputs", n_inputs, MAX_INPUTS.min(ctx.info().max_texture_units.max(0) as usize))?;
        check_count("n_outputs", n_outputs, MAX_OUTPUTS.min(ctx.info().max_draw_buffers.max(0) as usize))?;
        let gl = ctx.gl();
        let fs_source = fragment_source(body, n_inputs, n_outputs);
        let program = program(gl, VERTEX_SHADER, &fs_source, body)?;
        // SAFETY: GL calls on the current context with owned objects.
        unsafe {
            gl.use_program(Some(program));
            for k in 0..n_inputs {
                let loc = gl.get_uniform_location(program, &format!("lightlab_input_{k}"));
                gl.uniform_1_i32(loc.as_ref(), k as i32);
            }
            let vao = match gl.create_vertex_array() {
                Ok(vao) => vao,
                Err(detail) => {
                    gl.delete_program(program);
                    return Err(GlError::Gl { call: "glGenVertexArrays".into(), detail });
                }
            };
            Ok(Batch { ctx, program, vao, n_inputs, n_outputs })
        }
    }

    /// Sets a uniform of the program for all later runs (for values shared by all cases,
    /// such as a scene's lights). Errors: [`GlError::Input`] naming `name` if the program
    /// has no active uniform of that name (GLSL drops unused uniforms).
    pub fn set_uniform(&self, name: &str, value: Uniform) -> Result<(), GlError> {
        let gl = self.ctx.gl();
        // SAFETY: GL calls on the current context with this batch's program.
        unsafe {
            gl.use_program(Some(self.program));
            let loc = gl.get_uniform_location(self.program, name).ok_or_else(|| GlError::Input {
                field: name.into(),
                reason: "no active uniform of that name in the program".into(),
            })?;
            apply_uniform(gl, &loc, &value);
            gl_check(gl, "glUniform")
        }
    }

    /// Number of `vec4` inputs per case.
    pub fn n_inputs(&self) -> usize {
        self.n_inputs
    }

    /// Number of `vec4` outputs per case.
    pub fn n_outputs(&self) -> usize {
        self.n_outputs
    }

    /// Evaluates the body for every case: `inputs[k][i]` is input `k` of case `i`.
    /// Returns `outputs[m][i]`, output `m` of case `i`.
    ///
    /// All `inputs[k]` must have the same length `N`; `N = 0` returns empty outputs.
    /// Errors: [`GlError::Input`] naming `inputs` or `inputs[k]` on a count or length
    /// mismatch; [`GlError::Framebuffer`] / [`GlError::Gl`] if the driver refuses.
    pub fn run(&self, inputs: &[Vec<[f32; 4]>]) -> Result<Vec<Vec<[f32; 4]>>, GlError> {
        self.run_timed(inputs).map(|(outputs, _)| outputs)
    }

    /// As [`Batch::run`], also returning where the time went.
    pub fn run_timed(&self, inputs: &[Vec<[f32; 4]>]) -> Result<(Outputs, BatchTiming), GlError> {
        if inputs.len() != self.n_inputs {
            return Err(GlError::Input {
                field: "inputs".into(),
                reason: format!("{} inputs given, the batch reads {}", inputs.len(), self.n_inputs),
            });
        }
        let n = inputs[0].len();
        for (k, input) in inputs.iter().enumerate() {
            if input.len() != n {
                return Err(GlError::Input {
                    field: format!("inputs[{k}]"),
                    reason: format!("{} cases, inputs[0] has {n}", input.len()),
                });
            }
        }
        let mut timing = BatchTiming::default();
        if n == 0 {
            return Ok((vec![Vec::new(); self.n_outputs], timing));
        }
        let width = self.width(n);
        let chunk = width * self.max_rows();
        if n <= chunk {
            // One draw: the read-back buffers become the outputs, cut to n.
            let slices: Vec<&[[f32; 4]]> = inputs.iter().map(|v| &v[..]).collect();
            let mut outputs = self.draw(&slices, width, &mut timing)?;
            outputs.iter_mut().for_each(|o| o.truncate(n));
            return Ok((outputs, timing));
        }
        let mut outputs = vec![Vec::with_capacity(n); self.n_outputs];
        let mut start = 0;
        while start < n {
            let end = (start + chunk).min(n);
            let slices: Vec<&[[f32; 4]]> = inputs.iter().map(|v| &v[start..end]).collect();
            let results = self.draw(&slices, width, &mut timing)?;
            for (out, res) in outputs.iter_mut().zip(results) {
                out.extend_from_slice(&res[..end - start]);
            }
            start = end;
        }
        Ok((outputs, timing))
    }

    fn width(&self, n: usize) -> usize {
        let max_size = self.ctx.info().max_texture_size.max(1) as usize;
        n.clamp(1, MAX_WIDTH.min(max_size))
    }

    fn max_rows(&self) -> usize {
        MAX_ROWS_PER_DRAW.min(self.ctx.info().max_texture_size.max(1) as usize)
    }

    /// One draw over `slices` (all the same length, at most `width * max_rows`).
    /// Returns `width * rows` texels per output, padding included.
    fn draw(
        &self,
        slices: &[&[[f32; 4]]],
        width: usize,
        timing: &mut BatchTiming,
    ) -> Result<Vec<Vec<[f32; 4]>>, GlError> {
        let gl = self.ctx.gl();
        // SAFETY: GL calls on the current context; every object created here is deleted
        // before returning; uploads and read-backs use buffers of exactly `w x h` texels.
        unsafe {
            let mut textures = Vec::with_capacity(self.n_inputs + self.n_outputs);
            let result = self.draw_inner(gl, slices, width, &mut textures, timing);
            for t in textures {
                gl.delete_texture(t);
            }
            result
        }
    }

    unsafe fn draw_inner(
        &self,
        gl: &glow::Context,
        slices: &[&[[f32; 4]]],
        width: usize,
        textures: &mut Vec<glow::Texture>,
        timing: &mut BatchTiming,
    ) -> Result<Vec<Vec<[f32; 4]>>, GlError> {
        // SAFETY: the caller upholds this function's contract: a current GL context that owns every object passed in.
        unsafe {
            let rows = slices[0].len().div_ceil(width);
            let texels = width * rows;
            let (w, h) = (width as i32, rows as i32);
            let clock = Instant::now();
            for (k, slice) in slices.iter().enumerate() {
                gl.active_texture(glow::TEXTURE0 + k as u32);
                let tex = new_texture(gl, w, h, None)?;
                textures.push(tex);
                upload_rows(gl, slice, width)?;
            }
            timing.upload += clock.elapsed();
            let fbo =
                gl.create_framebuffer().map_err(|detail| GlError::Gl { call: "glGenFramebuffers".into(), detail })?;
            gl.bind_framebuffer(glow::FRAMEBUFFER, Some(fbo));
            let mut attachments = Vec::with_capacity(self.n_outputs);
            // Render targets are bound on a unit no input uses, so no sampler sees them.
            gl.active_texture(glow::TEXTURE0 + self.n_inputs as u32);
            for m in 0..self.n_outputs {
                let tex = new_texture(gl, w, h, None)?;
                textures.push(tex);
                let attachment = glow::COLOR_ATTACHMENT0 + m as u32;
                gl.framebuffer_texture_2d(glow::FRAMEBUFFER, attachment, glow::TEXTURE_2D, Some(tex), 0);
                attachments.push(attachment);
            }
            gl.draw_buffers(&attachments);
            let status = gl.check_framebuffer_status(glow::FRAMEBUFFER);
            let result = if status != glow::FRAMEBUFFER_COMPLETE {
                Err(GlError::Framebuffer { status })
            } else {
                self.render_and_read(gl, w, h, texels, &attachments, timing)
            };
            gl.bind_framebuffer(glow::FRAMEBUFFER, None);
            gl.delete_framebuffer(fbo);
            result
        }
    }

    unsafe fn render_and_read(
        &self,
        gl: &glow::Context,
        w: i32,
        h: i32,
        texels: usize,
        attachments: &[u32],
        timing: &mut BatchTiming,
    ) -> Result<Vec<Vec<[f32; 4]>>, GlError> {
        // SAFETY: the caller upholds this function's contract: a current GL context that owns every object passed in.
        unsafe {
            let clock = Instant::now();
            gl.viewport(0, 0, w, h);
            gl.disable(glow::BLEND);
            gl.disable(glow::DEPTH_TEST);
            gl.use_program(Some(self.program));
            gl.bind_vertex_array(Some(self.vao));
            gl.draw_arrays(glow::TRIANGLES, 0, 3);
            gl.finish();
            gl_check(gl, "glDrawArrays")?;
            timing.draw += clock.elapsed();
            let clock = Instant::now();
            gl.pixel_store_i32(glow::PACK_ALIGNMENT, 4);
            let mut outputs = Vec::with_capacity(attachments.len());
            for &attachment in attachments {
                let mut out = vec![[0.0f32; 4]; texels];
                gl.read_buffer(attachment);
                gl.read_pixels(
                    0,
                    0,
                    w,
                    h,
                    glow::RGBA,
                    glow::FLOAT,
                    glow::PixelPackData::Slice(Some(as_bytes_mut(&mut out))),
                );
                gl_check(gl, "glReadPixels")?;
                outputs.push(out);
            }
            timing.read += clock.elapsed();
            Ok(outputs)
        }
    }
}

/// Uploads `slice` into the bound texture: the full rows straight from the slice, then the
/// last partial row (if any); texels past the end stay unspecified and are never read back.
unsafe fn upload_rows(gl: &glow::Context, slice: &[[f32; 4]], width: usize) -> Result<(), GlError> {
    // SAFETY: the caller upholds this function's contract: a current GL context that owns every object passed in.
    unsafe {
        let full_rows = slice.len() / width;
        let rest = slice.len() % width;
        if full_rows > 0 {
            let data = &slice[..full_rows * width];
            gl.tex_sub_image_2d(
                glow::TEXTURE_2D,
                0,
                0,
                0,
                width as i32,
                full_rows as i32,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelUnpackData::Slice(Some(as_bytes(data))),
            );
        }
        if rest > 0 {
            let data = &slice[full_rows * width..];
            gl.tex_sub_image_2d(
                glow::TEXTURE_2D,
                0,
                0,
                full_rows as i32,
                rest as i32,
                1,
                glow::RGBA,
                glow::FLOAT,
                glow::PixelUnpackData::Slice(Some(as_bytes(data))),
            );
        }
        gl_check(gl, "glTexSubImage2D(RGBA32F)")
    }
}

/// A `w x h` RGBA32F texture with nearest filtering (complete without mipmaps), bound to
/// the active unit; `data` is `w * h` texels or `None` for a render target.
unsafe fn new_texture(gl: &glow::Context, w: i32, h: i32, data: Option<&[u8]>) -> Result<glow::Texture, GlError> {
    // SAFETY: the caller upholds this function's contract: a current GL context that owns every object passed in.
    unsafe {
        let tex = gl.create_texture().map_err(|detail| GlError::Gl { call: "glGenTextures".into(), detail })?;
        gl.bind_texture(glow::TEXTURE_2D, Some(tex));
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MIN_FILTER, glow::NEAREST as i32);
        gl.tex_parameter_i32(glow::TEXTURE_2D, glow::TEXTURE_MAG_FILTER, glow::NEAREST as i32);
        gl.pixel_store_i32(glow::UNPACK_ALIGNMENT, 4);
        gl.tex_image_2d(
            glow::TEXTURE_2D,
            0,
            glow::RGBA32F as i32,
            w,
            h,
            0,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelUnpackData::Slice(data),
        );
        if let Err(e) = gl_check(gl, "glTexImage2D(RGBA32F)") {
            gl.delete_texture(tex);
            return Err(e);
        }
        Ok(tex)
    }
}

impl Drop for Batch<'_> {
    fn drop(&mut self) {
        let gl = self.ctx.gl();
        // SAFETY: deleting objects this batch owns, on the context that created them.
        unsafe {
            gl.delete_vertex_array(self.vao);
            gl.delete_program(self.program);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::without_trailing_nuls;

    #[test]
    fn info_logs_lose_their_trailing_nuls_only() {
        assert_eq!(without_trailing_nuls("0:3(1): error: x\n\0\0".into()), "0:3(1): error: x\n");
        assert_eq!(without_trailing_nuls("a\0b".into()), "a\0b");
        assert_eq!(without_trailing_nuls(String::new()), "");
    }

    #[test]
    fn leading_extension_lines_go_right_after_the_version() {
        let body =
            "#extension GL_ARB_gpu_shader5 : enable\nvoid batch_main(vec4 i[1], inout vec4 o[1]) {}\n#extension GL_late : enable\n";
        let s = super::fragment_source(body, 1, 1);
        let lines: Vec<&str> = s.lines().collect();
        assert_eq!(&lines[..2], &["#version 330 core", "#extension GL_ARB_gpu_shader5 : enable"]);
        assert_eq!(s.matches("GL_ARB_gpu_shader5").count(), 1, "moved, not copied: {s}");
        // only the leading run moves: a later one is the body's own business
        assert!(s.find("GL_late").unwrap() > s.find("batch_main").unwrap(), "{s}");
    }
}
