//! One parsed `shade` case and its two evaluations: the `f32` path through lightlab's
//! core modules and the independent `f64` reference. Values are kept in `f64` as
//! read; the `f32` path converts them.

use glam::{DVec3, Vec3};

use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{LightProps, Material};
use crate::models::{Ogldev, OpenGLTutorial};
use crate::phong::{BasicLighting, Specular, Terms};
use crate::reference;

#[derive(Clone, Copy, Debug)]
pub(super) struct PropsIn {
    pub(super) ambient: DVec3,
    pub(super) diffuse: DVec3,
    pub(super) specular: DVec3,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct MaterialIn {
    pub(super) ambient: DVec3,
    pub(super) diffuse: DVec3,
    pub(super) specular: DVec3,
    pub(super) shininess: f64,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct AttenuationIn {
    pub(super) constant: f64,
    pub(super) linear: f64,
    pub(super) quadratic: f64,
}

#[derive(Clone, Copy, Debug)]
pub(super) enum LightIn {
    Directional {
        direction: DVec3,
        props: PropsIn,
    },
    Point {
        position: DVec3,
        attenuation: AttenuationIn,
        props: PropsIn,
    },
    Spot {
        position: DVec3,
        direction: DVec3,
        cut_off_deg: f64,
        outer_cut_off_deg: f64,
        attenuation: AttenuationIn,
        props: PropsIn,
    },
}

#[derive(Clone, Copy, Debug)]
pub(super) struct TutorialIn {
    pub(super) light_pos: DVec3,
    pub(super) light_color: DVec3,
    pub(super) light_power: f64,
    pub(super) diffuse: DVec3,
    pub(super) specular: DVec3,
    pub(super) ambient_factor: f64,
    pub(super) exponent: f64,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct OgldevIn {
    pub(super) color: DVec3,
    pub(super) ambient_intensity: f64,
    pub(super) diffuse_intensity: f64,
    /// As given (non-zero); each path normalizes it in its own precision, as
    /// the tutorial's CPU code normalizes it in `float`.
    pub(super) direction: DVec3,
    pub(super) specular_intensity: f64,
    pub(super) specular_power: f64,
    pub(super) texture_color: DVec3,
}

#[derive(Clone, Debug)]
pub(super) enum ModelCase {
    Lights { specular: Specular, material: MaterialIn, lights: Vec<LightIn> },
    OpenGLTutorial(TutorialIn),
    Ogldev(OgldevIn),
    Basic(BasicIn),
}

/// LearnOpenGL's basic-lighting shader, in the chapter's names (`view_pos` is the
/// case's own).
#[derive(Clone, Copy, Debug)]
pub(super) struct BasicIn {
    pub(super) light_pos: DVec3,
    pub(super) light_color: DVec3,
    pub(super) object_color: DVec3,
    pub(super) ambient_strength: f64,
    pub(super) specular_strength: f64,
    pub(super) shininess: f64,
}

impl BasicIn {
    fn to_f32(self, view_pos: DVec3) -> BasicLighting {
        BasicLighting {
            light_pos: self.light_pos.as_vec3(),
            view_pos: view_pos.as_vec3(),
            light_color: self.light_color.as_vec3(),
            object_color: self.object_color.as_vec3(),
            ambient_strength: self.ambient_strength as f32,
            specular_strength: self.specular_strength as f32,
            shininess: self.shininess as f32,
        }
    }

    fn to_f64(self, view_pos: DVec3) -> reference::phong::BasicLighting {
        reference::phong::BasicLighting {
            light_pos: self.light_pos,
            view_pos,
            light_color: self.light_color,
            object_color: self.object_color,
            ambient_strength: self.ambient_strength,
            specular_strength: self.specular_strength,
            shininess: self.shininess,
        }
    }
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
                let material = material.to_f32();
                let n = normal.normalize_or_zero();
                let view_dir = (view_pos - frag_pos).normalize_or_zero();
                lights.iter().map(|l| l.terms_f32(*specular, &material, n, frag_pos, view_dir)).collect()
            }
            ModelCase::OpenGLTutorial(t) => vec![t.to_f32().terms(frag_pos, normal, view_pos)],
            ModelCase::Ogldev(o) => vec![o.to_f32().terms(frag_pos, normal, view_pos)],
            ModelCase::Basic(b) => vec![b.to_f32(self.view_pos).terms(frag_pos, normal)],
        };
        (lights.iter().map(Terms::sum).sum(), lights)
    }
}

impl PropsIn {
    pub(super) fn to_f64(self) -> reference::material::LightProps {
        reference::material::LightProps { ambient: self.ambient, diffuse: self.diffuse, specular: self.specular }
    }

    pub(super) fn to_f32(self) -> LightProps {
        LightProps {
            ambient: self.ambient.as_vec3(),
            diffuse: self.diffuse.as_vec3(),
            specular: self.specular.as_vec3(),
        }
    }
}

impl MaterialIn {
    pub(super) fn to_f64(self) -> reference::material::Material {
        reference::material::Material {
            ambient: self.ambient,
            diffuse: self.diffuse,
            specular: self.specular,
            shininess: self.shininess,
        }
    }

    pub(super) fn to_f32(self) -> Material {
        Material {
            ambient: self.ambient.as_vec3(),
            diffuse: self.diffuse.as_vec3(),
            specular: self.specular.as_vec3(),
            shininess: self.shininess as f32,
        }
    }
}

impl AttenuationIn {
    pub(super) fn to_f64(self) -> reference::casters::Attenuation {
        reference::casters::Attenuation { constant: self.constant, linear: self.linear, quadratic: self.quadratic }
    }

    pub(super) fn to_f32(self) -> Result<Attenuation, crate::casters::ParamError> {
        Attenuation::new(self.constant as f32, self.linear as f32, self.quadratic as f32)
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
                    attenuation.to_f32()?,
                    props.to_f32(),
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
                DirLight { direction: direction.as_vec3(), props: props.to_f32() }
                    .terms_with(specular, material, n, view_dir)
            }
            LightIn::Point { position, attenuation, props } => {
                let Ok(attenuation) = attenuation.to_f32() else { return nan };
                let light = PointLight { position: position.as_vec3(), attenuation, props: props.to_f32() };
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
                reference::casters::DirLight { direction, props: props.to_f64() }
                    .terms_with(specular, material, n, view_dir)
            }
            LightIn::Point { position, attenuation, props } => {
                let light = reference::casters::PointLight {
                    position,
                    attenuation: attenuation.to_f64(),
                    props: props.to_f64(),
                };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
            LightIn::Spot { position, direction, cut_off_deg, outer_cut_off_deg, attenuation, props } => {
                let light = reference::casters::SpotLight {
                    position,
                    direction: direction.normalize_or_zero(),
                    cut_off: cut_off_deg.to_radians().cos(),
                    outer_cut_off: outer_cut_off_deg.to_radians().cos(),
                    attenuation: attenuation.to_f64(),
                    props: props.to_f64(),
                };
                light.terms_with(specular, material, n, frag_pos, view_dir)
            }
        }
    }
}

impl TutorialIn {
    pub(super) fn to_f64(self) -> reference::models::OpenGLTutorial {
        reference::models::OpenGLTutorial {
            light_pos: self.light_pos,
            light_color: self.light_color,
            light_power: self.light_power,
            diffuse: self.diffuse,
            specular: self.specular,
            ambient_factor: self.ambient_factor,
            exponent: self.exponent,
        }
    }

    pub(super) fn to_f32(self) -> OpenGLTutorial {
        OpenGLTutorial {
            light_pos: self.light_pos.as_vec3(),
            light_color: self.light_color.as_vec3(),
            light_power: self.light_power as f32,
            diffuse: self.diffuse.as_vec3(),
            specular: self.specular.as_vec3(),
            ambient_factor: self.ambient_factor as f32,
            exponent: self.exponent as f32,
        }
    }
}

impl OgldevIn {
    pub(super) fn to_f64(self) -> reference::models::Ogldev {
        reference::models::Ogldev {
            color: self.color,
            ambient_intensity: self.ambient_intensity,
            diffuse_intensity: self.diffuse_intensity,
            direction: self.direction.normalize_or_zero(),
            specular_intensity: self.specular_intensity,
            specular_power: self.specular_power,
            texture_color: self.texture_color,
        }
    }

    pub(super) fn to_f32(self) -> Ogldev {
        Ogldev {
            color: self.color.as_vec3(),
            ambient_intensity: self.ambient_intensity as f32,
            diffuse_intensity: self.diffuse_intensity as f32,
            direction: self.direction.as_vec3().normalize_or_zero(),
            specular_intensity: self.specular_intensity as f32,
            specular_power: self.specular_power as f32,
            texture_color: self.texture_color.as_vec3(),
        }
    }
}

/// The `rgb_f64` of a case: the independent `f64` reference ([`crate::reference`]).
pub(super) fn shade_f64(case: &Case) -> DVec3 {
    match &case.model {
        ModelCase::Lights { specular, material, lights } => {
            let material = material.to_f64();
            let n = case.normal.normalize_or_zero();
            let view_dir = (case.view_pos - case.frag_pos).normalize_or_zero();
            lights.iter().map(|l| l.terms_f64(*specular, &material, n, case.frag_pos, view_dir).sum()).sum()
        }
        ModelCase::OpenGLTutorial(t) => t.to_f64().terms(case.frag_pos, case.normal, case.view_pos).sum(),
        ModelCase::Ogldev(o) => o.to_f64().terms(case.frag_pos, case.normal, case.view_pos).sum(),
        ModelCase::Basic(b) => b.to_f64(case.view_pos).terms(case.frag_pos, case.normal).sum(),
    }
}
