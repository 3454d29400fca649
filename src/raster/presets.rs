//! The tutorials' scenes and the benchmark scenes of `../shared/DESIGN.md`, as [`World`]s.
//!
//! | preset | scene |
//! | --- | --- |
//! | `coral-cube` | LearnOpenGL Basic lighting: the coral cube and its lamp |
//! | `materials-grid` | the 24 classic materials on spheres under a white light |
//! | `container` | LearnOpenGL Lighting maps: the container with diffuse, specular and emission maps |
//! | `casters-directional`, `casters-point`, `casters-spot` | LearnOpenGL Light casters: ten containers |
//! | `multiple-lights`, `multiple-lights-<atmosphere>` | LearnOpenGL Multiple lights and its four atmospheres |
//! | `quad-single`, `quad-multi`, `cube-multi`, `sphere4096-multi`, `sphere4096-gouraud` | the benchmark scenes |
//!
//! Sources: LearnOpenGL, Lighting chapters (constants in `/work/scratch/research.md` §4);
//! `../shared/DESIGN.md` and `../shared/tools/llvmpipe_bench.py` for the benchmark scenes.

use glam::{Mat4, Quat, Vec3, Vec4};

use super::camera::Camera;
use super::mesh::Mesh;
use super::pipeline::{Geometry, Object, World};
use super::rasterize::CullMode;
use super::shade::{ShadingMode, Surface};
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material, CLASSIC_MATERIALS};
use crate::phong::BasicLighting;
use crate::scene::{Atmosphere, Scene, POINT_LIGHT_POSITIONS};

/// The benchmark scenes, in `llvmpipe_bench.py`'s order.
pub const BENCH_SCENES: [&str; 5] =
    ["quad-single", "quad-multi", "cube-multi", "sphere4096-multi", "sphere4096-gouraud"];

/// The tutorial presets (the benchmark scenes are presets too).
pub const TUTORIAL_PRESETS: [&str; 11] = [
    "coral-cube",
    "materials-grid",
    "container",
    "casters-directional",
    "casters-point",
    "casters-spot",
    "multiple-lights",
    "multiple-lights-desert",
    "multiple-lights-factory",
    "multiple-lights-horror",
    "multiple-lights-biochemical-lab",
];

/// The benchmark image size.
pub const BENCH_SIZE: (u32, u32) = (800, 600);

/// LearnOpenGL's ten container positions (`cubePositions`).
pub const CUBE_POSITIONS: [Vec3; 10] = [
    Vec3::new(0.0, 0.0, 0.0),
    Vec3::new(2.0, 5.0, -15.0),
    Vec3::new(-1.5, -2.2, -2.5),
    Vec3::new(-3.8, -2.0, -12.3),
    Vec3::new(2.4, -0.4, -3.5),
    Vec3::new(-1.7, 3.0, -7.5),
    Vec3::new(1.3, -2.0, -2.5),
    Vec3::new(1.5, 2.0, -2.5),
    Vec3::new(1.5, 0.2, -1.5),
    Vec3::new(-1.3, 1.0, -1.5),
];

/// Every preset name.
pub fn names() -> Vec<&'static str> {
    TUTORIAL_PRESETS.iter().chain(BENCH_SCENES.iter()).copied().collect()
}

/// The Basic lighting shader as a one-light [`Scene`] and [`Material`]: a point
/// light with attenuation (1, 0, 0), ambient `ambient_strength · light_color`,
/// diffuse `light_color`, specular `specular_strength · light_color`, on a
/// material whose three reflectances are `object_color`. The sum is the
/// chapter's `(ambient + diffuse + specular) · objectColor`.
pub fn basic_lighting_scene(b: &BasicLighting) -> (Scene, Material) {
    let light = PointLight {
        position: b.light_pos,
        attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
        props: LightProps {
            ambient: b.ambient_strength * b.light_color,
            diffuse: b.light_color,
            specular: b.specular_strength * b.light_color,
        },
    };
    let scene = Scene { dir_light: None, point_lights: vec![light], spot_light: None, clear_color: Vec3::splat(0.1) };
    let m = b.object_color;
    (scene, Material { ambient: m, diffuse: m, specular: m, shininess: b.shininess })
}

fn object(geometry: Geometry, model: Mat4, surface: Surface, cull: CullMode) -> Object {
    Object { geometry, model, surface, cull }
}

fn bench_world(objects: Vec<Object>, lights: Scene, shading: ShadingMode, depth_test: bool) -> World {
    World {
        camera: Camera::learnopengl(BENCH_SIZE.0 as f32 / BENCH_SIZE.1 as f32),
        lights,
        objects,
        shading,
        clear: Vec4::ZERO,
        depth_test,
    }
}

/// A benchmark scene by name, exactly as `../shared/DESIGN.md` defines it; `None` if unknown.
pub fn bench_scene(name: &str) -> Option<World> {
    let multi = Scene::learnopengl_default;
    let coral = Material::coral();
    Some(match name {
        "quad-single" => {
            let (lights, material) = basic_lighting_scene(&BasicLighting::learnopengl());
            let quad = object(Geometry::NdcQuad, Mat4::IDENTITY, Surface::Material(material), CullMode::None);
            bench_world(vec![quad], lights, ShadingMode::Phong, false)
        }
        "quad-multi" => {
            let quad = object(Geometry::NdcQuad, Mat4::IDENTITY, Surface::Material(coral), CullMode::None);
            bench_world(vec![quad], multi(), ShadingMode::Phong, false)
        }
        "cube-multi" => {
            let model = Mat4::from_axis_angle(Vec3::new(1.0, 0.3, 0.5).normalize(), 50f32.to_radians())
                * Mat4::from_scale(Vec3::splat(1.5));
            let cube = object(Geometry::Mesh(Mesh::benchmark_cube()), model, Surface::Material(coral), CullMode::Back);
            bench_world(vec![cube], multi(), ShadingMode::Phong, true)
        }
        "sphere4096-multi" | "sphere4096-gouraud" => {
            let sphere = object(
                Geometry::Mesh(Mesh::uv_sphere(32, 64)),
                Mat4::IDENTITY,
                Surface::Material(coral),
                CullMode::Back,
            );
            let shading = if name == "sphere4096-multi" { ShadingMode::Phong } else { ShadingMode::Gouraud };
            bench_world(vec![sphere], multi(), shading, true)
        }
        _ => return None,
    })
}

/// A camera at `eye` looking between the cube (origin) and its lamp (1.2, 1, 2), so both show.
fn tutorial_camera(eye: Vec3, aspect: f32) -> Camera {
    Camera::new(eye, Vec3::new(0.5, 0.4, 0.8), Vec3::Y, 45.0, aspect, 0.1, 100.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect))
}

fn lamp(position: Vec3, color: Vec3) -> Object {
    object(
        Geometry::Mesh(Mesh::learnopengl_cube()),
        Mat4::from_translation(position) * Mat4::from_scale(Vec3::splat(0.2)),
        Surface::Unlit(color),
        CullMode::None,
    )
}

fn container_maps() -> crate::maps::LightingMaps {
    crate::maps::container(128, false).expect("128 is a valid container size")
}

fn ten_containers(maps: &crate::maps::LightingMaps) -> Vec<Object> {
    let axis = Vec3::new(1.0, 0.3, 0.5).normalize();
    CUBE_POSITIONS
        .iter()
        .enumerate()
        .map(|(i, &p)| {
            let model = Mat4::from_translation(p)
                * Mat4::from_quat(Quat::from_axis_angle(axis, (20.0 * i as f32).to_radians()));
            object(Geometry::Mesh(Mesh::learnopengl_cube()), model, Surface::Maps(maps.clone()), CullMode::None)
        })
        .collect()
}

fn grey(a: f32, d: f32, s: f32) -> LightProps {
    LightProps { ambient: Vec3::splat(a), diffuse: Vec3::splat(d), specular: Vec3::splat(s) }
}

fn empty_scene(clear: f32) -> Scene {
    Scene { dir_light: None, point_lights: Vec::new(), spot_light: None, clear_color: Vec3::splat(clear) }
}

fn tutorial_world(camera: Camera, lights: Scene, objects: Vec<Object>) -> World {
    let clear = lights.clear_color.extend(1.0);
    World { camera, lights, objects, shading: ShadingMode::Phong, clear, depth_test: true }
}

/// A preset by name (tutorial scenes and benchmark scenes), for an image of
/// `aspect` = width / height; `None` if unknown.
///
/// Deviation: the Light casters spot (5.4) keeps its ambient term outside the
/// cone; the [`Scene`] sum scales a spot's ambient by the intensity (the
/// Multiple lights shader), so the preset adds an ambient-only point light at
/// the spot with the same attenuation, which gives the 5.4 sum exactly.
pub fn preset(name: &str, aspect: f32) -> Option<World> {
    if let Some(mut w) = bench_scene(name) {
        w.camera = Camera::learnopengl(aspect);
        return Some(w);
    }
    let eye_angle = Vec3::new(-1.6, 1.4, 4.6);
    let default_eye = Camera::learnopengl(aspect);
    Some(match name {
        "coral-cube" => {
            let (lights, material) = basic_lighting_scene(&BasicLighting::learnopengl());
            let lamp_pos = BasicLighting::learnopengl().light_pos;
            let cube = object(
                Geometry::Mesh(Mesh::learnopengl_cube()),
                Mat4::IDENTITY,
                Surface::Material(material),
                CullMode::None,
            );
            tutorial_world(tutorial_camera(eye_angle, aspect), lights, vec![cube, lamp(lamp_pos, Vec3::ONE)])
        }
        "materials-grid" => {
            let light = PointLight {
                position: Vec3::new(0.0, 4.0, 8.0),
                attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
                props: LightProps::white(),
            };
            let mut lights = empty_scene(0.1);
            lights.point_lights.push(light);
            let sphere = Mesh::uv_sphere(24, 48);
            let objects = CLASSIC_MATERIALS
                .iter()
                .enumerate()
                .map(|(k, m)| {
                    let (col, row) = ((k % 6) as f32, (k / 6) as f32);
                    let centre = Vec3::new((col - 2.5) * 1.2, (1.5 - row) * 1.2, 0.0);
                    let model = Mat4::from_translation(centre) * Mat4::from_scale(Vec3::splat(0.5));
                    object(Geometry::Mesh(sphere.clone()), model, Surface::Material(m.material()), CullMode::Back)
                })
                .collect();
            let camera = Camera::new(Vec3::new(0.0, 0.0, 9.5), Vec3::ZERO, Vec3::Y, 45.0, aspect, 0.1, 100.0)
                .unwrap_or(default_eye);
            tutorial_world(camera, lights, objects)
        }
        "container" => {
            let mut lights = empty_scene(0.1);
            lights.point_lights.push(PointLight {
                position: Vec3::new(1.2, 1.0, 2.0),
                attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
                props: grey(0.2, 0.5, 1.0),
            });
            let mut maps = crate::maps::container(128, true).expect("128 is a valid container size");
            maps.shininess = 64.0;
            let cube =
                object(Geometry::Mesh(Mesh::learnopengl_cube()), Mat4::IDENTITY, Surface::Maps(maps), CullMode::None);
            tutorial_world(
                tutorial_camera(eye_angle, aspect),
                lights,
                vec![cube, lamp(Vec3::new(1.2, 1.0, 2.0), Vec3::ONE)],
            )
        }
        "casters-directional" | "casters-point" | "casters-spot" => {
            let mut lights = empty_scene(0.1);
            let mut objects = ten_containers(&container_maps());
            match name {
                "casters-directional" => {
                    lights.dir_light =
                        Some(DirLight { direction: Vec3::new(-0.2, -1.0, -0.3), props: grey(0.2, 0.5, 1.0) })
                }
                "casters-point" => {
                    let position = Vec3::new(1.2, 1.0, 2.0);
                    lights.point_lights.push(PointLight {
                        position,
                        attenuation: Attenuation::LEARNOPENGL,
                        props: grey(0.2, 0.5, 1.0),
                    });
                    objects.push(lamp(position, Vec3::ONE));
                }
                _ => {
                    let (eye, front) = (default_eye.eye, Vec3::NEG_Z);
                    lights.spot_light =
                        SpotLight::new(eye, front, 12.5, 17.5, Attenuation::LEARNOPENGL, grey(0.0, 0.8, 1.0)).ok();
                    lights.point_lights.push(PointLight {
                        position: eye,
                        attenuation: Attenuation::LEARNOPENGL,
                        props: grey(0.1, 0.0, 0.0),
                    });
                }
            }
            tutorial_world(default_eye, lights, objects)
        }
        _ => {
            let lights = match name.strip_prefix("multiple-lights") {
                Some("") => Scene::learnopengl_default(),
                Some(rest) => Atmosphere::from_name(rest.strip_prefix('-')?)?.scene(),
                None => return None,
            };
            let mut objects = ten_containers(&container_maps());
            for (p, light) in POINT_LIGHT_POSITIONS.iter().zip(&lights.point_lights) {
                let color = if name == "multiple-lights" { Vec3::ONE } else { light.props.diffuse };
                objects.push(lamp(*p, color));
            }
            tutorial_world(default_eye, lights, objects)
        }
    })
}
