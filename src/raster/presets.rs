//! The tutorials' scenes and the benchmark scenes of `../shared/DESIGN.md`, as [`World`]s.
//!
//! | preset | scene |
//! | --- | --- |
//! | `coral-cube` | LearnOpenGL Basic lighting: the coral cube and its lamp |
//! | `materials-grid` | the 24 classic materials on spheres under a white light |
//! | `container` | LearnOpenGL Lighting maps: the container with diffuse, specular and emission maps |
//! | `casters-directional`, `casters-point`, `casters-spot` | LearnOpenGL Light casters: ten containers |
//! | `multiple-lights`, `multiple-lights-<atmosphere>` | LearnOpenGL Multiple lights and its four atmospheres |
//! | `quad-single`, `quad-multi`, `cube-multi`, `sphere4096-multi`, `sphere4096-gouraud`, `floor-lights256` | the benchmark scenes |
//! | `quad-multi-ATM`, `sphere4096-multi-ATM` (ATM: `desert`, `factory`, `horror`, `biochemical-lab`) | the multi scenes under an atmosphere's coloured lights |
//!
//! Every preset is a [`SceneDesc`] ([`preset_desc`]), the same data a scene
//! file holds, so `lightlab render --preset NAME --dump-scene` can write any
//! of them as a scene file that renders the same image.
//!
//! Sources: LearnOpenGL, Lighting chapters (Basic lighting: light at (1.2, 1, 2),
//! ambient 0.1, specular 0.5, shininess 32; Lighting maps: light (0.2, 0.5, 1.0),
//! shininess 64; Light casters: `cubePositions`, direction (−0.2, −1, −0.3),
//! attenuation (1, 0.09, 0.032), cut-offs 12.5° and 17.5°; Multiple lights:
//! `pointLightPositions` and the atmospheres of the chapter's exercise), and
//! `../shared/DESIGN.md` with `../shared/tools/llvmpipe_bench.py` for the benchmark scenes.

use glam::{Mat4, Vec3, Vec4};

use super::camera::{Camera, CameraError};
use super::kernel::RangeWindow;
use super::mesh::Mesh;
use super::pipeline::{Geometry, Object, World};
use super::rasterize::CullMode;
use super::scene_desc::{CameraDesc, MaterialDesc, MeshKind, ObjectDesc, SceneDesc};
use super::shade::{ShadingMode, Surface, TutorialModel};

use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material, CLASSIC_MATERIALS};
use crate::models::{ogldev_comparable, Ogldev, OpenGLTutorial, ShadingModel};
use crate::phong::BasicLighting;
use crate::scene::{Atmosphere, Scene};

/// The benchmark scenes of `../shared/DESIGN.md`, in `llvmpipe_bench.py`'s order.
pub const BENCH_SCENES: [&str; 6] =
    ["quad-single", "quad-multi", "cube-multi", "sphere4096-multi", "sphere4096-gouraud", "floor-lights256"];

/// The scenes that carry an atmosphere's coloured lights: `SCENE-ATMOSPHERE`.
pub const COLOURED_BASES: [&str; 2] = ["quad-multi", "sphere4096-multi"];

/// The coloured-light benchmark scenes, in `llvmpipe_bench.py`'s order: for each
/// [`Atmosphere`] in turn, `quad-multi-ATM` then `sphere4096-multi-ATM`. Each is its base
/// scene (same geometry, camera and coral material) under [`Atmosphere::scene`]'s lights
/// in place of the chapter's grey ones.
pub fn coloured_scenes() -> Vec<String> {
    Atmosphere::ALL.iter().flat_map(|a| COLOURED_BASES.iter().map(move |base| format!("{base}-{}", a.name()))).collect()
}

/// Every scene `lightlab bench` times by default: [`BENCH_SCENES`], then
/// [`coloured_scenes`] (`llvmpipe_bench.py`'s list).
pub fn all_bench_scenes() -> Vec<String> {
    BENCH_SCENES.iter().map(|s| s.to_string()).chain(coloured_scenes()).collect()
}

/// A coloured-light scene's base scene and atmosphere (`quad-multi-desert` →
/// `("quad-multi", Desert)`); `None` for any other name.
pub fn coloured_scene(name: &str) -> Option<(&'static str, Atmosphere)> {
    COLOURED_BASES.iter().find_map(|&base| {
        let atmosphere = name.strip_prefix(base)?.strip_prefix('-')?;
        Some((base, Atmosphere::from_name(atmosphere)?))
    })
}

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

/// Every preset name: [`TUTORIAL_PRESETS`], then [`all_bench_scenes`] (the benchmark
/// scenes and their coloured-light variants), the tables [`preset_desc`] reads.
pub fn names() -> Vec<String> {
    TUTORIAL_PRESETS.iter().map(|s| s.to_string()).chain(all_bench_scenes()).collect()
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

/// The eye of the tight close-ups (the container exercises, the three tutorials'
/// models): near the coral cube, below and to its left, so the cube fills the frame and
/// LearnOpenGL's lamp is out of view while the front face's highlight still shows.
pub const TIGHT_EYE: Vec3 = Vec3::new(-1.2, -0.8, 3.2);

/// Where the tight camera looks: just right of the cube's centre.
pub const TIGHT_TARGET: Vec3 = Vec3::new(0.05, 0.0, 0.0);

/// The tight camera: from [`TIGHT_EYE`] at [`TIGHT_TARGET`], y up, 45° vertical field of
/// view, near 0.1, far 100, at `aspect` (width / height); an error for a degenerate aspect.
pub fn tight_camera(aspect: f32) -> Result<Camera, CameraError> {
    Camera::new(TIGHT_EYE, TIGHT_TARGET, Vec3::Y, 45.0, aspect, 0.1, 100.0)
}

/// The lamp cube's model matrix at `position`: `translate(position) · scale(0.2)`, as
/// LearnOpenGL's Basic lighting draws it.
pub fn lamp_model(position: Vec3) -> Mat4 {
    Mat4::from_translation(position) * Mat4::from_scale(Vec3::splat(0.2))
}

/// The three tutorials' shaders as the conventions chapter compares them, with one light
/// at `light_pos` and the eye at `eye`: each one's constants as close to LearnOpenGL's as
/// its model allows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConventionsModels {
    /// LearnOpenGL's Basic lighting with its lamp at `light_pos`.
    pub learnopengl: BasicLighting,
    /// opengl-tutorial 8's defaults ([`OpenGLTutorial::with_defaults`]) on the coral color.
    pub opengl_tutorial: OpenGLTutorial,
    /// ogldev 19's directional light from `light_pos` toward the origin ([`ogldev_comparable`]).
    pub ogldev: Ogldev,
}

impl ConventionsModels {
    /// The three models with the light at `light_pos` and the eye at `eye`.
    pub fn new(light_pos: Vec3, eye: Vec3) -> ConventionsModels {
        let learnopengl = BasicLighting { light_pos, view_pos: eye, ..BasicLighting::learnopengl() };
        ConventionsModels {
            learnopengl,
            opengl_tutorial: OpenGLTutorial::with_defaults(light_pos, learnopengl.object_color),
            ogldev: ogldev_comparable(light_pos),
        }
    }

    /// `model`'s shader when it is one of the other tutorials' (opengl-tutorial 8, ogldev
    /// 19: a [`Surface::Tutorial`], carrying its own light); `None` for LearnOpenGL and
    /// Blinn-Phong, which the scene's lights shade through [`Self::learnopengl`].
    pub fn tutorial(&self, model: ShadingModel) -> Option<TutorialModel> {
        match model {
            ShadingModel::OpenGLTutorial => Some(TutorialModel::OpenGLTutorial(self.opengl_tutorial)),
            ShadingModel::Ogldev => Some(TutorialModel::Ogldev(self.ogldev)),
            ShadingModel::LearnOpenGL | ShadingModel::BlinnPhong => None,
        }
    }
}

/// The conventions chapter's scene: LearnOpenGL's coral cube (identity model matrix, no
/// culling) and its white lamp cube (scale 0.2, unlit) at `light_pos`, seen by
/// [`tight_camera`] on LearnOpenGL's grey 0.1, shaded by `model` with the light at
/// `light_pos` and each model's eye at the camera:
///
/// | model | surface |
/// | --- | --- |
/// | `learnopengl`, `blinn-phong` | Basic lighting ([`basic_lighting_scene`]), `reflect` or halfway lobe |
/// | `opengl-tutorial` | [`OpenGLTutorial::with_defaults`]`(light_pos, coral)`: `LightPower` 50, exponent 5 |
/// | `ogldev` | [`ogldev_comparable`]`(light_pos)`: directional, from `light_pos` toward the cube's centre |
///
/// Per fragment. An error for a degenerate aspect. Sources: LearnOpenGL, Basic lighting;
/// opengl-tutorial 8; ogldev 19.
pub fn conventions_world(model: ShadingModel, light_pos: Vec3, aspect: f32) -> Result<World, CameraError> {
    let camera = tight_camera(aspect)?;
    let models = ConventionsModels::new(light_pos, camera.eye);
    let (scene, material) = basic_lighting_scene(&models.learnopengl);
    let no_lights = Scene { point_lights: Vec::new(), ..scene.clone() };
    let shading = if model == ShadingModel::BlinnPhong { ShadingMode::BlinnPhong } else { ShadingMode::Phong };
    let (lights, surface) = match models.tutorial(model) {
        Some(tutorial) => (no_lights, Surface::Tutorial(tutorial)),
        None => (scene, Surface::Material(material)),
    };
    let cube = Object {
        geometry: Geometry::Mesh(Mesh::learnopengl_cube()),
        model: Mat4::IDENTITY,
        surface,
        cull: CullMode::None,
    };
    let lamp = Object {
        geometry: Geometry::Mesh(Mesh::learnopengl_cube()),
        model: lamp_model(light_pos),
        surface: Surface::Unlit(models.learnopengl.light_color),
        cull: CullMode::None,
    };
    let clear = lights.clear_color.extend(1.0);
    Ok(World {
        camera,
        lights,
        objects: vec![cube, lamp],
        shading,
        clear,
        depth_test: true,
        range_window: None,
        specialisations: crate::raster::kernel::Specialisations::ALL,
    })
}

fn bench_desc(objects: Vec<ObjectDesc>, lights: Scene, shading: ShadingMode, depth_test: bool) -> SceneDesc {
    SceneDesc { shading, clear: Vec4::ZERO, depth_test, objects, lights, ..SceneDesc::empty() }
}

fn bench_desc_by_name(name: &str) -> Option<SceneDesc> {
    if let Some((base, atmosphere)) = coloured_scene(name) {
        let mut desc = bench_desc_by_name(base)?;
        desc.lights = atmosphere.scene();
        return Some(desc);
    }
    let multi = Scene::learnopengl_default;
    let quad = |material| ObjectDesc { material, cull: CullMode::None, ..ObjectDesc::new(MeshKind::NdcQuad) };
    Some(match name {
        "quad-single" => {
            let (lights, material) = basic_lighting_scene(&BasicLighting::learnopengl());
            bench_desc(vec![quad(MaterialDesc::Custom(material))], lights, ShadingMode::Phong, false)
        }
        "quad-multi" => bench_desc(vec![quad(MaterialDesc::Coral)], multi(), ShadingMode::Phong, false),
        "cube-multi" => {
            let cube = ObjectDesc {
                rotate_deg: 50.0,
                rotate_axis: Vec3::new(1.0, 0.3, 0.5),
                scale: Vec3::splat(1.5),
                ..ObjectDesc::new(MeshKind::Cube)
            };
            bench_desc(vec![cube], multi(), ShadingMode::Phong, true)
        }
        "sphere4096-multi" | "sphere4096-gouraud" => {
            let sphere = ObjectDesc { detail: Some(32), ..ObjectDesc::new(MeshKind::UvSphere) };
            let shading = if name == "sphere4096-multi" { ShadingMode::Phong } else { ShadingMode::Gouraud };
            bench_desc(vec![sphere], multi(), shading, true)
        }
        "floor-lights256" => {
            // Mesh::plane(1) spans [-1, 1]² at y = 0; this maps it exactly onto x ∈ [-10, 10],
            // z ∈ [-20, 3], y = -1, with the same diagonal as the script's two triangles
            let floor = ObjectDesc {
                detail: Some(1),
                scale: Vec3::new(10.0, 1.0, 11.5),
                translate: Vec3::new(0.0, -1.0, -8.5),
                cull: CullMode::Back,
                ..ObjectDesc::new(MeshKind::Plane)
            };
            bench_desc(vec![floor], floor_lights(), ShadingMode::Phong, true)
        }
        _ => return None,
    })
}

/// The 256 point lights of `floor-lights256`: a 16 × 16 grid at y = -0.75,
/// `x = -7.5 + i`, `z = -15.5 + j` (light `k` at `i = k mod 16`, `j = k div 16`),
/// each the LearnOpenGL point light (ambient 0.05, diffuse 0.8, specular 1, times
/// its color) with Ogre's range-7 attenuation (1, 0.7, 1.8); colors cycle
/// through eight hues by `(i + 3j) mod 8`.
///
/// Source: `../shared/tools/llvmpipe_bench.py` (`many_lights`, `FS_MANY`);
/// Ogre's point light attenuation table (range 7).
pub fn floor_lights() -> Scene {
    const HUES: [Vec3; 8] = [
        Vec3::new(1.0, 0.2, 0.2),
        Vec3::new(0.2, 1.0, 0.2),
        Vec3::new(0.2, 0.2, 1.0),
        Vec3::new(1.0, 1.0, 0.2),
        Vec3::new(1.0, 0.2, 1.0),
        Vec3::new(0.2, 1.0, 1.0),
        Vec3::new(1.0, 0.6, 0.2),
        Vec3::new(1.0, 1.0, 1.0),
    ];
    let point_lights = (0..256)
        .map(|k| {
            let (i, j) = (k % 16, k / 16);
            let color = HUES[(i + 3 * j) % 8];
            PointLight {
                position: Vec3::new(-7.5 + i as f32, -0.75, -15.5 + j as f32),
                attenuation: Attenuation { constant: 1.0, linear: 0.7, quadratic: 1.8 },
                props: LightProps { ambient: 0.05 * color, diffuse: 0.8 * color, specular: color },
            }
        })
        .collect();
    Scene { dir_light: None, point_lights, spot_light: None, clear_color: Vec3::ZERO }
}

/// A benchmark scene by name, exactly as `../shared/DESIGN.md` defines it, at
/// [`BENCH_SIZE`]'s aspect; `None` if unknown.
pub fn bench_scene(name: &str) -> Option<World> {
    bench_scene_at(name, BENCH_SIZE.0 as f32 / BENCH_SIZE.1 as f32)
}

/// A benchmark scene by name at another aspect (width / height); `None` if unknown.
pub fn bench_scene_at(name: &str, aspect: f32) -> Option<World> {
    let cull = match name {
        "floor-lights256-windowed" => false,
        "floor-lights256-windowed-culled" => true,
        _ => return bench_desc_by_name(name)?.to_world(aspect).ok(),
    };
    let mut world = bench_desc_by_name("floor-lights256")?.to_world(aspect).ok()?;
    world.range_window = Some(RangeWindow { range: FLOOR_RANGE, cull });
    Some(world)
}

/// The UV sphere tessellations of the triangle-size sweep (`bench --sweep`), as stacks `d`
/// (slices `2d`, so `4d²` triangles): 256 to 262,144 triangles, from about 800 covered
/// pixels a triangle at 800 × 600 down to about one.
pub const SWEEP_STACKS: [u32; 6] = [8, 16, 32, 64, 128, 256];

/// `sphere4096-multi` with the sphere tessellated with `stacks` stacks and `2 · stacks`
/// slices (`sphere4096-multi` itself at 32); `None` outside the preset's 2..=512 stacks.
pub fn sphere_multi(stacks: u32) -> Option<World> {
    let mut desc = bench_desc_by_name("sphere4096-multi")?;
    desc.objects.first_mut()?.detail = Some(stacks);
    desc.to_world(BENCH_SIZE.0 as f32 / BENCH_SIZE.1 as f32).ok()
}

/// The nominal range of `floor-lights256`'s lights: the row of LearnOpenGL's range table
/// (Ogre's) whose coefficients they use, `(1, 0.7, 1.8)`.
pub const FLOOR_RANGE: f32 = 7.0;

/// `floor-lights256` with its falloff times the range window at [`FLOOR_RANGE`], without
/// and with culling the lights beyond the range. Not the tutorials' falloff, so never
/// compared with llvmpipe's 256-light shader as the same work.
pub const WINDOWED_SCENES: [&str; 2] = ["floor-lights256-windowed", "floor-lights256-windowed-culled"];

/// A camera at `eye` looking between the cube (origin) and its lamp (1.2, 1, 2), so both show.
fn tutorial_camera(eye: Vec3) -> CameraDesc {
    CameraDesc::LookAt { eye, target: Vec3::new(0.5, 0.4, 0.8), up: Vec3::Y, fovy_deg: 45.0, near: 0.1, far: 100.0 }
}

/// LearnOpenGL's ten containers: `cubePositions[i]`, rotated 20·i degrees about (1, 0.3, 0.5).
fn ten_containers() -> Vec<ObjectDesc> {
    CUBE_POSITIONS
        .iter()
        .enumerate()
        .map(|(i, &p)| ObjectDesc {
            translate: p,
            rotate_deg: 20.0 * i as f32,
            rotate_axis: Vec3::new(1.0, 0.3, 0.5),
            material: MaterialDesc::Container { emission: false, shininess: 32.0 },
            cull: CullMode::None,
            ..ObjectDesc::new(MeshKind::LearnOpenGLCube)
        })
        .collect()
}

fn grey(a: f32, d: f32, s: f32) -> LightProps {
    LightProps { ambient: Vec3::splat(a), diffuse: Vec3::splat(d), specular: Vec3::splat(s) }
}

fn empty_scene() -> Scene {
    Scene { dir_light: None, point_lights: Vec::new(), spot_light: None, clear_color: Vec3::splat(0.1) }
}

fn tutorial_desc(camera: CameraDesc, lights: Scene, objects: Vec<ObjectDesc>) -> SceneDesc {
    let clear = lights.clear_color.extend(1.0);
    SceneDesc { camera, lights, objects, clear, ..SceneDesc::empty() }
}

/// A preset by name (tutorial scenes and benchmark scenes) as a [`SceneDesc`]; `None` if unknown.
///
/// Deviation: the Light casters spot (5.4) keeps its ambient term outside the
/// cone; the [`Scene`] sum scales a spot's ambient by the intensity (the
/// Multiple lights shader), so the preset adds an ambient-only point light at
/// the spot with the same attenuation, which gives the 5.4 sum exactly.
pub fn preset_desc(name: &str) -> Option<SceneDesc> {
    let mut desc = match bench_desc_by_name(name) {
        Some(d) => d,
        None => tutorial_desc_by_name(name)?,
    };
    // the background is the scene's clear colour, whatever the lights' atmosphere says
    desc.lights.clear_color = desc.clear.truncate();
    // one lamp entry per point light, `None` where no lamp is drawn
    desc.lamps.resize(desc.lights.point_lights.len(), None);
    Some(desc)
}

fn tutorial_desc_by_name(name: &str) -> Option<SceneDesc> {
    let eye_angle = Vec3::new(-1.6, 1.4, 4.6);
    let cube = |material| ObjectDesc { material, cull: CullMode::None, ..ObjectDesc::new(MeshKind::LearnOpenGLCube) };
    Some(match name {
        "coral-cube" => {
            let (lights, material) = basic_lighting_scene(&BasicLighting::learnopengl());
            tutorial_desc(tutorial_camera(eye_angle), lights, vec![cube(MaterialDesc::Custom(material))])
                .with_white_lamps()
        }
        "materials-grid" => {
            let mut lights = empty_scene();
            lights.point_lights.push(PointLight {
                position: Vec3::new(0.0, 4.0, 8.0),
                attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
                props: LightProps::white(),
            });
            let objects = CLASSIC_MATERIALS
                .iter()
                .enumerate()
                .map(|(k, m)| {
                    let (col, row) = ((k % 6) as f32, (k / 6) as f32);
                    ObjectDesc {
                        detail: Some(24),
                        translate: Vec3::new((col - 2.5) * 1.2, (1.5 - row) * 1.2, 0.0),
                        scale: Vec3::splat(0.5),
                        material: MaterialDesc::Classic(m.name.to_string()),
                        ..ObjectDesc::new(MeshKind::UvSphere)
                    }
                })
                .collect();
            let camera = CameraDesc::LookAt {
                eye: Vec3::new(0.0, 0.0, 9.5),
                target: Vec3::ZERO,
                up: Vec3::Y,
                fovy_deg: 45.0,
                near: 0.1,
                far: 100.0,
            };
            tutorial_desc(camera, lights, objects)
        }
        "container" => {
            let mut lights = empty_scene();
            lights.point_lights.push(PointLight {
                position: Vec3::new(1.2, 1.0, 2.0),
                attenuation: Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
                props: grey(0.2, 0.5, 1.0),
            });
            let material = MaterialDesc::Container { emission: true, shininess: 64.0 };
            tutorial_desc(tutorial_camera(eye_angle), lights, vec![cube(material)]).with_white_lamps()
        }
        "casters-directional" | "casters-point" | "casters-spot" => {
            let mut lights = empty_scene();
            let mut lamps = false;
            match name {
                "casters-directional" => {
                    lights.dir_light =
                        Some(DirLight { direction: Vec3::new(-0.2, -1.0, -0.3), props: grey(0.2, 0.5, 1.0) })
                }
                "casters-point" => {
                    lights.point_lights.push(PointLight {
                        position: Vec3::new(1.2, 1.0, 2.0),
                        attenuation: Attenuation::LEARNOPENGL,
                        props: grey(0.2, 0.5, 1.0),
                    });
                    lamps = true;
                }
                _ => {
                    let (eye, front) = (Vec3::new(0.0, 0.0, 3.0), Vec3::NEG_Z);
                    lights.spot_light =
                        SpotLight::new(eye, front, 12.5, 17.5, Attenuation::LEARNOPENGL, grey(0.0, 0.8, 1.0)).ok();
                    lights.point_lights.push(PointLight {
                        position: eye,
                        attenuation: Attenuation::LEARNOPENGL,
                        props: grey(0.1, 0.0, 0.0),
                    });
                }
            }
            let desc = tutorial_desc(CameraDesc::LearnOpenGL, lights, ten_containers());
            if lamps {
                desc.with_white_lamps()
            } else {
                SceneDesc { lamps: vec![None; desc.lights.point_lights.len()], ..desc }
            }
        }
        _ => {
            let (lights, white) = match name.strip_prefix("multiple-lights") {
                Some("") => (Scene::learnopengl_default(), true),
                Some(rest) => (Atmosphere::from_name(rest.strip_prefix('-')?)?.scene(), false),
                None => return None,
            };
            let desc = tutorial_desc(CameraDesc::LearnOpenGL, lights, ten_containers());
            if white {
                desc.with_white_lamps()
            } else {
                desc.with_light_coloured_lamps()
            }
        }
    })
}

/// A preset by name (tutorial scenes and benchmark scenes), for an image of
/// `aspect` = width / height; `None` if unknown. See [`preset_desc`].
pub fn preset(name: &str, aspect: f32) -> Option<World> {
    preset_desc(name)?.to_world(aspect).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `render --list` prints [`names`]: each is a preset, none twice, and the coloured
    /// benchmark scenes (which `render --preset` draws) are among them.
    #[test]
    fn every_listed_name_is_a_preset_and_every_bench_scene_is_listed() {
        let listed = names();
        for name in &listed {
            assert!(preset_desc(name).is_some(), "{name} is listed but is no preset");
        }
        let mut unique = listed.clone();
        unique.sort();
        unique.dedup();
        assert_eq!(unique.len(), listed.len(), "{listed:?}");
        for scene in all_bench_scenes() {
            assert!(listed.contains(&scene), "{scene} is a preset but is not listed");
        }
        assert!(listed.iter().any(|n| n == "sphere4096-multi-biochemical-lab"), "{listed:?}");
    }
}
