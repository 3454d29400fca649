//! The study's material, sphere model, floor scene and floor camera.

use glam::{DVec3, Mat4, Vec3, Vec4};

use crate::casters::{DirLight, PointLight, RANGE_TABLE};
use crate::material::{LightProps, Material};
use crate::raster::camera::Camera;
use crate::raster::kernel::Specular;
use crate::raster::raycast::{RayObject, RayScene, Shape};
use crate::scene::Scene;

/// The study's material: LearnOpenGL's coral (ambient = diffuse = (1, 0.5, 0.31)), specular 0.5, shininess 32.
pub fn study_material() -> Material {
    Material {
        ambient: Vec3::new(1.0, 0.5, 0.31),
        diffuse: Vec3::new(1.0, 0.5, 0.31),
        specular: Vec3::splat(0.5),
        shininess: 32.0,
    }
}

/// The sphere's model matrix: `rotate(50°, (1, 0.3, 0.5))`, the tutorials' cube
/// rotation; it maps the unit sphere onto itself, so the ray caster's sphere is exact.
pub fn sphere_model() -> Mat4 {
    Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50f32.to_radians())
}

/// The floor scene's lights: a dim directional light and a 5 × 5 grid of white
/// range-7 point lights (LearnOpenGL's `(1, 0.7, 1.8)`), 100 units apart, 1 unit above the floor.
pub fn floor_scene() -> Scene {
    let attenuation = RANGE_TABLE[0].attenuation;
    let props = LightProps { ambient: Vec3::splat(0.05), diffuse: Vec3::splat(0.8), specular: Vec3::ONE };
    let mut point_lights = Vec::new();
    for i in -2..=2 {
        for j in -2..=2 {
            let position = Vec3::new(100.0 * i as f32, 1.0, 100.0 * j as f32);
            point_lights.push(PointLight { position, attenuation, props });
        }
    }
    let dir = LightProps { ambient: Vec3::splat(0.05), diffuse: Vec3::splat(0.2), specular: Vec3::ZERO };
    Scene {
        dir_light: Some(DirLight { direction: Vec3::new(-0.2, -1.0, -0.3), props: dir }),
        point_lights,
        spot_light: None,
        clear_color: Vec3::ZERO,
    }
}

pub(super) fn floor_camera(aspect: f32) -> Camera {
    Camera::new(Vec3::new(0.0, 260.0, 260.0), Vec3::ZERO, Vec3::Y, 45.0, aspect, 1.0, 2000.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect))
}

/// The sphere studies' setup at `w × h`: the tutorials' camera, the Multiple lights
/// chapter's default lights, [`study_material`], and the ray-cast scene of the exact unit
/// sphere at the origin with them (the `f64` reference).
pub(super) struct UnitSphere {
    pub camera: Camera,
    pub lights: Scene,
    pub material: Material,
    pub ray: RayScene,
}

/// [`UnitSphere`] for an image of `w × h` pixels.
pub(super) fn unit_sphere(w: u32, h: u32) -> UnitSphere {
    let camera = Camera::learnopengl(w as f32 / h as f32);
    let lights = Scene::learnopengl_default();
    let material = study_material();
    let ray = RayScene {
        camera,
        lights: lights.clone(),
        objects: vec![RayObject { shape: Shape::Sphere { center: DVec3::ZERO, radius: 1.0 }, material }],
        clear: Vec4::ZERO,
        specular: Specular::Phong,
    };
    UnitSphere { camera, lights, material, ray }
}
