//! [`SceneDesc::to_toml`]: a description written back as a scene file.
//!
//! Numbers are written with Rust's shortest round-trip form, so reading the
//! file back gives the same `f32`s. A spot light keeps only the cosines of its
//! cut-offs; the writer prints the shortest decimal number of degrees whose
//! cosine (computed as [`SpotLight::new`] does) is that same `f32`.

use std::fmt::Write as _;

use glam::{Vec3, Vec4};

use super::{CameraDesc, MaterialDesc, MeshKind, SceneDesc};
use crate::casters::{Attenuation, SpotLight};
use crate::material::LightProps;
use crate::raster::rasterize::CullMode;

fn num(x: f32) -> String {
    let s = format!("{x:?}");
    // TOML floats need a digit after a decimal point and none of Rust's "inf"/"NaN"
    // (non-finite values never reach a SceneDesc that came from a scene file)
    if s.contains(['.', 'e']) || !x.is_finite() {
        s
    } else {
        format!("{s}.0")
    }
}

fn v3(v: Vec3) -> String {
    format!("[{}, {}, {}]", num(v.x), num(v.y), num(v.z))
}

fn v4(v: Vec4) -> String {
    format!("[{}, {}, {}, {}]", num(v.x), num(v.y), num(v.z), num(v.w))
}

/// The shortest decimal number of degrees `d` with `d.to_radians().cos() == cosine`,
/// or the nearest `f32` to `acos(cosine)` in degrees if no decimal up to 9 places reproduces it.
pub fn degrees_for_cosine(cosine: f32) -> f32 {
    let exact = (cosine as f64).clamp(-1.0, 1.0).acos().to_degrees();
    for places in 0..=9 {
        let scale = 10f64.powi(places);
        let d = ((exact * scale).round() / scale) as f32;
        if d.to_radians().cos() == cosine {
            return d;
        }
    }
    exact as f32
}

fn props(out: &mut String, p: &LightProps) {
    let _ = writeln!(out, "ambient = {}", v3(p.ambient));
    let _ = writeln!(out, "diffuse = {}", v3(p.diffuse));
    let _ = writeln!(out, "specular = {}", v3(p.specular));
}

fn attenuation(a: &Attenuation) -> String {
    format!("[{}, {}, {}]", num(a.constant), num(a.linear), num(a.quadratic))
}

fn spot(out: &mut String, s: &SpotLight) {
    let _ = writeln!(out, "\n[lights.spot]");
    let _ = writeln!(out, "position = {}", v3(s.position));
    let _ = writeln!(out, "direction = {}", v3(s.direction));
    let _ = writeln!(out, "cut_off_deg = {}", num(degrees_for_cosine(s.cut_off)));
    let _ = writeln!(out, "outer_cut_off_deg = {}", num(degrees_for_cosine(s.outer_cut_off)));
    let _ = writeln!(out, "attenuation = {}", attenuation(&s.attenuation));
    props(out, &s.props);
}

impl SceneDesc {
    /// The description as a scene file, opening with `header` (each line
    /// written as a `#` comment). Keys at their default are left out, except
    /// the lights, which are written in full so that every number can be edited.
    ///
    /// Reading the result back gives an equal [`SceneDesc`] when every spot
    /// cut-off is reproduced by [`degrees_for_cosine`] (true of every preset).
    pub fn to_toml(&self, header: &str) -> String {
        let mut out = String::new();
        for line in header.lines() {
            let _ = writeln!(out, "# {line}");
        }
        let _ = writeln!(out, "shading = \"{}\"", self.shading.name());
        if self.clear.w == 1.0 {
            let _ = writeln!(out, "clear = {}", v3(self.clear.truncate()));
        } else {
            let _ = writeln!(out, "clear = {}", v4(self.clear));
        }
        if !self.depth_test {
            let _ = writeln!(out, "depth_test = false");
        }
        if let CameraDesc::LookAt { eye, target, up, fovy_deg, near, far } = self.camera {
            let _ = writeln!(out, "\n[camera]");
            let _ = writeln!(out, "eye = {}", v3(eye));
            let _ = writeln!(out, "target = {}", v3(target));
            let _ = writeln!(out, "up = {}", v3(up));
            let _ = writeln!(out, "fovy_deg = {}", num(fovy_deg));
            let _ = writeln!(out, "near = {}", num(near));
            let _ = writeln!(out, "far = {}", num(far));
        }
        for o in &self.objects {
            let _ = writeln!(out, "\n[[object]]");
            let _ = writeln!(out, "mesh = \"{}\"", o.mesh.name());
            if let Some(d) = o.detail {
                let _ = writeln!(out, "detail = {d}");
            }
            if let Some(w) = o.normals {
                let _ = writeln!(out, "normals = \"{}\"", weighting_name(w));
            }
            if o.translate != Vec3::ZERO {
                let _ = writeln!(out, "translate = {}", v3(o.translate));
            }
            if o.rotate_deg != 0.0 || o.rotate_axis != Vec3::Y {
                let _ = writeln!(out, "rotate_deg = {}", num(o.rotate_deg));
                let _ = writeln!(out, "rotate_axis = {}", v3(o.rotate_axis));
            }
            if o.scale != Vec3::ONE {
                if o.scale.x == o.scale.y && o.scale.y == o.scale.z {
                    let _ = writeln!(out, "scale = {}", num(o.scale.x));
                } else {
                    let _ = writeln!(out, "scale = {}", v3(o.scale));
                }
            }
            let material = match &o.material {
                MaterialDesc::Coral => None,
                MaterialDesc::Classic(name) => Some(format!("\"{name}\"")),
                MaterialDesc::Custom(m) => Some(format!(
                    "{{ ambient = {}, diffuse = {}, specular = {}, shininess = {} }}",
                    v3(m.ambient),
                    v3(m.diffuse),
                    v3(m.specular),
                    num(m.shininess)
                )),
                MaterialDesc::Container { emission, shininess } => {
                    Some(format!("{{ maps = \"container\", emission = {emission}, shininess = {} }}", num(*shininess)))
                }
                MaterialDesc::Unlit(c) => Some(format!("{{ unlit = {} }}", v3(*c))),
            };
            if let Some(m) = material {
                let _ = writeln!(out, "material = {m}");
            }
            let cull = match o.cull {
                CullMode::Back => None,
                CullMode::None => Some("none"),
                CullMode::Front => Some("front"),
            };
            if let Some(c) = cull {
                let _ = writeln!(out, "cull = \"{c}\"");
            }
            if o.mesh == MeshKind::NdcQuad {
                let _ = writeln!(out, "# ndc-quad ignores the camera and the transform");
            }
        }
        self.write_lights(&mut out);
        out
    }

    fn write_lights(&self, out: &mut String) {
        let _ = writeln!(out, "\n[lights]");
        let _ = writeln!(out, "preset = \"none\"");
        let points = &self.lights.point_lights;
        let all =
            |f: &dyn Fn(usize) -> Option<Vec3>| (0..points.len()).all(|i| self.lamps.get(i).copied().flatten() == f(i));
        let mode = if points.is_empty() || all(&|_| None) {
            "none"
        } else if all(&|_| Some(Vec3::ONE)) {
            "white"
        } else if all(&|i| Some(points[i].props.diffuse)) {
            "light"
        } else {
            "none"
        };
        if mode != "none" {
            let _ = writeln!(out, "lamps = \"{mode}\"");
        }
        if self.lamp_scale != super::LAMP_SCALE {
            let _ = writeln!(out, "lamp_scale = {}", num(self.lamp_scale));
        }
        if let Some(d) = &self.lights.dir_light {
            let _ = writeln!(out, "\n[lights.dir]");
            let _ = writeln!(out, "direction = {}", v3(d.direction));
            props(out, &d.props);
        }
        for (i, p) in points.iter().enumerate() {
            let _ = writeln!(out, "\n[[lights.point]]");
            let _ = writeln!(out, "position = {}", v3(p.position));
            props(out, &p.props);
            let _ = writeln!(out, "attenuation = {}", attenuation(&p.attenuation));
            if mode == "none" {
                if let Some(c) = self.lamps.get(i).copied().flatten() {
                    let _ = writeln!(out, "lamp_color = {}", v3(c));
                }
            }
        }
        if let Some(s) = &self.lights.spot_light {
            spot(out, s);
        }
    }
}

/// The scene file's name for a vertex-normal weighting.
pub fn weighting_name(w: crate::normals::VertexWeighting) -> &'static str {
    use crate::normals::VertexWeighting as W;
    match w {
        W::Unweighted => "unweighted",
        W::Area => "area",
        W::Angle => "angle",
    }
}
