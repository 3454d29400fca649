//! # lightlab
//!
//! The lighting math of real-time graphics, implemented, tested by its
//! invariants and checked against the tutorials it comes from: LearnOpenGL
//! "Lighting", opengl-tutorial 8 and ogldev 19.
//!
//! ## Crate map: chapter → module
//!
//! | chapter | module |
//! | --- | --- |
//! | GLSL built-ins (`reflect`, `clamp`, `pow`'s domain) | [`glsl`] |
//! | 1. Colors | [`color`] |
//! | 2. Basic lighting: ambient, diffuse, specular, Blinn-Phong, view space | [`phong`] |
//! | 2. Normals and the normal matrix | [`normals`] |
//! | 3. Materials and the classic table | [`material`] |
//! | 4. Lighting maps | [`maps`] |
//! | 5. Light casters | [`casters`] |
//! | 6. Multiple lights | [`scene`] |
//! | Three tutorials, three conventions | [`models`] |
//! | Published numbers and errata | [`errata`] |
//! | The independent `f64` reference | [`reference`](mod@reference) |
//! | Where methods fail; light culling; advisors | [`study`] |
//! | CPU raster back end: meshes, pipeline, shading modes, ray-cast ground truth | [`raster`] |
//! | Real OpenGL: headless llvmpipe context, batch runs, packed layouts, the tutorials' GLSL | [`gl`] |
//! | The oracle: random cases and bounds, llvmpipe against the `f32` core and the `f64` reference | [`oracle`] |
//! | `check-shader`: a learner's shader checked, its mistake named | [`checker`] |
//!
//! ## Conventions
//!
//! - **Vectors at a surface point** are unit length and point *away* from the
//!   surface: `n` (normal), `light_dir` (toward the light), `view_dir` (toward
//!   the eye), `reflect_dir = reflect(-light_dir, n)`,
//!   `halfway = normalize(light_dir + view_dir)`. Names follow the tutorials'
//!   shaders so Rust and GLSL read side by side.
//! - **Directional lights** store the direction *from* the light; the shader
//!   negates it.
//! - **Matrices** follow glam: column vectors, `m * v`. The normal matrix is
//!   `transpose(inverse(mat3(model)))`; the cofactor form gives the same
//!   directions and survives singular scale.
//! - **Angles** enter the API in degrees; cosines are used inside.
//! - **Colors** are linear `f32` RGB, unclamped until output, then clamped to
//!   [0, 1] and quantized to 8 bits. No gamma unless asked.
//! - **Precision**: `f32` is the shader path; [`reference`](mod@reference) is written
//!   separately in `f64` and never calls the `f32` code.
//! - **Degenerate input** (NaN, zero vectors, zero-area triangles, singular
//!   matrices, inverted cones, negative attenuation) has a documented result
//!   on every function; operations that break at zero come as a family
//!   `f` / `try_f` / `f_or_zero`, and constructors that can be invalid return
//!   `Result` with an error naming the field.
//!
//! ## Features
//!
//! - `book` (default): the CLI, figures, charts and the mdBook build. It needs `gl`: the
//!   book's exercises and live figures carry the verified GLSL and the checker's cases.
//! - `gl` (default): the OpenGL runtime on Mesa llvmpipe ([`gl`]), through khronos-egl
//!   (loaded at run time) and glow, and what runs on it: the randomized oracle ([`oracle`])
//!   and the checker of learners' shaders ([`checker`]). Dependencies flow one way:
//!   `checker` → `oracle` → `gl`.
//!
//! Without default features, `lightlab` depends on glam alone.
#![deny(missing_docs)]

pub mod blanks;
pub mod casters;
#[cfg(feature = "book")]
pub mod cli;
pub mod color;
pub mod errata;
pub mod error;
#[cfg(feature = "gl")]
pub mod exercises;
pub mod glsl;
pub mod maps;
pub mod material;
pub mod models;
mod named;
pub mod normals;
pub mod phong;
pub mod raster;
pub mod reference;
pub mod scene;
#[cfg(test)]
mod scratch;
pub mod study;
pub mod table;
pub mod tables;
pub mod timing;

// Headless OpenGL on Mesa llvmpipe (feature `gl`): context, batches, layouts, the tutorials' GLSL.
#[cfg(feature = "gl")]
pub mod gl;

// The randomized oracle: the tutorials' shaders on llvmpipe against the f32 core and the f64 reference.
#[cfg(feature = "gl")]
pub mod oracle;

// The checker: a learner's shader run against a model, its mistake named.
#[cfg(feature = "gl")]
pub mod checker;

// Figures for the book: SVG diagrams rasterized with resvg, line charts drawn with plotters.
#[cfg(feature = "book")]
pub mod figures;

// The book build: generate figures and tables, then render the HTML with mdBook + KaTeX.
#[cfg(feature = "book")]
pub mod book;

// The book and the checker in English, French and Ukrainian: gettext PO files, checked.
#[cfg(feature = "book")]
pub mod i18n;

// Output files written through a temporary file and a rename; directory locks.
#[cfg(feature = "book")]
pub mod outfile;

// Live WebGL2 figures for the book: data, programs and reference images (src/live/mod.rs).
#[cfg(feature = "book")]
pub mod live;
