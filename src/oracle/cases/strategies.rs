//! The distributions of the cases (see [`crate::oracle::cases`] for what a case is), written
//! into rows through the layouts ([`Packed`]). The values drawn, and their order, are part
//! of the oracle's published output: changing a distribution changes `book/data/oracle.md`.

use glam::{Mat4, Quat, Vec3};
use proptest::prelude::*;

use super::fields;
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::gl::layout::{self, Packed};
use crate::gl::model_id::ModelId;
use crate::material::LightProps;
use crate::scene::Scene;

type Row = Vec<[f32; 4]>;

/// A uniformly distributed unit direction (z uniform in [-1, 1], azimuth uniform).
fn direction() -> impl Strategy<Value = Vec3> {
    (-1.0f32..=1.0, 0.0f32..std::f32::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z)
    })
}

fn color() -> impl Strategy<Value = Vec3> {
    (0.0f32..=1.0, 0.0f32..=1.0, 0.0f32..=1.0).prop_map(Vec3::from)
}

/// An interpolated normal: a direction of length in [0.2, 5]; 1 in 100 is zero.
fn normal() -> impl Strategy<Value = Vec3> {
    prop_oneof![99 => (direction(), 0.2f32..5.0).prop_map(|(d, l)| d * l), 1 => Just(Vec3::ZERO)]
}

/// An offset from the fragment to a light or the eye, length in [min, 20]; 1 in 200 is
/// zero (the point sits on the fragment).
fn offset(min: f32) -> impl Strategy<Value = Vec3> {
    prop_oneof![199 => (direction(), min..20.0f32).prop_map(|(d, l)| d * l), 1 => Just(Vec3::ZERO)]
}

fn position(half: f32) -> impl Strategy<Value = Vec3> {
    (-half..=half, -half..=half, -half..=half).prop_map(Vec3::from)
}

/// Shininess in [1, max]; 1 in 100 is 0 when `with_zero` (pow(0, 0) shows up).
fn shininess(max: f32, with_zero: bool) -> BoxedStrategy<f32> {
    if with_zero {
        prop_oneof![99 => 1.0f32..=max, 1 => Just(0.0f32)].boxed()
    } else {
        (1.0f32..=max).boxed()
    }
}

fn attenuation() -> impl Strategy<Value = [f32; 4]> {
    (0.5f32..=2.0, 0.0f32..=1.0, 0.0f32..=2.0).prop_map(|(c, l, q)| [c, l, q, 0.0])
}

/// Spot cone: (cutOff, outerCutOff) cosines; inner angle in [5°, 60°], outer 2° to 15° wider;
/// 1 in 100 has equal angles (ε = 0).
fn cone() -> impl Strategy<Value = (f32, f32)> {
    (5.0f32..=60.0, 2.0f32..=15.0, 0u32..100).prop_map(|(inner, extra, k)| {
        let outer = if k == 0 { inner } else { inner + extra };
        (inner.to_radians().cos(), outer.to_radians().cos())
    })
}

/// A spot axis around the ray from the light to the fragment: tilted by up to 1.5 times
/// the outer angle (so θ covers the inside, the soft edge and the outside), scaled by a
/// length in [0.2, 5] (the shader normalizes it); 1 in 200 is zero.
fn spot_axis(to_frag: Vec3, outer_cos: f32, tilt: (f32, Vec3, f32), zero: bool) -> Vec3 {
    if zero {
        return Vec3::ZERO;
    }
    let (fraction, axis_hint, len) = tilt;
    let ray = to_frag.normalize_or_zero();
    let axis = ray.cross(axis_hint).normalize_or_zero();
    let angle = fraction * 1.5 * outer_cos.clamp(-1.0, 1.0).acos();
    let dir = if axis == Vec3::ZERO { ray } else { Quat::from_axis_angle(axis, angle) * ray };
    dir * len
}

/// A model matrix `T·R·S`: translation in [-2, 2]³, a random rotation, scales in [0.25, 4].
fn model_matrix() -> impl Strategy<Value = Mat4> {
    (position(2.0), direction(), 0.0f32..std::f32::consts::TAU, (0.25f32..4.0, 0.25f32..4.0, 0.25f32..4.0)).prop_map(
        |(t, axis, angle, s)| {
            Mat4::from_scale_rotation_translation(Vec3::from(s), Quat::from_axis_angle(axis, angle), t)
        },
    )
}

/// The common surface: FragPos in [-5, 5]³, normal, eye offset, light offset.
fn surface() -> impl Strategy<Value = (Vec3, Vec3, Vec3, Vec3)> {
    (position(5.0), normal(), offset(0.5), offset(0.5))
}

fn basic_strategy() -> BoxedStrategy<Row> {
    (surface(), color(), color(), 0.0f32..=1.0, 0.0f32..=1.0, shininess(256.0, true))
        .prop_map(|((frag, n, eye, light), lc, oc, a, ss, s)| {
            let f = &fields::BASIC;
            Packed::new(&layout::BASIC_LIGHTING)
                .vec3(f.pos, frag)
                .float(f.ambient_strength, a)
                .vec3(f.normal, n)
                .float(f.specular_strength, ss)
                .vec3(f.light_pos, frag + light)
                .float(f.shininess, s)
                .vec3(f.view_pos, frag + eye)
                .vec3(f.light_color, lc)
                .vec3(f.object_color, oc)
                .into_row()
        })
        .boxed()
}

/// Gouraud (`aPos` in object space, moved by `model`) and the normal-matrix model
/// (`FragPos` already in world space, five times `aPos`; only the normal needs `model`).
fn model_rows_strategy(world_space_frag: bool) -> BoxedStrategy<Row> {
    (
        position(1.0),
        normal(),
        (direction(), 1.0f32..20.0),
        (direction(), 1.0f32..20.0),
        (color(), color(), 0.0f32..=1.0, 0.0f32..=1.0, shininess(256.0, false)),
        model_matrix(),
    )
        .prop_map(move |(a_pos, a_normal, (ld, ll), (vd, vl), (lc, oc, a, ss, s), m)| {
            let world = if world_space_frag { a_pos * 5.0 } else { m.transform_point3(a_pos) };
            let frag = if world_space_frag { world } else { a_pos };
            let (f, l) = if world_space_frag {
                (&fields::NORMAL_MATRIX, &layout::NORMAL_MATRIX)
            } else {
                (&fields::GOURAUD, &layout::GOURAUD)
            };
            Packed::new(l)
                .vec3(f.pos, frag)
                .float(f.ambient_strength, a)
                .vec3(f.normal, a_normal)
                .float(f.specular_strength, ss)
                .vec3(f.light_pos, world + ld * ll)
                .float(f.shininess, s)
                .vec3(f.view_pos, world + vd * vl)
                .vec3(f.light_color, lc)
                .vec3(f.object_color, oc)
                .mat4(f.model(), m)
                .into_row()
        })
        .boxed()
}

fn materials_strategy() -> BoxedStrategy<Row> {
    (surface(), (color(), color(), color(), shininess(256.0, true)), (color(), color(), color()))
        .prop_map(|((frag, n, eye, light), (ka, kd, ks, s), (la, ld, ls))| {
            let (m, l) = &fields::MATERIALS;
            Packed::new(&layout::MATERIALS)
                .vec3(m.frag, frag)
                .vec3(m.normal, n)
                .vec3(m.view_pos, frag + eye)
                .vec3(m.ambient, ka)
                .float(m.shininess, s)
                .vec3(m.diffuse, kd)
                .vec3(m.specular, ks)
                .vec3(l.at, frag + light)
                .vec3(l.ambient, la)
                .vec3(l.diffuse, ld)
                .vec3(l.specular, ls)
                .into_row()
        })
        .boxed()
}

/// The mapped surface (fragment, normal, eye, the two texels, shininess).
fn mapped(packed: Packed, m: &fields::Surface, frag: Vec3, n: Vec3, eye: Vec3, maps: (Vec3, Vec3, f32)) -> Packed {
    let (dt, st, s) = maps;
    packed
        .vec3(m.frag, frag)
        .float(m.shininess, s)
        .vec3(m.normal, n)
        .vec3(m.view_pos, frag + eye)
        .vec3(m.diffuse, dt)
        .vec3(m.specular, st)
}

/// A light's colours.
fn light_props(packed: Packed, l: &fields::Light, (la, ld, ls): (Vec3, Vec3, Vec3)) -> Packed {
    packed.vec3(l.ambient, la).vec3(l.diffuse, ld).vec3(l.specular, ls)
}

fn with_attenuation(packed: Packed, l: &fields::Light, a: [f32; 4]) -> Packed {
    let [kc, kl, kq] = l.attenuation();
    packed.float(kc, a[0]).float(kl, a[1]).float(kq, a[2])
}

/// The light of a mapped single-light model: where `light.position` or `light.direction`
/// comes from, and whether it has an attenuation.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum MappedLight {
    /// Lighting maps: a light at a position.
    Position,
    /// Light casters, directional: a direction.
    Direction,
    /// Light casters, point: a position and an attenuation.
    Attenuated,
}

/// Lighting maps, directional and point share the mapped surface; `light` is the position
/// (or the direction for the directional light) and the point light adds its attenuation.
fn mapped_strategy(
    (m, l): &'static (fields::Surface, fields::Light),
    lay: &'static layout::Layout,
    kind: MappedLight,
) -> BoxedStrategy<Row> {
    (surface(), (color(), color(), shininess(256.0, false)), (color(), color(), color()), normal(), attenuation())
        .prop_map(move |((frag, n, eye, light), maps, props, dir, att)| {
            let light_vec = if kind == MappedLight::Direction { dir } else { frag + light };
            let packed = light_props(mapped(Packed::new(lay), m, frag, n, eye, maps).vec3(l.at, light_vec), l, props);
            if kind == MappedLight::Attenuated {
                with_attenuation(packed, l, att).into_row()
            } else {
                packed.into_row()
            }
        })
        .boxed()
}

/// Lighting maps' exercise 4: the lighting-maps case plus an emission texel.
fn emission_strategy() -> BoxedStrategy<Row> {
    (surface(), (color(), color(), shininess(256.0, false)), (color(), color(), color()), color())
        .prop_map(|((frag, n, eye, light), maps, props, emission)| {
            let (m, l) = &fields::LIGHTING_MAPS_EMISSION;
            let packed = mapped(Packed::new(&layout::LIGHTING_MAPS_EMISSION), m, frag, n, eye, maps)
                .vec3(l.at, frag + light)
                .vec3(fields::EMISSION, emission);
            light_props(packed, l, props).into_row()
        })
        .boxed()
}

fn spot_strategy() -> BoxedStrategy<Row> {
    (
        surface(),
        (color(), color(), shininess(256.0, false)),
        (color(), color(), color()),
        cone(),
        ((0.0f32..=1.0, direction(), 0.2f32..5.0), 0u32..200),
        attenuation(),
    )
        .prop_map(|((frag, n, eye, light), maps, props, (cut, outer), (tilt, z), att)| {
            let (m, l) = &fields::SPOT;
            let pos = frag + light;
            let axis = spot_axis(frag - pos, outer, tilt, z == 0);
            let packed = mapped(Packed::new(&layout::SPOT), m, frag, n, eye, maps)
                .vec3(l.at, pos)
                .float(fields::SPOT_CUT_OFF, cut)
                .vec3(fields::SPOT_DIRECTION, axis)
                .float(fields::SPOT_OUTER_CUT_OFF, outer);
            with_attenuation(light_props(packed, l, props), l, att).into_row()
        })
        .boxed()
}

fn multiple_strategy() -> BoxedStrategy<Row> {
    // The eye and the fragment are placed in the chapter's scene volume.
    (position(5.0), normal(), offset(0.5), color(), color(), shininess(256.0, false))
        .prop_map(|(frag, n, eye, dt, st, s)| {
            mapped(Packed::new(&layout::MULTIPLE_LIGHTS), &fields::MULTIPLE_LIGHTS, frag, n, eye, (dt, st, s))
                .into_row()
        })
        .boxed()
}

fn ot8_strategy() -> BoxedStrategy<Row> {
    // Camera at the origin (V = identity): camera space is world space, EyeDirection is
    // -Position and LightDirection is LightPosition - Position, both exact in f32 or one
    // rounding, the same operations as the Rust path. Fragments in [-5, 5]³; 1 in 200 sits
    // at the eye (EyeDirection = 0).
    (
        prop_oneof![199 => position(5.0), 1 => Just(Vec3::ZERO)],
        normal(),
        offset(1.0),
        (1.0f32..=60.0, shininess(128.0, true), 0.0f32..=1.0),
        (color(), color(), color()),
    )
        .prop_map(|(frag, n, light, (power, s, ambient), (kd, ks, lc))| {
            let f = &fields::OT8;
            let light_pos = frag + light;
            Packed::new(&layout::OPENGL_TUTORIAL8)
                .vec3(f.position, frag)
                .float(f.light_power, power)
                .vec3(f.normal, n)
                .float(f.exponent, s)
                .vec3(f.eye_direction, -frag)
                .vec3(f.light_direction, light_pos - frag)
                .vec3(f.light_position, light_pos)
                .vec3(f.diffuse, kd)
                .vec3(f.specular, ks)
                .vec3(f.light_color, lc)
                .vec3(f.ambient_factor, Vec3::splat(ambient))
                .into_row()
        })
        .boxed()
}

fn ogldev_strategy() -> BoxedStrategy<Row> {
    (
        surface(),
        (shininess(128.0, true), 0.0f32..=1.0),
        (color(), 0.0f32..=1.0, 0.0f32..=1.0),
        direction(),
        (color(), 0.0f32..=1.0),
    )
        .prop_map(|((frag, n, eye, _), (power, si), (c, ia, id), dir, (texel, alpha))| {
            // The tutorial normalizes the direction on the CPU; the packed value is the
            // f32-normalized direction, used as given by every path.
            let dir = dir.normalize_or_zero();
            let f = &fields::OGLDEV;
            Packed::new(&layout::OGLDEV19)
                .vec3(f.world_pos, frag)
                .float(f.specular_power, power)
                .vec3(f.normal, n)
                .float(f.specular_intensity, si)
                .vec3(f.eye_world_pos, frag + eye)
                .vec3(f.color, c)
                .float(f.ambient_intensity, ia)
                .vec3(f.direction, dir)
                .float(f.diffuse_intensity, id)
                .rgba(f.texel, [texel.x, texel.y, texel.z, alpha])
                .into_row()
        })
        .boxed()
}

/// The case strategy of `model`: one packed row per value.
pub fn strategy(model: ModelId) -> BoxedStrategy<Row> {
    match model {
        ModelId::BasicLighting | ModelId::BlinnPhong => basic_strategy(),
        ModelId::Gouraud => model_rows_strategy(false),
        ModelId::NormalMatrix => model_rows_strategy(true),
        ModelId::Materials => materials_strategy(),
        ModelId::LightingMaps => mapped_strategy(&fields::LIGHTING_MAPS, &layout::LIGHTING_MAPS, MappedLight::Position),
        ModelId::LightingMapsEmission => emission_strategy(),
        ModelId::Directional => mapped_strategy(&fields::DIRECTIONAL, &layout::DIRECTIONAL, MappedLight::Direction),
        ModelId::Point => mapped_strategy(&fields::POINT, &layout::POINT, MappedLight::Attenuated),
        ModelId::Spot => spot_strategy(),
        ModelId::MultipleLights => multiple_strategy(),
        ModelId::OpenGLTutorial8 => ot8_strategy(),
        ModelId::Ogldev19 => ogldev_strategy(),
    }
}

/// A random scene for `multiple_lights`: a directional light, four point lights in
/// [-6, 6]³ and a spot light pointing at the origin's neighbourhood, colors in [0, 1],
/// attenuation and cones as for the single casters.
pub(super) fn scene_strategy() -> impl Strategy<Value = Scene> {
    let props = || {
        (color(), color(), color()).prop_map(|(ambient, diffuse, specular)| LightProps { ambient, diffuse, specular })
    };
    let point = move || {
        (position(6.0), attenuation(), props()).prop_map(|(position, a, props)| PointLight {
            position,
            attenuation: Attenuation { constant: a[0], linear: a[1], quadratic: a[2] },
            props,
        })
    };
    (
        (direction(), props()),
        [point(), point(), point(), point()],
        (position(6.0), position(1.0), cone(), attenuation(), props()),
    )
        .prop_map(|((dir, dprops), points, (pos, aim, (cut, outer), a, sprops))| Scene {
            dir_light: Some(DirLight { direction: dir, props: dprops }),
            point_lights: points.to_vec(),
            spot_light: Some(SpotLight {
                position: pos,
                direction: (aim - pos).normalize_or_zero(),
                cut_off: cut,
                // Equal cones are excluded here: the scene is shared by every case of the
                // group, and an undefined ε = 0 would void the whole group.
                outer_cut_off: if outer == cut { (cut.acos() + 0.05).cos() } else { outer },
                attenuation: Attenuation { constant: a[0], linear: a[1], quadratic: a[2] },
                props: sprops,
            }),
            clear_color: Vec3::ZERO,
        })
}

/// One triangle of a vertex + fragment pair check: three rows of [`layout::VERTEX_PAIR`],
/// one per vertex (they differ only in `aPos` and `aNormal`), and the barycentric weights
/// of the point the fragment shader is evaluated at.
#[derive(Debug, Clone, PartialEq)]
pub struct Triangle {
    /// The rows of the three vertices.
    pub rows: [Row; 3],
    /// Barycentric weights, each in [0, 1], summing to 1 (up to `f32` rounding).
    pub weights: [f32; 3],
}

/// A vertex normal within 30° of `base`, of length in [0.5, 2]: the normals of one
/// triangle of a smooth mesh, never interpolating to zero.
fn vertex_normal(base: Vec3, (hint, angle, len): (Vec3, f32, f32)) -> Vec3 {
    let axis = base.cross(hint).try_normalize().unwrap_or_else(|| base.any_orthonormal_vector());
    Quat::from_axis_angle(axis, angle.to_radians()) * base * len
}

/// The triangles of the pair check:
/// - `aPos` of each vertex in [-1, 1]³, `model` as for Gouraud (`T·R·S`, scales in
///   [0.25, 4]);
/// - vertex normals within 30° of a random direction, lengths in [0.5, 2];
/// - the weights uniform over the triangle;
/// - the light at a distance in [1, 20] from the sampled point (world space); the eye
///   (`viewPos`) is the camera's, set per group ([`camera_strategy`]);
/// - colours, strengths in [0, 1], shininess in [1, 256].
pub fn triangle_strategy() -> BoxedStrategy<Triangle> {
    let tilt = || (direction(), 0.0f32..30.0, 0.5f32..2.0);
    (
        [position(1.0), position(1.0), position(1.0)],
        (direction(), [tilt(), tilt(), tilt()]),
        model_matrix(),
        (0.0f32..=1.0, 0.0f32..=1.0),
        (direction(), 1.0f32..20.0),
        (color(), color(), 0.0f32..=1.0, 0.0f32..=1.0, shininess(256.0, false)),
    )
        .prop_map(|(a_pos, (base, tilts), model, (u, v), light, lit)| {
            let (u, v) = if u + v > 1.0 { (1.0 - u, 1.0 - v) } else { (u, v) };
            let weights = [1.0 - u - v, u, v];
            let sample: Vec3 = (0..3).map(|k| model.transform_point3(a_pos[k]) * weights[k]).sum();
            let (light_color, object_color, ambient, specular, shininess) = lit;
            let l = &layout::VERTEX_PAIR;
            let row = |k: usize| {
                Packed::new(l)
                    .vec3(l.get("aPos"), a_pos[k])
                    .vec3(l.get("aNormal"), vertex_normal(base, tilts[k]))
                    .mat4(l.get("model"), model)
                    .vec3(l.get("lightPos"), sample + light.0 * light.1)
                    .vec3(l.get("lightColor"), light_color)
                    .vec3(l.get("objectColor"), object_color)
                    .float(l.get("ambientStrength"), ambient)
                    .float(l.get("specularStrength"), specular)
                    .float(l.get("shininess"), shininess)
                    .into_row()
            };
            Triangle { rows: [row(0), row(1), row(2)], weights }
        })
        .boxed()
}

/// The camera of one group of triangles in the pair check: an eye at a distance in
/// [15, 25] from the origin (the triangles' sample points lie within 10.4 of it, so the eye
/// stays at least 4.6 from each), looking at a point in [-2, 2]³ with a random up
/// direction; `view` is that rigid transform, `projection` a perspective of 30° to 90°
/// (aspect 1, near 0.1, far 100), which only places the triangle. Returns `(view,
/// projection, eye)`.
pub fn camera_strategy() -> impl Strategy<Value = (Mat4, Mat4, Vec3)> {
    ((direction(), 15.0f32..25.0), position(2.0), direction(), 30.0f32..90.0).prop_map(|((d, r), target, up, fov)| {
        let eye = d * r;
        let forward = (target - eye).normalize();
        let up = (up - forward * up.dot(forward)).try_normalize().unwrap_or_else(|| forward.any_orthonormal_vector());
        (
            glam::camera::rh::view::look_at_mat4(eye, target, up),
            glam::camera::rh::proj::opengl::perspective(fov.to_radians(), 1.0, 0.1, 100.0),
            eye,
        )
    })
}
