//! The live figures of chapters 1–3 (and the shared helpers); chapters 4–6 are in
//! [`super::casters`]. Each figure's state is computed from the same Rust values that
//! build its raster world (the chapter's presets where one exists), so the page and the
//! reference cannot drift apart.

use glam::{Mat4, Vec3, Vec4};

use super::assets::{sphere_name, SMOOTH_SPHERE, SPHERE_TESSELLATIONS};
use super::{put, select, Apply, Control, Draw, Kind, Panel, Spec, State};
use crate::material::{LightProps, Material, CLASSIC_MATERIALS};
use crate::phong::BasicLighting;
use crate::raster::camera::Camera;
use crate::raster::mesh::Mesh;
use crate::raster::pipeline::{Geometry, Object, World};
use crate::raster::presets::basic_lighting_scene;
use crate::raster::rasterize::CullMode;
use crate::raster::shade::{ShadingMode, Surface};

/// Panel size of most figures (4:3).
pub const PANEL: (u32, u32) = (320, 240);

/// The aspect ratio of `size`.
pub fn aspect(size: (u32, u32)) -> f32 {
    size.0 as f32 / size.1 as f32
}

/// An option that applies `f`.
pub fn opt<P>(label: impl Into<String>, f: impl Fn(&mut P) + Send + Sync + 'static) -> (String, Apply<P>) {
    (label.into(), Box::new(f))
}

/// A draw of `program` on `mesh` with `model`.
pub fn draw(program: &str, mesh: &str, model: Mat4, cull: bool) -> Draw {
    Draw {
        program: program.to_owned(),
        mesh: mesh.to_owned(),
        model,
        uniforms: Vec::new(),
        textures: Vec::new(),
        cull,
        when: None,
    }
}

/// The lamp cube at `position` (scale 0.2, as the chapters draw it), colored by state key `color_key`.
pub fn lamp_draw(model_key: &str, color_key: &str) -> Draw {
    let mut d = draw("lamp", "cube", Mat4::IDENTITY, false);
    d.uniforms = vec![("model".into(), model_key.into()), ("lampColor".into(), color_key.into())];
    d
}

pub use crate::raster::presets::lamp_model;

/// The lamp as a raster object.
pub fn lamp_object(position: Vec3, color: Vec3) -> Object {
    Object {
        geometry: Geometry::Mesh(Mesh::learnopengl_cube()),
        model: lamp_model(position),
        surface: Surface::Unlit(color),
        cull: CullMode::None,
    }
}

/// Camera uniforms and the clear color.
pub fn camera_state(s: &mut State, c: &Camera, clear: Vec4) {
    put(s, "view", &c.view.to_cols_array());
    put(s, "projection", &c.projection.to_cols_array());
    put(s, "viewPos", &c.eye.to_array());
    put(s, "clearColor", &clear.to_array());
}

/// A light's three terms under `prefix` (`light`, `dirLight`, `pointLights[0]`).
pub fn props_state(s: &mut State, prefix: &str, p: &LightProps) {
    put(s, &format!("{prefix}.ambient"), &p.ambient.to_array());
    put(s, &format!("{prefix}.diffuse"), &p.diffuse.to_array());
    put(s, &format!("{prefix}.specular"), &p.specular.to_array());
}

/// The camera the Basic lighting figures look through: from the front left, at the cube and its lamp.
pub fn tutorial_camera(size: (u32, u32)) -> Camera {
    Camera::new(Vec3::new(-1.6, 1.4, 4.6), Vec3::new(0.5, 0.4, 0.8), Vec3::Y, 45.0, aspect(size), 0.1, 100.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect(size)))
}

/// Basic lighting parameters plus the view.
#[derive(Clone)]
pub struct Basic {
    /// The shader's parameters.
    pub b: BasicLighting,
    /// The camera.
    pub camera: Camera,
    /// Where the lighting is evaluated (Phong, Blinn-Phong, Gouraud).
    pub shading: ShadingMode,
    /// The program drawn (`basic`, `basic_view`, `blinn`).
    pub program: &'static str,
    /// The mesh drawn.
    pub mesh: String,
    /// The object's model matrix.
    pub model: Mat4,
}

fn basic_default(camera: Camera) -> Basic {
    let b = BasicLighting::learnopengl();
    Basic { b, camera, shading: ShadingMode::Phong, program: "basic", mesh: "cube".into(), model: Mat4::IDENTITY }
}

fn basic_state(p: &Basic) -> State {
    let mut s = State::new();
    let b = &p.b;
    put(&mut s, "lightPos", &b.light_pos.to_array());
    put(&mut s, "lightColor", &b.light_color.to_array());
    put(&mut s, "objectColor", &b.object_color.to_array());
    put(&mut s, "ambientStrength", &[b.ambient_strength]);
    put(&mut s, "specularStrength", &[b.specular_strength]);
    put(&mut s, "shininess", &[b.shininess]);
    put(&mut s, "lampModel", &lamp_model(b.light_pos).to_cols_array());
    camera_state(&mut s, &p.camera, Vec4::new(0.1, 0.1, 0.1, 1.0));
    // the shader's viewPos is the camera's eye
    put(&mut s, "viewPos", &p.camera.eye.to_array());
    select(&mut s, "@prog", p.program);
    select(&mut s, "@mesh", &p.mesh);
    s
}

/// The raster world of a Basic lighting figure: the object and its lamp.
fn basic_world(p: &Basic, with_lamp: bool) -> World {
    let mut b = p.b;
    b.view_pos = p.camera.eye;
    let (lights, material) = basic_lighting_scene(&b);
    let mesh = super::assets::mesh(&p.mesh).unwrap_or_else(|_| Mesh::learnopengl_cube());
    let cull = if p.mesh == "cube" { CullMode::None } else { CullMode::Back };
    let mut objects =
        vec![Object { geometry: Geometry::Mesh(mesh), model: p.model, surface: Surface::Material(material), cull }];
    if with_lamp {
        objects.push(lamp_object(b.light_pos, b.light_color));
    }
    let clear = lights.clear_color.extend(1.0);
    World {
        camera: p.camera,
        lights,
        objects,
        shading: p.shading,
        clear,
        depth_test: true,
        range_window: None,
        specialisations: crate::raster::kernel::Specialisations::ALL,
    }
}

fn basic_panels(with_lamp: bool) -> Vec<Panel> {
    let mut draws = vec![draw("@prog", "@mesh", Mat4::IDENTITY, false)];
    if with_lamp {
        draws.push(lamp_draw("lampModel", "lightColor"));
    }
    vec![Panel { label: String::new(), draws }]
}

fn basic_spec(
    id: &'static str,
    title: &str,
    controls: Vec<Control<Basic>>,
    points: Vec<(String, Basic)>,
) -> Spec<Basic> {
    Spec {
        id,
        chapter: "02-basic-lighting",
        title: title.to_owned(),
        size: PANEL,
        panels: basic_panels(true),
        default: basic_default(tutorial_camera(PANEL)),
        state: basic_state,
        worlds: |p| vec![basic_world(p, true)],
        controls,
        points,
        editor: None,
        curve_axes: None,
    }
}

fn point<P: Clone>(name: &str, default: &P, f: impl Fn(&mut P)) -> (String, P) {
    let mut p = default.clone();
    f(&mut p);
    (name.to_owned(), p)
}

pub(super) fn range<P>(label: &str, values: &[f32], default: f32, play: bool, set: fn(&mut P, f32)) -> Control<P>
where
    P: 'static,
{
    let options = values.iter().map(|&v| opt(trim(v), move |p: &mut P| set(p, v))).collect();
    let default = values.iter().position(|&v| v == default).unwrap_or(0);
    Control::new(label, Kind::Range { play }, options, default)
}

/// A number as the slider shows it (up to three decimals, no trailing zeros).
pub fn trim(v: f32) -> String {
    let s = format!("{v:.3}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// `n` values from `a` by `step`.
pub fn steps(a: f32, step: f32, n: usize) -> Vec<f32> {
    (0..n).map(|k| a + step * k as f32).collect()
}

const SHININESS: [f32; 8] = [2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0, 256.0];

pub(super) fn colors() -> Spec<Basic> {
    let mut spec =
        basic_spec("colors", "the light's color times the object's color, on the lit cube", Vec::new(), Vec::new());
    spec.chapter = "01-colors";
    let d = spec.default.clone();
    spec.controls = vec![
        Control::new("light color", Kind::Color { key: "lightColor".into() }, Vec::new(), 0),
        Control::new("object color", Kind::Color { key: "objectColor".into() }, Vec::new(), 0),
    ];
    spec.points = vec![
        point("green light", &d, |p| p.b.light_color = Vec3::new(0.0, 1.0, 0.0)),
        point("blue object under yellow light", &d, |p| {
            p.b.light_color = Vec3::new(1.0, 1.0, 0.0);
            p.b.object_color = Vec3::new(0.2, 0.4, 1.0);
        }),
    ];
    spec
}

pub(super) fn basic_strengths() -> Spec<Basic> {
    let d = basic_default(tutorial_camera(PANEL));
    let controls = vec![
        range("ambientStrength", &steps(0.0, 0.05, 21), 0.1, false, |p: &mut Basic, v| p.b.ambient_strength = v),
        range("specularStrength", &steps(0.0, 0.1, 11), 0.5, false, |p: &mut Basic, v| p.b.specular_strength = v),
        range("shininess", &SHININESS, 32.0, false, |p: &mut Basic, v| p.b.shininess = v),
    ];
    let points = vec![
        point("ambient 0.5, specular 1, shininess 8", &d, |p| {
            p.b.ambient_strength = 0.5;
            p.b.specular_strength = 1.0;
            p.b.shininess = 8.0;
        }),
        point("ambient 0, specular 0.2, shininess 256", &d, |p| {
            p.b.ambient_strength = 0.0;
            p.b.specular_strength = 0.2;
            p.b.shininess = 256.0;
        }),
    ];
    let mut spec = basic_spec("basic-strengths", "ambient strength, specular strength and shininess", controls, points);
    spec.editor = Some("basic");
    spec
}

/// Frames of the moving light: the chapter's exercise moves it with `sin` and `cos` of time.
pub const LIGHT_FRAMES: usize = 96;

/// The light position of frame `k`: `(1 + 2 sin t, sin(t/2), 2 cos t)` with `t = 4πk / LIGHT_FRAMES`.
fn light_at(k: usize) -> Vec3 {
    // one period of sin(t/2): t over [0, 4π)
    let t = 4.0 * std::f32::consts::PI * k as f32 / LIGHT_FRAMES as f32;
    Vec3::new(1.0 + 2.0 * t.sin(), (t / 2.0).sin(), 2.0 * t.cos())
}

pub(super) fn basic_move_light() -> Spec<Basic> {
    let d = basic_default(tutorial_camera(PANEL));
    let options = (0..LIGHT_FRAMES)
        .map(|k| {
            let pos = light_at(k);
            opt(
                crate::blanks::fill(
                    super::texts::LABEL_TIME,
                    &[&trim(4.0 * std::f32::consts::PI * k as f32 / LIGHT_FRAMES as f32)],
                ),
                move |p: &mut Basic| p.b.light_pos = pos,
            )
        })
        .collect();
    let controls = vec![Control::new("light position over time", Kind::Range { play: true }, options, 0)];
    let mut d0 = d.clone();
    d0.b.light_pos = light_at(0);
    let points = vec![
        point("frame 20", &d0, |p| p.b.light_pos = light_at(20)),
        point("frame 61", &d0, |p| p.b.light_pos = light_at(61)),
    ];
    let mut spec =
        basic_spec("basic-move-light", "the light moved with sin and cos of time (press play)", controls, points);
    spec.default = d0;
    spec
}

/// Phong (left) and Blinn-Phong (right) side by side on the smooth sphere, one shininess
/// for both. On the cube the tutorial's view shows no highlight on any face, and both lobes
/// looked the same; a sphere always shows the highlight, so the wider Blinn lobe is plain.
pub(super) fn phong_blinn() -> Spec<Basic> {
    let mut d = basic_default(Camera::learnopengl(aspect(PANEL)));
    d.mesh = sphere_name(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1);
    let worlds = |p: &Basic| {
        let mut blinn = p.clone();
        blinn.shading = ShadingMode::BlinnPhong;
        vec![basic_world(p, false), basic_world(&blinn, false)]
    };
    let sphere = sphere_name(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1);
    Spec {
        id: "phong-blinn",
        chapter: "02-basic-lighting",
        title: "Phong against Blinn-Phong: the same exponent gives a wider highlight".into(),
        size: PANEL,
        panels: vec![
            Panel {
                label: "Phong: reflect(-lightDir, norm)".into(),
                draws: vec![draw("basic", &sphere, Mat4::IDENTITY, true)],
            },
            Panel {
                label: "Blinn-Phong: halfway vector".into(),
                draws: vec![draw("blinn", &sphere, Mat4::IDENTITY, true)],
            },
        ],
        default: d.clone(),
        state: basic_state,
        worlds,
        controls: vec![range("shininess", &SHININESS, 32.0, false, |p: &mut Basic, v| p.b.shininess = v)],
        points: vec![
            point("shininess 8", &d, |p| p.b.shininess = 8.0),
            point("shininess 128", &d, |p| p.b.shininess = 128.0),
        ],
        editor: None,
        curve_axes: None,
    }
}

fn orbit_camera(azimuth_deg: f32, size: (u32, u32)) -> Camera {
    let target = Vec3::new(0.5, 0.4, 0.8);
    let base = Vec3::new(-1.6, 1.4, 4.6) - target;
    let eye = target + Mat4::from_rotation_y(azimuth_deg.to_radians()).transform_vector3(base);
    Camera::new(eye, target, Vec3::Y, 45.0, aspect(size), 0.1, 100.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect(size)))
}

pub(super) fn world_view() -> Spec<Basic> {
    let d = basic_default(tutorial_camera(PANEL));
    let controls = vec![
        Control::select(
            "lighting computed in",
            vec![
                opt("world space", |p: &mut Basic| p.program = "basic"),
                opt("view space", |p: &mut Basic| p.program = "basic_view"),
            ],
        ),
        range("camera azimuth (degrees)", &steps(-60.0, 15.0, 9), 0.0, false, |p: &mut Basic, v| {
            p.camera = orbit_camera(v, PANEL)
        }),
    ];
    let points = vec![
        point("view space", &d, |p| p.program = "basic_view"),
        point("view space, camera turned 45 degrees", &d, |p| {
            p.program = "basic_view";
            p.camera = orbit_camera(45.0, PANEL)
        }),
    ];
    basic_spec("world-view", "world space against view space: the same image", controls, points)
}

/// Normals figure parameters: the object's scale along x.
#[derive(Clone)]
pub struct Scaled {
    sx: f32,
}

fn scaled_model(sx: f32) -> Mat4 {
    Mat4::from_rotation_z(0.5) * Mat4::from_scale(Vec3::new(sx, 1.0, 1.0)) * Mat4::from_scale(Vec3::splat(0.8))
}

pub(super) fn normal_matrix_figure() -> Spec<Scaled> {
    let camera = Camera::learnopengl(aspect(PANEL));
    let state = |p: &Scaled| {
        let mut s = basic_state(&basic_default(Camera::learnopengl(aspect(PANEL))));
        put(&mut s, "model", &scaled_model(p.sx).to_cols_array());
        s
    };
    let worlds = |p: &Scaled| {
        let camera = Camera::learnopengl(aspect(PANEL));
        let mut base = basic_default(camera);
        base.mesh = sphere_name(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1);
        let model = scaled_model(p.sx);
        // the mistake: normals through mat3(model); the raster gets the transformed mesh
        let sphere = Mesh::uv_sphere(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1);
        let m3 = glam::Mat3::from_mat4(model);
        let wrong = Mesh {
            positions: sphere.positions.iter().map(|&q| model.transform_point3(q)).collect(),
            normals: sphere.normals.iter().map(|&n| m3 * n).collect(),
            ..sphere
        };
        let mut left = basic_world(&base, false);
        left.objects[0].geometry = Geometry::Mesh(wrong);
        base.model = model;
        let right = basic_world(&base, false);
        vec![left, right]
    };
    let sphere = sphere_name(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1);
    let mut wrong = draw("basic_model_normal", &sphere, Mat4::IDENTITY, true);
    wrong.uniforms = vec![("model".into(), "model".into())];
    let mut right = draw("basic", &sphere, Mat4::IDENTITY, true);
    right.uniforms = vec![("model".into(), "model".into())];
    let d = Scaled { sx: 2.0 };
    let _ = camera;
    Spec {
        id: "normal-matrix",
        chapter: "02-basic-lighting",
        title: "a sphere scaled along x: normals through the model matrix (left) and the normal matrix (right)".into(),
        size: PANEL,
        panels: vec![
            Panel { label: "mat3(model) * aNormal".into(), draws: vec![wrong] },
            Panel { label: "transpose(inverse(mat3(model))) * aNormal".into(), draws: vec![right] },
        ],
        default: d.clone(),
        state,
        worlds,
        controls: vec![range("scale along x", &steps(0.25, 0.25, 12), 2.0, false, |p: &mut Scaled, v| p.sx = v)],
        points: vec![point("scale 0.5", &d, |p| p.sx = 0.5), point("scale 3", &d, |p| p.sx = 3.0)],
        editor: None,
        curve_axes: None,
    }
}

pub(super) fn gouraud_phong() -> Spec<Basic> {
    let camera = Camera::learnopengl(aspect(PANEL));
    let mut d = basic_default(camera);
    d.mesh = sphere_name(8, 16);
    let options = SPHERE_TESSELLATIONS
        .iter()
        .map(|&(a, b)| opt(format!("{a} x {b}"), move |p: &mut Basic| p.mesh = sphere_name(a, b)))
        .collect();
    let worlds = |p: &Basic| {
        let mut g = p.clone();
        g.shading = ShadingMode::Gouraud;
        vec![basic_world(&g, false), basic_world(p, false)]
    };
    Spec {
        id: "gouraud-phong",
        chapter: "02-basic-lighting",
        title: "Gouraud (left, per vertex) against Phong (right, per fragment) as the sphere gets finer".into(),
        size: PANEL,
        panels: vec![
            Panel { label: "Gouraud".into(), draws: vec![draw("gouraud", "@mesh", Mat4::IDENTITY, true)] },
            Panel { label: "Phong".into(), draws: vec![draw("basic", "@mesh", Mat4::IDENTITY, true)] },
        ],
        default: d.clone(),
        state: basic_state,
        worlds,
        controls: vec![Control::new("tessellation (stacks x slices)", Kind::Range { play: false }, options, 1)],
        points: vec![
            point("4 x 8", &d, |p| p.mesh = sphere_name(4, 8)),
            point("32 x 64", &d, |p| p.mesh = sphere_name(32, 64)),
        ],
        editor: None,
        curve_axes: None,
    }
}

/// Materials figure parameters: a row of the classic table and the light (white, or the
/// chapter's time-varying light at `t` seconds).
#[derive(Clone)]
pub struct Mat {
    index: usize,
    t: Option<f32>,
}

fn mat_light(p: &Mat) -> LightProps {
    p.t.map_or(LightProps::white(), LightProps::time_varying)
}

/// The light of the Materials chapter, at the Basic lighting lamp position.
const MAT_LIGHT_POS: Vec3 = Vec3::new(1.2, 1.0, 2.0);

pub(super) fn materials_figure() -> Spec<Mat> {
    let size = PANEL;
    let state = |p: &Mat| {
        let mut s = State::new();
        let m: Material = CLASSIC_MATERIALS[p.index].material();
        put(&mut s, "material.ambient", &m.ambient.to_array());
        put(&mut s, "material.diffuse", &m.diffuse.to_array());
        put(&mut s, "material.specular", &m.specular.to_array());
        put(&mut s, "material.shininess", &[m.shininess]);
        put(&mut s, "light.position", &MAT_LIGHT_POS.to_array());
        props_state(&mut s, "light", &mat_light(p));
        put(&mut s, "model", &Mat4::IDENTITY.to_cols_array());
        camera_state(&mut s, &Camera::learnopengl(aspect(PANEL)), Vec4::new(0.1, 0.1, 0.1, 1.0));
        s
    };
    let worlds = |p: &Mat| {
        let camera = Camera::learnopengl(aspect(PANEL));
        let light = crate::casters::PointLight {
            position: MAT_LIGHT_POS,
            attenuation: crate::casters::Attenuation { constant: 1.0, linear: 0.0, quadratic: 0.0 },
            props: mat_light(p),
        };
        let lights = crate::scene::Scene {
            dir_light: None,
            point_lights: vec![light],
            spot_light: None,
            clear_color: Vec3::splat(0.1),
        };
        let sphere = Object {
            geometry: Geometry::Mesh(Mesh::uv_sphere(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1)),
            model: Mat4::IDENTITY,
            surface: Surface::Material(CLASSIC_MATERIALS[p.index].material()),
            cull: CullMode::Back,
        };
        vec![World {
            camera,
            lights,
            objects: vec![sphere],
            shading: ShadingMode::Phong,
            clear: Vec4::new(0.1, 0.1, 0.1, 1.0),
            depth_test: true,
            range_window: None,
            specialisations: crate::raster::kernel::Specialisations::ALL,
        }]
    };
    let gold = CLASSIC_MATERIALS.iter().position(|m| m.name == "gold").unwrap_or(0);
    let by = |n: &str| CLASSIC_MATERIALS.iter().position(|m| m.name == n).unwrap_or(0);
    let d = Mat { index: gold, t: None };
    let materials =
        CLASSIC_MATERIALS.iter().enumerate().map(|(i, m)| opt(m.name, move |p: &mut Mat| p.index = i)).collect();
    let mut light_options = vec![opt("white", |p: &mut Mat| p.t = None)];
    light_options.extend((0..120).map(|k| {
        let t = 0.1 * k as f32;
        opt(crate::blanks::fill(super::texts::LABEL_SECONDS, &[&trim(t)]), move |p: &mut Mat| p.t = Some(t))
    }));
    let (jade, ruby) = (by("jade"), by("ruby"));
    Spec {
        id: "materials",
        chapter: "03-materials",
        title: "the 24 classic materials, under white light or the chapter's time-varying light (press play)".into(),
        size,
        panels: vec![Panel {
            label: String::new(),
            draws: vec![draw("materials", &sphere_name(SMOOTH_SPHERE.0, SMOOTH_SPHERE.1), Mat4::IDENTITY, true)],
        }],
        default: d.clone(),
        state,
        worlds,
        controls: vec![
            Control::new("material", Kind::Select, materials, gold),
            Control::new("light", Kind::Range { play: true }, light_options, 0),
        ],
        points: vec![
            point("jade, t = 1 s", &d, |p| {
                p.index = jade;
                p.t = Some(1.0)
            }),
            point("ruby, t = 4.2 s", &d, |p| {
                p.index = ruby;
                p.t = Some(4.2)
            }),
        ],
        editor: None,
        curve_axes: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::live::reference::{plain_share, plainly_different_pixels};

    /// From the chapter's 32 down, the two highlights differ over a plain area. Above it both
    /// shrink to a few dozen pixels (at 128: 548 pixels, under the 1 % bar), as they should.
    #[test]
    fn phong_and_blinn_panels_differ_plainly_at_one_exponent() {
        let spec = phong_blinn();
        let (w, h) = spec.size;
        for shininess in SHININESS.into_iter().filter(|&s| s <= 32.0) {
            let worlds = (spec.worlds)(&point("", &spec.default, |p| p.b.shininess = shininess).1);
            let n = plainly_different_pixels(&worlds[0], &worlds[1], w, h).unwrap();
            assert!(n >= plain_share(spec.size), "shininess {shininess}: Phong and Blinn-Phong differ in {n} pixels");
        }
    }
}
