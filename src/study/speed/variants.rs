//! The shading variants the study swaps in: `pow` evaluations, normalizations and the scalar shader that combines them (scalar f32, written out so each approximation can be swapped in).

use glam::Vec3;

use crate::casters::Attenuation;
use crate::material::{LightProps, Material};
use crate::raster::kernel::{pow_or_zero, Specular};
use crate::scene::Scene;

/// How `pow(base, shininess)` is evaluated for `base ∈ [0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub enum PowMethod {
    /// `f32::powf` (0 for a base ≤ 0).
    Powf,
    /// A table of `base^s` at `n` evenly spaced bases in [0, 1], linearly
    /// interpolated, in the manner of Mesa's fixed-function shininess table.
    Lut(Vec<f32>),
    /// Schlick 1994: `x / (s − s·x + x)`, a rational stand-in for `x^s`.
    Schlick,
    /// `exp2(s · log2 x)` with polynomial `exp2` and `log2` ([`pow_or_zero`] of the kernel).
    Exp2Log2,
}

impl PowMethod {
    /// A lookup table of `entries` values of `x^shininess` (`entries` below 2 is raised to 2).
    pub fn lut(entries: usize, shininess: f32) -> PowMethod {
        let n = entries.max(2);
        PowMethod::Lut((0..n).map(|k| (k as f32 / (n - 1) as f32).powf(shininess)).collect())
    }

    /// `base^s` for `base ≥ 0` (a negative or NaN base gives 0, as the shaders' clamp).
    pub fn eval(&self, base: f32, s: f32) -> f32 {
        if base.is_nan() || base <= 0.0 {
            return 0.0;
        }
        match self {
            PowMethod::Powf => base.powf(s),
            PowMethod::Lut(table) => {
                let f = base.min(1.0) * (table.len() - 1) as f32;
                let k = (f as usize).min(table.len() - 2);
                let t = f - k as f32;
                table[k] + t * (table[k + 1] - table[k])
            }
            PowMethod::Schlick => base / (s - s * base + base),
            PowMethod::Exp2Log2 => pow_or_zero(base, s),
        }
    }
}

/// How vectors are normalized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Normalize {
    /// `v / |v|` (glam's `normalize_or_zero`).
    Exact,
    /// `v · r` with `r` the magic-constant estimate of `1/√(v·v)` (Lomont's
    /// `0x5f375a86`) refined by one Newton step: relative error below 2e-3.
    RsqrtNewton,
}

/// `1/√x` by the magic-constant estimate and one Newton step; 0 for `x ≤ 0` or non-finite `x`.
pub fn rsqrt_newton(x: f32) -> f32 {
    if !(x > 0.0 && x.is_finite()) {
        return 0.0;
    }
    let y = f32::from_bits(0x5f37_5a86 - (x.to_bits() >> 1));
    y * (1.5 - 0.5 * x * y * y)
}

impl Normalize {
    fn apply(self, v: Vec3) -> Vec3 {
        match self {
            Normalize::Exact => v.normalize_or_zero(),
            Normalize::RsqrtNewton => v * rsqrt_newton(v.length_squared()),
        }
    }

    fn length(self, v: Vec3) -> f32 {
        match self {
            Normalize::Exact => v.length(),
            Normalize::RsqrtNewton => v.length_squared() * rsqrt_newton(v.length_squared()),
        }
    }
}

/// The Multiple lights sum in `f32` with a choice of `pow`, normalize and lobe.
///
/// Same formula as [`crate::scene::Scene::shade`] (and the `f64` [`crate::raster::raycast::shade_f64`]); with
/// [`PowMethod::Powf`] and [`Normalize::Exact`] it is the plain shader.
#[derive(Clone, Debug, PartialEq)]
pub struct VariantShader {
    /// The lights.
    pub scene: Scene,
    /// The material.
    pub material: Material,
    /// The eye (`viewPos`).
    pub eye: Vec3,
    /// `pow` method.
    pub pow: PowMethod,
    /// Normalize method.
    pub normalize: Normalize,
    /// Specular lobe.
    pub specular: Specular,
}

impl VariantShader {
    /// Shade one fragment at `p` with (not necessarily unit) normal `n`.
    pub fn shade(&self, p: Vec3, n: Vec3) -> Vec3 {
        let nz = self.normalize;
        let n = nz.apply(n);
        let view_dir = nz.apply(self.eye - p);
        let m = &self.material;
        let s = m.shininess;
        let term = |l: Vec3, props: &LightProps| -> Vec3 {
            let diff = n.dot(l).max(0.0);
            let base = match self.specular {
                Specular::Phong => view_dir.dot(2.0 * n.dot(l) * n - l),
                Specular::Blinn => n.dot(nz.apply(l + view_dir)),
            };
            let spec = self.pow.eval(base.max(0.0), s);
            props.ambient * m.ambient + props.diffuse * m.diffuse * diff + props.specular * m.specular * spec
        };
        let attenuation = |a: &Attenuation, d: f32| 1.0 / (a.constant + a.linear * d + a.quadratic * d * d);
        let mut sum = Vec3::ZERO;
        if let Some(d) = &self.scene.dir_light {
            sum += term(nz.apply(-d.direction), &d.props);
        }
        for pl in &self.scene.point_lights {
            let to = pl.position - p;
            sum += term(nz.apply(to), &pl.props) * attenuation(&pl.attenuation, nz.length(to));
        }
        if let Some(sp) = &self.scene.spot_light {
            let to = sp.position - p;
            let l = nz.apply(to);
            let theta = l.dot(nz.apply(-sp.direction));
            let epsilon = sp.cut_off - sp.outer_cut_off;
            let intensity = if epsilon > 0.0 {
                ((theta - sp.outer_cut_off) / epsilon).clamp(0.0, 1.0)
            } else if theta > sp.outer_cut_off {
                1.0
            } else {
                0.0
            };
            sum += term(l, &sp.props) * attenuation(&sp.attenuation, nz.length(to)) * intensity;
        }
        sum
    }
}
