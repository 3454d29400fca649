//! Scene files: a small TOML description of one image (meshes, transforms,
//! materials, lights, lamps, camera, shading mode), read into a [`SceneDesc`].
//!
//! ```toml
//! shading = "phong"                 # flat | gouraud | phong | blinn-phong
//!
//! [[object]]
//! mesh = "learnopengl-cube"
//! material = "gold"
//!
//! [lights]
//! preset = "learnopengl"            # none | learnopengl | desert | factory | horror | biochemical-lab
//! lamps = "white"                   # none | white | light
//!
//! [[lights.point]]
//! index = 0                         # change the preset's first point light
//! position = [2.0, 1.0, 0.0]
//! ```
//!
//! Every key, its default and an example are in the book's appendix "Scene
//! files". A bad file is an error naming its line and the field, in the
//! file's own words: `line 12: object[0].mesh: unknown mesh "cubee"; use cube,
//! learnopengl-cube, …`. Unknown keys, vectors of the wrong length, NaN or
//! infinite numbers, negative colours, zero directions and out-of-range
//! details are all errors.

use std::collections::BTreeMap;
use std::ops::Range;

use glam::{Vec3, Vec4};
use toml::de::{DeTable, DeValue};
use toml::Spanned;

use super::pipeline::World;
use super::rasterize::CullMode;
use super::scene_desc::{
    budget_message, detail_message, over_triangle_budget, CameraDesc, MaterialDesc, MeshKind, ObjectDesc, SceneDesc,
    LAMP_SCALE, MAX_OBJECTS,
};
use super::shade::ShadingMode;
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

type Value<'i> = Spanned<DeValue<'i>>;
type R<T> = Result<T, SceneFileError>;

/// The source text, for turning byte offsets into line numbers.
struct Src<'a>(&'a str);

impl Src<'_> {
    fn line(&self, offset: usize) -> usize {
        let end = offset.min(self.0.len());
        self.0.as_bytes()[..end].iter().filter(|&&b| b == b'\n').count() + 1
    }

    fn err<T>(&self, span: Range<usize>, field: &str, reason: impl Into<String>) -> R<T> {
        Err(SceneFileError { line: Some(self.line(span.start)), field: field.to_string(), reason: reason.into() })
    }
}

/// A table's entries by key, after checking that every key is one of `allowed`.
struct Table<'t, 'i> {
    path: String,
    span: Range<usize>,
    entries: BTreeMap<&'t str, &'t Value<'i>>,
}

impl<'t, 'i> Table<'t, 'i> {
    fn new(src: &Src, value: &'t Value<'i>, path: &str, allowed: &[&str], what: &str) -> R<Table<'t, 'i>> {
        let Some(table) = value.get_ref().as_table() else {
            return src.err(value.span(), path, format!("expected a table ({what}), got {}", kind(value.get_ref())));
        };
        let mut entries = BTreeMap::new();
        let mut keys: Vec<_> = table.iter().collect();
        keys.sort_by_key(|(k, _)| k.span().start);
        for (key, v) in keys {
            let name: &'t str = key.get_ref().as_ref();
            if !allowed.contains(&name) {
                let field = if path.is_empty() { name.to_string() } else { format!("{path}.{name}") };
                return src.err(
                    key.span(),
                    &field,
                    format!("unknown key {name:?} in {what}; the keys are {}", allowed.join(", ")),
                );
            }
            entries.insert(name, v);
        }
        Ok(Table { path: path.to_string(), span: value.span(), entries })
    }

    fn field(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    fn get(&self, key: &str) -> Option<&'t Value<'i>> {
        self.entries.get(key).copied()
    }

    fn require(&self, src: &Src, key: &str) -> R<&'t Value<'i>> {
        match self.get(key) {
            Some(v) => Ok(v),
            None => src.err(self.span.clone(), &self.field(key), "missing; this table needs it"),
        }
    }

    /// The value of `key`: read with `read` when the table gives it, else the preset
    /// light's (`base`), else an error naming it as missing.
    fn given_or<T>(&self, src: &Src, key: &str, base: Option<T>, read: fn(&Src, &Value, &str) -> R<T>) -> R<T> {
        match (self.get(key), base) {
            (Some(v), _) => read(src, v, &self.field(key)),
            (None, Some(b)) => Ok(b),
            (None, None) => read(src, self.require(src, key)?, &self.field(key)),
        }
    }
}

fn kind(v: &DeValue) -> &'static str {
    match v {
        DeValue::String(_) => "a string",
        DeValue::Integer(_) => "an integer",
        DeValue::Float(_) => "a number",
        DeValue::Boolean(_) => "true/false",
        DeValue::Datetime(_) => "a date",
        DeValue::Array(_) => "a list",
        DeValue::Table(_) => "a table",
    }
}

/// A number (TOML integer or float) as f64, or `None` if the value is not one.
fn as_number(v: &DeValue) -> Option<f64> {
    match v {
        DeValue::Integer(i) => i64::from_str_radix(&i.as_str().replace('_', ""), i.radix()).ok().map(|n| n as f64),
        DeValue::Float(f) => {
            let s = f.as_str().replace('_', "");
            match s.trim_start_matches(['+', '-']) {
                "inf" => Some(if s.starts_with('-') { f64::NEG_INFINITY } else { f64::INFINITY }),
                "nan" => Some(f64::NAN),
                _ => s.parse().ok(),
            }
        }
        _ => None,
    }
}

fn number(src: &Src, v: &Value, field: &str) -> R<f32> {
    let Some(x) = as_number(v.get_ref()) else {
        return src.err(v.span(), field, format!("expected a number, got {}", kind(v.get_ref())));
    };
    let x32 = x as f32;
    if !x32.is_finite() {
        return src.err(v.span(), field, format!("must be a finite number, got {x}"));
    }
    Ok(x32)
}

fn string<'v>(src: &Src, v: &'v Value, field: &str) -> R<&'v str> {
    match v.get_ref().as_str() {
        Some(s) => Ok(s),
        None => src.err(v.span(), field, format!("expected a string in quotes, got {}", kind(v.get_ref()))),
    }
}

fn boolean(src: &Src, v: &Value, field: &str) -> R<bool> {
    match v.get_ref().as_bool() {
        Some(b) => Ok(b),
        None => src.err(v.span(), field, format!("expected true or false, got {}", kind(v.get_ref()))),
    }
}

fn numbers<const N: usize>(src: &Src, v: &Value, field: &str, shape: &str) -> R<[f32; N]> {
    let Some(items) = v.get_ref().as_array() else {
        return src.err(v.span(), field, format!("expected {N} numbers {shape}, got {}", kind(v.get_ref())));
    };
    if items.len() != N {
        return src.err(v.span(), field, format!("expected {N} numbers {shape}, got {}", items.len()));
    }
    let mut out = [0.0; N];
    for (k, item) in items.iter().enumerate() {
        out[k] = number(src, item, &format!("{field}[{k}]"))?;
    }
    Ok(out)
}

fn vec3(src: &Src, v: &Value, field: &str) -> R<Vec3> {
    Ok(Vec3::from_array(numbers::<3>(src, v, field, "[x, y, z]")?))
}

fn direction(src: &Src, v: &Value, field: &str) -> R<Vec3> {
    let d = vec3(src, v, field)?;
    if d.try_normalize().is_none() {
        return src.err(v.span(), field, "a direction cannot be [0, 0, 0]");
    }
    Ok(d)
}

fn colour(src: &Src, v: &Value, field: &str) -> R<Vec3> {
    let c = Vec3::from_array(numbers::<3>(src, v, field, "[r, g, b]")?);
    if c.min_element() < 0.0 {
        return src.err(v.span(), field, format!("colours cannot be negative, got {}", show(c)));
    }
    Ok(c)
}

fn show(v: Vec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

fn positive(src: &Src, v: &Value, field: &str) -> R<f32> {
    let x = number(src, v, field)?;
    if x <= 0.0 {
        return src.err(v.span(), field, format!("must be > 0, got {x}"));
    }
    Ok(x)
}

fn name_of<T: Copy>(src: &Src, v: &Value, field: &str, what: &str, options: &[(&str, T)]) -> R<T> {
    let s = string(src, v, field)?;
    match options.iter().find(|(n, _)| *n == s) {
        Some((_, t)) => Ok(*t),
        None => {
            let names: Vec<&str> = options.iter().map(|(n, _)| *n).collect();
            src.err(v.span(), field, format!("unknown {what} {s:?}; use {}", names.join(", ")))
        }
    }
}

/// Parse a scene file's text into a [`SceneDesc`].
pub fn parse_desc(text: &str) -> R<SceneDesc> {
    let src = Src(text);
    let doc = DeTable::parse(text).map_err(|e| SceneFileError {
        line: e.span().map(|s| src.line(s.start)),
        field: "TOML".into(),
        reason: e.message().trim().to_string(),
    })?;
    let root_value: Value = Spanned::new(doc.span(), DeValue::Table(doc.into_inner()));
    let top = Table::new(
        &src,
        &root_value,
        "",
        &["shading", "clear", "depth_test", "camera", "object", "lights"],
        "the scene file's top level",
    )?;
    let mut desc = SceneDesc::empty();
    if let Some(v) = top.get("shading") {
        let modes: Vec<(&str, ShadingMode)> = ShadingMode::ALL.iter().map(|m| (m.name(), *m)).collect();
        desc.shading = name_of(&src, v, "shading", "shading mode", &modes)?;
    }
    if let Some(v) = top.get("depth_test") {
        desc.depth_test = boolean(&src, v, "depth_test")?;
    }
    if let Some(v) = top.get("camera") {
        desc.camera = camera(&src, v)?;
    }
    let (lights, lamps, lamp_scale) = match top.get("lights") {
        None => (Scene::learnopengl_default(), vec![None; 4], LAMP_SCALE),
        Some(v) => lights(&src, v)?,
    };
    desc.clear = lights.clear_color.extend(1.0);
    if let Some(v) = top.get("clear") {
        desc.clear = clear(&src, v)?;
    }
    desc.lights = Scene { clear_color: desc.clear.truncate(), ..lights };
    desc.lamps = lamps;
    desc.lamp_scale = lamp_scale;
    let Some(objects) = top.get("object") else {
        return Err(SceneFileError {
            line: None,
            field: "object".into(),
            reason: "the scene needs at least one [[object]] table".into(),
        });
    };
    let Some(items) = objects.get_ref().as_array() else {
        return src.err(objects.span(), "object", "write objects as [[object]] tables");
    };
    if items.is_empty() {
        return src.err(objects.span(), "object", "the scene needs at least one [[object]] table");
    }
    if items.len() > MAX_OBJECTS {
        return src.err(
            objects.span(),
            "object",
            format!("{} [[object]] tables, above the limit of {MAX_OBJECTS}", items.len()),
        );
    }
    for (i, o) in items.iter().enumerate() {
        desc.objects.push(object(&src, o, i)?);
    }
    // Before any mesh is made: a scene of huge meshes is refused, not aborted.
    if let Some((i, total)) = over_triangle_budget(&desc.objects) {
        return src.err(items[i].span(), &format!("object[{i}].detail"), budget_message(total));
    }
    Ok(desc)
}

/// Parse a scene file's text into a [`World`] for an image of `aspect` = width / height.
pub fn parse(text: &str, aspect: f32) -> R<World> {
    let desc = parse_desc(text)?;
    desc.to_world(aspect).map_err(|e| SceneFileError { line: None, field: e.field, reason: e.reason })
}

fn clear(src: &Src, v: &Value) -> R<Vec4> {
    let n = v.get_ref().as_array().map_or(0, |a| a.len());
    let c = if n == 4 {
        Vec4::from_array(numbers::<4>(src, v, "clear", "[r, g, b] or [r, g, b, a]")?)
    } else {
        Vec3::from_array(numbers::<3>(src, v, "clear", "[r, g, b] or [r, g, b, a]")?).extend(1.0)
    };
    if c.min_element() < 0.0 {
        return src.err(v.span(), "clear", "colours cannot be negative");
    }
    Ok(c)
}

fn camera(src: &Src, v: &Value) -> R<CameraDesc> {
    let t = Table::new(src, v, "camera", &["eye", "target", "up", "fovy_deg", "near", "far"], "[camera]")?;
    let eye = vec3(src, t.require(src, "eye")?, "camera.eye")?;
    let target = vec3(src, t.require(src, "target")?, "camera.target")?;
    let up = match t.get("up") {
        Some(v) => direction(src, v, "camera.up")?,
        None => Vec3::Y,
    };
    let get = |key: &str, default: f32| match t.get(key) {
        Some(v) => positive(src, v, &t.field(key)),
        None => Ok(default),
    };
    let desc = CameraDesc::LookAt {
        eye,
        target,
        up,
        fovy_deg: get("fovy_deg", 45.0)?,
        near: get("near", 0.1)?,
        far: get("far", 100.0)?,
    };
    // the aspect does not change which parameters are valid
    if let Err(e) = desc.camera(4.0 / 3.0) {
        let at = t.get(e.field).map_or(t.span.clone(), |v| v.span());
        return src.err(at, &format!("camera.{}", e.field), e.reason);
    }
    Ok(desc)
}

fn object(src: &Src, v: &Value, i: usize) -> R<ObjectDesc> {
    let path = format!("object[{i}]");
    let keys = ["mesh", "detail", "normals", "translate", "rotate_deg", "rotate_axis", "scale", "material", "cull"];
    let t = Table::new(src, v, &path, &keys, "an [[object]]")?;
    let meshes: Vec<(&str, MeshKind)> = MeshKind::ALL.iter().map(|k| (k.name(), *k)).collect();
    let mesh = name_of(src, t.require(src, "mesh")?, &t.field("mesh"), "mesh", &meshes)?;
    let mut o = ObjectDesc::new(mesh);
    if let Some(v) = t.get("detail") {
        let field = t.field("detail");
        let Some((_, range)) = mesh.detail_range() else {
            return src.err(v.span(), &field, format!("{} takes no detail", mesh.name()));
        };
        let n = match as_number(v.get_ref()) {
            Some(n) if v.get_ref().is_integer() => n,
            _ => return src.err(v.span(), &field, format!("expected a whole number, got {}", kind(v.get_ref()))),
        };
        if n < 0.0 || n > u32::MAX as f64 || !range.contains(&(n as u32)) {
            return src.err(v.span(), &field, detail_message(mesh, &range, n.clamp(0.0, u32::MAX as f64) as u32));
        }
        o.detail = Some(n as u32);
    }
    if let Some(v) = t.get("normals") {
        let options = [
            ("mesh", None),
            ("unweighted", Some(VertexWeighting::Unweighted)),
            ("area", Some(VertexWeighting::Area)),
            ("angle", Some(VertexWeighting::Angle)),
        ];
        o.normals = name_of(src, v, &t.field("normals"), "weighting", &options)?;
        if o.normals.is_some() && mesh == MeshKind::NdcQuad {
            return src.err(v.span(), &t.field("normals"), "ndc-quad has no mesh normals to recompute");
        }
    }
    if let Some(v) = t.get("translate") {
        o.translate = vec3(src, v, &t.field("translate"))?;
    }
    if let Some(v) = t.get("rotate_deg") {
        o.rotate_deg = number(src, v, &t.field("rotate_deg"))?;
    }
    if let Some(v) = t.get("rotate_axis") {
        o.rotate_axis = direction(src, v, &t.field("rotate_axis"))?;
    }
    if let Some(v) = t.get("scale") {
        let field = t.field("scale");
        o.scale = if v.get_ref().is_array() {
            Vec3::from_array(numbers::<3>(src, v, &field, "[x, y, z] (or one number)")?)
        } else {
            Vec3::splat(number(src, v, &field)?)
        };
    }
    if let Some(v) = t.get("material") {
        o.material = material(src, v, &t.field("material"))?;
    }
    if let Some(v) = t.get("cull") {
        let options = [("back", CullMode::Back), ("none", CullMode::None), ("front", CullMode::Front)];
        o.cull = name_of(src, v, &t.field("cull"), "cull mode", &options)?;
    }
    Ok(o)
}

fn material(src: &Src, v: &Value, field: &str) -> R<MaterialDesc> {
    if let Some(name) = v.get_ref().as_str() {
        return match name {
            "coral" => Ok(MaterialDesc::Coral),
            "container" => Ok(MaterialDesc::Container { emission: false, shininess: 32.0 }),
            other if classic_material(other).is_some() => Ok(MaterialDesc::Classic(other.to_string())),
            other => src.err(
                v.span(),
                field,
                format!(
                    "unknown material {other:?}; use coral, container, a name from the classic materials table \
                     (gold, emerald, …) or a table {{ ambient = [..], diffuse = [..], specular = [..], shininess = .. }}"
                ),
            ),
        };
    }
    let Some(table) = v.get_ref().as_table() else {
        return src.err(
            v.span(),
            field,
            format!("expected a material name in quotes or a table {{ .. }}, got {}", kind(v.get_ref())),
        );
    };
    let has = |k: &str| table.iter().any(|(key, _)| AsRef::<str>::as_ref(key.get_ref()) == k);
    let shininess = |t: &Table, default: Option<f32>| -> R<f32> {
        let s = match (t.get("shininess"), default) {
            (Some(v), _) => number(src, v, &t.field("shininess"))?,
            (None, Some(d)) => d,
            (None, None) => number(src, t.require(src, "shininess")?, &t.field("shininess"))?,
        };
        if s < 0.0 {
            return src.err(
                t.get("shininess").map_or(t.span.clone(), |v| v.span()),
                &t.field("shininess"),
                "must be >= 0",
            );
        }
        Ok(s)
    };
    if has("maps") {
        let t = Table::new(src, v, field, &["maps", "emission", "shininess"], "a lighting-maps material")?;
        let maps = t.require(src, "maps")?;
        if string(src, maps, &t.field("maps"))? != "container" {
            return src.err(maps.span(), &t.field("maps"), "the only maps are \"container\"");
        }
        let emission = match t.get("emission") {
            Some(e) => boolean(src, e, &t.field("emission"))?,
            None => false,
        };
        return Ok(MaterialDesc::Container { emission, shininess: shininess(&t, Some(32.0))? });
    }
    if has("unlit") {
        let t = Table::new(src, v, field, &["unlit"], "an unlit material")?;
        return Ok(MaterialDesc::Unlit(colour(src, t.require(src, "unlit")?, &t.field("unlit"))?));
    }
    let t = Table::new(
        src,
        v,
        field,
        &["ambient", "diffuse", "specular", "shininess"],
        "a material table (or use maps = \"container\", or unlit = [r, g, b])",
    )?;
    let c = |k: &str| colour(src, t.require(src, k)?, &t.field(k));
    Ok(MaterialDesc::Custom(Material {
        ambient: c("ambient")?,
        diffuse: c("diffuse")?,
        specular: c("specular")?,
        shininess: shininess(&t, None)?,
    }))
}

type Lights = (Scene, Vec<Option<Vec3>>, f32);

fn lights(src: &Src, v: &Value) -> R<Lights> {
    let t = Table::new(src, v, "lights", &["preset", "lamps", "lamp_scale", "dir", "point", "spot"], "[lights]")?;
    let empty = Scene { dir_light: None, point_lights: Vec::new(), spot_light: None, clear_color: Vec3::splat(0.1) };
    let mut scene = match t.get("preset") {
        None => empty,
        Some(p) => match string(src, p, "lights.preset")? {
            "none" => empty,
            "learnopengl" => Scene::learnopengl_default(),
            other => match Atmosphere::from_name(other) {
                Some(a) => a.scene(),
                None => {
                    return src.err(
                        p.span(),
                        "lights.preset",
                        format!(
                        "unknown preset {other:?}; use none, learnopengl, desert, factory, horror or biochemical-lab"
                    ),
                    )
                }
            },
        },
    };
    #[derive(Clone, Copy, PartialEq)]
    enum Lamps {
        None,
        White,
        Light,
    }
    let mode = match t.get("lamps") {
        None => Lamps::None,
        Some(v) => name_of(
            src,
            v,
            "lights.lamps",
            "lamp mode",
            &[("none", Lamps::None), ("white", Lamps::White), ("light", Lamps::Light)],
        )?,
    };
    let lamp_scale = match t.get("lamp_scale") {
        None => LAMP_SCALE,
        Some(v) => positive(src, v, "lights.lamp_scale")?,
    };
    if let Some(v) = t.get("dir") {
        dir(src, v, &mut scene.dir_light)?;
    }
    // point lights: the preset's, edited by index or switched off, then the new ones
    let mut points: Vec<Option<PointLight>> = scene.point_lights.iter().copied().map(Some).collect();
    let mut lamp_colours: Vec<Option<Vec3>> = vec![None; points.len()];
    if let Some(list) = t.get("point") {
        let Some(items) = list.get_ref().as_array() else {
            return src.err(list.span(), "lights.point", "write point lights as [[lights.point]] tables");
        };
        let preset_count = points.len();
        for (i, item) in items.iter().enumerate() {
            point(src, item, i, preset_count, &mut points, &mut lamp_colours)?;
        }
    }
    let mut lamps = Vec::new();
    scene.point_lights.clear();
    for (p, c) in points.into_iter().zip(lamp_colours) {
        let Some(p) = p else { continue };
        let default = match mode {
            Lamps::None => None,
            Lamps::White => Some(Vec3::ONE),
            Lamps::Light => Some(p.props.diffuse),
        };
        lamps.push(c.or(default));
        scene.point_lights.push(p);
    }
    if let Some(v) = t.get("spot") {
        spot(src, v, &mut scene.spot_light)?;
    }
    Ok((scene, lamps, lamp_scale))
}

/// Read `ambient`, `diffuse`, `specular` over `base` (all three required when there is no base).
fn props(src: &Src, t: &Table, base: Option<LightProps>) -> R<LightProps> {
    let get = |k: &str, b: Option<Vec3>| match (t.get(k), b) {
        (Some(v), _) => colour(src, v, &t.field(k)),
        (None, Some(b)) => Ok(b),
        (None, None) => colour(src, t.require(src, k)?, &t.field(k)),
    };
    Ok(LightProps {
        ambient: get("ambient", base.map(|b| b.ambient))?,
        diffuse: get("diffuse", base.map(|b| b.diffuse))?,
        specular: get("specular", base.map(|b| b.specular))?,
    })
}

fn off(src: &Src, t: &Table) -> R<bool> {
    match t.get("off") {
        Some(v) => boolean(src, v, &t.field("off")),
        None => Ok(false),
    }
}

fn attenuation(src: &Src, t: &Table, base: Option<Attenuation>) -> R<Attenuation> {
    match t.get("attenuation") {
        None => Ok(base.unwrap_or(Attenuation::LEARNOPENGL)),
        Some(v) => {
            let field = t.field("attenuation");
            let [c, l, q] = numbers::<3>(src, v, &field, "[constant, linear, quadratic]")?;
            Attenuation::new(c, l, q).or_else(|e| src.err(v.span(), &field, e.to_string()))
        }
    }
}

fn dir(src: &Src, v: &Value, light: &mut Option<DirLight>) -> R<()> {
    let keys = ["direction", "ambient", "diffuse", "specular", "off"];
    let t = Table::new(src, v, "lights.dir", &keys, "[lights.dir]")?;
    if off(src, &t)? {
        *light = None;
        return Ok(());
    }
    let base = *light;
    let direction = t.given_or(src, "direction", base.map(|b| b.direction), direction)?;
    *light = Some(DirLight { direction, props: props(src, &t, base.map(|b| b.props))? });
    Ok(())
}

fn point(
    src: &Src,
    v: &Value,
    i: usize,
    preset_count: usize,
    points: &mut Vec<Option<PointLight>>,
    lamp_colours: &mut Vec<Option<Vec3>>,
) -> R<()> {
    let path = format!("lights.point[{i}]");
    let keys = ["index", "position", "ambient", "diffuse", "specular", "attenuation", "lamp_color", "off"];
    let t = Table::new(src, v, &path, &keys, "a [[lights.point]]")?;
    let slot = match t.get("index") {
        None => None,
        Some(iv) => {
            let n = match as_number(iv.get_ref()) {
                Some(n) if iv.get_ref().is_integer() => n,
                _ => return src.err(iv.span(), &t.field("index"), "expected a whole number"),
            };
            if n < 0.0 || n as usize >= preset_count {
                let have = match preset_count {
                    0 => "the preset has no point lights (leave index out to add one)".to_string(),
                    c => format!("the preset's point lights are 0..={}", c - 1),
                };
                return src.err(iv.span(), &t.field("index"), format!("no point light {n}; {have}"));
            }
            Some(n as usize)
        }
    };
    let lamp = match t.get("lamp_color") {
        Some(c) => Some(colour(src, c, &t.field("lamp_color"))?),
        None => None,
    };
    if off(src, &t)? {
        match slot {
            Some(k) => points[k] = None,
            None => return src.err(t.span.clone(), &t.field("off"), "off = true needs the index of a preset light"),
        }
        return Ok(());
    }
    let base = slot.and_then(|k| points[k]);
    let position = t.given_or(src, "position", base.map(|b| b.position), vec3)?;
    let light = PointLight {
        position,
        attenuation: attenuation(src, &t, base.map(|b| b.attenuation))?,
        props: props(src, &t, base.map(|b| b.props))?,
    };
    match slot {
        Some(k) => {
            points[k] = Some(light);
            if lamp.is_some() {
                lamp_colours[k] = lamp;
            }
        }
        None => {
            points.push(Some(light));
            lamp_colours.push(lamp);
        }
    }
    Ok(())
}

fn spot(src: &Src, v: &Value, light: &mut Option<SpotLight>) -> R<()> {
    let keys = [
        "position",
        "direction",
        "cut_off_deg",
        "outer_cut_off_deg",
        "attenuation",
        "ambient",
        "diffuse",
        "specular",
        "off",
    ];
    let t = Table::new(src, v, "lights.spot", &keys, "[lights.spot]")?;
    if off(src, &t)? {
        *light = None;
        return Ok(());
    }
    let base = *light;
    let position = t.given_or(src, "position", base.map(|b| b.position), vec3)?;
    let dir_value = t.get("direction");
    let direction = t.given_or(src, "direction", base.map(|b| b.direction), direction)?;
    let attenuation = attenuation(src, &t, base.map(|b| b.attenuation))?;
    let props = props(src, &t, base.map(|b| b.props))?;
    let (inner, outer) = (t.get("cut_off_deg"), t.get("outer_cut_off_deg"));
    let spot = match (inner, outer, base) {
        (None, None, Some(b)) => {
            let direction = if dir_value.is_some() { direction.normalize() } else { b.direction };
            SpotLight { position, direction, attenuation, props, ..b }
        }
        (Some(i), Some(o), _) => {
            let (i_deg, o_deg) =
                (number(src, i, "lights.spot.cut_off_deg")?, number(src, o, "lights.spot.outer_cut_off_deg")?);
            SpotLight::new(position, direction, i_deg, o_deg, attenuation, props).or_else(|e| {
                let at = if e.field == "outer_cut_off_deg" { o.span() } else { i.span() };
                src.err(at, &format!("lights.spot.{}", e.field), e.reason)
            })?
        }
        _ => {
            return src.err(
                t.span.clone(),
                "lights.spot",
                "give both cut_off_deg and outer_cut_off_deg (or neither, to keep the preset's)",
            )
        }
    };
    *light = Some(spot);
    Ok(())
}

/// Read and parse a scene file; errors name the file, line and field.
pub fn load(path: &std::path::Path, aspect: f32) -> Result<World, Box<dyn std::error::Error>> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse(&text, aspect).map_err(|e| format!("{}: {e}", path.display()).into())
}
