//! One parsed `shade` case and its two evaluations: the `f32` path through lightlab's
//! core modules and the independent `f64` reference. Values are kept in `f64` as
//! read; the `f32` path converts them.

use crate::casters::LocalLight as _;
use crate::reference::casters::LocalLight as _;
use glam::{DVec3, Vec3};

use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material};
use crate::models::{Ogldev, OpenGLTutorial};
use crate::phong::{BasicLighting, Specular, Terms};
use crate::reference;
use crate::reference::casters::Attenuation as Attenuation64;
use crate::reference::material::{LightProps as LightProps64, Material as Material64};
use crate::reference::models::{Ogldev as Ogldev64, OpenGLTutorial as Tutorial64};

#[derive(Clone, Copy, Debug)]
pub(super) enum LightIn {
    Directional {
        direction: DVec3,
        props: LightProps64,
    },
    Point {
        position: DVec3,
        attenuation: Attenuation64,
        props: LightProps64,
    },
    Spot {
        position: DVec3,
        direction: DVec3,
        cut_off_deg: f64,
        outer_cut_off_deg: f64,
        attenuation: Attenuation64,
        props: LightProps64,
    },
}

#[derive(Clone, Debug)]
pub(super) enum ModelCase {
    Lights {
        specular: Specular,
        material: Material64,
        lights: Vec<LightIn>,
    },
    /// The inputs as read, in the reference's own type.
    OpenGLTutorial(Tutorial64),
    /// The inputs as read; `direction` as given (non-zero): each path normalizes it in
    /// its own precision, as the tutorial's CPU code normalizes it in `float`.
    Ogldev(Ogldev64),
    /// LearnOpenGL's basic-lighting shader, in the chapter's names; its `view_pos` is the
    /// case's own.
    Basic(reference::phong::BasicLighting),
}

#[derive(Clone, Debug)]
pub(super) struct Case {
    pub(super) frag_pos: DVec3,
    pub(super) normal: DVec3,
    pub(super) view_pos: DVec3,
    pub(super) model: ModelCase,
}

impl Case {
    /// The f32 path: lightlab's core modules.
    pub(super) fn shade_f32(&self) -> (Vec3, Vec<Terms>) {
        let frag_pos = self.frag_pos.as_vec3();
        let normal = self.normal.as_vec3();
        let view_pos = self.view_pos.as_vec3();
        let lights = match &self.model {
            ModelCase::Lights { specular, material, lights } => {
                let material = material_f32(material);
                let n = normal.normalize_or_zero();
                let view_dir = (view_pos - frag_pos).normalize_or_zero();
                lights.iter().map(|l| l.terms_f32(*specular, &material, n, frag_pos, view_dir)).collect()
            }
            ModelCase::OpenGLTutorial(t) => vec![tutorial_f32(t).terms(frag_pos, normal, view_pos)],
            ModelCase::Ogldev(o) => vec![ogldev_f32(o).terms(frag_pos, normal, view_pos)],
            ModelCase::Basic(b) => vec![basic_f32(b).terms(frag_pos, normal)],
        };
        (lights.iter().map(Terms::sum).sum(), lights)
    }
}

impl LightIn {
    pub(super) fn spot_f32(&self) -> Result<SpotLight, crate::casters::ParamError> {
        match *self {
            LightIn::Spot { position, direction, cut_off_deg, outer_cut_off_deg, attenuation, props } => {
                SpotLight::new(
                    position.as_vec3(),
                    direction.as_vec3(),
                    cut_off_deg as f32,
                    outer_cut_off_deg as f32,
                    attenuation_f32(&attenuation)?,
                    props_f32(&props),
                )
            }
            _ => Err(crate::casters::ParamError { field: "kind", reason: "not a spot light".to_string() }),
        }
    }

    /// One light's terms through the core modules (`casters`).
    /// Inputs were validated at parse time, so the constructors succeed; a
    /// failure here gives NaN terms, which `shade_line` reports.
    fn terms_f32(&self, specular: Specular, material: &Material, n: Vec3, frag_pos: Vec3, view_dir: Vec3) -> Terms {
        let nan = Terms { ambient: Vec3::NAN, diffuse: Vec3::NAN, specular: Vec3::NAN };
        match *self {
            LightIn::Directional { direction, props } => {
                DirLight { direction: direction.as_vec3(), props: props_f32(&props) }
                    .terms_with(specular, material, n, view_dir)
            }
            LightIn::Point { position, attenuation, props } => {
                let Ok(attenuation) = attenuation_f32(&attenuation) else { return nan };
                let light = PointLight { position: position.as_vec3(), attenuation, props: props_f32(&props) };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
            LightIn::Spot { .. } => {
                let Ok(light) = self.spot_f32() else { return nan };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
        }
    }

    /// One light's terms through the independent `f64` reference, built from
    /// the inputs as parsed (in `f64`, not widened from `f32`).
    fn terms_f64(
        &self,
        specular: Specular,
        material: &reference::material::Material,
        n: DVec3,
        frag_pos: DVec3,
        view_dir: DVec3,
    ) -> reference::phong::Terms {
        match *self {
            LightIn::Directional { direction, props } => {
                reference::casters::DirLight { direction, props }.terms_with(specular, material, n, view_dir)
            }
            LightIn::Point { position, attenuation, props } => {
                let light = reference::casters::PointLight { position, attenuation, props };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
            LightIn::Spot { position, direction, cut_off_deg, outer_cut_off_deg, attenuation, props } => {
                let light = reference::casters::SpotLight {
                    position,
                    direction: direction.normalize_or_zero(),
                    cut_off: cut_off_deg.to_radians().cos(),
                    outer_cut_off: outer_cut_off_deg.to_radians().cos(),
                    attenuation,
                    props,
                };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
        }
    }
}

/// The `f32` path's light intensities, narrowed from the inputs as read.
fn props_f32(p: &LightProps64) -> LightProps {
    LightProps { ambient: p.ambient.as_vec3(), diffuse: p.diffuse.as_vec3(), specular: p.specular.as_vec3() }
}

/// The `f32` path's material, narrowed from the inputs as read.
fn material_f32(m: &Material64) -> Material {
    Material {
        ambient: m.ambient.as_vec3(),
        diffuse: m.diffuse.as_vec3(),
        specular: m.specular.as_vec3(),
        shininess: m.shininess as f32,
    }
}

/// The `f32` path's checked attenuation, narrowed from the inputs as read.
pub(super) fn attenuation_f32(a: &Attenuation64) -> Result<Attenuation, crate::casters::ParamError> {
    Attenuation::new(a.constant as f32, a.linear as f32, a.quadratic as f32)
}

fn basic_f32(b: &reference::phong::BasicLighting) -> BasicLighting {
    BasicLighting {
        light_pos: b.light_pos.as_vec3(),
        view_pos: b.view_pos.as_vec3(),
        light_color: b.light_color.as_vec3(),
        object_color: b.object_color.as_vec3(),
        ambient_strength: b.ambient_strength as f32,
        specular_strength: b.specular_strength as f32,
        shininess: b.shininess as f32,
    }
}

fn tutorial_f32(t: &Tutorial64) -> OpenGLTutorial {
    OpenGLTutorial {
        light_pos: t.light_pos.as_vec3(),
        light_color: t.light_color.as_vec3(),
        light_power: t.light_power as f32,
        diffuse: t.diffuse.as_vec3(),
        specular: t.specular.as_vec3(),
        ambient_factor: t.ambient_factor as f32,
        exponent: t.exponent as f32,
    }
}

fn ogldev_f32(o: &Ogldev64) -> Ogldev {
    Ogldev {
        color: o.color.as_vec3(),
        ambient_intensity: o.ambient_intensity as f32,
        diffuse_intensity: o.diffuse_intensity as f32,
        direction: o.direction.as_vec3().normalize_or_zero(),
        specular_intensity: o.specular_intensity as f32,
        specular_power: o.specular_power as f32,
        texture_color: o.texture_color.as_vec3(),
    }
}

/// The `rgb_f64` of a case: the independent `f64` reference ([`crate::reference`]).
pub(super) fn shade_f64(case: &Case) -> DVec3 {
    match &case.model {
        ModelCase::Lights { specular, material, lights } => {
            let n = case.normal.normalize_or_zero();
            let view_dir = (case.view_pos - case.frag_pos).normalize_or_zero();
            lights.iter().map(|l| l.terms_f64(*specular, material, n, case.frag_pos, view_dir).sum()).sum()
        }
        ModelCase::OpenGLTutorial(t) => t.terms(case.frag_pos, case.normal, case.view_pos).sum(),
        ModelCase::Ogldev(o) => Ogldev64 { direction: o.direction.normalize_or_zero(), ..*o }
            .terms(case.frag_pos, case.normal, case.view_pos)
            .sum(),
        ModelCase::Basic(b) => b.terms(case.frag_pos, case.normal).sum(),
    }
}
