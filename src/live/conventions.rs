//! The live figure of the conventions chapter: the coral cube of the chapter's static
//! render under LearnOpenGL's Basic lighting, opengl-tutorial 8 and ogldev 19 side by side,
//! each panel running its tutorial's verified function file, with one light the reader
//! moves for all three.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `lamp` | LearnOpenGL's lamp position (1.2, 1, 2): the light at the start |
//! | `turn` | the light turned about the cube's vertical axis, degrees (0 = `lamp`) |
//! | `raise` | the light's elevation seen from the cube's centre, raised by this many degrees |
//! | `distance` | the light's distance from the cube's centre, as a multiple of `lamp`'s |
//! | `light_pos` | `distance · R_y(turn) · R_tilt(raise) · lamp`, see [`light_position`] |
//!
//! The state (every uniform of the three programs) and the raster worlds come from the
//! same [`ConventionsModels`], so the page and the reference cannot drift apart. ogldev's
//! light is directional, along the direction from `light_pos` to the cube's centre, as
//! [`crate::models::ogldev_comparable`] sets it for the static render.
//!
//! Sources: LearnOpenGL, Basic lighting; opengl-tutorial 8, "Basic shading"; ogldev 19,
//! "Specular lighting".

use glam::{Quat, Vec3};

use super::chapters::{aspect, camera_state, draw, lamp_draw, trim};
use super::{put, Axis, Control, Panel, Spec, State};
use crate::models::ShadingModel;
use crate::raster::pipeline::World;
use crate::raster::presets::{conventions_world, lamp_model, tight_camera, ConventionsModels};

/// Panel size: the static render's three-column panels (4:3), side by side.
pub const CONVENTIONS_PANEL: (u32, u32) = (240, 180);

/// The three models, left to right.
pub const MODELS: [ShadingModel; 3] = [ShadingModel::LearnOpenGL, ShadingModel::OpenGLTutorial, ShadingModel::Ogldev];

/// The turn slider's angles, degrees: a full circle in 15° steps, 0 in the middle.
fn turns() -> Vec<f32> {
    (-12..12).map(|k| 15.0 * k as f32).collect()
}

/// The raise slider's angles, degrees: −60° to +60° in 15° steps. The lamp sits 23.2°
/// above the horizontal, so the light ranges from 36.8° below to 83.2° above, never over
/// the pole (where the turn would flip it).
fn raises() -> Vec<f32> {
    (-4..=4).map(|k| 15.0 * k as f32).collect()
}

/// The distance slider's multiples of the lamp's distance (2.54): from 1.27, near the
/// cube's corners (0.87 from the centre), to 7.6, where opengl-tutorial's `LightPower / d²`
/// = 50 / 58 falls below 1 and its lit faces stop clipping to white.
const DISTANCES: [f32; 5] = [0.5, 1.0, 1.5, 2.0, 3.0];

/// Where the reader has put the light (see the module's symbols).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// Degrees about the vertical axis from the lamp.
    pub turn: f32,
    /// Degrees of elevation added to the lamp's.
    pub raise: f32,
    /// Multiple of the lamp's distance from the cube's centre.
    pub distance: f32,
}

/// The light at the start: LearnOpenGL's lamp.
pub const AT_LAMP: Light = Light { turn: 0.0, raise: 0.0, distance: 1.0 };

/// LearnOpenGL's lamp position, (1.2, 1, 2).
fn lamp() -> Vec3 {
    crate::phong::BasicLighting::learnopengl().light_pos
}

/// The light's position:
///
/// ```text
/// h = normalize(lamp.x, 0, lamp.z)             the lamp's horizontal direction
/// light_pos = distance · R_y(turn) · R_{h × y}(raise) · lamp
/// ```
///
/// `R_{h × y}(raise)` turns the lamp within its vertical plane, toward +y for a positive
/// angle, so the elevation grows by `raise`; `R_y` then turns it about the vertical axis.
/// At `turn = raise = 0` and `distance = 1` both rotations are the identity quaternion
/// and the result is `lamp` exactly. Angles in degrees.
pub fn light_position(light: &Light) -> Vec3 {
    let lamp = lamp();
    let tilt_axis = Vec3::new(lamp.x, 0.0, lamp.z).normalize_or_zero().cross(Vec3::Y);
    let tilt = if tilt_axis == Vec3::ZERO {
        Quat::IDENTITY
    } else {
        Quat::from_axis_angle(tilt_axis, light.raise.to_radians())
    };
    light.distance * (Quat::from_rotation_y(light.turn.to_radians()) * tilt * lamp)
}

/// The three panels' worlds (LearnOpenGL, opengl-tutorial 8, ogldev 19), each with the
/// lamp drawn at the light; none when the camera cannot be made (the build then fails).
fn conventions_worlds(light: &Light) -> Vec<World> {
    let light_pos = light_position(light);
    MODELS.iter().filter_map(|&m| conventions_world(m, light_pos, aspect(CONVENTIONS_PANEL)).ok()).collect()
}

/// Every uniform of the three programs and the lamp at `light`, from the same
/// [`ConventionsModels`] and camera the worlds are made of (empty when the camera cannot
/// be made; the worlds are then empty too and the build fails).
fn conventions_state(light: &Light) -> State {
    let mut s = State::new();
    let light_pos = light_position(light);
    let Ok(world) = conventions_world(ShadingModel::LearnOpenGL, light_pos, aspect(CONVENTIONS_PANEL)) else {
        return s;
    };
    camera_state(&mut s, &world.camera, world.clear);
    let models = ConventionsModels::new(light_pos, world.camera.eye);
    learnopengl_state(&mut s, &models);
    opengl_tutorial_state(&mut s, &models);
    ogldev_state(&mut s, &models);
    put(&mut s, "lampModel", &lamp_model(light_pos).to_cols_array());
    s
}

/// LearnOpenGL's Basic lighting uniforms (the `basic` program).
fn learnopengl_state(s: &mut State, models: &ConventionsModels) {
    let b = &models.learnopengl;
    put(s, "lightPos", &b.light_pos.to_array());
    put(s, "lightColor", &b.light_color.to_array());
    put(s, "objectColor", &b.object_color.to_array());
    put(s, "ambientStrength", &[b.ambient_strength]);
    put(s, "specularStrength", &[b.specular_strength]);
    put(s, "shininess", &[b.shininess]);
    put(s, "viewPos", &b.view_pos.to_array());
}

/// opengl-tutorial 8's uniforms, named as its shader names them (the `opengl_tutorial8`
/// program); its eye is the camera, through the view matrix. Its light position is
/// LearnOpenGL's `lightPos` key ([`OT8_UNIFORMS`]; [`ConventionsModels::new`] gives both
/// models the one `light_pos`), so a slider's patch holds it once.
fn opengl_tutorial_state(s: &mut State, models: &ConventionsModels) {
    let t = &models.opengl_tutorial;
    debug_assert_eq!(t.light_pos, models.learnopengl.light_pos);
    put(s, "LightColor", &t.light_color.to_array());
    put(s, "LightPower", &[t.light_power]);
    put(s, "MaterialDiffuseColor", &t.diffuse.to_array());
    put(s, "MaterialSpecularColor", &t.specular.to_array());
    put(s, "MaterialAmbientFactor", &Vec3::splat(t.ambient_factor).to_array());
    put(s, "specularExponent", &[t.exponent]);
}

/// ogldev 19's uniforms, named as its shader names them (the `ogldev19` program); the
/// texture color stands for its sampled texel, opaque.
fn ogldev_state(s: &mut State, models: &ConventionsModels) {
    let o = &models.ogldev;
    put(s, "gDirectionalLight.Color", &o.color.to_array());
    put(s, "gDirectionalLight.AmbientIntensity", &[o.ambient_intensity]);
    put(s, "gDirectionalLight.Direction", &o.direction.to_array());
    put(s, "gDirectionalLight.DiffuseIntensity", &[o.diffuse_intensity]);
    put(s, "gEyeWorldPos", &models.learnopengl.view_pos.to_array());
    put(s, "gMatSpecularIntensity", &[o.specular_intensity]);
    put(s, "gSpecularPower", &[o.specular_power]);
    put(s, "gTexel", &o.texture_color.extend(1.0).to_array());
}

/// A panel drawing `program` on the cube (no culling, as the raster's cube), its
/// `uniforms` read from other state keys, and the lamp.
fn panel(label: &str, program: &str, uniforms: &[(&str, &str)]) -> Panel {
    let mut cube = draw(program, "cube", glam::Mat4::IDENTITY, false);
    cube.uniforms = uniforms.iter().map(|&(u, key)| (u.to_owned(), key.to_owned())).collect();
    Panel { label: label.to_owned(), draws: vec![cube, lamp_draw("lampModel", "lightColor")] }
}

/// The `opengl_tutorial8` program's uniforms read from another state key:
/// `LightPosition_worldspace` is the `lightPos` key (the same light as LearnOpenGL's).
const OT8_UNIFORMS: [(&str, &str); 1] = [("LightPosition_worldspace", "lightPos")];

/// A number with a degree sign, as the turn and raise sliders show it.
fn degrees(v: f32) -> String {
    format!("{}°", trim(v))
}

/// The light's three sliders: turn, raise, distance (one grid, since all three move the
/// same uniforms), starting at the lamp.
fn light_control() -> Control<Light> {
    let lamp_distance = lamp().length();
    let axes = vec![
        Axis { label: "turn around the cube".into(), ticks: turns().into_iter().map(degrees).collect() },
        Axis { label: "raise or lower".into(), ticks: raises().into_iter().map(degrees).collect() },
        Axis {
            label: "distance from the cube's centre".into(),
            ticks: DISTANCES.iter().map(|f| trim(f * lamp_distance)).collect(),
        },
    ];
    let start = [
        turns().iter().position(|&t| t == AT_LAMP.turn).unwrap_or(0),
        raises().iter().position(|&r| r == AT_LAMP.raise).unwrap_or(0),
        DISTANCES.iter().position(|&d| d == AT_LAMP.distance).unwrap_or(0),
    ];
    Control::grid("the light", axes, &start, |p: &mut Light, at: &[usize]| {
        let pick = |values: &[f32], k: Option<&usize>| k.and_then(|&k| values.get(k).copied());
        p.turn = pick(&turns(), at.first()).unwrap_or(p.turn);
        p.raise = pick(&raises(), at.get(1)).unwrap_or(p.raise);
        p.distance = pick(&DISTANCES, at.get(2)).unwrap_or(p.distance);
    })
}

/// The light near the cube, turned a quarter round to the front left, where it lights the
/// two faces the camera sees from the side: LearnOpenGL's point light strikes each point
/// of a face at its own angle, ogldev's directional light every point at one.
pub const CLOSE: Light = Light { turn: -90.0, raise: 0.0, distance: 0.5 };

/// The light three times as far along the lamp's direction: opengl-tutorial's lit face
/// falls out of saturation (`50 / 7.6² = 0.86`); LearnOpenGL's has no falloff.
pub const FAR: Light = Light { turn: 0.0, raise: 0.0, distance: 3.0 };

/// The light below the cube and to the left: the bottom face the camera sees is lit.
/// (Turned −45° instead, ogldev's `pow` would meet negative bases on the lit faces, whose
/// result GLSL leaves undefined; see the tests.)
pub const BELOW: Light = Light { turn: -90.0, raise: -60.0, distance: 2.0 };

/// The light the chapter points at for the ghost of the undefined `pow`: turned −45° and
/// lowered 30°, where light and eye both graze the bottom face.
pub const GHOST: Light = Light { turn: -45.0, raise: -30.0, distance: 1.0 };

/// The most GLSL's undefined `pow` of a negative base can do to ogldev's panel at one light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UndefinedPow {
    /// The most it can add to a pixel, 8-bit levels.
    pub levels: f32,
    /// The most negative `V·R` where `pow` is taken (0 when none is negative).
    pub v_dot_r: f32,
}

/// What GLSL's undefined `pow` of a negative base can do to ogldev's panel with the light
/// at `light`. ogldev 19 takes `pow(V·R, p)` before its `> 0` test wherever the gate
/// `n·l > 0` passes; for `V·R < 0` llvmpipe returns NaN (the term is dropped, as the
/// crate's model does), SwiftShader (headless Chromium) returns `|V·R|^p` (measured:
/// `pow(-0.89, 32)` = 0.024, `pow(-0.89, 5)` = 0.56), C's `powf` `±|V·R|^p`. Any of them
/// moves a pixel by at most
///
/// ```text
/// specular_intensity · |V·R|^p · max(color ⊙ texture) · 255   levels
/// ```
///
/// The maximum over a 101 × 101 grid on every face of the cube the camera sees (a face
/// spans about 80 pixels, so the grid is finer than the pixels). `None` when the camera
/// cannot be made.
pub fn undefined_pow(light: &Light) -> Option<UndefinedPow> {
    let eye = tight_camera(aspect(CONVENTIONS_PANEL)).ok()?.eye;
    let o = ConventionsModels::new(light_position(light), eye).ogldev;
    let scale = o.specular_intensity * (o.color * o.texture_color).max_element() * 255.0;
    let mut worst = UndefinedPow { levels: 0.0, v_dot_r: 0.0 };
    for n in [Vec3::X, Vec3::NEG_X, Vec3::Y, Vec3::NEG_Y, Vec3::Z, Vec3::NEG_Z] {
        let centre = 0.5 * n;
        if n.dot(eye - centre) <= 0.0 || n.dot(-o.direction) <= 0.0 {
            continue; // not seen, or the gate fails and pow is never taken
        }
        let (u, v) = n.any_orthonormal_pair();
        let r = crate::glsl::reflect(o.direction, n).normalize_or_zero();
        for i in 0..=100 {
            for j in 0..=100 {
                let p = centre + u * (i as f32 / 100.0 - 0.5) + v * (j as f32 / 100.0 - 0.5);
                let x = (eye - p).normalize_or_zero().dot(r);
                if x < worst.v_dot_r {
                    worst = UndefinedPow { levels: scale * (-x).powf(o.specular_power), v_dot_r: x };
                }
            }
        }
    }
    Some(worst)
}

/// A signed number as the book prints it: a minus sign (U+2212), not a hyphen.
fn signed(text: String) -> String {
    match text.strip_prefix('-') {
        Some(rest) => format!("−{rest}"),
        None => text,
    }
}

/// The chapter's paragraph under the figure, `generated/live/conventions-try.md`: what to
/// try, with every number computed from the figure's constants and the models.
pub fn what_to_try() -> Result<String, super::LiveError> {
    let err = |what: &str| super::LiveError::Spec { id: "conventions", what: what.to_owned() };
    let far = light_position(&FAR);
    let eye = tight_camera(aspect(CONVENTIONS_PANEL)).map_err(|e| err(&e.to_string()))?.eye;
    let tutorial = ConventionsModels::new(far, eye).opengl_tutorial;
    let far_falloff = tutorial.light_power / far.length_squared();
    let ghost = undefined_pow(&GHOST).ok_or_else(|| err("no camera for the ghost"))?;
    Ok(format!(
        "Live, each panel runs its tutorial's own shader function, the text `lightlab oracle` \
         checks, and the three sliders move one light for all three. Pull the light away: \
         opengl-tutorial's white face turns coral as `LightPower / d²` drops (at the slider's far \
         end, {far_distance:.1} units from the cube's centre, it is {far_falloff:.2}), while LearnOpenGL has \
         no falloff at all. Bring it close ({close_distance:.1}) and turn it to {close_turn}°: \
         LearnOpenGL's point light meets each point \
         of a face at its own angle, so a face brightens toward the lamp, while ogldev's \
         directional light meets a whole face at one angle and leaves it one flat color under \
         its highlight. Then turn the light to {turn}° and lower it by {lower}°: the light and \
         the eye now both graze the bottom face, and there ogldev's shader takes `pow` of a \
         $\\mathbf V\\cdot\\mathbf R$ down to {v_dot_r}. Where `pow` gives NaN, as on llvmpipe and \
         in lightlab's model, the term is dropped; SwiftShader, the software renderer of \
         headless Chromium, returns $|x|^{{p}}$ and brightens that thin face by up to {percent:.0} % \
         of full scale: the ghost highlight of case 2 of the atlas. Your GPU decides which one \
         you see; the page's self-check compares only where the two cannot differ.\n",
        far_distance = far.length(),
        close_distance = light_position(&CLOSE).length(),
        close_turn = signed(trim(CLOSE.turn)),
        turn = signed(trim(GHOST.turn)),
        lower = trim(-GHOST.raise),
        v_dot_r = signed(format!("{:.2}", ghost.v_dot_r)),
        percent = 100.0 * ghost.levels / 255.0,
    ))
}

/// The conventions figure.
pub(super) fn conventions() -> Spec<Light> {
    Spec {
        id: "conventions",
        chapter: "07-conventions",
        title: "the same cube under LearnOpenGL, opengl-tutorial 8 and ogldev 19, one light for all three".into(),
        size: CONVENTIONS_PANEL,
        panels: vec![
            panel("LearnOpenGL: point light, no falloff", "basic", &[]),
            panel("opengl-tutorial 8: LightPower / d²", "opengl_tutorial8", &OT8_UNIFORMS),
            panel("ogldev 19: directional light", "ogldev19", &[]),
        ],
        default: AT_LAMP,
        state: conventions_state,
        worlds: conventions_worlds,
        controls: vec![light_control()],
        points: vec![
            ("close, turned -90 degrees".into(), CLOSE),
            ("three times as far".into(), FAR),
            ("below, turned -90 degrees".into(), BELOW),
        ],
        editor: None,
        curve_axes: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::live::reference::{plain_share, plainly_different_pixels};

    fn panels(light: &Light) -> [World; 3] {
        conventions_worlds(light).try_into().expect("three worlds")
    }

    /// At every self-check point the undefined `pow` adds under half a level, so the page
    /// matches the raster on any GPU: with the quantization's half level, a pixel moves by at
    /// most one level, the untextured figures' measured [`crate::live::UNTEXTURED`] level.
    /// (Elsewhere the reader may see the ghost highlight of the failure atlas's case 2.)
    #[test]
    fn no_self_check_point_depends_on_the_undefined_pow() {
        let spec = conventions();
        for (name, light) in std::iter::once(("default".to_owned(), spec.default)).chain(spec.points) {
            let levels = undefined_pow(&light).unwrap().levels;
            assert!(levels < 0.5, "{name}: the undefined pow can add {levels} levels");
        }
        // and it matters elsewhere: below the cube, turned 45° to the left, it adds 3 levels
        // (3.1 here; SwiftShader's page measured 3 over the CPU raster there), and at the
        // light the chapter names a plain ghost
        let below_left = Light { turn: -45.0, raise: -60.0, distance: 2.0 };
        let levels = undefined_pow(&below_left).unwrap().levels;
        assert!((3.0..3.2).contains(&levels), "{levels}");
        let ghost = undefined_pow(&GHOST).unwrap();
        assert!(ghost.levels >= f32::from(crate::live::reference::PLAIN_LEVELS) && ghost.v_dot_r < -0.9, "{ghost:?}");
    }

    /// The paragraph's numbers come from the figure's constants (the shown text, checked).
    #[test]
    fn the_paragraph_says_what_the_figure_shows() {
        let text = what_to_try().unwrap();
        let parts =
            ["7.6 units", "it is 0.86", "close (1.3)", "to −90°", "to −45°", "by 30°", "down to −0.98", "27 % of full"];
        for part in parts {
            assert!(text.contains(part), "{part:?} not in {text}");
        }
    }

    #[test]
    fn the_light_starts_exactly_at_the_lamp_and_keeps_its_distance_when_turned() {
        assert_eq!(light_position(&AT_LAMP), Vec3::new(1.2, 1.0, 2.0));
        let d = lamp().length();
        for turn in turns() {
            for raise in raises() {
                for f in DISTANCES {
                    let p = light_position(&Light { turn, raise, distance: f });
                    assert!((p.length() - f * d).abs() < 1e-5 * d, "{turn} {raise} {f}: {p}");
                    // the elevation grows by raise: 23.2° + raise, from asin(y / |p|)
                    let elevation = (p.y / p.length()).asin().to_degrees();
                    let want = (1.0 / d).asin().to_degrees() + raise;
                    assert!((elevation - want).abs() < 1e-3, "{turn} {raise}: {elevation} against {want}");
                }
            }
        }
        // a quarter turn about +y takes the lamp's (x, z) = (1.2, 2) to (2, −1.2)
        let q = light_position(&Light { turn: 90.0, ..AT_LAMP });
        assert!((q - Vec3::new(2.0, 1.0, -1.2)).abs().max_element() < 1e-5, "{q}");
    }

    /// The default matches the chapter's static render: the same scene and models, through
    /// the raster's tutorial surfaces instead of the render's closure. opengl-tutorial's and
    /// ogldev's panels call the same `terms` and match bit for bit. LearnOpenGL's world is
    /// lit by the 16-lane kernel, the render by the scalar `BasicLighting::terms`: the same
    /// formula in another f32 order, so a channel near a rounding boundary can flip one
    /// 8-bit level (measured: 1 channel of 129 600), and no more.
    #[test]
    fn the_default_is_the_static_render() {
        let (w, h) = CONVENTIONS_PANEL;
        for (world, model) in panels(&AT_LAMP).iter().zip(MODELS) {
            let mut fb = crate::raster::framebuffer::Framebuffer::new(w, h).unwrap();
            world.render(&mut fb);
            let rgb: Vec<u8> = fb.to_rgba8(false).chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect();
            let still = crate::figures::renders::model_image(model, CONVENTIONS_PANEL).unwrap().into_raw();
            let diffs: Vec<u8> = rgb.iter().zip(&still).map(|(a, b)| a.abs_diff(*b)).collect();
            let (off, max) = (diffs.iter().filter(|&&d| d > 0).count(), diffs.iter().max().copied().unwrap_or(0));
            if model == ShadingModel::LearnOpenGL {
                // 0.1 % of the channels, one level each: rounding, not a different formula
                assert!(max <= 1 && off <= rgb.len() / 1000, "{model:?}: {off} channels off, by up to {max}");
            } else {
                assert_eq!((off, max), (0, 0), "{model:?}");
            }
        }
    }

    /// Where the chapter says the panels differ, they differ over a plain area
    /// ([`plainly_different_pixels`], [`plain_share`]): at the lamp opengl-tutorial's lit face
    /// clips to white and LearnOpenGL's does not; three times as far opengl-tutorial clips
    /// nowhere and changes plainly; and with the light close, LearnOpenGL's point light and
    /// ogldev's directional light shade the faces plainly differently.
    #[test]
    fn the_panels_differ_plainly_where_the_chapter_says() {
        let (w, h) = CONVENTIONS_PANEL;
        let plain = plain_share(CONVENTIONS_PANEL);
        let differ = |a: &World, b: &World| plainly_different_pixels(a, b, w, h).unwrap();
        let [learn, tutorial, _] = panels(&AT_LAMP);
        let n = differ(&learn, &tutorial);
        assert!(n >= plain, "at the lamp, LearnOpenGL and opengl-tutorial differ in {n} pixels");
        // saturation: every channel clipped to white over a plain area at the lamp, nowhere far off
        let white = |world: &World| {
            let mut fb = crate::raster::framebuffer::Framebuffer::new(w, h).unwrap();
            world.render(&mut fb);
            fb.to_rgba8(false).chunks_exact(4).filter(|p| p[..3] == [255, 255, 255]).count()
        };
        let [_, tutorial_far, _] = panels(&FAR);
        let (near, far) = (white(&tutorial), white(&tutorial_far));
        assert!(
            near >= plain && far == 0,
            "opengl-tutorial's white pixels: {near} at the lamp, {far} three times as far"
        );
        assert_eq!(white(&learn), 0, "LearnOpenGL clips nowhere at the lamp");
        let n = differ(&tutorial, &tutorial_far);
        assert!(n >= plain, "opengl-tutorial near and far differ in {n} pixels");
        let [learn_close, _, ogldev_close] = panels(&CLOSE);
        let n = differ(&learn_close, &ogldev_close);
        assert!(n >= plain, "close to the cube, LearnOpenGL and ogldev differ in {n} pixels");
    }
}
