//! The rasterized sphere: the vertex stage, how a frame is drawn and shaded, and the sphere scene's methods (tessellation, Gouraud against Phong, the normal matrix, the 16-lane kernel).

use glam::{Mat3, Mat4, Vec2, Vec3, Vec4};

use crate::normals::{normal_matrix_cofactor, normal_matrix_inverse_transpose};
use crate::raster::camera::Camera;
use crate::raster::clip::{ClipVertex, MAX_VARYINGS};
use crate::raster::framebuffer::Framebuffer;
use crate::raster::kernel::{Lanes, MultiLightKernel, Specular};
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::light_points;
use crate::raster::rasterize::{render, CullMode, DrawCall, FragmentBatch, FragmentShader};
use crate::raster::shade::{ColorShader, LitShader, Surface};

use super::super::culling::{cull, threshold_for, MaterialBound};
use super::*;

/// Where the normal matrix is computed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NormalMatrixAt {
    /// `transpose(inverse(mat3(model)))` for every vertex, as a vertex shader that computes it.
    PerVertex,
    /// The inverse-transpose once per draw (a uniform).
    PerDraw,
    /// The cofactor matrix once per draw.
    Cofactor,
}

/// The vertex stage: clip position, world position, world normal per vertex.
pub fn sphere_vertices(mesh: &Mesh, model: Mat4, camera: &Camera, at: NormalMatrixAt) -> Vec<(Vec4, Vec3, Vec3)> {
    let vp = camera.view_projection();
    let nm_of = |m: Mat4| {
        let m3 = Mat3::from_mat4(m);
        normal_matrix_inverse_transpose(m3).unwrap_or_else(|| normal_matrix_cofactor(m3))
    };
    let once = match at {
        NormalMatrixAt::Cofactor => normal_matrix_cofactor(Mat3::from_mat4(model)),
        _ => nm_of(model),
    };
    mesh.positions
        .iter()
        .zip(&mesh.normals)
        .map(|(&p, &n)| {
            let nm = if at == NormalMatrixAt::PerVertex { nm_of(std::hint::black_box(model)) } else { once };
            let world = model.transform_point3(p);
            (vp * world.extend(1.0), world, nm * n)
        })
        .collect()
}

/// Per-fragment shading by a scalar function of (world position, normal), lane by lane.
pub(super) struct PerLane<F: Fn(Vec3, Vec3) -> Vec3 + Sync>(pub(super) F);

impl<F: Fn(Vec3, Vec3) -> Vec3 + Sync> FragmentShader for PerLane<F> {
    fn shade(&self, batch: &FragmentBatch, out: &mut [Lanes; 3]) {
        let v = &batch.varyings;
        for l in 0..batch.len {
            let c = (self.0)(Vec3::new(v[0][l], v[1][l], v[2][l]), Vec3::new(v[3][l], v[4][l], v[5][l]));
            for k in 0..3 {
                out[k][l] = c[k];
            }
        }
    }
}

/// How a rasterized frame is shaded.
pub(super) enum Shading<'a> {
    /// Lit per vertex by the kernel, colors interpolated.
    Gouraud(&'a MultiLightKernel),
    /// Lit per fragment by this shader.
    PerFragment(&'a dyn FragmentShader),
}

pub(super) struct RasterFrame<'a> {
    pub(super) mesh: &'a Mesh,
    pub(super) model: Mat4,
    pub(super) camera: &'a Camera,
    pub(super) at: NormalMatrixAt,
    pub(super) surface: Surface,
}

impl RasterFrame<'_> {
    pub(super) fn draw(&self, fb: &mut Framebuffer, shading: &Shading) {
        let verts = sphere_vertices(self.mesh, self.model, self.camera, self.at);
        let (vertices, count, shader): (Vec<ClipVertex>, usize, &dyn FragmentShader) = match shading {
            Shading::Gouraud(kernel) => {
                let points: Vec<_> = verts.iter().map(|v| (v.1, v.2, Vec2::ZERO)).collect();
                let colors = light_points(kernel, &self.surface, &points);
                let vs = verts.iter().zip(&colors).map(|(v, c)| clip_vertex(v.0, &[*c])).collect();
                (vs, 3, &ColorShader)
            }
            Shading::PerFragment(shader) => (verts.iter().map(|v| clip_vertex(v.0, &[v.1, v.2])).collect(), 6, *shader),
        };
        let draw = DrawCall {
            vertices: &vertices,
            triangles: &self.mesh.triangles,
            varying_count: count,
            cull: CullMode::Back,
            depth_test: true,
            shader,
        };
        render(fb, Some(Vec4::new(0.0, 0.0, 0.0, 0.0)), &[draw]);
    }
}

pub(super) fn clip_vertex(clip: Vec4, parts: &[Vec3]) -> ClipVertex {
    let mut varyings = [0.0; MAX_VARYINGS];
    for (k, v) in parts.iter().enumerate() {
        varyings[3 * k..3 * k + 3].copy_from_slice(&v.to_array());
    }
    ClipVertex { clip, varyings }
}

pub(super) fn sphere_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let scenes::UnitSphere { camera, lights, material, ray } = scenes::unit_sphere(w, h);
    let surface = Surface::Material(material);
    (ctx.progress)(&format!("{SPHERE}: ray-cast reference"));
    let reference = ray_reference(&ray, w, h);
    let kernel = MultiLightKernel::new(&lights, camera.eye, material.shininess, Specular::Phong);
    let lit = LitShader::new(kernel.clone(), surface.clone());
    let model = sphere_model();
    for &stacks in &ctx.opts.tessellations.clone() {
        let mesh = Mesh::uv_sphere(stacks, 2 * stacks);
        let frame =
            RasterFrame { mesh: &mesh, model, camera: &camera, at: NormalMatrixAt::PerDraw, surface: surface.clone() };
        let size = format!("{stacks}×{}", 2 * stacks);
        ctx.raster(SPHERE, "tessellation", &format!("Gouraud {size}"), &frame, &Shading::Gouraud(&kernel), &reference);
        ctx.raster(SPHERE, "tessellation", &format!("Phong {size}"), &frame, &Shading::PerFragment(&lit), &reference);
    }
    let stacks = ctx.opts.method_stacks;
    let mesh = Mesh::uv_sphere(stacks, 2 * stacks);
    let size = format!("{stacks}×{}", 2 * stacks);
    let frame = |at| RasterFrame { mesh: &mesh, model, camera: &camera, at, surface: surface.clone() };
    for (at, label) in [
        (NormalMatrixAt::PerVertex, "normal matrix per vertex"),
        (NormalMatrixAt::PerDraw, "normal matrix per draw"),
        (NormalMatrixAt::Cofactor, "normal matrix cofactor"),
    ] {
        ctx.raster(
            SPHERE,
            "normal matrix",
            &format!("{label}, {size}"),
            &frame(at),
            &Shading::PerFragment(&lit),
            &reference,
        );
    }
    let eye = camera.eye;
    let scalar = PerLane(|p, n| lights.shade(&material, p, n, eye).rgb());
    let culled = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len() + 1));
    let culled_shader = PerLane(|p, n| culled.shade(&material, p, n, eye).shaded.rgb());
    let f = frame(NormalMatrixAt::PerDraw);
    ctx.raster(SPHERE, "simd", &format!("16-lane kernel, {size}"), &f, &Shading::PerFragment(&lit), &reference);
    ctx.raster(SPHERE, "simd", &format!("scalar Scene::shade, {size}"), &f, &Shading::PerFragment(&scalar), &reference);
    ctx.raster(
        SPHERE,
        "culling",
        &format!("culling on (scalar), {size}"),
        &f,
        &Shading::PerFragment(&culled_shader),
        &reference,
    );
}
