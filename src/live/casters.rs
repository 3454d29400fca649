//! The live figures of chapters 4–6: lighting maps, light casters, multiple lights.
//! Worlds come from the chapters' raster presets; the state is read from those worlds.

use glam::{Mat4, Vec3};

use super::assets::constant_texture;
use super::chapters::{aspect, camera_state, draw, lamp_draw, lamp_model, opt, props_state, range, steps, PANEL};
use super::{put, select, Control, Draw, Kind, Panel, Spec, State};
use crate::casters::{Attenuation, SpotLight, RANGE_TABLE};
use crate::maps::Sampler;
use crate::material::LightProps;
use crate::raster::camera::Camera;
use crate::raster::pipeline::{Object, World};
use crate::raster::presets::{preset, CUBE_POSITIONS};
use crate::raster::shade::Surface;
use crate::scene::{Atmosphere, Scene};

const TEXTURES: [(&str, &str); 3] =
    [("diffuseMap", "container-diffuse"), ("specularMap", "container-specular"), ("emissionMap", "container-emission")];

fn mapped(program: &str, model: Mat4) -> Draw {
    let mut d = draw(program, "cube", model, false);
    d.textures = TEXTURES.iter().map(|(s, t)| (s.to_string(), t.to_string())).collect();
    d
}

/// The ten containers' model matrices, as the casters presets place them.
fn container_models() -> Vec<Mat4> {
    let axis = Vec3::new(1.0, 0.3, 0.5).normalize();
    CUBE_POSITIONS
        .iter()
        .enumerate()
        .map(|(i, &p)| Mat4::from_translation(p) * Mat4::from_axis_angle(axis, (20.0 * i as f32).to_radians()))
        .collect()
}

/// The maps block of the state: every map on, shininess, filter.
fn maps_state(s: &mut State, shininess: f32, diffuse: bool, specular: bool, emission: bool) {
    put(s, "useDiffuseMap", &[f32::from(u8::from(diffuse))]);
    put(s, "useSpecularMap", &[f32::from(u8::from(specular))]);
    put(s, "useEmissionMap", &[f32::from(u8::from(emission))]);
    put(s, "diffuseConst", &DIFFUSE_OFF.to_array());
    put(s, "specularConst", &Vec3::ZERO.to_array());
    put(s, "shininess", &[shininess]);
    select(s, "@filter", "linear");
}

/// The diffuse color that replaces a switched-off diffuse map: a neutral mid grey.
const DIFFUSE_OFF: Vec3 = Vec3::splat(0.5);

/// Uses the world's maps: the container's, at the live figures' size, sampled with
/// `GL_LINEAR` and `GL_REPEAT` as the page's textures are at first.
fn with_live_maps(world: &mut World, diffuse: bool, specular: bool, emission: bool, shininess: f32) {
    let Ok(mut maps) = super::assets::container() else { return };
    maps.shininess = shininess;
    if !diffuse {
        maps.diffuse = constant_texture(DIFFUSE_OFF).unwrap_or(maps.diffuse);
    }
    if !specular {
        maps.specular = constant_texture(Vec3::ZERO).unwrap_or(maps.specular);
    }
    if !emission {
        maps.emission = None;
    }
    for o in &mut world.objects {
        if matches!(o.surface, Surface::Maps(..)) {
            o.surface = Surface::Maps(maps.clone(), Sampler::LINEAR_REPEAT);
        }
    }
}

// ---------------------------------------------------------------- lighting maps

/// Lighting maps figure parameters.
#[derive(Clone)]
pub struct Maps {
    diffuse: bool,
    specular: bool,
    emission: bool,
    nearest: bool,
}

fn maps_world(p: &Maps) -> World {
    let mut w = preset("container", aspect(PANEL)).expect("the container preset exists");
    let shininess = w.objects.iter().map(|o| o.surface.shininess()).fold(1.0, f32::max);
    with_live_maps(&mut w, p.diffuse, p.specular, p.emission, shininess);
    if p.nearest {
        // the page sets GL_NEAREST as both filters of every map and keeps GL_REPEAT
        for o in &mut w.objects {
            if let Surface::Maps(_, sampler) = &mut o.surface {
                *sampler = Sampler::NEAREST_REPEAT;
            }
        }
    }
    w
}

fn maps_state_of(p: &Maps) -> State {
    let w = maps_world(p);
    let mut s = State::new();
    camera_state(&mut s, &w.camera, w.clear);
    let light = &w.lights.point_lights[0];
    put(&mut s, "light.position", &light.position.to_array());
    props_state(&mut s, "light", &light.props);
    put(&mut s, "lampModel", &lamp_model(light.position).to_cols_array());
    put(&mut s, "lampColor", &Vec3::ONE.to_array());
    maps_state(&mut s, w.objects[0].surface.shininess(), p.diffuse, p.specular, p.emission);
    if p.nearest {
        select(&mut s, "@filter", "nearest");
    }
    s
}

pub(super) fn lighting_maps() -> Spec<Maps> {
    let d = Maps { diffuse: true, specular: true, emission: false, nearest: false };
    let toggle = |label: &str, key: &str, f: fn(&mut Maps, bool)| {
        Control::new(
            label,
            Kind::Toggle { zero: vec![key.to_owned()] },
            vec![opt("on", move |p: &mut Maps| f(p, true)), opt("off", move |p: &mut Maps| f(p, false))],
            0,
        )
    };
    let mut emission = toggle("emission map", "useEmissionMap", |p, v| p.emission = v);
    emission.default = 1;
    Spec {
        id: "lighting-maps",
        chapter: "04-lighting-maps",
        title:
            "the container's diffuse, specular and emission maps switched on and off; nearest against bilinear sampling"
                .into(),
        size: PANEL,
        panels: vec![Panel {
            label: String::new(),
            draws: vec![mapped("maps", Mat4::IDENTITY), lamp_draw("lampModel", "lampColor")],
        }],
        default: d.clone(),
        state: maps_state_of,
        worlds: |p| vec![maps_world(p)],
        controls: vec![
            toggle("diffuse map", "useDiffuseMap", |p, v| p.diffuse = v),
            toggle("specular map", "useSpecularMap", |p, v| p.specular = v),
            emission,
            Control::select(
                "sampling",
                vec![
                    opt("bilinear (GL_LINEAR)", |p: &mut Maps| p.nearest = false),
                    opt("nearest (GL_NEAREST)", |p: &mut Maps| p.nearest = true),
                ],
            ),
        ],
        points: vec![
            ("no specular map, emission on".into(), Maps { specular: false, emission: true, ..d.clone() }),
            ("no diffuse map".into(), Maps { diffuse: false, ..d.clone() }),
            ("nearest (GL_NEAREST), emission on".into(), Maps { nearest: true, emission: true, ..d }),
        ],
        editor: None,
        curve_axes: None,
    }
}

// ---------------------------------------------------------------- light casters

/// Light casters parameters: which caster, the attenuation row, the cone, the camera.
#[derive(Clone)]
pub struct Caster {
    kind: &'static str,
    row: Option<usize>,
    cone: Option<(f32, f32)>,
    camera: Option<Camera>,
    /// How far in front of the camera the spotlight sits, along its axis (0: at the eye, the flashlight).
    spot_ahead: f32,
}

fn caster_world(p: &Caster) -> World {
    let name = format!("casters-{}", p.kind);
    let mut w = preset(&name, aspect(PANEL)).expect("the casters presets exist");
    let shininess = w.objects[0].surface.shininess();
    with_live_maps(&mut w, true, true, false, shininess);
    if let Some(row) = p.row {
        for l in &mut w.lights.point_lights {
            l.attenuation = RANGE_TABLE[row].attenuation;
        }
    }
    if let Some(camera) = p.camera {
        w.camera = camera;
        let front = (camera.view.inverse().transform_vector3(Vec3::NEG_Z)).normalize();
        if let Some(s) = &mut w.lights.spot_light {
            s.position = camera.eye;
            s.direction = front;
        }
        for l in &mut w.lights.point_lights {
            l.position = camera.eye;
        }
    }
    if let Some(s) = &mut w.lights.spot_light {
        s.position += p.spot_ahead * s.direction;
    }
    if let (Some((inner, outer)), Some(s)) = (p.cone, &mut w.lights.spot_light) {
        if let Ok(new) = SpotLight::new(s.position, s.direction, inner, outer, s.attenuation, s.props) {
            *s = new;
        }
    }
    w
}

fn attenuation_state(s: &mut State, a: &Attenuation) {
    put(s, "light.constant", &[a.constant]);
    put(s, "light.linear", &[a.linear]);
    put(s, "light.quadratic", &[a.quadratic]);
}

fn caster_state(p: &Caster) -> State {
    let w = caster_world(p);
    let mut s = State::new();
    camera_state(&mut s, &w.camera, w.clear);
    maps_state(&mut s, w.objects[0].surface.shininess(), true, true, false);
    select(&mut s, "@prog", p.kind);
    let l = &w.lights;
    let mut lamp = None;
    if let Some(d) = &l.dir_light {
        put(&mut s, "light.direction", &d.direction.to_array());
        props_state(&mut s, "light", &d.props);
    } else if let Some(spot) = &l.spot_light {
        put(&mut s, "light.position", &spot.position.to_array());
        put(&mut s, "light.direction", &spot.direction.to_array());
        put(&mut s, "light.cutOff", &[spot.cut_off]);
        put(&mut s, "light.outerCutOff", &[spot.outer_cut_off]);
        // the preset gives the 5.4 spot's ambient (kept outside the cone) as a point light
        let ambient = l.point_lights.first().map_or(Vec3::ZERO, |q| q.props.ambient);
        props_state(&mut s, "light", &LightProps { ambient, ..spot.props });
        attenuation_state(&mut s, &spot.attenuation);
    } else if let Some(q) = l.point_lights.first() {
        put(&mut s, "light.position", &q.position.to_array());
        props_state(&mut s, "light", &q.props);
        attenuation_state(&mut s, &q.attenuation);
        lamp = Some(q.position);
    }
    put(&mut s, "lampOn", &[f32::from(u8::from(lamp.is_some()))]);
    put(&mut s, "lampModel", &lamp_model(lamp.unwrap_or(Vec3::ZERO)).to_cols_array());
    put(&mut s, "lampColor", &Vec3::ONE.to_array());
    s
}

fn caster_panels(program: &str) -> Vec<Panel> {
    let mut draws: Vec<Draw> = container_models().into_iter().map(|m| mapped(program, m)).collect();
    let mut lamp = lamp_draw("lampModel", "lampColor");
    lamp.when = Some("lampOn".into());
    draws.push(lamp);
    vec![Panel { label: String::new(), draws }]
}

fn caster_spec(id: &'static str, title: &str, d: Caster, program: &str) -> Spec<Caster> {
    Spec {
        id,
        chapter: "05-light-casters",
        title: title.to_owned(),
        size: PANEL,
        panels: caster_panels(program),
        default: d,
        state: caster_state,
        worlds: |p| vec![caster_world(p)],
        controls: Vec::new(),
        points: Vec::new(),
        editor: None,
        curve_axes: None,
    }
}

pub(super) fn casters() -> Spec<Caster> {
    let d = Caster { kind: "point", row: None, cone: None, camera: None, spot_ahead: 0.0 };
    let mut spec = caster_spec(
        "casters",
        "a directional light, a point light and a spotlight on the ten containers",
        d.clone(),
        "@prog",
    );
    spec.controls = vec![Control::new(
        "light caster",
        Kind::Select,
        vec![
            opt("directional", |p: &mut Caster| p.kind = "directional"),
            opt("point", |p: &mut Caster| p.kind = "point"),
            opt("spot", |p: &mut Caster| p.kind = "spot"),
        ],
        1,
    )];
    spec.points = vec![
        ("directional".into(), Caster { kind: "directional", ..d.clone() }),
        ("spot".into(), Caster { kind: "spot", ..d }),
    ];
    spec.editor = Some("point");
    spec
}

/// The largest distance on the attenuation curve.
const CURVE_MAX: f32 = 20.0;

pub(super) fn attenuation() -> Spec<Caster> {
    let default_row = RANGE_TABLE.iter().position(|r| r.attenuation == Attenuation::LEARNOPENGL).unwrap_or(4);
    let d = Caster { kind: "point", row: Some(default_row), cone: None, camera: None, spot_ahead: 0.0 };
    let mut spec =
        caster_spec("attenuation", "a point light with each row of the range table, and its curve", d.clone(), "point");
    let options = RANGE_TABLE
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let a = r.attenuation;
            let numbers = [r.range, a.constant, a.linear, a.quadratic].map(|x| x.to_string());
            let label = crate::blanks::fill(super::texts::LABEL_RANGE, &numbers.each_ref().map(String::as_str));
            opt(label, move |p: &mut Caster| p.row = Some(i))
        })
        .collect();
    let mut c = Control::new("attenuation row", Kind::Range { play: false }, options, default_row);
    c.curves = RANGE_TABLE
        .iter()
        .map(|r| (0..=100).map(|k| CURVE_MAX * k as f32 / 100.0).map(|x| (x, r.attenuation.at(x))).collect())
        .collect();
    spec.controls = vec![c];
    spec.curve_axes = Some(("distance".into(), "attenuation".into(), CURVE_MAX));
    spec.points = vec![
        ("range 7".into(), Caster { row: Some(0), ..d.clone() }),
        ("range 3250".into(), Caster { row: Some(11), ..d }),
    ];
    spec
}

/// The spot-cone figure's starting cone: inner and outer cut-off in degrees (LearnOpenGL's).
const SPOT_CONE: (f32, f32) = (12.5, 17.5);

/// The spot-cone figure's light sits this far in front of the camera (world units). From
/// there the front container's face (1 × 1, 1.5 away) spans a half-angle of atan(0.5 / 1.5)
/// = 18.4°, so the chapter's whole soft edge, 12.5° to 17.5°, falls on the face; from the
/// eye (2.5 away, 11.3°) the edge fell past the face into the background.
const SPOT_CONE_AHEAD: f32 = 1.0;

/// The inner slider's angles (degrees): 2.5 to 15.
fn inner_angles() -> Vec<f32> {
    steps(2.5, 2.5, 6)
}

/// The outer slider's angles (degrees): 15 to 37.5. No inner angle exceeds an outer one, so
/// every pair of slider positions is a valid cone and each slider sets its own uniform
/// (an inverted pair used to be refused and silently drawn as the starting cone).
fn outer_angles() -> Vec<f32> {
    steps(15.0, 2.5, 10)
}

pub(super) fn spot_cone() -> Spec<Caster> {
    let d = Caster { kind: "spot", row: None, cone: Some(SPOT_CONE), camera: None, spot_ahead: SPOT_CONE_AHEAD };
    let mut spec = caster_spec("spot-cone", "the spotlight's inner and outer cones: the soft edge", d.clone(), "spot");
    spec.controls = vec![
        range("inner cut-off (degrees)", &inner_angles(), SPOT_CONE.0, false, |p: &mut Caster, v| {
            p.cone = Some((v, p.cone.unwrap_or(SPOT_CONE).1))
        }),
        range("outer cut-off (degrees)", &outer_angles(), SPOT_CONE.1, false, |p: &mut Caster, v| {
            p.cone = Some((p.cone.unwrap_or(SPOT_CONE).0, v))
        }),
    ];
    spec.points = vec![
        ("inner 5, outer 25".into(), Caster { cone: Some((5.0, 25.0)), ..d.clone() }),
        ("inner 15, outer 15".into(), Caster { cone: Some((15.0, 15.0)), ..d }),
    ];
    spec.editor = Some("spot");
    spec
}

/// Flashlight orbit grid: azimuth steps and elevation steps.
const ORBIT: (usize, usize) = (24, 5);

fn orbit(col: usize, row: usize) -> Camera {
    let target = Vec3::new(0.0, 0.0, -3.0);
    let az = (col as f32 / ORBIT.0 as f32) * 360.0;
    let el = -20.0 + 10.0 * row as f32;
    let (r, az, el) = (6.0, az.to_radians(), el.to_radians());
    let eye = target + r * Vec3::new(el.cos() * az.sin(), el.sin(), el.cos() * az.cos());
    Camera::new(eye, target, Vec3::Y, 45.0, aspect(PANEL), 0.1, 100.0)
        .unwrap_or_else(|_| Camera::learnopengl(aspect(PANEL)))
}

pub(super) fn flashlight() -> Spec<Caster> {
    let d = Caster { kind: "spot", row: None, cone: None, camera: Some(orbit(0, 2)), spot_ahead: 0.0 };
    let mut spec = caster_spec(
        "flashlight",
        "the flashlight follows the camera: drag the figure (or use the arrow keys) to orbit",
        d.clone(),
        "spot",
    );
    let options = (0..ORBIT.1)
        .flat_map(|row| (0..ORBIT.0).map(move |col| (col, row)))
        .map(|(col, row)| {
            opt(
                crate::blanks::fill(
                    super::texts::LABEL_ORBIT,
                    &[&(col * 360 / ORBIT.0).to_string(), &(-20 + 10 * row as i32).to_string()],
                ),
                move |p: &mut Caster| p.camera = Some(orbit(col, row)),
            )
        })
        .collect();
    spec.controls = vec![Control::new("camera", Kind::Orbit { cols: ORBIT.0, rows: ORBIT.1 }, options, 2 * ORBIT.0)];
    spec.points = vec![
        ("azimuth 45".into(), Caster { camera: Some(orbit(3, 2)), ..d.clone() }),
        ("azimuth 300, elevation 20".into(), Caster { camera: Some(orbit(20, 4)), ..d }),
    ];
    spec
}

// ---------------------------------------------------------------- multiple lights

/// Multiple lights parameters: the atmosphere (`None` = the chapter's default) and which lights are on.
#[derive(Clone)]
pub struct Multi {
    atmosphere: Option<Atmosphere>,
    /// dir, point 0..3, spot.
    on: [bool; 6],
}

/// The multiple-lights panel size (the figure the speed target names): the same 320 × 240
/// as the others; at 400 × 300 it drew at 8 frames/s in headless Chromium here (see
/// the module docs of [`super`] for the table).
pub const MULTI_PANEL: (u32, u32) = PANEL;

fn multi_world(p: &Multi) -> World {
    let name = p.atmosphere.map_or("multiple-lights".to_owned(), |a| format!("multiple-lights-{}", a.name()));
    let mut w = preset(&name, aspect(MULTI_PANEL)).expect("the multiple lights presets exist");
    let shininess = w.objects[0].surface.shininess();
    with_live_maps(&mut w, true, true, false, shininess);
    let off = LightProps { ambient: Vec3::ZERO, diffuse: Vec3::ZERO, specular: Vec3::ZERO };
    let l: &mut Scene = &mut w.lights;
    if let (false, Some(d)) = (p.on[0], &mut l.dir_light) {
        d.props = off;
    }
    for (i, q) in l.point_lights.iter_mut().enumerate() {
        if !p.on[1 + i] {
            q.props = off;
        }
    }
    if let (false, Some(s)) = (p.on[5], &mut l.spot_light) {
        s.props = off;
    }
    w
}

fn multi_state(p: &Multi) -> State {
    let w = multi_world(p);
    let mut s = State::new();
    camera_state(&mut s, &w.camera, w.clear);
    maps_state(&mut s, w.objects[0].surface.shininess(), true, true, false);
    let l = &w.lights;
    if let Some(d) = &l.dir_light {
        put(&mut s, "dirLight.direction", &d.direction.to_array());
        props_state(&mut s, "dirLight", &d.props);
    }
    for (i, q) in l.point_lights.iter().enumerate() {
        let k = format!("pointLights[{i}]");
        put(&mut s, &format!("{k}.position"), &q.position.to_array());
        put(&mut s, &format!("{k}.constant"), &[q.attenuation.constant]);
        put(&mut s, &format!("{k}.linear"), &[q.attenuation.linear]);
        put(&mut s, &format!("{k}.quadratic"), &[q.attenuation.quadratic]);
        props_state(&mut s, &k, &q.props);
    }
    if let Some(q) = &l.spot_light {
        put(&mut s, "spotLight.position", &q.position.to_array());
        put(&mut s, "spotLight.direction", &q.direction.to_array());
        put(&mut s, "spotLight.cutOff", &[q.cut_off]);
        put(&mut s, "spotLight.outerCutOff", &[q.outer_cut_off]);
        put(&mut s, "spotLight.constant", &[q.attenuation.constant]);
        put(&mut s, "spotLight.linear", &[q.attenuation.linear]);
        put(&mut s, "spotLight.quadratic", &[q.attenuation.quadratic]);
        props_state(&mut s, "spotLight", &q.props);
    }
    // the lamps: the preset's last four objects
    let lamps: Vec<&Object> = w.objects.iter().rev().take(4).collect();
    for (i, o) in lamps.iter().rev().enumerate() {
        if let Surface::Unlit(c) = o.surface {
            put(&mut s, &format!("lampColor{i}"), &c.to_array());
        }
        put(&mut s, &format!("lampModel{i}"), &o.model.to_cols_array());
    }
    s
}

pub(super) fn multiple_lights() -> Spec<Multi> {
    let d = Multi { atmosphere: None, on: [true; 6] };
    let mut draws: Vec<Draw> = container_models().into_iter().map(|m| mapped("multiple", m)).collect();
    for i in 0..4 {
        draws.push(lamp_draw(&format!("lampModel{i}"), &format!("lampColor{i}")));
    }
    let mut atmospheres = vec![opt("the chapter's lights", |p: &mut Multi| p.atmosphere = None)];
    atmospheres.extend(Atmosphere::ALL.iter().map(|&a| opt(a.name(), move |p: &mut Multi| p.atmosphere = Some(a))));
    let mut controls = vec![Control::select("atmosphere", atmospheres)];
    let names = ["dirLight", "pointLights[0]", "pointLights[1]", "pointLights[2]", "pointLights[3]", "spotLight"];
    let labels =
        ["directional light", "point light 1", "point light 2", "point light 3", "point light 4", "flashlight"];
    for (i, (n, label)) in names.iter().zip(labels).enumerate() {
        let zero = ["ambient", "diffuse", "specular"].iter().map(|t| format!("{n}.{t}")).collect();
        controls.push(Control::new(
            label,
            Kind::Toggle { zero },
            vec![opt("on", move |p: &mut Multi| p.on[i] = true), opt("off", move |p: &mut Multi| p.on[i] = false)],
            0,
        ));
    }
    let mut two_off = d.clone();
    two_off.on[0] = false;
    two_off.on[5] = false;
    Spec {
        id: "multiple-lights",
        chapter: "06-multiple-lights",
        title: "the chapter's lights and the four atmospheres; switch each light on and off".into(),
        size: MULTI_PANEL,
        panels: vec![Panel { label: String::new(), draws }],
        default: d.clone(),
        state: multi_state,
        worlds: |p| vec![multi_world(p)],
        controls,
        points: vec![
            ("desert".into(), Multi { atmosphere: Some(Atmosphere::Desert), ..d.clone() }),
            ("horror".into(), Multi { atmosphere: Some(Atmosphere::Horror), ..d.clone() }),
            (
                "biochemical lab, sun and flashlight off".into(),
                Multi { atmosphere: Some(Atmosphere::BiochemicalLab), ..two_off },
            ),
        ],
        editor: Some("multiple"),
        curve_axes: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn camera_front_of_orbit_points_at_the_target() {
        let c = orbit(5, 1);
        let front = c.view.inverse().transform_vector3(Vec3::NEG_Z).normalize();
        let to_target = (Vec3::new(0.0, 0.0, -3.0) - c.eye).normalize();
        assert!(front.dot(to_target) > 0.9999, "{front} vs {to_target}");
    }

    #[test]
    fn the_spot_cone_figure_shows_its_soft_edge() {
        let spec = spot_cone();
        let soft = caster_world(&spec.default);
        let hard = caster_world(&Caster { cone: Some((SPOT_CONE.1, SPOT_CONE.1)), ..spec.default.clone() });
        let (w, h) = spec.size;
        let n = crate::live::reference::plainly_different_pixels(&soft, &hard, w, h).unwrap();
        assert!(
            n >= crate::live::reference::plain_share(spec.size),
            "soft and hard edges differ plainly in only {n} pixels"
        );
    }

    #[test]
    fn every_spot_cone_slider_position_draws_the_cone_it_names() {
        let spec = spot_cone();
        for inner in inner_angles() {
            for outer in outer_angles() {
                let w = caster_world(&Caster { cone: Some((inner, outer)), ..spec.default.clone() });
                let s = w.lights.spot_light.expect("the spot preset has a spotlight");
                assert_eq!((s.cut_off, s.outer_cut_off), (inner.to_radians().cos(), outer.to_radians().cos()));
            }
        }
    }
}
