//! The Rust answers for one case: the `f32` core and the `f64` [`crate::reference`], with
//! the inputs read through the layouts ([`Row`]). Every formula is the core's
//! ([`crate::phong`], [`crate::material`], [`crate::casters`], [`crate::scene`],
//! [`crate::models`]); this file only unpacks.

use crate::casters::LocalLight as _;
use crate::reference::casters::LocalLight as _;
use glam::{DMat3, DVec2, DVec3, Mat3, Vec2, Vec3};

use super::fields::{self, Basic, Light, Surface};
use super::{CaseModel, GroupScene, MAX_CHANNELS};
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::gl::layout::Row;
use crate::gl::model_id::ModelId;
use crate::material::{LightProps, Material};
use crate::reference as r64;

/// Channels of one case: up to [`MAX_CHANNELS`] numbers.
pub type Channels<T> = [T; MAX_CHANNELS];

fn ch3<T: Copy + Default>(a: [T; 3]) -> Channels<T> {
    let mut c = [T::default(); MAX_CHANNELS];
    c[..3].copy_from_slice(&a);
    c
}

fn ch6<T: Copy + Default>(a: [T; 3], b: [T; 3]) -> Channels<T> {
    let mut c = [T::default(); MAX_CHANNELS];
    c[..3].copy_from_slice(&a);
    c[3..].copy_from_slice(&b);
    c
}

fn basic_f32(r: Row, f: &Basic, normal: Vec3, frag: Vec3) -> Vec3 {
    crate::phong::BasicLighting {
        light_pos: r.vec3(f.light_pos),
        view_pos: r.vec3(f.view_pos),
        light_color: r.vec3(f.light_color),
        object_color: r.vec3(f.object_color),
        ambient_strength: r.float(f.ambient_strength),
        specular_strength: r.float(f.specular_strength),
        shininess: r.float(f.shininess),
    }
    .terms(frag, normal)
    .sum()
}

fn basic_f64(r: Row, f: &Basic, normal: DVec3, frag: DVec3) -> DVec3 {
    r64::phong::BasicLighting {
        light_pos: r.dvec3(f.light_pos),
        view_pos: r.dvec3(f.view_pos),
        light_color: r.dvec3(f.light_color),
        object_color: r.dvec3(f.object_color),
        ambient_strength: r.float(f.ambient_strength) as f64,
        specular_strength: r.float(f.specular_strength) as f64,
        shininess: r.float(f.shininess) as f64,
    }
    .terms(frag, normal)
    .sum()
}

/// Blinn-Phong on the basic-lighting inputs: Basic lighting's ambient and diffuse terms
/// with the specular factor of [`crate::phong::Specular::Blinn`].
fn blinn_f32(r: Row, f: &Basic) -> Vec3 {
    let (frag, normal) = (r.vec3(f.pos), r.vec3(f.normal));
    let lit = r.vec3(f.light_color) * r.vec3(f.object_color);
    let norm = normal.normalize_or_zero();
    let light_dir = (r.vec3(f.light_pos) - frag).normalize_or_zero();
    let view_dir = (r.vec3(f.view_pos) - frag).normalize_or_zero();
    let spec = crate::phong::Specular::Blinn.factor(norm, light_dir, view_dir, r.float(f.shininess));
    crate::phong::Terms {
        ambient: crate::phong::ambient(r.float(f.ambient_strength), lit),
        diffuse: crate::phong::diffuse_factor(norm, light_dir) * lit,
        specular: r.float(f.specular_strength) * spec * lit,
    }
    .sum()
}

/// [`blinn_f32`] in the `f64` reference.
fn blinn_f64(r: Row, f: &Basic) -> DVec3 {
    use r64::phong as p;
    let (frag, normal) = (r.dvec3(f.pos), r.dvec3(f.normal));
    let lit = r64::color::modulate(r.dvec3(f.light_color), r.dvec3(f.object_color));
    let norm = r64::glsl::normalize_or_zero(normal);
    let light_dir = r64::glsl::normalize_or_zero(r.dvec3(f.light_pos) - frag);
    let view_dir = r64::glsl::normalize_or_zero(r.dvec3(f.view_pos) - frag);
    let spec = p::blinn_specular_factor(norm, light_dir, view_dir, r.float(f.shininess) as f64);
    p::Terms {
        ambient: p::ambient(r.float(f.ambient_strength) as f64, lit),
        diffuse: lit * p::diffuse_factor(norm, light_dir),
        specular: lit * (r.float(f.specular_strength) as f64 * spec),
    }
    .sum()
}

fn material(r: Row, m: &Surface) -> Material {
    Material {
        ambient: r.vec3(m.ambient),
        diffuse: r.vec3(m.diffuse),
        specular: r.vec3(m.specular),
        shininess: r.float(m.shininess),
    }
}

fn material64(r: Row, m: &Surface) -> r64::material::Material {
    r64::material::Material::from_f32(&material(r, m))
}

fn props(r: Row, l: &Light) -> LightProps {
    LightProps { ambient: r.vec3(l.ambient), diffuse: r.vec3(l.diffuse), specular: r.vec3(l.specular) }
}

fn att(r: Row, l: &Light) -> Attenuation {
    let [kc, kl, kq] = l.attenuation();
    Attenuation { constant: r.float(kc), linear: r.float(kl), quadratic: r.float(kq) }
}

fn point_light(r: Row, l: &Light) -> PointLight {
    PointLight { position: r.vec3(l.at), attenuation: att(r, l), props: props(r, l) }
}

fn spot_light(r: Row, l: &Light) -> SpotLight {
    SpotLight {
        position: r.vec3(l.at),
        direction: r.vec3(fields::SPOT_DIRECTION),
        cut_off: r.float(fields::SPOT_CUT_OFF),
        outer_cut_off: r.float(fields::SPOT_OUTER_CUT_OFF),
        attenuation: att(r, l),
        props: props(r, l),
    }
}

fn ot8(r: Row) -> crate::models::OpenGLTutorial {
    let f = &fields::OT8;
    crate::models::OpenGLTutorial {
        light_pos: r.vec3(f.light_position),
        light_color: r.vec3(f.light_color),
        light_power: r.float(f.light_power),
        diffuse: r.vec3(f.diffuse),
        specular: r.vec3(f.specular),
        ambient_factor: r.float(f.ambient_factor),
        exponent: r.float(f.exponent),
    }
}

fn ogldev(r: Row) -> crate::models::Ogldev {
    let f = &fields::OGLDEV;
    crate::models::Ogldev {
        color: r.vec3(f.color),
        ambient_intensity: r.float(f.ambient_intensity),
        diffuse_intensity: r.float(f.diffuse_intensity),
        direction: r.vec3(f.direction),
        specular_intensity: r.float(f.specular_intensity),
        specular_power: r.float(f.specular_power),
        texture_color: r.vec3(f.texel),
    }
}

/// The surface vectors of the mapped models (`norm`, `viewDir`, and `lightDir` toward
/// `light_pos`), as the shaders compute them, with zero for a zero vector.
fn surface_dirs(r: Row, m: &Surface, light_pos: Vec3) -> (Vec3, Vec3, Vec3) {
    let frag = r.vec3(m.frag);
    (
        r.vec3(m.normal).normalize_or_zero(),
        (light_pos - frag).normalize_or_zero(),
        (r.vec3(m.view_pos) - frag).normalize_or_zero(),
    )
}

fn surface_dirs64(r: Row, m: &Surface, light_pos: DVec3) -> (DVec3, DVec3, DVec3) {
    use r64::glsl::normalize_or_zero as nz;
    let frag = r.dvec3(m.frag);
    (nz(r.dvec3(m.normal)), nz(light_pos - frag), nz(r.dvec3(m.view_pos) - frag))
}

/// Materials and Lighting maps: one light at `light.position`, the surface's colours.
fn material_f32(r: Row, (m, l): &(Surface, Light)) -> Channels<f32> {
    let (n, ld, v) = surface_dirs(r, m, r.vec3(l.at));
    ch3(crate::material::material_terms(&material(r, m), &props(r, l), n, ld, v).sum().to_array())
}

fn material_f64(r: Row, (m, l): &(Surface, Light)) -> Channels<f64> {
    let (n, ld, v) = surface_dirs64(r, m, r.dvec3(l.at));
    let light = r64::material::LightProps::from_f32(&props(r, l));
    ch3(r64::material::material_terms(&material64(r, m), &light, n, ld, v).sum().to_array())
}

/// Lighting maps' exercise 4 (emission map): the case's three texels as the chapter's maps,
/// 1×1 textures shaded at their centre by [`crate::maps::LightingMaps::shade`] (the bilinear
/// weights there are 1 and 0, so each texel comes back exactly), and the emission it
/// returns added to the terms without lighting.
fn emission_f32(r: Row, (m, l): &(Surface, Light)) -> Channels<f32> {
    let texel = |q| crate::maps::Texture::new(1, 1, vec![r.vec3(q)]).expect("one texel makes a 1x1 texture");
    let maps = crate::maps::LightingMaps {
        diffuse: texel(m.diffuse),
        specular: texel(m.specular),
        emission: Some(texel(fields::EMISSION)),
        shininess: r.float(m.shininess),
    };
    let (n, ld, v) = surface_dirs(r, m, r.vec3(l.at));
    let (terms, emission) = maps.shade(&props(r, l), Vec2::splat(0.5), n, ld, v);
    ch3((terms.sum() + emission).to_array())
}

/// [`emission_f32`] in the `f64` reference ([`r64::maps::LightingMaps::shade`]).
fn emission_f64(r: Row, (m, l): &(Surface, Light)) -> Channels<f64> {
    let texel = |q| r64::maps::Texture::new(1, 1, vec![r.dvec3(q)]).expect("one texel makes a 1x1 texture");
    let maps = r64::maps::LightingMaps {
        diffuse: texel(m.diffuse),
        specular: texel(m.specular),
        emission: Some(texel(fields::EMISSION)),
        shininess: r.float(m.shininess) as f64,
    };
    let (n, ld, v) = surface_dirs64(r, m, r.dvec3(l.at));
    let light = r64::material::LightProps::from_f32(&props(r, l));
    let (terms, emission) = maps.shade(&light, DVec2::splat(0.5), n, ld, v);
    ch3((terms.sum() + emission).to_array())
}

fn directional_f32(r: Row, (m, l): &(Surface, Light)) -> Channels<f32> {
    let (n, _, v) = surface_dirs(r, m, r.vec3(m.frag));
    let light = DirLight { direction: r.vec3(l.at), props: props(r, l) };
    ch3(light.terms(&material(r, m), n, v).sum().to_array())
}

fn directional_f64(r: Row, (m, l): &(Surface, Light)) -> Channels<f64> {
    let (n, _, v) = surface_dirs64(r, m, r.dvec3(m.frag));
    let light = r64::casters::DirLight::from_f32(&DirLight { direction: r.vec3(l.at), props: props(r, l) });
    ch3(light.terms(&material64(r, m), n, v).sum().to_array())
}

fn point_f32(r: Row, (m, l): &(Surface, Light)) -> Channels<f32> {
    let frag = r.vec3(m.frag);
    let (n, _, v) = surface_dirs(r, m, frag);
    ch3(point_light(r, l).terms(&material(r, m), n, frag, v).sum().to_array())
}

fn point_f64(r: Row, (m, l): &(Surface, Light)) -> Channels<f64> {
    let frag = r.dvec3(m.frag);
    let (n, _, v) = surface_dirs64(r, m, frag);
    let light = r64::casters::PointLight::from_f32(&point_light(r, l));
    ch3(light.terms(&material64(r, m), n, frag, v).sum().to_array())
}

/// The spotlight: the soft-edged result, then the hard cut-off's.
fn spot_f32(r: Row, (m, l): &(Surface, Light)) -> Channels<f32> {
    let frag = r.vec3(m.frag);
    let (n, _, v) = surface_dirs(r, m, frag);
    let (mat, light) = (material(r, m), spot_light(r, l));
    let soft = light.terms_keep_ambient(&mat, n, frag, v).sum();
    let hard = light.terms_hard_edge(&mat, n, frag, v).sum();
    ch6(soft.to_array(), hard.to_array())
}

fn spot_f64(r: Row, (m, l): &(Surface, Light)) -> Channels<f64> {
    let frag = r.dvec3(m.frag);
    let (n, _, v) = surface_dirs64(r, m, frag);
    let (mat, light) = (material64(r, m), r64::casters::SpotLight::from_f32(&spot_light(r, l)));
    let soft = light.terms_keep_ambient(&mat, n, frag, v).sum();
    let hard = light.terms_hard_edge(&mat, n, frag, v).sum();
    ch6(soft.to_array(), hard.to_array())
}

/// Gouraud (`to_world`: the position is `model·aPos`) and the normal-matrix model (the
/// position is already in world space): the normal goes through the normal matrix.
fn moved_f32(r: Row, f: &Basic, to_world: bool) -> Channels<f32> {
    let m = r.mat4(f.model());
    let frag = r.vec3(f.pos);
    let world = if to_world { m.transform_point3(frag) } else { frag };
    let nm = crate::normals::normal_matrix_inverse_transpose(Mat3::from_mat4(m));
    let n = nm.map_or(Vec3::ZERO, |nm| nm * r.vec3(f.normal));
    ch3(basic_f32(r, f, n, world).to_array())
}

fn moved_f64(r: Row, f: &Basic, to_world: bool) -> Channels<f64> {
    let m = r64::dmat4(r.mat4(f.model()));
    let frag = r.dvec3(f.pos);
    let world = if to_world { m.transform_point3(frag) } else { frag };
    let nm = r64::normals::normal_matrix_inverse_transpose(DMat3::from_mat4(m));
    let n = nm.map_or(DVec3::ZERO, |nm| nm * r.dvec3(f.normal));
    ch3(basic_f64(r, f, n, world).to_array())
}

impl CaseModel {
    /// The `f32` core's answer for one case (`scene` for `multiple_lights`).
    ///
    /// Every formula is the core's ([`crate::phong`], [`crate::material`],
    /// [`crate::casters`], [`crate::scene`], [`crate::models`]); this function only unpacks.
    pub fn eval_f32(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Channels<f32> {
        let r = Row(r);
        match self.id {
            ModelId::BasicLighting => {
                let f = &fields::BASIC;
                ch3(basic_f32(r, f, r.vec3(f.normal), r.vec3(f.pos)).to_array())
            }
            ModelId::Gouraud => moved_f32(r, &fields::GOURAUD, true),
            ModelId::NormalMatrix => moved_f32(r, &fields::NORMAL_MATRIX, false),
            ModelId::BlinnPhong => ch3(blinn_f32(r, &fields::BLINN_PHONG).to_array()),
            ModelId::Materials => material_f32(r, &fields::MATERIALS),
            ModelId::LightingMaps => material_f32(r, &fields::LIGHTING_MAPS),
            ModelId::LightingMapsEmission => emission_f32(r, &fields::LIGHTING_MAPS_EMISSION),
            ModelId::Directional => directional_f32(r, &fields::DIRECTIONAL),
            ModelId::Point => point_f32(r, &fields::POINT),
            ModelId::Spot => spot_f32(r, &fields::SPOT),
            ModelId::MultipleLights => {
                let m = &fields::MULTIPLE_LIGHTS;
                match scene {
                    Some(s) => ch3(s
                        .f32
                        .shade(&material(r, m), r.vec3(m.frag), r.vec3(m.normal), r.vec3(m.view_pos))
                        .rgb()
                        .to_array()),
                    None => [f32::NAN; MAX_CHANNELS],
                }
            }
            ModelId::OpenGLTutorial8 => {
                let f = &fields::OT8;
                ch3(ot8(r).terms(r.vec3(f.position), r.vec3(f.normal), Vec3::ZERO).sum().to_array())
            }
            ModelId::Ogldev19 => {
                let f = &fields::OGLDEV;
                ch3(ogldev(r).terms(r.vec3(f.world_pos), r.vec3(f.normal), r.vec3(f.eye_world_pos)).sum().to_array())
            }
        }
    }

    /// The `f64` reference's answer for one case ([`crate::reference`], inputs widened exactly).
    pub fn eval_f64(&self, r: &[[f32; 4]], scene: Option<&GroupScene>) -> Channels<f64> {
        let r = Row(r);
        match self.id {
            ModelId::BasicLighting => {
                let f = &fields::BASIC;
                ch3(basic_f64(r, f, r.dvec3(f.normal), r.dvec3(f.pos)).to_array())
            }
            ModelId::Gouraud => moved_f64(r, &fields::GOURAUD, true),
            ModelId::NormalMatrix => moved_f64(r, &fields::NORMAL_MATRIX, false),
            ModelId::BlinnPhong => ch3(blinn_f64(r, &fields::BLINN_PHONG).to_array()),
            ModelId::Materials => material_f64(r, &fields::MATERIALS),
            ModelId::LightingMaps => material_f64(r, &fields::LIGHTING_MAPS),
            ModelId::LightingMapsEmission => emission_f64(r, &fields::LIGHTING_MAPS_EMISSION),
            ModelId::Directional => directional_f64(r, &fields::DIRECTIONAL),
            ModelId::Point => point_f64(r, &fields::POINT),
            ModelId::Spot => spot_f64(r, &fields::SPOT),
            ModelId::MultipleLights => {
                let m = &fields::MULTIPLE_LIGHTS;
                match scene {
                    Some(s) => ch3(s
                        .f64
                        .shade(&material64(r, m), r.dvec3(m.frag), r.dvec3(m.normal), r.dvec3(m.view_pos))
                        .rgb()
                        .to_array()),
                    None => [f64::NAN; MAX_CHANNELS],
                }
            }
            ModelId::OpenGLTutorial8 => {
                let f = &fields::OT8;
                let model = r64::models::OpenGLTutorial::from_f32(&ot8(r));
                ch3(model.terms(r.dvec3(f.position), r.dvec3(f.normal), DVec3::ZERO).sum().to_array())
            }
            ModelId::Ogldev19 => {
                let f = &fields::OGLDEV;
                let model = r64::models::Ogldev::from_f32(&ogldev(r));
                ch3(model.terms(r.dvec3(f.world_pos), r.dvec3(f.normal), r.dvec3(f.eye_world_pos)).sum().to_array())
            }
        }
    }

    /// The compared channels of the shader's outputs for one case (`outs[m]` = output `m`):
    /// the first output's colour, and the second's for a model of six channels (spot).
    pub fn gl_channels(&self, outs: &[[f32; 4]]) -> Channels<f32> {
        let rgb = |o: [f32; 4]| [o[0], o[1], o[2]];
        if self.channels > 3 && outs.len() > 1 {
            ch6(rgb(outs[0]), rgb(outs[1]))
        } else {
            ch3(rgb(outs[0]))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::generate_cases;
    use super::*;

    /// The emission model's answers are Lighting maps' on the same first nine inputs (its
    /// layout extends Lighting maps' with the emission texel in input 9) plus the emission
    /// texel, unlit: in `f64` to rounding of the one sum, in `f32` likewise.
    #[test]
    fn the_emission_model_is_lighting_maps_plus_the_emission_texel_unlit() {
        let emission = ModelId::LightingMapsEmission.case_model();
        let maps = ModelId::LightingMaps.case_model();
        assert_eq!(maps.n_inputs, 9);
        let groups = generate_cases(emission, 2000, 7, &[]).unwrap();
        let mut seen = 0;
        for row in &groups[0].rows {
            let texel = Row(row).dvec3(fields::EMISSION);
            let (with, without) = (emission.eval_f64(row, None), maps.eval_f64(&row[..9], None));
            let (with32, without32) = (emission.eval_f32(row, None), maps.eval_f32(&row[..9], None));
            if !(without.iter().all(|x| x.is_finite())) {
                continue;
            }
            seen += 1;
            for c in 0..3 {
                let expected = without[c] + texel[c];
                assert!((with[c] - expected).abs() <= 1e-15 * expected.abs().max(1.0), "f64 {c}: {with:?} {expected}");
                let expected32 = without32[c] + texel[c] as f32;
                assert!((with32[c] - expected32).abs() <= 1e-6 * expected32.abs().max(1.0), "f32 {c}: {with32:?}");
            }
        }
        assert!(seen > 1900, "{seen} finite cases");
        assert!(groups[0].rows.iter().any(|r| Row(r).vec3(fields::EMISSION).max_element() > 0.5));
    }
}
