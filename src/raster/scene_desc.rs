//! What a scene file describes, as plain data: the presets are written as
//! [`SceneDesc`]s, scene files are read into one (`raster::scene_file`, feature `book`),
//! and [`SceneDesc::to_toml`] writes one back as a scene file
//! (`lightlab render --preset NAME --dump-scene`).
//!
//! | field | meaning |
//! | --- | --- |
//! | `shading` | where lighting is evaluated (flat, Gouraud, Phong, Blinn-Phong) |
//! | `clear` | the background, RGBA |
//! | `camera` | LearnOpenGL's camera or a look-at camera |
//! | `objects` | meshes with a transform `translate · rotate · scale`, a material and a cull mode |
//! | `lights` | the lights, summed as the Multiple lights shader does |
//! | `lamps` | per point light, the colour of its light cube (LearnOpenGL's lamp), or none |
//!
//! The format, key by key, is the book's appendix "Scene files".

use glam::{Mat4, Vec3, Vec4};

use super::camera::{Camera, CameraError};
use super::mesh::Mesh;
use super::pipeline::{Geometry, Object, World};
use super::rasterize::CullMode;
use super::shade::{ShadingMode, Surface};
use crate::material::{classic_material, Material};
use crate::normals::VertexWeighting;
use crate::scene::Scene;

mod write;
pub use write::{degrees_for_cosine, weighting_name};

/// The texel size of the procedural container maps scene files use.
pub const CONTAINER_MAP_SIZE: usize = 128;

/// LearnOpenGL's light-cube scale (`glm::scale(model, glm::vec3(0.2f))`).
pub const LAMP_SCALE: f32 = 0.2;

/// One image, as a scene file says it.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneDesc {
    /// Where lighting is evaluated.
    pub shading: ShadingMode,
    /// Background RGBA.
    pub clear: Vec4,
    /// Depth test on (the tutorials') or off (the benchmark quads).
    pub depth_test: bool,
    /// The camera.
    pub camera: CameraDesc,
    /// The lit (or unlit) objects, drawn in order, before the lamps.
    pub objects: Vec<ObjectDesc>,
    /// The lights.
    pub lights: Scene,
    /// One entry per point light: the colour of its lamp cube, or `None` for no lamp.
    pub lamps: Vec<Option<Vec3>>,
    /// The lamp cubes' scale (LearnOpenGL: [`LAMP_SCALE`]).
    pub lamp_scale: f32,
}

/// A camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraDesc {
    /// LearnOpenGL's: at (0, 0, 3) looking down −z, 45° vertical field of view, near 0.1, far 100.
    LearnOpenGL,
    /// `look_at(eye, target, up)` and `perspective(fovy_deg, aspect, near, far)`.
    LookAt {
        /// Eye position.
        eye: Vec3,
        /// Point looked at.
        target: Vec3,
        /// Up direction.
        up: Vec3,
        /// Vertical field of view, degrees.
        fovy_deg: f32,
        /// Near plane distance.
        near: f32,
        /// Far plane distance.
        far: f32,
    },
}

impl CameraDesc {
    /// The camera for an image of `aspect` = width / height; errors name the field.
    pub fn camera(&self, aspect: f32) -> Result<Camera, CameraError> {
        match *self {
            CameraDesc::LearnOpenGL => Ok(Camera::learnopengl(aspect)),
            CameraDesc::LookAt { eye, target, up, fovy_deg, near, far } => {
                Camera::new(eye, target, up, fovy_deg, aspect, near, far)
            }
        }
    }
}

crate::named::named_enum! {
    /// The meshes a scene file can name, in the order the appendix lists them.
    pub enum MeshKind {
        /// [`Mesh::benchmark_cube`].
        Cube => "cube",
        /// [`Mesh::learnopengl_cube`] (the tutorial's vertices, wound outward).
        LearnOpenGLCube => "learnopengl-cube",
        /// [`Mesh::uv_sphere`], `detail` stacks and `2 · detail` slices.
        UvSphere => "uv-sphere",
        /// [`Mesh::icosphere`], `detail` subdivisions.
        Icosphere => "icosphere",
        /// [`Mesh::plane`], `detail × detail` cells.
        Plane => "plane",
        /// [`Mesh::torus`] (radii 0.7 and 0.3), `detail` rings and `detail / 2` sides.
        Torus => "torus",
        /// The benchmark's full-screen quad ([`Geometry::NdcQuad`]); camera and transform are ignored.
        NdcQuad => "ndc-quad",
    }
}

impl MeshKind {
    /// The default `detail` and its allowed range (`None`: the mesh takes no detail).
    pub fn detail_range(self) -> Option<(u32, std::ops::RangeInclusive<u32>)> {
        match self {
            MeshKind::UvSphere => Some((32, 2..=512)),
            MeshKind::Icosphere => Some((3, 0..=7)),
            MeshKind::Plane => Some((8, 1..=1024)),
            MeshKind::Torus => Some((48, 6..=1024)),
            MeshKind::Cube | MeshKind::LearnOpenGLCube | MeshKind::NdcQuad => None,
        }
    }

    /// What `detail` counts, for messages and the appendix.
    pub fn detail_meaning(self) -> &'static str {
        match self {
            MeshKind::UvSphere => "stacks (slices = 2 × stacks)",
            MeshKind::Icosphere => "subdivisions",
            MeshKind::Plane => "cells per side",
            MeshKind::Torus => "rings (sides = rings / 2)",
            MeshKind::Cube | MeshKind::LearnOpenGLCube | MeshKind::NdcQuad => "nothing",
        }
    }

    /// The triangles of this mesh at `detail` (`None`: the kind's default), as its
    /// constructor makes them (an upper bound for the UV sphere, whose pole triangles are
    /// zero-area); 0 for the full-screen quad, which draws no mesh.
    pub fn triangles(self, detail: Option<u32>) -> u64 {
        let d = u64::from(detail.or(self.detail_range().map(|(d, _)| d)).unwrap_or(0));
        match self {
            MeshKind::Cube | MeshKind::LearnOpenGLCube => 12,
            MeshKind::NdcQuad => 0,
            MeshKind::UvSphere => 2 * d.max(1) * (2 * d).max(3),
            MeshKind::Icosphere => 20 * 4u64.saturating_pow(d.min(31) as u32),
            MeshKind::Plane => 2 * d.max(1) * d.max(1),
            MeshKind::Torus => 2 * d.max(3) * (d / 2).max(3),
        }
    }

    /// The mesh, with `detail` already checked against [`MeshKind::detail_range`].
    fn mesh(self, detail: Option<u32>) -> Option<Mesh> {
        let d = detail.or(self.detail_range().map(|(d, _)| d));
        Some(match self {
            MeshKind::Cube => Mesh::benchmark_cube(),
            MeshKind::LearnOpenGLCube => Mesh::learnopengl_cube(),
            MeshKind::UvSphere => Mesh::uv_sphere(d?, 2 * d?),
            MeshKind::Icosphere => Mesh::icosphere(d?),
            MeshKind::Plane => Mesh::plane(d?),
            MeshKind::Torus => Mesh::torus(0.7, 0.3, d?, d? / 2),
            MeshKind::NdcQuad => return None,
        })
    }
}

/// An object's reflectances.
#[derive(Clone, Debug, PartialEq)]
pub enum MaterialDesc {
    /// [`Material::coral`].
    Coral,
    /// A row of the classic materials table, by name (`gold`, `emerald`, …).
    Classic(String),
    /// Explicit reflectances.
    Custom(Material),
    /// The procedural container's diffuse and specular maps, with the
    /// emission map if `emission`, and this shininess.
    Container {
        /// Add the emission map (LearnOpenGL, Lighting maps exercise).
        emission: bool,
        /// Specular exponent.
        shininess: f32,
    },
    /// No lighting: this colour everywhere (LearnOpenGL's lamp shader).
    Unlit(Vec3),
}

impl MaterialDesc {
    /// The surface it draws with; `None` for an unknown classic name.
    pub fn surface(&self) -> Option<Surface> {
        Some(match self {
            MaterialDesc::Coral => Surface::Material(Material::coral()),
            MaterialDesc::Classic(name) => Surface::Material(classic_material(name)?.material()),
            MaterialDesc::Custom(m) => Surface::Material(*m),
            MaterialDesc::Container { emission, shininess } => {
                let mut maps = crate::maps::container(CONTAINER_MAP_SIZE, *emission).ok()?;
                maps.shininess = *shininess;
                Surface::Maps(maps, crate::maps::Sampler::LINEAR_REPEAT)
            }
            MaterialDesc::Unlit(c) => Surface::Unlit(*c),
        })
    }
}

/// One `[[object]]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ObjectDesc {
    /// Which mesh.
    pub mesh: MeshKind,
    /// Its detail, `None` for the kind's default.
    pub detail: Option<u32>,
    /// Recomputed vertex normals (welded first), or `None` to keep the mesh's.
    pub normals: Option<VertexWeighting>,
    /// Translation.
    pub translate: Vec3,
    /// Rotation angle, degrees, about `rotate_axis`.
    pub rotate_deg: f32,
    /// Rotation axis (any non-zero length; normalized when the matrix is made).
    pub rotate_axis: Vec3,
    /// Scale per axis.
    pub scale: Vec3,
    /// Reflectances.
    pub material: MaterialDesc,
    /// Face culling.
    pub cull: CullMode,
}

impl ObjectDesc {
    /// A `mesh` at the origin: no rotation, unit scale, coral, back faces culled
    /// (the scene file's defaults).
    pub fn new(mesh: MeshKind) -> ObjectDesc {
        ObjectDesc {
            mesh,
            detail: None,
            normals: None,
            translate: Vec3::ZERO,
            rotate_deg: 0.0,
            rotate_axis: Vec3::Y,
            scale: Vec3::ONE,
            material: MaterialDesc::Coral,
            cull: CullMode::Back,
        }
    }

    /// The model matrix.
    ///
    /// ```text
    /// model = translate(translate) · rotate(rotate_deg, normalize(rotate_axis)) · scale(scale)
    /// ```
    ///
    /// A zero or non-finite axis gives no rotation (scene files refuse it before this).
    pub fn model(&self) -> Mat4 {
        let rotation = match self.rotate_axis.try_normalize() {
            Some(axis) => Mat4::from_axis_angle(axis, self.rotate_deg.to_radians()),
            None => Mat4::IDENTITY,
        };
        Mat4::from_translation(self.translate) * rotation * Mat4::from_scale(self.scale)
    }

    /// The object to draw, or a reason naming the field (`detail`, `normals`, `material`).
    pub fn object(&self) -> Result<Object, (&'static str, String)> {
        if let (Some(d), Some((_, range))) = (self.detail, self.mesh.detail_range()) {
            if !range.contains(&d) {
                return Err(("detail", detail_message(self.mesh, &range, d)));
            }
        }
        let geometry = match self.mesh.mesh(self.detail) {
            None => Geometry::NdcQuad,
            Some(mesh) => Geometry::Mesh(match self.normals {
                None => mesh,
                Some(w) => mesh.welded().with_vertex_normals(w).map_err(|e| ("normals", e.to_string()))?,
            }),
        };
        let surface = self.material.surface().ok_or_else(|| ("material", "unknown material".to_string()))?;
        Ok(Object { geometry, model: self.model(), surface, cull: self.cull })
    }
}

/// The message for a `detail` outside its range.
pub(crate) fn detail_message(kind: MeshKind, range: &std::ops::RangeInclusive<u32>, got: u32) -> String {
    format!("{} takes {}..={} {}, got {got}", kind.name(), range.start(), range.end(), kind.detail_meaning())
}

/// Most objects a scene may hold (lamps not counted).
pub const MAX_OBJECTS: usize = 1024;

/// Most triangles a scene's meshes may hold in all, 2²²: one plane at its finest detail
/// (1024, about 2.1 M triangles) fits twice. 200 tori at detail 1024 (210 M
/// triangles) aborted at 2.6 GB; they are now refused before any mesh is made.
pub const MAX_TRIANGLES: u64 = 1 << 22;

/// The first object whose mesh takes the scene past [`MAX_TRIANGLES`], with the running
/// total there; `None` when the scene fits.
pub fn over_triangle_budget<'a>(objects: impl IntoIterator<Item = &'a ObjectDesc>) -> Option<(usize, u64)> {
    let mut total = 0u64;
    for (i, o) in objects.into_iter().enumerate() {
        total = total.saturating_add(o.mesh.triangles(o.detail));
        if total > MAX_TRIANGLES {
            return Some((i, total));
        }
    }
    None
}

/// The reason for an object that takes the scene to `total` triangles.
pub(crate) fn budget_message(total: u64) -> String {
    format!(
        "the scene's meshes reach {total} triangles here, above the limit of {MAX_TRIANGLES}: lower the detail or use \
         fewer objects"
    )
}

/// A [`SceneDesc`] that cannot make a [`World`]: the field path and the reason.
#[derive(Clone, Debug, PartialEq)]
pub struct DescError {
    /// The field (`camera.near`, `object[2].detail`).
    pub field: String,
    /// What is wrong.
    pub reason: String,
}

impl std::fmt::Display for DescError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.reason)
    }
}

impl std::error::Error for DescError {}

impl SceneDesc {
    /// A scene with LearnOpenGL's camera, Phong shading, a 0.1 grey background,
    /// depth test on, no objects, no lights and no lamps.
    pub fn empty() -> SceneDesc {
        SceneDesc {
            shading: ShadingMode::Phong,
            clear: Vec4::new(0.1, 0.1, 0.1, 1.0),
            depth_test: true,
            camera: CameraDesc::LearnOpenGL,
            objects: Vec::new(),
            lights: Scene {
                dir_light: None,
                point_lights: Vec::new(),
                spot_light: None,
                clear_color: Vec3::splat(0.1),
            },
            lamps: Vec::new(),
            lamp_scale: LAMP_SCALE,
        }
    }

    /// Draw a white lamp cube at every point light (LearnOpenGL's lamp shader, `FragColor = vec4(1.0)`).
    pub fn with_white_lamps(mut self) -> SceneDesc {
        self.lamps = vec![Some(Vec3::ONE); self.lights.point_lights.len()];
        self
    }

    /// Draw a lamp cube at every point light in its light's diffuse colour
    /// (the Multiple lights atmospheres colour their lamps this way).
    pub fn with_light_coloured_lamps(mut self) -> SceneDesc {
        self.lamps = self.lights.point_lights.iter().map(|p| Some(p.props.diffuse)).collect();
        self
    }

    /// The lamp objects: LearnOpenGL's cube, scaled by `lamp_scale`, at each
    /// point light that has a lamp colour, unlit, drawn without culling.
    pub fn lamp_objects(&self) -> Vec<Object> {
        self.lights
            .point_lights
            .iter()
            .zip(&self.lamps)
            .filter_map(|(light, colour)| {
                let colour = (*colour)?;
                Some(Object {
                    geometry: Geometry::Mesh(Mesh::learnopengl_cube()),
                    model: Mat4::from_translation(light.position) * Mat4::from_scale(Vec3::splat(self.lamp_scale)),
                    surface: Surface::Unlit(colour),
                    cull: CullMode::None,
                })
            })
            .collect()
    }

    /// The world to render at `aspect` = width / height: the objects, then the
    /// lamps. Errors name the field (`camera.near`, `object[1].detail`).
    pub fn to_world(&self, aspect: f32) -> Result<World, DescError> {
        let camera = self
            .camera
            .camera(aspect)
            .map_err(|e| DescError { field: format!("camera.{}", e.field), reason: e.reason })?;
        if self.objects.len() > MAX_OBJECTS {
            return Err(DescError {
                field: "object".into(),
                reason: format!("{} objects, above the limit of {MAX_OBJECTS}", self.objects.len()),
            });
        }
        if let Some((i, total)) = over_triangle_budget(&self.objects) {
            return Err(DescError { field: format!("object[{i}].detail"), reason: budget_message(total) });
        }
        let mut objects = Vec::with_capacity(self.objects.len() + self.lamps.len());
        for (i, o) in self.objects.iter().enumerate() {
            objects.push(o.object().map_err(|(f, reason)| DescError { field: format!("object[{i}].{f}"), reason })?);
        }
        objects.extend(self.lamp_objects());
        Ok(World {
            camera,
            lights: self.lights.clone(),
            objects,
            shading: self.shading,
            clear: self.clear,
            depth_test: self.depth_test,
            range_window: None,
            specialisations: crate::raster::kernel::Specialisations::ALL,
        })
    }
}
