//! Which cases GLSL leaves undefined: [`Class`], decided in `f64` from the exact inputs,
//! read through the layouts.

use glam::{DMat3, DVec3};

use super::fields::{self, Basic, Light, Surface};
use super::{CaseModel, GroupScene};
use crate::gl::layout::Row;
use crate::gl::model_id::ModelId;
use crate::reference as r64;

/// Why a case is left out of the asserted bound.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Class {
    /// Every operation is defined and the result is a continuous function of the inputs.
    Defined,
    /// `normalize` of a zero vector (zero normal, light or eye at the fragment, zero direction).
    /// GLSL's other undefined case, `clamp(NaN)`, only arises downstream of this one in the
    /// tutorials' shaders (opengl-tutorial 8 clamps a dot product with a NaN vector), so it
    /// is counted here.
    NormalizeZero,
    /// `pow(x, y)` with `x < 0` (ogldev 19 takes `pow` before testing the sign).
    PowNegative,
    /// `pow(0, y)` with `y <= 0`; the base is within 1e-4 of 0 with shininess 0.
    PowZeroNonPositive,
    /// A division by zero: a spot light with `cutOff == outerCutOff` (ε = 0).
    DivisionByZero,
    /// Within 1e-5 of a discontinuity (a `> 0` or `theta > cutOff` test), where rounding
    /// may take either branch. Defined, but not bounded by a rounding analysis.
    NearDiscontinuity,
    /// Blinn-Phong with the light and view directions nearly opposite
    /// (`|lightDir + viewDir| <` [`super::bounds::BLINN_MIN_HALFWAY`]): the halfway vector
    /// is defined but ill-conditioned, so rounding moves it far.
    NearOpposite,
}

impl Class {
    /// A short description for reports.
    pub fn describe(self) -> &'static str {
        match self {
            Class::Defined => "defined",
            Class::NormalizeZero => "normalize(0)",
            Class::PowNegative => "pow(x < 0, y)",
            Class::PowZeroNonPositive => "pow(0, y <= 0)",
            Class::DivisionByZero => "x / 0 (cutOff == outerCutOff)",
            Class::NearDiscontinuity => "within 1e-5 of a branch",
            Class::NearOpposite => "light and eye nearly opposite (halfway ill-conditioned)",
        }
    }
}

impl CaseModel {
    /// Sorts a case into [`Class`]: defined, or which undefined operation it reaches.
    ///
    /// Decided in `f64` from the exact inputs; the bands (1e-4 for `pow(0, 0)`, 1e-5 for
    /// branches) are far wider than the `f32` errors, so no case near the edge of a class
    /// is counted as defined.
    pub fn classify(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Class {
        let r = Row(r);
        match self.id {
            ModelId::Materials => single_light(r, &fields::MATERIALS, Cast::Position),
            ModelId::LightingMaps => single_light(r, &fields::LIGHTING_MAPS, Cast::Position),
            ModelId::LightingMapsEmission => single_light(r, &fields::LIGHTING_MAPS_EMISSION, Cast::Position),
            ModelId::Directional => single_light(r, &fields::DIRECTIONAL, Cast::Direction),
            ModelId::Point => single_light(r, &fields::POINT, Cast::Position),
            ModelId::Spot => single_light(r, &fields::SPOT, Cast::Spot),
            ModelId::BasicLighting => {
                let f = &fields::BASIC;
                basic(r, f, r.dvec3(f.pos), r.dvec3(f.normal))
            }
            ModelId::Gouraud => {
                let f = &fields::GOURAUD;
                let (m, n) = moved_normal(r, f);
                basic(r, f, m.transform_point3(r.dvec3(f.pos)), n)
            }
            ModelId::NormalMatrix => {
                let f = &fields::NORMAL_MATRIX;
                basic(r, f, r.dvec3(f.pos), moved_normal(r, f).1)
            }
            ModelId::BlinnPhong => {
                let f = &fields::BLINN_PHONG;
                let frag = r.dvec3(f.pos);
                let (n, l, v) = (r.dvec3(f.normal), r.dvec3(f.light_pos) - frag, r.dvec3(f.view_pos) - frag);
                if zero(n) || zero(l) || zero(v) {
                    return Class::NormalizeZero;
                }
                let sum = nz(l) + nz(v);
                if sum.length() < super::bounds::BLINN_MIN_HALFWAY {
                    return Class::NearOpposite;
                }
                pow_class(r.float(f.shininess), nz(n).dot(nz(sum)).max(0.0))
            }
            ModelId::MultipleLights => {
                let m = &fields::MULTIPLE_LIGHTS;
                let frag = r.dvec3(m.frag);
                if zero(r.dvec3(m.normal)) || zero(r.dvec3(m.view_pos) - frag) {
                    return Class::NormalizeZero;
                }
                let at_a_light = scene.is_some_and(|s| {
                    s.f64.point_lights.iter().any(|l| l.position == frag)
                        || s.f64.spot_light.as_ref().is_some_and(|l| l.position == frag)
                });
                if at_a_light {
                    Class::NormalizeZero
                } else {
                    Class::Defined
                }
            }
            ModelId::OpenGLTutorial8 => {
                let f = &fields::OT8;
                let (n, l, e) = (r.dvec3(f.normal), r.dvec3(f.light_direction), r.dvec3(f.eye_direction));
                if zero(n) || zero(l) || zero(e) {
                    return Class::NormalizeZero;
                }
                let cos_alpha = nz(e).dot(r64::glsl::reflect(-nz(l), nz(n))).clamp(0.0, 1.0);
                pow_class(r.float(f.exponent), cos_alpha)
            }
            ModelId::Ogldev19 => {
                let f = &fields::OGLDEV;
                let frag = r.dvec3(f.world_pos);
                let (n, v) = (r.dvec3(f.normal), r.dvec3(f.eye_world_pos) - frag);
                if zero(n) {
                    return Class::NormalizeZero;
                }
                let n = nz(n);
                let dir = r.dvec3(f.direction);
                let diffuse_factor = n.dot(-dir);
                if diffuse_factor.abs() < 1e-5 {
                    return Class::NearDiscontinuity;
                }
                if diffuse_factor < 0.0 {
                    return Class::Defined;
                }
                if zero(v) {
                    return Class::NormalizeZero;
                }
                let c = nz(v).dot(nz(r64::glsl::reflect(dir, n)));
                if c < 0.0 {
                    Class::PowNegative
                } else {
                    pow_class(r.float(f.specular_power), c)
                }
            }
        }
    }
}

fn nz(v: DVec3) -> DVec3 {
    r64::glsl::normalize_or_zero(v)
}

fn zero(v: DVec3) -> bool {
    v == DVec3::ZERO
}

/// Phong's base for the light toward `l` (unit), the normal `n` and the eye `v`.
fn base(n: DVec3, l: DVec3, v: DVec3) -> f64 {
    v.dot(r64::glsl::reflect(-l, n)).max(0.0)
}

/// `pow(b, s)` is undefined for a base near 0 and an exponent `s <= 0`.
fn pow_class(s: f32, b: f64) -> Class {
    if s <= 0.0 && b < 1e-4 {
        Class::PowZeroNonPositive
    } else {
        Class::Defined
    }
}

/// The light of a single-light model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Cast {
    /// A light at `light.position`.
    Position,
    /// A directional light: `light.direction` points from the light.
    Direction,
    /// A spotlight at `light.position`, with its cone.
    Spot,
}

/// The class of a single-light case (Materials, Lighting maps, the three casters).
fn single_light(r: Row, (m, l): &(Surface, Light), cast: Cast) -> Class {
    let frag = r.dvec3(m.frag);
    let light = match cast {
        Cast::Direction => -r.dvec3(l.at),
        Cast::Position | Cast::Spot => r.dvec3(l.at) - frag,
    };
    let (n, v) = (r.dvec3(m.normal), r.dvec3(m.view_pos) - frag);
    let spot = cast == Cast::Spot;
    if zero(n) || zero(light) || zero(v) || (spot && zero(r.dvec3(fields::SPOT_DIRECTION))) {
        return Class::NormalizeZero;
    }
    if spot {
        let (cut, outer) = (r.float(fields::SPOT_CUT_OFF), r.float(fields::SPOT_OUTER_CUT_OFF));
        if cut == outer {
            return Class::DivisionByZero;
        }
        let theta = nz(light).dot(nz(-r.dvec3(fields::SPOT_DIRECTION)));
        if (theta - cut as f64).abs() < 1e-5 {
            return Class::NearDiscontinuity;
        }
    }
    pow_class(r.float(m.shininess), base(nz(n), nz(light), nz(v)))
}

/// The model matrix of a case of Gouraud or the normal-matrix model, and the normal moved
/// by its normal matrix (zero for a singular matrix).
fn moved_normal(r: Row, f: &Basic) -> (glam::DMat4, DVec3) {
    let m = r64::dmat4(r.mat4(f.model()));
    let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
    (m, nm.map_or(DVec3::ZERO, |nm| nm * r.dvec3(f.normal)))
}

/// The class of a basic-lighting case with the fragment at `frag` and the normal `n`.
fn basic(r: Row, f: &Basic, frag: DVec3, n: DVec3) -> Class {
    let (l, v) = (r.dvec3(f.light_pos) - frag, r.dvec3(f.view_pos) - frag);
    if zero(n) || zero(l) || zero(v) {
        return Class::NormalizeZero;
    }
    pow_class(r.float(f.shininess), base(nz(n), nz(l), nz(v)))
}
