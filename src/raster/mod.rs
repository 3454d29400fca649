//! The CPU raster back end: meshes, camera, clipping, rasterization, shading, ray-cast ground truth.
//!
//! | stage | module |
//! | --- | --- |
//! | meshes (cube, spheres, plane, torus) | [`mesh`] |
//! | `look_at`, `perspective`, viewport | [`camera`] |
//! | near/far and guard-band clipping | [`clip`] |
//! | setup, fill rule, depth, varyings | [`rasterize`] |
//! | 16-lane multi-light kernel | [`kernel`] |
//! | instruction-set detection and dispatch, intrinsics | `simd` (private) |
//! | fragment stages, shading modes | [`shade`] |
//! | vertex stage and renderable world | [`pipeline`] |
//! | float framebuffer, PNG | [`framebuffer`] |
//! | f64 ray caster | [`raycast`] |
//! | tutorial and benchmark scenes | [`presets`] |
//! | scene descriptions, written as scene files | [`scene_desc`] |
//! | reading scene files (feature `book`) | `scene_file` |
//!
//! Conventions: OpenGL's (window origin lower left, counter-clockwise front
//! faces, depth test `LESS`, depth cleared to 1), glam's matrices.

pub mod camera;
pub mod clip;
pub mod framebuffer;
pub mod kernel;
pub mod mesh;
pub mod pipeline;
pub mod presets;
pub mod rasterize;
pub mod raycast;
pub mod scene_desc;
#[cfg(feature = "book")]
pub mod scene_file;
pub mod shade;
pub(crate) mod simd;
pub(crate) mod wide;
