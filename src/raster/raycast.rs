//! The ray-cast ground truth: analytic spheres, planes and boxes in `f64`, exact normals.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `origin`, `dir` | the eye ray through a sample point of a pixel (unit `dir`) |
//! | `t` | ray parameter of the nearest hit, `t > 0` |
//! | `n` | the exact unit surface normal at the hit, facing the ray's side for planes |
//! | `samples` | `s × s` stratified sample centres per pixel (supersampling) |
//!
//! Shading is the Multiple lights sum written again in `f64` (dir light,
//! point lights, spot, each `ambient + diffuse + specular`, × attenuation
//! (× intensity)), with the same [`Scene`] lights and [`Material`]s as the
//! rasterizer, converted to `f64` once. It never calls the `f32` shading code,
//! so the rasterizer's error can be measured against it.
//!
//! Source: Whitted 1980 (eye rays); LearnOpenGL, Multiple lights (the sum).

use glam::{DMat3, DMat4, DVec3, DVec4, Vec4};

use super::camera::Camera;
use super::framebuffer::Framebuffer;
use super::kernel::Specular;
use crate::material::Material;
use crate::scene::Scene;

/// An analytic surface.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A sphere.
    Sphere {
        /// Centre.
        center: DVec3,
        /// Radius (> 0; otherwise never hit).
        radius: f64,
    },
    /// An infinite plane through `point` with normal `normal` (two-sided).
    Plane {
        /// A point on the plane.
        point: DVec3,
        /// Its normal (need not be unit; zero means never hit).
        normal: DVec3,
    },
    /// The box `[−½, ½]³` under an affine `model` matrix (the cube of the tutorials).
    Box {
        /// Object → world (must be invertible; otherwise never hit).
        model: DMat4,
    },
}

/// A shape and its material.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayObject {
    /// The surface.
    pub shape: Shape,
    /// Its reflectances.
    pub material: Material,
}

/// A nearest hit: distance along the ray, unit normal, object index.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hit {
    /// Ray parameter.
    pub t: f64,
    /// Unit normal at the hit.
    pub n: DVec3,
    /// Which object.
    pub object: usize,
}

impl Shape {
    /// The nearest `t > 1e-9` where the ray meets the shape, with the outward
    /// unit normal (planes: the normal facing the ray origin). `None` if missed
    /// or degenerate.
    pub fn intersect(&self, origin: DVec3, dir: DVec3) -> Option<(f64, DVec3)> {
        const EPS: f64 = 1e-9;
        match *self {
            Shape::Sphere { center, radius } => {
                if radius.is_nan() || radius <= 0.0 {
                    return None;
                }
                let oc = origin - center;
                let b = oc.dot(dir);
                let c = oc.length_squared() - radius * radius;
                let disc = b * b - c;
                if disc < 0.0 {
                    return None;
                }
                let sq = disc.sqrt();
                // the root of smaller magnitude computed without cancellation
                let q = -b - sq.copysign(b);
                let (t0, t1) = if q != 0.0 { (q.min(c / q), q.max(c / q)) } else { (0.0, 0.0) };
                let t = if t0 > EPS {
                    t0
                } else if t1 > EPS {
                    t1
                } else {
                    return None;
                };
                Some((t, (origin + t * dir - center) / radius))
            }
            Shape::Plane { point, normal } => {
                let n = normal.try_normalize()?;
                let denom = n.dot(dir);
                if denom == 0.0 {
                    return None;
                }
                let t = n.dot(point - origin) / denom;
                (t > EPS).then_some((t, if denom < 0.0 { n } else { -n }))
            }
            Shape::Box { model } => {
                let inv = model.inverse();
                if !inv.is_finite() || model.determinant() == 0.0 {
                    return None;
                }
                let o = inv.transform_point3(origin);
                let d = inv.transform_vector3(dir);
                let (mut t_near, mut t_far) = (f64::NEG_INFINITY, f64::INFINITY);
                let (mut axis_near, mut axis_far) = (0usize, 0usize);
                for k in 0..3 {
                    if d[k] == 0.0 {
                        if o[k].abs() > 0.5 {
                            return None;
                        }
                        continue;
                    }
                    let (a, b) = ((-0.5 - o[k]) / d[k], (0.5 - o[k]) / d[k]);
                    let (lo, hi) = (a.min(b), a.max(b));
                    if lo > t_near {
                        t_near = lo;
                        axis_near = k;
                    }
                    if hi < t_far {
                        t_far = hi;
                        axis_far = k;
                    }
                }
                if t_near > t_far {
                    return None;
                }
                let (t, axis) = if t_near > EPS {
                    (t_near, axis_near)
                } else if t_far > EPS {
                    (t_far, axis_far)
                } else {
                    return None;
                };
                let mut n_obj = DVec3::ZERO;
                n_obj[axis] = (o[axis] + t * d[axis]).signum();
                let normal_matrix = DMat3::from_mat4(inv).transpose();
                Some((t, (normal_matrix * n_obj).try_normalize()?))
            }
        }
    }
}

/// The f64 lights: the [`Scene`] converted once.
struct Lights64 {
    scene: Scene,
}

/// The Multiple lights sum in `f64` at point `p` with unit normal `n`, seen from `eye`:
/// the ground truth the rasterizer's `f32` shading is measured against.
///
/// ```text
/// Σ_lights (ambient ⊙ ka + diffuse ⊙ kd · max(n·l, 0) + specular ⊙ ks · pow(max(v·r, 0), s)) · attenuation · intensity
/// ```
///
/// `n` must be unit length (it is used as given). Degenerate input as the
/// shader: a zero `eye − p` or `light − p` direction gives ambient only.
pub fn shade_f64(scene: &Scene, material: &Material, p: DVec3, n: DVec3, eye: DVec3, specular: Specular) -> DVec3 {
    Lights64 { scene: scene.clone() }.shade(material, p, n, eye, specular)
}

fn v64(v: glam::Vec3) -> DVec3 {
    v.as_dvec3()
}

fn pow_or_zero(x: f64, y: f64) -> f64 {
    if x > 0.0 || (x == 0.0 && y > 0.0) {
        x.powf(y)
    } else {
        0.0
    }
}

impl Lights64 {
    /// The Multiple lights sum at `p` with unit normal `n`, in f64.
    fn shade(&self, m: &Material, p: DVec3, n: DVec3, eye: DVec3, specular: Specular) -> DVec3 {
        let view_dir = (eye - p).normalize_or_zero();
        let (ka, kd, ks, s) = (v64(m.ambient), v64(m.diffuse), v64(m.specular), m.shininess as f64);
        let lobe = |l: DVec3| -> f64 {
            let base = match specular {
                Specular::Phong => {
                    let r = 2.0 * n.dot(l) * n - l;
                    view_dir.dot(r)
                }
                Specular::Blinn => n.dot((l + view_dir).normalize_or_zero()),
            };
            pow_or_zero(base.max(0.0), s)
        };
        let terms = |l: DVec3, props: &crate::material::LightProps| -> DVec3 {
            let diff = n.dot(l).max(0.0);
            v64(props.ambient) * ka + v64(props.diffuse) * kd * diff + v64(props.specular) * ks * lobe(l)
        };
        let mut sum = DVec3::ZERO;
        if let Some(d) = &self.scene.dir_light {
            sum += terms((-v64(d.direction)).normalize_or_zero(), &d.props);
        }
        let attenuation = |a: &crate::casters::Attenuation, dist: f64| {
            1.0 / (a.constant as f64 + a.linear as f64 * dist + a.quadratic as f64 * dist * dist)
        };
        for pl in &self.scene.point_lights {
            let to = v64(pl.position) - p;
            sum += terms(to.normalize_or_zero(), &pl.props) * attenuation(&pl.attenuation, to.length());
        }
        if let Some(sp) = &self.scene.spot_light {
            let to = v64(sp.position) - p;
            let l = to.normalize_or_zero();
            let theta = l.dot((-v64(sp.direction)).normalize_or_zero());
            let (inner, outer) = (sp.cut_off as f64, sp.outer_cut_off as f64);
            let epsilon = inner - outer;
            let intensity = if epsilon > 0.0 {
                ((theta - outer) / epsilon).clamp(0.0, 1.0)
            } else if theta > outer {
                1.0
            } else {
                0.0
            };
            sum += terms(l, &sp.props) * attenuation(&sp.attenuation, to.length()) * intensity;
        }
        sum
    }
}

/// A ray-cast image: f64 linear RGBA per pixel, top row first (alpha = covered fraction).
#[derive(Clone, Debug, PartialEq)]
pub struct RayImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// RGBA per pixel; RGB is the average over the samples, background where missed.
    pub color: Vec<[f64; 4]>,
}

impl RayImage {
    /// The image in a float [`Framebuffer`] (values rounded to f32).
    pub fn to_framebuffer(&self) -> Framebuffer {
        let mut fb = Framebuffer::new(self.width, self.height).expect("a RayImage has a valid size");
        for (dst, src) in fb.color.iter_mut().zip(&self.color) {
            *dst = src.map(|v| v as f32);
        }
        fb
    }
}

/// What to ray-cast.
#[derive(Clone, Debug, PartialEq)]
pub struct RayScene {
    /// The camera (same matrices as the rasterizer's).
    pub camera: Camera,
    /// The lights.
    pub lights: Scene,
    /// The objects.
    pub objects: Vec<RayObject>,
    /// Background (RGBA) where a sample misses.
    pub clear: Vec4,
    /// The specular lobe.
    pub specular: Specular,
}

impl RayScene {
    /// The nearest hit of a ray, or `None`.
    pub fn hit(&self, origin: DVec3, dir: DVec3) -> Option<Hit> {
        let mut best: Option<Hit> = None;
        for (object, o) in self.objects.iter().enumerate() {
            if let Some((t, n)) = o.shape.intersect(origin, dir) {
                if best.is_none_or(|b| t < b.t) {
                    best = Some(Hit { t, n, object });
                }
            }
        }
        best
    }

    /// Cast `samples × samples` rays per pixel (`samples` 0 is taken as 1).
    ///
    /// Sample `(a, b)` of pixel `(i, j)` (window coordinates, y up) is at
    /// `(i + (a + ½)/s, j + (b + ½)/s)`; with `s = 1` it is the pixel centre,
    /// where the rasterizer samples too. Errors name the field for a zero or
    /// oversized `width`/`height`.
    pub fn render(&self, width: u32, height: u32, samples: u32) -> Result<RayImage, super::framebuffer::SizeError> {
        Framebuffer::new(width, height)?;
        let s = samples.max(1);
        let inv_vp = (self.camera.projection.as_dmat4() * self.camera.view.as_dmat4()).inverse();
        let eye = self.camera.eye.as_dvec3();
        let lights = Lights64 { scene: self.lights.clone() };
        let clear = self.clear.as_dvec4();
        let mut color = Vec::with_capacity(width as usize * height as usize);
        for row in 0..height {
            let j = (height - 1 - row) as f64;
            for i in 0..width {
                let mut acc = DVec4::ZERO;
                for a in 0..s {
                    for b in 0..s {
                        let x = i as f64 + (a as f64 + 0.5) / s as f64;
                        let y = j + (b as f64 + 0.5) / s as f64;
                        let ndc_x = 2.0 * x / width as f64 - 1.0;
                        let ndc_y = 2.0 * y / height as f64 - 1.0;
                        let near = inv_vp.project_point3(DVec3::new(ndc_x, ndc_y, -1.0));
                        let far = inv_vp.project_point3(DVec3::new(ndc_x, ndc_y, 1.0));
                        let dir = (far - near).normalize_or_zero();
                        acc += match self.hit(near, dir) {
                            Some(h) => {
                                let p = near + h.t * dir;
                                let m = &self.objects[h.object].material;
                                lights.shade(m, p, h.n, eye, self.specular).extend(1.0)
                            }
                            None => DVec4::new(clear.x, clear.y, clear.z, 0.0),
                        };
                    }
                }
                color.push((acc / (s * s) as f64).to_array());
            }
        }
        Ok(RayImage { width, height, color })
    }
}
