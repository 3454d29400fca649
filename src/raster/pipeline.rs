//! The vertex stage and a renderable world: objects, lights, camera, shading mode.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `model` | object → world |
//! | `normal_matrix` | `transpose(inverse(mat3(model)))`, the cofactor form if `model` is singular |
//! | `FragPos` | world position, interpolated (varyings 0..3) |
//! | `Normal` | `normal_matrix · n`, interpolated, renormalized per fragment (varyings 3..6) |
//! | `TexCoords` | uv (varyings 6..8) |
//!
//! Source: LearnOpenGL, Basic lighting (vertex shader, normal matrix).

use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};

use super::camera::Camera;
use super::clip::{ClipVertex, MAX_VARYINGS};
use super::framebuffer::{Framebuffer, Rgba8Framebuffer};
use super::kernel::{LaneMaterial, Lanes, MultiLightKernel, RangeWindow, Specialisations, LANES};
use super::mesh::Mesh;
use super::rasterize::{
    render, render_rgba8_with, render_with, CullMode, DrawCall, FragmentBatch, FragmentShader, RasterScratch,
    RenderStats,
};
use super::shade::{ColorShader, LitShader, ShadingMode, Surface};
use crate::normals::{normal_matrix_cofactor, normal_matrix_inverse_transpose};
use crate::scene::Scene;

/// What an object's vertices are.
#[derive(Clone, Debug, PartialEq)]
pub enum Geometry {
    /// A mesh, transformed by the object's model matrix and the camera.
    Mesh(Mesh),
    /// The benchmark's full-screen quad: vertices at NDC `(±1, ±1)` carry
    /// `FragPos = (x·4/3, y, 0)`, `Normal = (x/2, y/2, 1)`, uv `((x+1)/2, (y+1)/2)`;
    /// camera and model matrix are ignored (`../shared/DESIGN.md`, quad-single).
    NdcQuad,
}

/// One thing to draw.
#[derive(Clone, Debug, PartialEq)]
pub struct Object {
    /// Its vertices.
    pub geometry: Geometry,
    /// Object → world.
    pub model: Mat4,
    /// Its reflectances.
    pub surface: Surface,
    /// Face culling for it.
    pub cull: CullMode,
}

/// Everything one image needs.
#[derive(Clone, Debug, PartialEq)]
pub struct World {
    /// The camera (its eye is the shaders' `viewPos`).
    pub camera: Camera,
    /// The lights, summed as the Multiple lights shader does (a
    /// [`Surface::Tutorial`] carries its own light and ignores them).
    pub lights: Scene,
    /// Objects, drawn in order.
    pub objects: Vec<Object>,
    /// Where lighting is evaluated.
    pub shading: ShadingMode,
    /// Clear color (RGBA).
    pub clear: Vec4,
    /// Depth test on or off.
    pub depth_test: bool,
    /// LearnOpenGL's falloff times a range window, with or without culling (`None`: the
    /// tutorials' falloff).
    pub range_window: Option<RangeWindow>,
    /// The kernel's value-based specialisations allowed ([`Specialisations::ALL`]: the
    /// image is the same within rounding; [`Specialisations::NONE`]: `bench --general`).
    pub specialisations: Specialisations,
}

/// A vertex before shading: clip position, world position, world normal, uv.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadedVertex {
    /// `projection · view · model · p`.
    pub clip: Vec4,
    /// `model · p`.
    pub world: Vec3,
    /// `normal_matrix · n` (not renormalized).
    pub normal: Vec3,
    /// Texture coordinates.
    pub uv: Vec2,
}

impl ShadedVertex {
    /// The vertex for a per-fragment shader: its clip position, with varyings world
    /// position (0..3), normal (3..6) and uv (6..8). A draw that needs no uv passes a
    /// `varying_count` of 6 and the rasterizer interpolates only the first six.
    pub fn lit_clip_vertex(&self) -> ClipVertex {
        let mut varyings = [0.0; MAX_VARYINGS];
        varyings[..3].copy_from_slice(&self.world.to_array());
        varyings[3..6].copy_from_slice(&self.normal.to_array());
        varyings[6..8].copy_from_slice(&self.uv.to_array());
        ClipVertex { clip: self.clip, varyings }
    }
}

/// The normal matrix `transpose(inverse(mat3(model)))`; the cofactor form
/// (same directions up to the sign of the determinant) when `model` is singular.
pub fn normal_matrix(model: Mat4) -> Mat3 {
    let m = Mat3::from_mat4(model);
    normal_matrix_inverse_transpose(m).unwrap_or_else(|| normal_matrix_cofactor(m))
}

/// Run the vertex stage of `geometry` (the quad ignores `model` and `camera`).
pub fn vertex_stage(geometry: &Geometry, model: Mat4, camera: &Camera) -> (Vec<ShadedVertex>, Vec<[u32; 3]>) {
    let mut verts = Vec::new();
    let triangles = vertex_stage_into(geometry, model, camera, &mut verts).to_vec();
    (verts, triangles)
}

/// The quad's triangles in `GL_TRIANGLE_STRIP` order: (0, 1, 2), (2, 1, 3).
const QUAD_TRIANGLES: [[u32; 3]; 2] = [[0, 1, 2], [2, 1, 3]];

/// [`vertex_stage`] into `verts` (cleared first, its buffer reused), returning the
/// triangles without copying them: the mesh's own, or the quad's.
pub fn vertex_stage_into<'a>(
    geometry: &'a Geometry,
    model: Mat4,
    camera: &Camera,
    verts: &mut Vec<ShadedVertex>,
) -> &'a [[u32; 3]] {
    verts.clear();
    match geometry {
        Geometry::NdcQuad => {
            let corners = [(-1.0f32, -1.0f32), (1.0, -1.0), (-1.0, 1.0), (1.0, 1.0)];
            verts.extend(corners.iter().map(|&(x, y)| ShadedVertex {
                clip: Vec4::new(x, y, 0.0, 1.0),
                world: Vec3::new(x * (4.0 / 3.0), y, 0.0),
                normal: Vec3::new(x * 0.5, y * 0.5, 1.0),
                uv: Vec2::new(0.5 * (x + 1.0), 0.5 * (y + 1.0)),
            }));
            &QUAD_TRIANGLES
        }
        Geometry::Mesh(mesh) => {
            let view_projection = camera.view_projection();
            let nm = normal_matrix(model);
            verts.extend(mesh.positions.iter().enumerate().map(|(i, &p)| {
                let world = model.transform_point3(p);
                ShadedVertex {
                    clip: view_projection * world.extend(1.0),
                    world,
                    normal: nm * mesh.normals.get(i).copied().unwrap_or(Vec3::ZERO),
                    uv: mesh.uvs.get(i).copied().unwrap_or(Vec2::ZERO),
                }
            }));
            &mesh.triangles
        }
    }
}

/// Light points (position, normal, uv) with the kernel, 16 at a time; emission added.
/// A [`Surface::Tutorial`] is shaded by its own model instead, with the kernel's eye.
pub fn light_points(kernel: &MultiLightKernel, surface: &Surface, points: &[(Vec3, Vec3, Vec2)]) -> Vec<Vec3> {
    let mut out = Vec::with_capacity(points.len());
    light_each(kernel, surface, points.len(), |i| points[i], |_, c| out.push(c));
    out
}

/// [`light_points`] without the lists: `emit(i, color)` for each `i < n` in order, where
/// `point(i)` is point `i`'s (position, normal, uv). Gouraud's vertex stage reads its
/// vertices and writes the rasterizer's in one pass, with no list of points or colours
/// between them.
fn light_each(
    kernel: &MultiLightKernel,
    surface: &Surface,
    n: usize,
    point: impl Fn(usize) -> (Vec3, Vec3, Vec2),
    mut emit: impl FnMut(usize, Vec3),
) {
    if let Surface::Unlit(c) = surface {
        (0..n).for_each(|i| emit(i, *c));
        return;
    }
    if let Surface::Tutorial(model) = surface {
        for i in 0..n {
            let (p, normal, _) = point(i);
            emit(i, model.shade(p, normal, kernel.view_pos()));
        }
        return;
    }
    let maps = matches!(surface, Surface::Maps(..));
    let mut material = LaneMaterial::uniform(&surface.material_at(Vec2::ZERO));
    for start in (0..n).step_by(LANES) {
        let points = start..(start + LANES).min(n);
        let mut pos = [[0.0; LANES]; 3];
        let mut normal = [[0.0; LANES]; 3];
        for (l, i) in points.clone().enumerate() {
            let (p, nl, uv) = point(i);
            for c in 0..3 {
                pos[c][l] = p[c];
                normal[c][l] = nl[c];
            }
            if maps {
                material.set(l, &surface.material_at(uv));
            }
        }
        let mut rgb = [[0.0; LANES]; 3];
        kernel.shade(&pos, &normal, &material, &mut rgb);
        for (l, i) in points.enumerate() {
            emit(i, Vec3::new(rgb[0][l], rgb[1][l], rgb[2][l]) + surface.emission_at(point(i).2));
        }
    }
}

fn color_vertex(clip: Vec4, color: Vec3) -> ClipVertex {
    let mut varyings = [0.0; MAX_VARYINGS];
    varyings[..3].copy_from_slice(&color.to_array());
    ClipVertex { clip, varyings }
}

/// One object ready to draw: its vertices after the vertex stage (in an
/// [`ObjectScratch`]), its triangles and its fragment stage.
struct Prepared<'a> {
    vertices: &'a [ClipVertex],
    triangles: &'a [[u32; 3]],
    varying_count: usize,
    shader: Box<dyn FragmentShader>,
    cull: CullMode,
}

/// One object's per-frame buffers, kept for the next frame.
#[derive(Debug, Default)]
struct ObjectScratch {
    /// The vertex stage's output.
    shaded: Vec<ShadedVertex>,
    /// The vertices handed to the rasterizer.
    vertices: Vec<ClipVertex>,
    /// Flat shading's own triangles (three vertices of its own each).
    triangles: Vec<[u32; 3]>,
}

/// The buffers one frame fills and the next reuses ([`World::render_with`]): the vertex
/// stage's output, the rasterizer's vertices, and the rasterizer's setup
/// ([`RasterScratch`]).
///
/// At 262,144 triangles these are about 50 MB (the vertex stage's output and the
/// rasterizer's vertices are 6 MB each, the rest is [`RasterScratch`]'s). Allocated
/// each frame, their pages were
/// mapped, zeroed and faulted in again every frame. Any scratch gives the same image,
/// a fresh one included.
#[derive(Debug, Default)]
pub struct FrameScratch {
    objects: Vec<ObjectScratch>,
    raster: RasterScratch,
}

impl World {
    fn kernel(&self, surface: &Surface) -> MultiLightKernel {
        MultiLightKernel::new(&self.lights, self.camera.eye, surface.shininess(), self.shading.specular())
            .with_range_window(self.range_window)
            .with_specialisations(self.specialisations)
    }

    fn prepare<'a>(&self, object: &'a Object, buffers: &'a mut ObjectScratch) -> Prepared<'a> {
        let ObjectScratch { shaded, vertices, triangles: own_triangles } = buffers;
        let triangles = vertex_stage_into(&object.geometry, object.model, &self.camera, shaded);
        let verts = &shaded[..];
        let kernel = self.kernel(&object.surface);
        let cull = object.cull;
        vertices.clear();
        let per_fragment = matches!(self.shading, ShadingMode::Phong | ShadingMode::BlinnPhong);
        if per_fragment && !matches!(object.surface, Surface::Unlit(_)) {
            vertices.extend(verts.iter().map(ShadedVertex::lit_clip_vertex));
            let varying_count = if matches!(object.surface, Surface::Maps(..)) { 8 } else { 6 };
            return Prepared {
                vertices,
                triangles,
                varying_count,
                shader: Box::new(LitShader::new(kernel, object.surface.clone())),
                cull,
            };
        }
        if self.shading == ShadingMode::Flat {
            let mut points = Vec::with_capacity(triangles.len());
            let mut corners = Vec::with_capacity(triangles.len());
            for t in triangles {
                let [Some(a), Some(b), Some(c)] = t.map(|i| verts.get(i as usize)) else {
                    continue;
                };
                let centroid = (a.world + b.world + c.world) / 3.0;
                let mut n = (b.world - a.world).cross(c.world - a.world).normalize_or_zero();
                if n.dot(a.normal + b.normal + c.normal) < 0.0 {
                    n = -n;
                }
                points.push((centroid, n, (a.uv + b.uv + c.uv) / 3.0));
                corners.push([a.clip, b.clip, c.clip]);
            }
            let colors = light_points(&kernel, &object.surface, &points);
            for (clips, color) in corners.iter().zip(&colors) {
                vertices.extend(clips.iter().map(|&clip| color_vertex(clip, *color)));
            }
            own_triangles.clear();
            own_triangles.extend((0..corners.len() as u32).map(|k| [3 * k, 3 * k + 1, 3 * k + 2]));
            return Prepared {
                vertices,
                triangles: own_triangles,
                varying_count: 3,
                shader: Box::new(ColorShader),
                cull,
            };
        }
        vertices.reserve(verts.len());
        let point = |i: usize| (verts[i].world, verts[i].normal, verts[i].uv);
        light_each(&kernel, &object.surface, verts.len(), point, |i, c| vertices.push(color_vertex(verts[i].clip, c)));
        Prepared { vertices, triangles, varying_count: 3, shader: Box::new(ColorShader), cull }
    }

    /// Every object prepared, each into its own buffers of `objects` (grown or cut to
    /// the number of objects).
    fn prepare_all<'a>(&'a self, objects: &'a mut Vec<ObjectScratch>) -> Vec<Prepared<'a>> {
        objects.resize_with(self.objects.len(), ObjectScratch::default);
        self.objects.iter().zip(objects.iter_mut()).map(|(o, b)| self.prepare(o, b)).collect()
    }

    /// The share of the point lights and spots that the kernel evaluates over one frame
    /// rendered into `fb`, averaged over the live fragments of every batch it shades: 1
    /// unless the range window culls ([`RangeWindow::cull`]), when a light is skipped for a
    /// whole batch of 16 fragments whose bounding box lies beyond its range. For the
    /// roofline's operation count ([`crate::study::bench::roofline::frame_cost`]).
    pub fn evaluated_light_share(&self, fb: &mut Framebuffer) -> f64 {
        use std::sync::atomic::{AtomicU64, Ordering};
        /// The lit shader, counting `(lights evaluated, lights in all)` times live lanes.
        struct Counting<'a> {
            inner: &'a dyn FragmentShader,
            kernel: MultiLightKernel,
            evaluated: AtomicU64,
            total: AtomicU64,
        }
        impl FragmentShader for Counting<'_> {
            fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
                if let Some(pos) = batch.varyings.first_chunk::<3>() {
                    let (evaluated, total) = self.kernel.cones_evaluated(pos);
                    self.evaluated.fetch_add((evaluated * batch.len) as u64, Ordering::Relaxed);
                    self.total.fetch_add((total * batch.len) as u64, Ordering::Relaxed);
                }
                self.inner.shade(batch, out);
            }
            fn passes_varyings_through(&self) -> bool {
                self.inner.passes_varyings_through()
            }
        }
        if !self.range_window.is_some_and(|w| w.cull) {
            return 1.0;
        }
        let mut scratch = FrameScratch::default();
        let prepared = self.prepare_all(&mut scratch.objects);
        let counting: Vec<Counting> = prepared
            .iter()
            .zip(&self.objects)
            .map(|(p, o)| Counting {
                inner: p.shader.as_ref(),
                kernel: self.kernel(&o.surface),
                evaluated: AtomicU64::new(0),
                total: AtomicU64::new(0),
            })
            .collect();
        let draws: Vec<DrawCall> = prepared
            .iter()
            .zip(&counting)
            .map(|(p, c)| DrawCall {
                vertices: p.vertices,
                triangles: p.triangles,
                varying_count: p.varying_count,
                cull: p.cull,
                depth_test: self.depth_test,
                shader: c,
            })
            .collect();
        render(fb, Some(self.clear), &draws);
        let (evaluated, total) = counting.iter().fold((0u64, 0u64), |(e, t), c| {
            (e + c.evaluated.load(Ordering::Relaxed), t + c.total.load(Ordering::Relaxed))
        });
        if total == 0 {
            1.0
        } else {
            evaluated as f64 / total as f64
        }
    }

    /// Render into `fb` (cleared to [`World::clear`] first).
    pub fn render(&self, fb: &mut Framebuffer) -> RenderStats {
        self.render_with(fb, &mut FrameScratch::default())
    }

    /// [`World::render`], with the frame's buffers taken from `scratch` and left there for
    /// the next frame: a loop of frames (a benchmark, an animation) allocates them once.
    /// The image does not depend on what `scratch` held.
    pub fn render_with(&self, fb: &mut Framebuffer, scratch: &mut FrameScratch) -> RenderStats {
        self.draw_with(scratch, |draws, raster| render_with(fb, Some(self.clear), draws, raster))
    }

    /// [`World::render_with`] into an RGBA8 colour buffer: the bytes are
    /// [`Framebuffer::to_rgba8`]`(false)` of the frame [`World::render_with`] draws
    /// ([`super::rasterize::render_rgba8_with`]), with a quarter of the colour bytes
    /// cleared and stored. For frames that are only shown or saved, as the benchmarks'
    /// `--rgba8`.
    pub fn render_rgba8_with(&self, fb: &mut Rgba8Framebuffer, scratch: &mut FrameScratch) -> RenderStats {
        self.draw_with(scratch, |draws, raster| render_rgba8_with(fb, Some(self.clear), draws, raster))
    }

    /// Run the vertex stage into `scratch`, then `raster` on the frame's draws.
    fn draw_with(
        &self,
        scratch: &mut FrameScratch,
        raster: impl FnOnce(&[DrawCall], &mut RasterScratch) -> RenderStats,
    ) -> RenderStats {
        let FrameScratch { objects, raster: raster_scratch } = scratch;
        let prepared = self.prepare_all(objects);
        let draws: Vec<DrawCall> = prepared
            .iter()
            .map(|p| DrawCall {
                vertices: p.vertices,
                triangles: p.triangles,
                varying_count: p.varying_count,
                cull: p.cull,
                depth_test: self.depth_test,
                shader: p.shader.as_ref(),
            })
            .collect();
        raster(&draws, raster_scratch)
    }
}

#[cfg(test)]
mod scratch_tests {
    use super::*;
    use crate::raster::presets::{bench_scene, sphere_multi};

    /// A scratch holds buffers, not results: a frame rendered with a scratch that earlier
    /// frames of other worlds (more objects, more triangles, other shading modes) left
    /// full is the frame a fresh scratch gives, pixel for pixel, with the same counts.
    #[test]
    fn a_reused_scratch_gives_the_fresh_frame() {
        let worlds = [
            sphere_multi(8).unwrap(),
            bench_scene("sphere4096-gouraud").unwrap(),
            World { shading: ShadingMode::Flat, ..sphere_multi(4).unwrap() },
            bench_scene("quad-single").unwrap(),
            bench_scene("cube-multi").unwrap(),
            sphere_multi(8).unwrap(),
        ];
        let mut scratch = FrameScratch::default();
        for world in &worlds {
            let mut fresh = Framebuffer::new(160, 120).unwrap();
            let fresh_stats = world.render(&mut fresh);
            let mut reused = Framebuffer::new(160, 120).unwrap();
            let reused_stats = world.render_with(&mut reused, &mut scratch);
            assert_eq!(reused_stats, fresh_stats);
            assert!(reused.color == fresh.color && reused.depth == fresh.depth, "{:?}", world.shading);
        }
    }
}

#[cfg(test)]
mod rgba8_tests {
    use super::*;
    use crate::raster::presets::{all_bench_scenes, bench_scene, sphere_multi};

    /// A frame drawn into an [`Rgba8Framebuffer`] holds exactly the bytes of the same frame
    /// drawn into a [`Framebuffer`] and quantized ([`Framebuffer::to_rgba8`]), with the same
    /// depth and counts: every benchmark scene (lights brighter than 1 included), flat
    /// and Gouraud shading, a clear colour that is not black, and no depth test.
    #[test]
    fn an_rgba8_frame_is_the_float_frame_quantized() {
        let mut worlds: Vec<World> = all_bench_scenes().iter().map(|n| bench_scene(n).unwrap()).collect();
        worlds.push(World { shading: ShadingMode::Flat, ..sphere_multi(8).unwrap() });
        worlds.push(World { clear: Vec4::new(0.2, 1.5, -0.3, 0.5), depth_test: false, ..sphere_multi(16).unwrap() });
        worlds.push(World { clear: Vec4::new(0.1, 0.2, 0.3, 1.0), ..bench_scene("sphere4096-gouraud").unwrap() });
        let mut scratch = FrameScratch::default();
        for world in &worlds {
            // 203 × 151: rows and bands that are not multiples of 16 or of the band height
            let mut float = Framebuffer::new(203, 151).unwrap();
            let float_stats = world.render_with(&mut float, &mut scratch);
            let mut bytes = Rgba8Framebuffer::new(203, 151).unwrap();
            let bytes_stats = world.render_rgba8_with(&mut bytes, &mut scratch);
            assert_eq!(bytes_stats, float_stats);
            assert!(bytes.depth == float.depth, "{:?}", world.shading);
            let (expected, actual) = (float.to_rgba8(false), bytes.to_rgba8());
            let differ = expected.iter().zip(&actual).filter(|(a, b)| a != b).count();
            assert_eq!(differ, 0, "{:?}: {differ} bytes differ", world.shading);
            assert_eq!(bytes.covered(), float.covered());
        }
    }
}
