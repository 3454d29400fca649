//! The floor under many short-range lights, where culling skips lights.

use glam::{DVec3, Mat4, Vec3, Vec4};

use crate::material::Material;
use crate::raster::camera::Camera;
use crate::raster::kernel::{MultiLightKernel, Specular};
use crate::raster::mesh::Mesh;
use crate::raster::raycast::{RayObject, RayScene, Shape};
use crate::raster::shade::{LitShader, Surface};
use crate::scene::Scene;

use super::super::culling::{cull, threshold_for, CulledScene, MaterialBound};
use super::*;

pub(super) fn floor_study(ctx: &mut Ctx) {
    let (w, h) = (ctx.opts.width, ctx.opts.height);
    let camera = floor_camera(w as f32 / h as f32);
    let lights = floor_scene();
    let material = study_material();
    let surface = Surface::Material(material);
    let ray = floor_ray_scene(camera, &lights, material);
    (ctx.progress)(&format!("{FLOOR}: ray-cast reference"));
    let reference = ray_reference(&ray, w, h);
    let mesh = Mesh::plane(8);
    let model = Mat4::from_scale(Vec3::new(2000.0, 1.0, 2000.0));
    let frame =
        RasterFrame { mesh: &mesh, model, camera: &camera, at: NormalMatrixAt::PerDraw, surface: surface.clone() };
    let eye = camera.eye;
    let kernel = MultiLightKernel::new(&lights, eye, material.shininess, Specular::Phong);
    let lit = LitShader::new(kernel, surface);
    let scalar = PerLane(|p, n| lights.shade(&material, p, n, eye).rgb());
    let culled: CulledScene = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len()));
    let culled_shader = PerLane(|p, n| culled.shade(&material, p, n, eye).shaded.rgb());
    ctx.raster(FLOOR, "culling", "culling off (scalar)", &frame, &Shading::PerFragment(&scalar), &reference);
    ctx.raster(FLOOR, "culling", "culling on (scalar)", &frame, &Shading::PerFragment(&culled_shader), &reference);
    ctx.raster(FLOOR, "simd", "16-lane kernel (no culling)", &frame, &Shading::PerFragment(&lit), &reference);
}

/// The floor plane y = 0 under `lights`, for the ray caster (the study's reference).
fn floor_ray_scene(camera: Camera, lights: &Scene, material: Material) -> RayScene {
    RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Plane { point: DVec3::ZERO, normal: DVec3::Y }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    }
}

/// The share of light evaluations culling skips on the floor scene's visible
/// fragments (`width × height` frame), from [`super::super::culling::skipped_share`].
pub fn floor_skipped_share(width: u32, height: u32) -> f32 {
    let camera = floor_camera(width as f32 / height.max(1) as f32);
    let lights = floor_scene();
    let material = study_material();
    let ray = floor_ray_scene(camera, &lights, material);
    let frags: Vec<(Vec3, Vec3)> = super::gbuffer::gbuffer(&ray, width, height).iter().map(|f| (f.p, f.n)).collect();
    let culled = cull(&lights, &MaterialBound::of(&material), threshold_for(lights.point_lights.len()));
    super::super::culling::skipped_share(&culled, &material, &frags, camera.eye)
}
