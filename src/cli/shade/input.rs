//! Reading one `shade` line: `#[derive(Deserialize)]` types, one per model and per
//! light kind, read through `serde_path_to_error` so that every error names its
//! field path (`lights[1].cut_off_deg`) and column.
//!
//! A line is read in two passes: the first reads only `model` (or a light's `kind`),
//! the second reads the whole object into that model's own type, which denies
//! unknown fields and duplicate keys. Numbers must be finite in `f32`; vectors are
//! arrays of exactly 3 numbers; optional fields may be absent but never `null`.

use std::fmt;
use std::marker::PhantomData;

use glam::{DVec3, Vec3};
use serde::de::{self, DeserializeOwned, Deserializer, IgnoredAny, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use serde_json::value::RawValue;

use super::eval::{attenuation_f32, Case, LightIn, ModelCase};
use super::LineError;
use crate::material::classic_material;
use crate::phong::{BasicLighting, Specular};
use crate::reference::casters::Attenuation as Attenuation64;
use crate::reference::material::{LightProps as LightProps64, Material as Material64};
use crate::reference::models::{Ogldev as Ogldev64, OpenGLTutorial as Tutorial64};

/// A JSON number that is finite in `f64` and in `f32`.
#[derive(Clone, Copy, Debug)]
struct Num(f64);

fn finite<E: de::Error>(x: f64) -> Result<Num, E> {
    if x.is_finite() && (x as f32).is_finite() {
        Ok(Num(x))
    } else {
        Err(E::custom(format_args!("not finite in f32 ({x:e})")))
    }
}

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Num;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_f64<E: de::Error>(self, x: f64) -> Result<Num, E> {
                finite(x)
            }
            fn visit_i64<E: de::Error>(self, x: i64) -> Result<Num, E> {
                finite(x as f64)
            }
            fn visit_u64<E: de::Error>(self, x: u64) -> Result<Num, E> {
                finite(x as f64)
            }
        }
        d.deserialize_any(V)
    }
}

/// `[x, y, z]`: exactly three [`Num`]s.
#[derive(Clone, Copy, Debug)]
struct V3(DVec3);

impl<'de> Deserialize<'de> for V3 {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = V3;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an array of 3 numbers")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<V3, A::Error> {
                let mut v = [0.0; 3];
                let mut n = 0;
                while n < 3 {
                    match seq.next_element::<Num>()? {
                        Some(x) => v[n] = x.0,
                        None => break,
                    }
                    n += 1;
                }
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    n += 1;
                }
                if n != 3 {
                    return Err(de::Error::custom(format_args!("expected an array of 3 numbers, got {n} elements")));
                }
                Ok(V3(DVec3::from_array(v)))
            }
        }
        d.deserialize_any(V)
    }
}

/// An optional field: absent is `None`, but `null` is an error (not a silent default).
#[derive(Clone, Debug)]
struct Opt<T>(Option<T>);

impl<T> Default for Opt<T> {
    fn default() -> Self {
        Opt(None)
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Opt<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        T::deserialize(d).map(|v| Opt(Some(v)))
    }
}

impl Opt<V3> {
    fn or(&self, default: DVec3) -> DVec3 {
        self.0.map_or(default, |v| v.0)
    }
}

impl Opt<Num> {
    fn or(&self, default: f64) -> f64 {
        self.0.map_or(default, |v| v.0)
    }
}

/// A JSON object read into `T` (a derived struct would also accept an array, by position).
struct Object<T>(T);

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Object<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V<T>(PhantomData<T>);
        impl<'de, T: Deserialize<'de>> Visitor<'de> for V<T> {
            type Value = Object<T>;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("an object")
            }
            fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<Object<T>, A::Error> {
                T::deserialize(de::value::MapAccessDeserializer::new(map)).map(Object)
            }
        }
        d.deserialize_map(V(PhantomData))
    }
}

/// First pass over a line: only `model` (every other key is skipped).
#[derive(Deserialize)]
struct Head {
    #[serde(default)]
    model: Opt<String>,
}

/// First pass over a light: only `kind`.
#[derive(Deserialize)]
struct KindOnly {
    #[serde(default)]
    kind: Opt<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct LightsLine<'a> {
    #[serde(default)]
    #[allow(dead_code)] // read in the first pass
    model: Opt<String>,
    frag_pos: V3,
    normal: V3,
    view_pos: V3,
    material: Object<MaterialJson>,
    #[serde(borrow)]
    lights: Vec<&'a RawValue>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct MaterialJson {
    #[serde(default)]
    name: Opt<String>,
    #[serde(default)]
    ambient: Opt<V3>,
    #[serde(default)]
    diffuse: Opt<V3>,
    #[serde(default)]
    specular: Opt<V3>,
    #[serde(default)]
    shininess: Opt<Num>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TutorialLine {
    #[allow(dead_code)] // read in the first pass
    model: String,
    frag_pos: V3,
    normal: V3,
    view_pos: V3,
    light_pos: V3,
    diffuse: V3,
    #[serde(default)]
    light_color: Opt<V3>,
    #[serde(default)]
    light_power: Opt<Num>,
    #[serde(default)]
    specular: Opt<V3>,
    #[serde(default)]
    ambient_factor: Opt<Num>,
    #[serde(default)]
    exponent: Opt<Num>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct OgldevLine {
    #[allow(dead_code)] // read in the first pass
    model: String,
    frag_pos: V3,
    normal: V3,
    view_pos: V3,
    #[serde(default)]
    color: Opt<V3>,
    #[serde(default)]
    ambient_intensity: Opt<Num>,
    #[serde(default)]
    diffuse_intensity: Opt<Num>,
    #[serde(default)]
    direction: Opt<V3>,
    #[serde(default)]
    specular_intensity: Opt<Num>,
    #[serde(default)]
    specular_power: Opt<Num>,
    #[serde(default)]
    texture_color: Opt<V3>,
}

/// `basic_lighting`: the chapter's shader, in its own names.
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
#[allow(non_snake_case)] // the names are the shader's
struct BasicLine {
    #[allow(dead_code)] // read in the first pass
    model: String,
    FragPos: V3,
    Normal: V3,
    #[serde(default)]
    viewPos: Opt<V3>,
    #[serde(default)]
    lightPos: Opt<V3>,
    #[serde(default)]
    lightColor: Opt<V3>,
    #[serde(default)]
    objectColor: Opt<V3>,
    #[serde(default)]
    ambientStrength: Opt<Num>,
    #[serde(default)]
    specularStrength: Opt<Num>,
    #[serde(default)]
    shininess: Opt<Num>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct DirectionalJson {
    #[allow(dead_code)] // read in the first pass
    kind: String,
    direction: V3,
    ambient: V3,
    diffuse: V3,
    specular: V3,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct PointJson {
    #[allow(dead_code)] // read in the first pass
    kind: String,
    position: V3,
    constant: Num,
    linear: Num,
    quadratic: Num,
    ambient: V3,
    diffuse: V3,
    specular: V3,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SpotJson {
    #[allow(dead_code)] // read in the first pass
    kind: String,
    position: V3,
    direction: V3,
    cut_off_deg: Num,
    outer_cut_off_deg: Num,
    constant: Num,
    linear: Num,
    quadratic: Num,
    ambient: V3,
    diffuse: V3,
    specular: V3,
}

/// The models `shade` knows, by their input name.
pub(super) const MODEL_NAMES: [&str; 5] = ["learnopengl", "blinn-phong", "opengl-tutorial", "ogldev", "basic_lighting"];

/// Read `text` (a slice of the line starting at byte `offset`) into `T`; errors get
/// the field path under `prefix` and the line's 1-based column.
fn read<'a, T: Deserialize<'a>>(text: &'a str, offset: usize, prefix: &str, context: &str) -> Result<T, LineError> {
    let mut de = serde_json::Deserializer::from_str(text);
    let value = serde_path_to_error::deserialize(&mut de).map_err(|e| describe(e, offset, prefix, context))?;
    de.end().map_err(|e| LineError::new("line", format!("invalid JSON: {}", strip_position(&e.to_string()))))?;
    Ok(value)
}

/// `read` for a value borrowed from the line (`RawValue`), with its offset in the line.
fn read_raw<T: DeserializeOwned>(line: &str, raw: &RawValue, prefix: &str, context: &str) -> Result<T, LineError> {
    let offset = (raw.get().as_ptr() as usize).saturating_sub(line.as_ptr() as usize);
    read(raw.get(), offset, prefix, context)
}

/// Parse one line into a [`Case`]. Errors name the field path and what is wrong.
pub(super) fn parse_case(line: &str) -> Result<Case, LineError> {
    let head: Object<Head> = read(line, 0, "", "")?;
    let model = head.0.model.0.unwrap_or_else(|| "learnopengl".to_string());
    let context = format!(" for model {model:?}");
    let nonzero_normal = |n: V3, field: &str| normalizable(n.0, field);
    match model.as_str() {
        "learnopengl" | "blinn-phong" => {
            let c: Object<LightsLine> = read(line, 0, "", &context)?;
            let c = c.0;
            let specular = if model == "blinn-phong" { Specular::Blinn } else { Specular::Phong };
            let lights = c
                .lights
                .iter()
                .enumerate()
                .map(|(i, raw)| parse_light(line, raw, &format!("lights[{i}]")))
                .collect::<Result<Vec<_>, _>>()?;
            Ok(Case {
                frag_pos: c.frag_pos.0,
                normal: nonzero_normal(c.normal, "normal")?,
                view_pos: c.view_pos.0,
                model: ModelCase::Lights { specular, material: material(c.material.0)?, lights },
            })
        }
        "opengl-tutorial" => {
            let c: Object<TutorialLine> = read(line, 0, "", &context)?;
            let c = c.0;
            let t = Tutorial64 {
                light_pos: c.light_pos.0,
                light_color: c.light_color.or(DVec3::ONE),
                light_power: c.light_power.or(50.0),
                diffuse: c.diffuse.0,
                specular: c.specular.or(DVec3::splat(0.3)),
                ambient_factor: c.ambient_factor.or(0.1),
                exponent: c.exponent.or(5.0),
            };
            let normal = nonzero_normal(c.normal, "normal")?;
            Ok(Case { frag_pos: c.frag_pos.0, normal, view_pos: c.view_pos.0, model: ModelCase::OpenGLTutorial(t) })
        }
        "ogldev" => {
            let c: Object<OgldevLine> = read(line, 0, "", &context)?;
            let c = c.0;
            let direction = normalizable(c.direction.or(DVec3::Z), "direction")?;
            let o = Ogldev64 {
                color: c.color.or(DVec3::ONE),
                ambient_intensity: c.ambient_intensity.or(0.0),
                diffuse_intensity: c.diffuse_intensity.or(0.2),
                direction,
                specular_intensity: c.specular_intensity.or(1.0),
                specular_power: c.specular_power.or(32.0),
                texture_color: c.texture_color.or(DVec3::ONE),
            };
            let normal = nonzero_normal(c.normal, "normal")?;
            Ok(Case { frag_pos: c.frag_pos.0, normal, view_pos: c.view_pos.0, model: ModelCase::Ogldev(o) })
        }
        "basic_lighting" => {
            let c: Object<BasicLine> = read(line, 0, "", &context)?;
            let c = c.0;
            let d = BasicLighting::learnopengl();
            let v = |x: Vec3| x.as_dvec3();
            let view_pos = c.viewPos.or(v(d.view_pos));
            let b = crate::reference::phong::BasicLighting {
                light_pos: c.lightPos.or(v(d.light_pos)),
                view_pos,
                light_color: c.lightColor.or(v(d.light_color)),
                object_color: c.objectColor.or(v(d.object_color)),
                ambient_strength: c.ambientStrength.or(f64::from(d.ambient_strength)),
                specular_strength: c.specularStrength.or(f64::from(d.specular_strength)),
                shininess: c.shininess.or(f64::from(d.shininess)),
            };
            if b.shininess < 0.0 {
                return Err(LineError::new("shininess", format!("must be >= 0, got {}", b.shininess)));
            }
            let normal = nonzero_normal(c.Normal, "Normal")?;
            Ok(Case { frag_pos: c.FragPos.0, normal, view_pos, model: ModelCase::Basic(b) })
        }
        other => {
            Err(LineError::new("model", format!("unknown model {other:?}; expected one of {}", MODEL_NAMES.join(", "))))
        }
    }
}

/// `v` when the f32 path can normalize it as the f64 reference does; otherwise an error
/// naming `field`.
///
/// The shader's `normalize` squares the length in f32. When that square is zero or a
/// subnormal number (a length below 2⁻⁶³ ≈ 1.08e-19; a normal of `[0, 0, 1e-46]` is even
/// zero in f32), `normalize` returns garbage while the f64 reference still finds a unit
/// vector: an audit saw `rgb` 0.02 against `rgb_f64` 0.065. When it overflows (a length
/// above about 1.84e19) it returns zero. Both are refused rather than answered two ways.
fn normalizable(v: DVec3, field: &str) -> Result<DVec3, LineError> {
    if v == DVec3::ZERO {
        return Err(LineError::new(field, "must be non-zero"));
    }
    let length = v.length();
    let squared = v.as_vec3().length_squared();
    if squared < f32::MIN_POSITIVE {
        return Err(LineError::new(
            field,
            format!(
                "has length {length:e}, below 1.08e-19, the shortest vector f32 can normalize (its squared length \
                 underflows f32's smallest normal number, 1.18e-38); scale it up"
            ),
        ));
    }
    if !squared.is_finite() {
        return Err(LineError::new(
            field,
            format!(
                "has length {length:e}, above 1.84e19, the longest vector f32 can normalize (its squared length \
                 overflows f32); scale it down"
            ),
        ));
    }
    Ok(v)
}

fn material(m: MaterialJson) -> Result<Material64, LineError> {
    let others = [
        ("ambient", m.ambient.0.is_some()),
        ("diffuse", m.diffuse.0.is_some()),
        ("specular", m.specular.0.is_some()),
        ("shininess", m.shininess.0.is_some()),
    ];
    if let Some(name) = m.name.0 {
        if let Some((field, _)) = others.iter().find(|(_, present)| *present) {
            return Err(LineError::new(
                format!("material.{field}"),
                "unknown field (a named material takes only \"name\")",
            ));
        }
        let row = classic_material(&name)
            .ok_or_else(|| LineError::new("material.name", format!("unknown material {name:?}")))?;
        let v = |a: [f32; 3]| Vec3::from_array(a).as_dvec3();
        return Ok(Material64 {
            ambient: v(row.ambient),
            diffuse: v(row.diffuse),
            specular: v(row.specular),
            shininess: f64::from(row.shininess()),
        });
    }
    let missing = |field: &str| LineError::new(format!("material.{field}"), "missing");
    let material = Material64 {
        ambient: m.ambient.0.ok_or_else(|| missing("ambient"))?.0,
        diffuse: m.diffuse.0.ok_or_else(|| missing("diffuse"))?.0,
        specular: m.specular.0.ok_or_else(|| missing("specular"))?.0,
        shininess: m.shininess.0.ok_or_else(|| missing("shininess"))?.0,
    };
    if material.shininess < 0.0 {
        return Err(LineError::new("material.shininess", format!("must be >= 0, got {}", material.shininess)));
    }
    Ok(material)
}

fn props(ambient: V3, diffuse: V3, specular: V3) -> LightProps64 {
    LightProps64 { ambient: ambient.0, diffuse: diffuse.0, specular: specular.0 }
}

fn attenuation(path: &str, constant: Num, linear: Num, quadratic: Num) -> Result<Attenuation64, LineError> {
    let a = Attenuation64 { constant: constant.0, linear: linear.0, quadratic: quadratic.0 };
    attenuation_f32(&a).map_err(|e| LineError::new(format!("{path}.{}", e.field), e.reason))?;
    Ok(a)
}

fn parse_light(line: &str, raw: &RawValue, path: &str) -> Result<LightIn, LineError> {
    let kind: Object<KindOnly> = read_raw(line, raw, path, "")?;
    let Some(kind) = kind.0.kind.0 else {
        return Err(LineError::new(format!("{path}.kind"), "missing"));
    };
    match kind.as_str() {
        "directional" => {
            let l: Object<DirectionalJson> = read_raw(line, raw, path, " for a directional light")?;
            let l = l.0;
            normalizable(l.direction.0, &format!("{path}.direction"))?;
            Ok(LightIn::Directional { direction: l.direction.0, props: props(l.ambient, l.diffuse, l.specular) })
        }
        "point" => {
            let l: Object<PointJson> = read_raw(line, raw, path, " for a point light")?;
            let l = l.0;
            Ok(LightIn::Point {
                position: l.position.0,
                attenuation: attenuation(path, l.constant, l.linear, l.quadratic)?,
                props: props(l.ambient, l.diffuse, l.specular),
            })
        }
        "spot" => {
            let l: Object<SpotJson> = read_raw(line, raw, path, " for a spot light")?;
            let l = l.0;
            normalizable(l.direction.0, &format!("{path}.direction"))?;
            let light = LightIn::Spot {
                position: l.position.0,
                direction: l.direction.0,
                cut_off_deg: l.cut_off_deg.0,
                outer_cut_off_deg: l.outer_cut_off_deg.0,
                attenuation: attenuation(path, l.constant, l.linear, l.quadratic)?,
                props: props(l.ambient, l.diffuse, l.specular),
            };
            // The library's checked constructor names the field (direction,
            // cut_off_deg > outer_cut_off_deg, angle out of range).
            light.spot_f32().map_err(|e| LineError::new(format!("{path}.{}", e.field), e.reason))?;
            Ok(light)
        }
        other => Err(LineError::new(
            format!("{path}.kind"),
            format!("unknown light kind {other:?}; expected directional, point or spot"),
        )),
    }
}

// ---------------------------------------------------------------------------
// serde's messages in the line's own words.

/// `message` without serde_json's trailing " at line L column C".
fn strip_position(message: &str) -> &str {
    match message.rfind(" at line ") {
        Some(i) if message[i..].contains(" column ") => &message[..i],
        _ => message,
    }
}

/// serde's name of an unexpected value (`string "x"`, `integer 5`) as "a string", "a number".
fn article(unexpected: &str) -> String {
    let kind = unexpected.split([' ', '`']).next().unwrap_or(unexpected);
    match kind {
        "boolean" => "a boolean",
        "integer" | "floating" => "a number",
        "string" => "a string",
        "null" | "unit" => "null",
        "sequence" => "an array",
        "map" => "an object",
        _ => return unexpected.to_string(),
    }
    .to_string()
}

/// The name inside the first pair of backticks of `message`.
fn quoted(message: &str) -> Option<&str> {
    let rest = &message[message.find('`')? + 1..];
    Some(&rest[..rest.find('`')?])
}

/// A serde error as a [`LineError`]: the field path (under `prefix`), serde's message
/// rephrased, and the column in the line.
fn describe(e: serde_path_to_error::Error<serde_json::Error>, offset: usize, prefix: &str, context: &str) -> LineError {
    let mut path = prefix.to_string();
    let mut last_key = None;
    for segment in e.path() {
        last_key = match segment {
            serde_path_to_error::Segment::Map { key } => Some(key.clone()),
            _ => None,
        };
        match segment {
            serde_path_to_error::Segment::Seq { index } => path.push_str(&format!("[{index}]")),
            serde_path_to_error::Segment::Map { key } => {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
            }
            serde_path_to_error::Segment::Enum { .. } | serde_path_to_error::Segment::Unknown => {}
        }
    }
    let inner = e.into_inner();
    // serde_json counts columns from 1 within the slice it read.
    let column = (inner.column() > 0).then(|| offset + inner.column());
    let full = inner.to_string();
    if !inner.is_data() {
        let field = if path.is_empty() { "line".to_string() } else { path };
        return LineError { field, reason: format!("invalid JSON: {}", strip_position(&full)), column };
    }
    let message = strip_position(&full);
    // For an unknown or repeated key the path may already end with that key.
    let join = |name: &str| match () {
        _ if last_key.as_deref() == Some(name) => path.clone(),
        _ if path.is_empty() => name.to_string(),
        _ => format!("{path}.{name}"),
    };
    let (field, reason) = if let (true, Some(name)) = (message.starts_with("unknown field"), quoted(message)) {
        let expected = message.split_once(", expected ").map(|(_, list)| format!("; expected {list}"));
        (join(name), format!("unknown field{context}{}", expected.unwrap_or_default()))
    } else if let (true, Some(name)) = (message.starts_with("missing field"), quoted(message)) {
        (join(name), "missing".to_string())
    } else if let (true, Some(name)) = (message.starts_with("duplicate field"), quoted(message)) {
        (join(name), "duplicate key (each key may appear once)".to_string())
    } else if let Some((unexpected, expected)) =
        message.strip_prefix("invalid type: ").and_then(|m| m.split_once(", expected "))
    {
        let expected = if expected == "a sequence" { "an array" } else { expected };
        (path, format!("expected {expected}, got {}", article(unexpected)))
    } else {
        (path, message.to_string())
    };
    let field = if field.is_empty() { "line".to_string() } else { field };
    LineError { field, reason, column }
}
