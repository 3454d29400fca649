//! Scene files: a small TOML description of one image (mesh, transform,
//! material, lights, camera, shading mode), no more than a scene needs.
//!
//! ```toml
//! shading = "phong"                 # flat | gouraud | phong | blinn-phong (default phong)
//! clear = [0.1, 0.1, 0.1]           # default 0.1 grey
//!
//! [camera]                          # default: LearnOpenGL's, at (0, 0, 3) looking down -z
//! eye = [2.0, 1.5, 4.0]
//! target = [0.0, 0.0, 0.0]
//! fovy_deg = 45.0                   # also: up, near, far
//!
//! [[object]]
//! mesh = "uv-sphere"                # cube | learnopengl-cube | uv-sphere | icosphere | plane | torus
//! detail = 32                       # stacks / subdivisions / cells / rings
//! normals = "mesh"                  # mesh | unweighted | area | angle
//! translate = [0.0, 0.0, 0.0]
//! rotate_deg = 30.0
//! rotate_axis = [0.0, 1.0, 0.0]
//! scale = 1.0
//! material = "gold"                 # coral, container, a classic-table name, or a table:
//! # material = { ambient = [..], diffuse = [..], specular = [..], shininess = 32.0 }
//! cull = "back"                     # back | none (default back)
//!
//! [lights]
//! preset = "learnopengl"            # learnopengl | desert | factory | horror | biochemical-lab | none
//! [[lights.point]]
//! position = [1.2, 1.0, 2.0]
//! ambient = [0.2, 0.2, 0.2]
//! diffuse = [0.5, 0.5, 0.5]
//! specular = [1.0, 1.0, 1.0]
//! attenuation = [1.0, 0.09, 0.032]
//! # [lights.dir]: direction, ambient, diffuse, specular
//! # [lights.spot]: position, direction, cut_off_deg, outer_cut_off_deg, attenuation, ambient, diffuse, specular
//! ```
//!
//! A bad file is an error naming its line and the field (`line 12: object[0].mesh: unknown mesh "cubee"`).

use glam::{Mat4, Vec3, Vec4};
use serde::Deserialize;
use toml::Spanned;

use super::camera::Camera;
use super::mesh::Mesh;
use super::pipeline::{Geometry, Object, World};
use super::rasterize::CullMode;
use super::shade::{ShadingMode, Surface};
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{classic_material, LightProps, Material};
use crate::normals::VertexWeighting;
use crate::scene::{Atmosphere, Scene};

/// A scene-file error: line (1-based, when known), field path and reason.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFileError {
    /// The line the problem is on, if known.
    pub line: Option<usize>,
    /// The field, as a path (`object[0].mesh`).
    pub field: String,
    /// What is wrong.
    pub reason: String,
}

impl std::fmt::Display for SceneFileError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self.line {
            Some(l) => write!(f, "line {l}: {}: {}", self.field, self.reason),
            None => write!(f, "{}: {}", self.field, self.reason),
        }
    }
}

impl std::error::Error for SceneFileError {}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSpec {
    shading: Option<Spanned<String>>,
    clear: Option<[f32; 3]>,
    camera: Option<Spanned<CameraSpec>>,
    #[serde(default)]
    object: Vec<Spanned<ObjectSpec>>,
    lights: Option<LightsSpec>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct CameraSpec {
    eye: [f32; 3],
    target: [f32; 3],
    up: Option<[f32; 3]>,
    fovy_deg: Option<f32>,
    near: Option<f32>,
    far: Option<f32>,
}

#[derive(Deserialize)]
#[serde(untagged)]
enum Scale {
    Uniform(f32),
    Axes([f32; 3]),
}

#[derive(Deserialize)]
#[serde(untagged)]
enum MaterialSpec {
    Named(String),
    Table { ambient: [f32; 3], diffuse: [f32; 3], specular: [f32; 3], shininess: f32 },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct ObjectSpec {
    mesh: Spanned<String>,
    detail: Option<u32>,
    normals: Option<Spanned<String>>,
    translate: Option<[f32; 3]>,
    rotate_deg: Option<f32>,
    rotate_axis: Option<[f32; 3]>,
    scale: Option<Scale>,
    material: Option<Spanned<MaterialSpec>>,
    cull: Option<Spanned<String>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightsSpec {
    preset: Option<Spanned<String>>,
    dir: Option<DirSpec>,
    #[serde(default)]
    point: Vec<PointSpec>,
    spot: Option<Spanned<SpotSpec>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DirSpec {
    direction: [f32; 3],
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PointSpec {
    position: [f32; 3],
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
    attenuation: Option<Spanned<[f32; 3]>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpotSpec {
    position: [f32; 3],
    direction: [f32; 3],
    cut_off_deg: f32,
    outer_cut_off_deg: f32,
    attenuation: Option<Spanned<[f32; 3]>>,
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
}

struct Source<'a>(&'a str);

impl Source<'_> {
    fn line(&self, offset: usize) -> usize {
        self.0[..offset.min(self.0.len())].bytes().filter(|&b| b == b'\n').count() + 1
    }

    fn err<T>(
        &self,
        span: std::ops::Range<usize>,
        field: impl Into<String>,
        reason: impl Into<String>,
    ) -> Result<T, SceneFileError> {
        Err(SceneFileError { line: Some(self.line(span.start)), field: field.into(), reason: reason.into() })
    }
}

fn v3(a: [f32; 3]) -> Vec3 {
    Vec3::from_array(a)
}

/// Parse a scene file's text into a [`World`] for an image of `aspect` = width / height.
pub fn parse(text: &str, aspect: f32) -> Result<World, SceneFileError> {
    let src = Source(text);
    let spec: FileSpec = toml::from_str(text).map_err(|e| {
        let line = e.span().map(|s| src.line(s.start));
        let message = e.message().trim().to_string();
        // serde names the offending key in its message ("unknown field `x`", "missing field `y`")
        SceneFileError { line, field: field_of(text, e.span()), reason: message }
    })?;
    let shading = match &spec.shading {
        None => ShadingMode::Phong,
        Some(s) => match ShadingMode::from_name(s.get_ref()) {
            Some(m) => m,
            None => {
                return src.err(
                    s.span(),
                    "shading",
                    format!("unknown mode {:?}; use flat, gouraud, phong or blinn-phong", s.get_ref()),
                )
            }
        },
    };
    let camera = match &spec.camera {
        None => Camera::learnopengl(aspect),
        Some(c) => {
            let span = c.span();
            let c = c.get_ref();
            Camera::new(
                v3(c.eye),
                v3(c.target),
                c.up.map(v3).unwrap_or(Vec3::Y),
                c.fovy_deg.unwrap_or(45.0),
                aspect,
                c.near.unwrap_or(0.1),
                c.far.unwrap_or(100.0),
            )
            .or_else(|e| src.err(span, format!("camera.{}", e.field), e.reason))?
        }
    };
    let lights = lights(&src, spec.lights.as_ref())?;
    if spec.object.is_empty() {
        return Err(SceneFileError {
            line: None,
            field: "object".into(),
            reason: "the scene needs at least one [[object]]".into(),
        });
    }
    let objects = spec.object.iter().enumerate().map(|(i, o)| object(&src, i, o)).collect::<Result<Vec<_>, _>>()?;
    let clear = spec.clear.map(v3).unwrap_or(Vec3::splat(0.1));
    Ok(World { camera, lights, objects, shading, clear: Vec4::new(clear.x, clear.y, clear.z, 1.0), depth_test: true })
}

/// The key at the start of an error span, for serde's messages that do not name it.
fn field_of(text: &str, span: Option<std::ops::Range<usize>>) -> String {
    let Some(span) = span else { return "file".into() };
    let line_start = text[..span.start.min(text.len())].rfind('\n').map_or(0, |i| i + 1);
    let line_end = text[line_start..].find('\n').map_or(text.len(), |i| line_start + i);
    let line = text[line_start..line_end].trim();
    match line.split_once('=') {
        Some((key, _)) => key.trim().to_string(),
        None => line.trim_matches(|c| c == '[' || c == ']').to_string(),
    }
}

fn attenuation(src: &Source, field: &str, a: &Option<Spanned<[f32; 3]>>) -> Result<Attenuation, SceneFileError> {
    match a {
        None => Ok(Attenuation::LEARNOPENGL),
        Some(s) => {
            let [c, l, q] = *s.get_ref();
            Attenuation::new(c, l, q).or_else(|e| src.err(s.span(), format!("{field}.attenuation"), e.to_string()))
        }
    }
}

fn lights(src: &Source, spec: Option<&LightsSpec>) -> Result<Scene, SceneFileError> {
    let Some(spec) = spec else { return Ok(Scene::learnopengl_default()) };
    let mut scene = match &spec.preset {
        None => Scene { dir_light: None, point_lights: Vec::new(), spot_light: None, clear_color: Vec3::splat(0.1) },
        Some(p) => match p.get_ref().as_str() {
            "learnopengl" => Scene::learnopengl_default(),
            "none" => {
                Scene { dir_light: None, point_lights: Vec::new(), spot_light: None, clear_color: Vec3::splat(0.1) }
            }
            other => match Atmosphere::from_name(other) {
                Some(a) => a.scene(),
                None => return src.err(p.span(), "lights.preset", format!("unknown preset {other:?}")),
            },
        },
    };
    let props = |a: [f32; 3], d: [f32; 3], s: [f32; 3]| LightProps { ambient: v3(a), diffuse: v3(d), specular: v3(s) };
    if let Some(d) = &spec.dir {
        scene.dir_light = Some(DirLight { direction: v3(d.direction), props: props(d.ambient, d.diffuse, d.specular) });
    }
    for (i, p) in spec.point.iter().enumerate() {
        scene.point_lights.push(PointLight {
            position: v3(p.position),
            attenuation: attenuation(src, &format!("lights.point[{i}]"), &p.attenuation)?,
            props: props(p.ambient, p.diffuse, p.specular),
        });
    }
    if let Some(s) = &spec.spot {
        let span = s.span();
        let s = s.get_ref();
        let att = attenuation(src, "lights.spot", &s.attenuation)?;
        let light = SpotLight::new(
            v3(s.position),
            v3(s.direction),
            s.cut_off_deg,
            s.outer_cut_off_deg,
            att,
            props(s.ambient, s.diffuse, s.specular),
        );
        scene.spot_light = Some(light.or_else(|e| src.err(span, format!("lights.spot.{}", e.field), e.reason))?);
    }
    Ok(scene)
}

fn object(src: &Source, i: usize, spanned: &Spanned<ObjectSpec>) -> Result<Object, SceneFileError> {
    let o = spanned.get_ref();
    let field = |f: &str| format!("object[{i}].{f}");
    let detail = o.detail;
    let mesh = match o.mesh.get_ref().as_str() {
        "cube" => Mesh::benchmark_cube(),
        "learnopengl-cube" => Mesh::learnopengl_cube(),
        "uv-sphere" => {
            let s = detail.unwrap_or(32).clamp(2, 512);
            Mesh::uv_sphere(s, 2 * s)
        }
        "icosphere" => Mesh::icosphere(detail.unwrap_or(3)),
        "plane" => Mesh::plane(detail.unwrap_or(8).clamp(1, 1024)),
        "torus" => {
            let r = detail.unwrap_or(48).clamp(3, 1024);
            Mesh::torus(0.7, 0.3, r, r / 2)
        }
        other => {
            return src.err(
                o.mesh.span(),
                field("mesh"),
                format!("unknown mesh {other:?}; use cube, learnopengl-cube, uv-sphere, icosphere, plane or torus"),
            )
        }
    };
    let mesh = match &o.normals {
        None => mesh,
        Some(n) => {
            let weighting = match n.get_ref().as_str() {
                "mesh" => None,
                "unweighted" => Some(VertexWeighting::Unweighted),
                "area" => Some(VertexWeighting::Area),
                "angle" => Some(VertexWeighting::Angle),
                other => {
                    return src.err(
                        n.span(),
                        field("normals"),
                        format!("unknown weighting {other:?}; use mesh, unweighted, area or angle"),
                    )
                }
            };
            match weighting {
                None => mesh,
                Some(w) => mesh
                    .welded()
                    .with_vertex_normals(w)
                    .or_else(|e| src.err(n.span(), field("normals"), e.to_string()))?,
            }
        }
    };
    let surface = match &o.material {
        None => Surface::Material(Material::coral()),
        Some(m) => match m.get_ref() {
            MaterialSpec::Named(name) => match name.as_str() {
                "coral" => Surface::Material(Material::coral()),
                "container" => {
                    Surface::Maps(crate::maps::container(128, false).expect("128 is a valid container size"))
                }
                other => match classic_material(other) {
                    Some(c) => Surface::Material(c.material()),
                    None => return src.err(m.span(), field("material"), format!("unknown material {other:?}")),
                },
            },
            MaterialSpec::Table { ambient, diffuse, specular, shininess } => {
                if !(shininess.is_finite() && *shininess >= 0.0) {
                    return src.err(
                        m.span(),
                        field("material.shininess"),
                        format!("must be finite and >= 0, got {shininess}"),
                    );
                }
                Surface::Material(Material {
                    ambient: v3(*ambient),
                    diffuse: v3(*diffuse),
                    specular: v3(*specular),
                    shininess: *shininess,
                })
            }
        },
    };
    let cull = match &o.cull {
        None => CullMode::Back,
        Some(c) => match c.get_ref().as_str() {
            "back" => CullMode::Back,
            "none" => CullMode::None,
            other => return src.err(c.span(), field("cull"), format!("unknown mode {other:?}; use back or none")),
        },
    };
    let scale = match &o.scale {
        None => Vec3::ONE,
        Some(Scale::Uniform(s)) => Vec3::splat(*s),
        Some(Scale::Axes(a)) => v3(*a),
    };
    let axis = o.rotate_axis.map(v3).unwrap_or(Vec3::Y);
    let Some(axis) = axis.try_normalize() else {
        return src.err(spanned.span(), field("rotate_axis"), "must be a non-zero finite vector");
    };
    let model = Mat4::from_translation(o.translate.map(v3).unwrap_or(Vec3::ZERO))
        * Mat4::from_axis_angle(axis, o.rotate_deg.unwrap_or(0.0).to_radians())
        * Mat4::from_scale(scale);
    Ok(Object { geometry: Geometry::Mesh(mesh), model, surface, cull })
}

/// Read and parse a scene file; errors name the file, line and field.
pub fn load(path: &std::path::Path, aspect: f32) -> Result<World, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse(&text, aspect).map_err(|e| format!("{}: {e}", path.display()).into())
}
