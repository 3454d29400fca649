//! `lightlab shade`: evaluate fragments given as JSON lines, print what each should be.
//!
//! | item | meaning |
//! | --- | --- |
//! | input line | one JSON object: `model`, `frag_pos`, `normal`, `view_pos` and the model's fields |
//! | `rgb` | the `f32` shader path (lightlab's core modules), unclamped linear RGB |
//! | `rgb_f64` | the same fragment in `f64`, unclamped |
//! | `lights` | each light's `ambient`, `diffuse`, `specular` terms (`f32`) |
//! | exit status | 0: every line succeeded; 1: some line failed; 2: usage or input error (bad argument, unreadable file); 3: internal failure (output cannot be written) |
//!
//! A bad line produces `{"line": N, "error": "..."}` naming the field and what is
//! wrong with it; the other lines are still processed. Blank lines and lines
//! starting with `#` are skipped (they still count in `line`).

use std::io::{BufRead, Write};
use std::path::PathBuf;

use glam::{DVec3, Vec3};
use serde::Serialize;
use serde_json::{Map, Value};

use super::{output, CliError, CliResult, Outcome};
use crate::casters::{Attenuation, DirLight, PointLight, SpotLight};
use crate::material::{classic_material, LightProps, Material};
use crate::models::{Ogldev, OpenGLTutorial, ShadingModel};
use crate::phong::{Specular, Terms};
use crate::reference;

/// The models and their fields, printed by `lightlab shade --help`.
pub const MODELS_HELP: &str = "\
INPUT: one JSON object per line (blank lines and lines starting with # are skipped).
Every model takes frag_pos, normal and view_pos ([x, y, z], world space); normal need
not be unit length (it is normalized, as the shader does) but must not be zero.
Unknown fields are errors, so a misspelt optional field is not silently ignored.

model \"learnopengl\" (the default) and \"blinn-phong\":
  material  {\"ambient\": [r,g,b], \"diffuse\": [r,g,b], \"specular\": [r,g,b], \"shininess\": s >= 0}
            or {\"name\": \"emerald\"}, a row of the classic materials table (shininess x 128)
  lights    array of lights, each with ambient, diffuse, specular [r,g,b] and a kind:
    {\"kind\": \"directional\", \"direction\": [x,y,z]}        direction FROM the light, non-zero
    {\"kind\": \"point\", \"position\": [x,y,z], \"constant\": Kc, \"linear\": Kl, \"quadratic\": Kq}
    {\"kind\": \"spot\", \"position\", \"direction\", \"cut_off_deg\", \"outer_cut_off_deg\",
     \"constant\", \"linear\", \"quadratic\"}                  angles in [0, 90], inner <= outer
  LearnOpenGL Multiple lights: point and spot terms x attenuation 1/(Kc + Kl d + Kq d^2),
  spot terms also x clamp((theta - cos outer)/(cos inner - cos outer), 0, 1); specular
  pow(max(view_dir . reflect_dir, 0), s), not gated by n . l. blinn-phong uses
  pow(max(n . halfway, 0), s) instead.

model \"opengl-tutorial\" (opengl-tutorial 8, one point light, power / d^2):
  light_pos [x,y,z] (required), diffuse [r,g,b] (required, MaterialDiffuseColor),
  light_color [r,g,b] (default [1,1,1]), light_power (default 50),
  specular [r,g,b] (default [0.3,0.3,0.3]), ambient_factor (default 0.1: ambient = 0.1 x diffuse),
  exponent (default 5). A fragment at light_pos (d = 0) is an error (infinite result).

model \"ogldev\" (ogldev 19, one directional light; defaults from tutorial19.cpp):
  color [r,g,b] (default [1,1,1]), ambient_intensity (default 0), diffuse_intensity (default 0.2),
  direction [x,y,z] FROM the light (default [0,0,1]; normalized in f32, as the tutorial's CPU code does),
  specular_intensity (default 1), specular_power (default 32), texture_color [r,g,b] (default [1,1,1]).
  Specular only where n . l > 0; pow is taken before its > 0 test (a negative base gives no specular).

OUTPUT: one JSON line per input line:
  {\"line\": N, \"rgb\": [r,g,b], \"rgb_f64\": [r,g,b], \"lights\": [{\"ambient\": [..], \"diffuse\": [..], \"specular\": [..]}, ..]}
  or {\"line\": N, \"error\": \"field: what is wrong\"}. rgb and rgb_f64 are unclamped linear RGB.
EXIT STATUS: 0 all lines succeeded, 1 some line failed, 2 usage or input error (bad argument,
unreadable file), 3 internal failure (standard output full).";

/// Arguments of `lightlab shade`.
#[derive(clap::Args, Clone, Debug, PartialEq, Eq)]
#[command(after_help = MODELS_HELP)]
pub struct ShadeArgs {
    /// JSON-lines file to read; standard input when absent or `-`.
    pub input: Option<PathBuf>,
}

/// Run `lightlab shade`: read the input, print one JSON line per case.
///
/// `Success` when every line succeeded, `Problems` when some line failed, an input
/// error when the input cannot be opened or read, an internal error when the output
/// cannot be written (a closed pipe stops quietly).
pub fn run(args: &ShadeArgs) -> CliResult {
    let mut out = output::stdout();
    let ok = match args.input.as_deref() {
        None => process(std::io::stdin().lock(), out.writer()),
        Some(p) if p.as_os_str() == "-" => process(std::io::stdin().lock(), out.writer()),
        Some(path) => match std::fs::File::open(path) {
            Ok(file) => process(std::io::BufReader::new(file), out.writer()),
            Err(e) => return Err(CliError::Input(format!("cannot open {}: {e}", path.display()))),
        },
    }
    .map_err(output::stdout_error)?;
    out.finish()?;
    Ok(Outcome::from_ok(ok))
}

/// Shade every line of `input`, writing one JSON line per case to `out`.
///
/// Returns `Ok(true)` when every case succeeded and `Ok(false)` when some line
/// produced an error object. I/O errors are returned as they are. A line
/// that is not valid UTF-8 is an error line, not an I/O error.
pub fn process(mut input: impl BufRead, out: &mut impl Write) -> std::io::Result<bool> {
    let mut all_ok = true;
    let mut bytes = Vec::new();
    let mut line_no = 0usize;
    loop {
        bytes.clear();
        if input.read_until(b'\n', &mut bytes)? == 0 {
            break;
        }
        line_no += 1;
        let result = match std::str::from_utf8(&bytes) {
            Err(_) => Some(Err("line: not valid UTF-8".to_string())),
            Ok(text) => {
                let text = text.trim();
                if text.is_empty() || text.starts_with('#') {
                    None
                } else {
                    Some(shade_line(text))
                }
            }
        };
        match result {
            None => {}
            Some(Ok(shaded)) => writeln!(out, "{}", shaded.to_json(line_no))?,
            Some(Err(message)) => {
                all_ok = false;
                writeln!(out, "{}", error_json(line_no, &message))?;
            }
        }
    }
    Ok(all_ok)
}

/// The result for one case.
#[derive(Clone, Debug, PartialEq)]
pub struct ShadeOutput {
    /// Unclamped linear RGB from the `f32` path.
    pub rgb: Vec3,
    /// Unclamped linear RGB from the `f64` path.
    pub rgb_f64: DVec3,
    /// Each light's terms (`f32`), in input order (one entry for the
    /// single-light models).
    pub lights: Vec<Terms>,
}

#[derive(Serialize)]
struct TermsJson {
    ambient: [f32; 3],
    diffuse: [f32; 3],
    specular: [f32; 3],
}

#[derive(Serialize)]
struct OutputJson {
    line: usize,
    rgb: [f32; 3],
    rgb_f64: [f64; 3],
    lights: Vec<TermsJson>,
}

#[derive(Serialize)]
struct ErrorJson<'a> {
    line: usize,
    error: &'a str,
}

impl ShadeOutput {
    /// The output line for input line `line` (`f32` values printed in their
    /// shortest round-trip form).
    pub fn to_json(&self, line: usize) -> String {
        let lights = self
            .lights
            .iter()
            .map(|t| TermsJson {
                ambient: t.ambient.to_array(),
                diffuse: t.diffuse.to_array(),
                specular: t.specular.to_array(),
            })
            .collect();
        let json = OutputJson { line, rgb: self.rgb.to_array(), rgb_f64: self.rgb_f64.to_array(), lights };
        serde_json::to_string(&json).unwrap_or_else(|e| error_json(line, &format!("output: {e}")))
    }
}

fn error_json(line: usize, message: &str) -> String {
    serde_json::to_string(&ErrorJson { line, error: message })
        .unwrap_or_else(|_| format!("{{\"line\": {line}, \"error\": \"unprintable error\"}}"))
}

/// Parse and shade one JSON case.
///
/// Errors name the field (`lights[1].cut_off_deg: ...`): invalid JSON, a
/// missing field, a wrong type, a number that is not finite in `f32`, an
/// unknown field, model or material, an inverted spot cone, invalid
/// attenuation, a zero normal or direction, or a result that is not finite.
pub fn shade_line(text: &str) -> Result<ShadeOutput, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("invalid JSON: {e}"))?;
    let case = Case::from_json(&value)?;
    let (rgb, lights) = case.shade_f32();
    let rgb_f64 = shade_f64(&case);
    let finite = rgb.is_finite()
        && rgb_f64.is_finite()
        && lights.iter().all(|t| t.ambient.is_finite() && t.diffuse.is_finite() && t.specular.is_finite());
    if !finite {
        return Err(match case.model {
            ModelCase::OpenGLTutorial(_) => {
                "result: not finite (frag_pos at light_pos gives light_power / 0, or inputs overflow f32)".to_string()
            }
            _ => "result: not finite (inputs overflow f32)".to_string(),
        });
    }
    Ok(ShadeOutput { rgb, rgb_f64, lights })
}

// ---------------------------------------------------------------------------
// Parsed case (values kept in f64, as read; the f32 path converts them).

#[derive(Clone, Copy, Debug)]
struct PropsIn {
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
}

#[derive(Clone, Copy, Debug)]
struct MaterialIn {
    ambient: DVec3,
    diffuse: DVec3,
    specular: DVec3,
    shininess: f64,
}

#[derive(Clone, Copy, Debug)]
struct AttenuationIn {
    constant: f64,
    linear: f64,
    quadratic: f64,
}

#[derive(Clone, Copy, Debug)]
enum LightIn {
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
struct TutorialIn {
    light_pos: DVec3,
    light_color: DVec3,
    light_power: f64,
    diffuse: DVec3,
    specular: DVec3,
    ambient_factor: f64,
    exponent: f64,
}

#[derive(Clone, Copy, Debug)]
struct OgldevIn {
    color: DVec3,
    ambient_intensity: f64,
    diffuse_intensity: f64,
    /// As given (non-zero); each path normalizes it in its own precision, as
    /// the tutorial's CPU code normalizes it in `float`.
    direction: DVec3,
    specular_intensity: f64,
    specular_power: f64,
    texture_color: DVec3,
}

#[derive(Clone, Debug)]
enum ModelCase {
    Lights { specular: Specular, material: MaterialIn, lights: Vec<LightIn> },
    OpenGLTutorial(TutorialIn),
    Ogldev(OgldevIn),
}

#[derive(Clone, Debug)]
struct Case {
    frag_pos: DVec3,
    normal: DVec3,
    view_pos: DVec3,
    model: ModelCase,
}

const COMMON_FIELDS: [&str; 4] = ["model", "frag_pos", "normal", "view_pos"];
const LIGHTS_FIELDS: [&str; 2] = ["material", "lights"];
const TUTORIAL_FIELDS: [&str; 7] =
    ["light_pos", "light_color", "light_power", "diffuse", "specular", "ambient_factor", "exponent"];
const OGLDEV_FIELDS: [&str; 7] = [
    "color",
    "ambient_intensity",
    "diffuse_intensity",
    "direction",
    "specular_intensity",
    "specular_power",
    "texture_color",
];

impl Case {
    fn from_json(value: &Value) -> Result<Case, String> {
        let obj = Obj::new(value, "")?;
        let model_name = match obj.get("model") {
            None => "learnopengl",
            Some(Value::String(s)) => s.as_str(),
            Some(other) => return Err(format!("model: expected a string, got {}", type_name(other))),
        };
        let model = ShadingModel::from_name(model_name).ok_or_else(|| {
            format!("model: unknown model {model_name:?}; expected learnopengl, blinn-phong, opengl-tutorial or ogldev")
        })?;
        let specific: &[&str] = match model {
            ShadingModel::LearnOpenGL | ShadingModel::BlinnPhong => &LIGHTS_FIELDS,
            ShadingModel::OpenGLTutorial => &TUTORIAL_FIELDS,
            ShadingModel::Ogldev => &OGLDEV_FIELDS,
        };
        obj.check_known(&[&COMMON_FIELDS[..], specific].concat(), &format!(" for model {model_name:?}"))?;
        let frag_pos = obj.vec3("frag_pos")?;
        let normal = obj.vec3("normal")?;
        if normal == DVec3::ZERO {
            return Err("normal: must be non-zero".to_string());
        }
        let view_pos = obj.vec3("view_pos")?;
        let model = match model {
            ShadingModel::LearnOpenGL | ShadingModel::BlinnPhong => ModelCase::Lights {
                specular: if model == ShadingModel::BlinnPhong { Specular::Blinn } else { Specular::Phong },
                material: parse_material(&obj)?,
                lights: parse_lights(&obj)?,
            },
            ShadingModel::OpenGLTutorial => ModelCase::OpenGLTutorial(TutorialIn {
                light_pos: obj.vec3("light_pos")?,
                light_color: obj.vec3_or("light_color", DVec3::ONE)?,
                light_power: obj.number_or("light_power", 50.0)?,
                diffuse: obj.vec3("diffuse")?,
                specular: obj.vec3_or("specular", DVec3::splat(0.3))?,
                ambient_factor: obj.number_or("ambient_factor", 0.1)?,
                exponent: obj.number_or("exponent", 5.0)?,
            }),
            ShadingModel::Ogldev => {
                let direction = obj.vec3_or("direction", DVec3::Z)?;
                if direction.as_vec3().try_normalize().is_none() || direction.try_normalize().is_none() {
                    return Err("direction: must be a non-zero vector".to_string());
                }
                ModelCase::Ogldev(OgldevIn {
                    color: obj.vec3_or("color", DVec3::ONE)?,
                    ambient_intensity: obj.number_or("ambient_intensity", 0.0)?,
                    diffuse_intensity: obj.number_or("diffuse_intensity", 0.2)?,
                    direction,
                    specular_intensity: obj.number_or("specular_intensity", 1.0)?,
                    specular_power: obj.number_or("specular_power", 32.0)?,
                    texture_color: obj.vec3_or("texture_color", DVec3::ONE)?,
                })
            }
        };
        Ok(Case { frag_pos, normal, view_pos, model })
    }

    /// The f32 path: lightlab's core modules.
    fn shade_f32(&self) -> (Vec3, Vec<Terms>) {
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
        };
        (lights.iter().map(Terms::sum).sum(), lights)
    }
}

fn parse_material(obj: &Obj) -> Result<MaterialIn, String> {
    let m = obj.object("material")?;
    if let Some(name) = m.get("name") {
        m.check_known(&["name"], " (a named material takes only \"name\")")?;
        let Value::String(name) = name else {
            return Err(format!("material.name: expected a string, got {}", type_name(name)));
        };
        let row = classic_material(name).ok_or_else(|| format!("material.name: unknown material {name:?}"))?;
        let v = |a: [f32; 3]| Vec3::from_array(a).as_dvec3();
        return Ok(MaterialIn {
            ambient: v(row.ambient),
            diffuse: v(row.diffuse),
            specular: v(row.specular),
            shininess: f64::from(row.shininess()),
        });
    }
    m.check_known(&["ambient", "diffuse", "specular", "shininess"], "")?;
    let material = MaterialIn {
        ambient: m.vec3("ambient")?,
        diffuse: m.vec3("diffuse")?,
        specular: m.vec3("specular")?,
        shininess: m.number("shininess")?,
    };
    if material.shininess < 0.0 {
        return Err(format!("material.shininess: must be >= 0, got {}", material.shininess));
    }
    Ok(material)
}

fn parse_lights(obj: &Obj) -> Result<Vec<LightIn>, String> {
    let lights = match obj.get("lights") {
        None => return Err("lights: missing".to_string()),
        Some(Value::Array(a)) => a,
        Some(other) => return Err(format!("lights: expected an array, got {}", type_name(other))),
    };
    lights.iter().enumerate().map(|(i, v)| parse_light(v, &format!("lights[{i}]"))).collect()
}

fn parse_light(value: &Value, path: &str) -> Result<LightIn, String> {
    let l = Obj::new(value, path)?;
    let kind = match l.get("kind") {
        None => return Err(format!("{path}.kind: missing")),
        Some(Value::String(s)) => s.as_str(),
        Some(other) => return Err(format!("{path}.kind: expected a string, got {}", type_name(other))),
    };
    const PROPS: [&str; 4] = ["kind", "ambient", "diffuse", "specular"];
    const ATT: [&str; 3] = ["constant", "linear", "quadratic"];
    let light = match kind {
        "directional" => {
            l.check_known(&[&PROPS[..], &["direction"]].concat(), " for a directional light")?;
            let direction = l.vec3("direction")?;
            if direction == DVec3::ZERO {
                return Err(format!("{path}.direction: must be non-zero"));
            }
            LightIn::Directional { direction, props: parse_props(&l)? }
        }
        "point" => {
            l.check_known(&[&PROPS[..], &ATT, &["position"]].concat(), " for a point light")?;
            LightIn::Point {
                position: l.vec3("position")?,
                attenuation: parse_attenuation(&l)?,
                props: parse_props(&l)?,
            }
        }
        "spot" => {
            let own = ["position", "direction", "cut_off_deg", "outer_cut_off_deg"];
            l.check_known(&[&PROPS[..], &ATT, &own].concat(), " for a spot light")?;
            let light = LightIn::Spot {
                position: l.vec3("position")?,
                direction: l.vec3("direction")?,
                cut_off_deg: l.number("cut_off_deg")?,
                outer_cut_off_deg: l.number("outer_cut_off_deg")?,
                attenuation: parse_attenuation(&l)?,
                props: parse_props(&l)?,
            };
            // The library's checked constructor names the field (direction,
            // cut_off_deg > outer_cut_off_deg, angle out of range).
            light.spot_f32().map_err(|e| format!("{path}.{e}"))?;
            light
        }
        other => {
            return Err(format!("{path}.kind: unknown light kind {other:?}; expected directional, point or spot"));
        }
    };
    Ok(light)
}

fn parse_props(l: &Obj) -> Result<PropsIn, String> {
    Ok(PropsIn { ambient: l.vec3("ambient")?, diffuse: l.vec3("diffuse")?, specular: l.vec3("specular")? })
}

fn parse_attenuation(l: &Obj) -> Result<AttenuationIn, String> {
    let a = AttenuationIn {
        constant: l.number("constant")?,
        linear: l.number("linear")?,
        quadratic: l.number("quadratic")?,
    };
    a.to_f32().map_err(|e| format!("{}.{e}", l.path))?;
    Ok(a)
}

impl PropsIn {
    fn to_f64(self) -> reference::material::LightProps {
        reference::material::LightProps { ambient: self.ambient, diffuse: self.diffuse, specular: self.specular }
    }

    fn to_f32(self) -> LightProps {
        LightProps {
            ambient: self.ambient.as_vec3(),
            diffuse: self.diffuse.as_vec3(),
            specular: self.specular.as_vec3(),
        }
    }
}

impl MaterialIn {
    fn to_f64(self) -> reference::material::Material {
        reference::material::Material {
            ambient: self.ambient,
            diffuse: self.diffuse,
            specular: self.specular,
            shininess: self.shininess,
        }
    }

    fn to_f32(self) -> Material {
        Material {
            ambient: self.ambient.as_vec3(),
            diffuse: self.diffuse.as_vec3(),
            specular: self.specular.as_vec3(),
            shininess: self.shininess as f32,
        }
    }
}

impl AttenuationIn {
    fn to_f64(self) -> reference::casters::Attenuation {
        reference::casters::Attenuation { constant: self.constant, linear: self.linear, quadratic: self.quadratic }
    }

    fn to_f32(self) -> Result<Attenuation, crate::casters::ParamError> {
        Attenuation::new(self.constant as f32, self.linear as f32, self.quadratic as f32)
    }
}

impl LightIn {
    fn spot_f32(&self) -> Result<SpotLight, crate::casters::ParamError> {
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
    fn to_f64(self) -> reference::models::OpenGLTutorial {
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

    fn to_f32(self) -> OpenGLTutorial {
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
    fn to_f64(self) -> reference::models::Ogldev {
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

    fn to_f32(self) -> Ogldev {
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

// ---------------------------------------------------------------------------
// The f64 path.

/// The `rgb_f64` of a case: the independent `f64` reference ([`crate::reference`]).
fn shade_f64(case: &Case) -> DVec3 {
    match &case.model {
        ModelCase::Lights { specular, material, lights } => {
            let material = material.to_f64();
            let n = case.normal.normalize_or_zero();
            let view_dir = (case.view_pos - case.frag_pos).normalize_or_zero();
            lights.iter().map(|l| l.terms_f64(*specular, &material, n, case.frag_pos, view_dir).sum()).sum()
        }
        ModelCase::OpenGLTutorial(t) => t.to_f64().terms(case.frag_pos, case.normal, case.view_pos).sum(),
        ModelCase::Ogldev(o) => o.to_f64().terms(case.frag_pos, case.normal, case.view_pos).sum(),
    }
}

// ---------------------------------------------------------------------------
// JSON field access with errors that name the field.

fn type_name(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "a boolean",
        Value::Number(_) => "a number",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Object(_) => "an object",
    }
}

/// A JSON object with the path that leads to it (`""` for the top level).
struct Obj<'a> {
    map: &'a Map<String, Value>,
    path: String,
}

impl<'a> Obj<'a> {
    fn new(value: &'a Value, path: &str) -> Result<Obj<'a>, String> {
        match value {
            Value::Object(map) => Ok(Obj { map, path: path.to_string() }),
            other => {
                let what = if path.is_empty() { "line" } else { path };
                Err(format!("{what}: expected an object, got {}", type_name(other)))
            }
        }
    }

    fn field_path(&self, name: &str) -> String {
        if self.path.is_empty() {
            name.to_string()
        } else {
            format!("{}.{name}", self.path)
        }
    }

    fn get(&self, name: &str) -> Option<&'a Value> {
        self.map.get(name)
    }

    fn require(&self, name: &str) -> Result<&'a Value, String> {
        self.get(name).ok_or_else(|| format!("{}: missing", self.field_path(name)))
    }

    /// Fields are checked in the object's order, so the first unknown one is reported.
    fn check_known(&self, allowed: &[&str], context: &str) -> Result<(), String> {
        match self.map.keys().find(|k| !allowed.contains(&k.as_str())) {
            Some(k) => Err(format!("{}: unknown field{context}", self.field_path(k))),
            None => Ok(()),
        }
    }

    fn object(&self, name: &str) -> Result<Obj<'a>, String> {
        Obj::new(self.require(name)?, &self.field_path(name))
    }

    fn number(&self, name: &str) -> Result<f64, String> {
        as_number(self.require(name)?, &self.field_path(name))
    }

    fn number_or(&self, name: &str, default: f64) -> Result<f64, String> {
        self.get(name).map_or(Ok(default), |v| as_number(v, &self.field_path(name)))
    }

    fn vec3(&self, name: &str) -> Result<DVec3, String> {
        as_vec3(self.require(name)?, &self.field_path(name))
    }

    fn vec3_or(&self, name: &str, default: DVec3) -> Result<DVec3, String> {
        self.get(name).map_or(Ok(default), |v| as_vec3(v, &self.field_path(name)))
    }
}

/// A JSON number that is finite in both `f64` and `f32`.
fn as_number(value: &Value, path: &str) -> Result<f64, String> {
    let Value::Number(n) = value else {
        return Err(format!("{path}: expected a number, got {}", type_name(value)));
    };
    let x = n.as_f64().ok_or_else(|| format!("{path}: not finite ({n})"))?;
    if !x.is_finite() || !(x as f32).is_finite() {
        return Err(format!("{path}: not finite in f32 ({n})"));
    }
    Ok(x)
}

fn as_vec3(value: &Value, path: &str) -> Result<DVec3, String> {
    let Value::Array(items) = value else {
        return Err(format!("{path}: expected an array of 3 numbers, got {}", type_name(value)));
    };
    if items.len() != 3 {
        return Err(format!("{path}: expected an array of 3 numbers, got {} elements", items.len()));
    }
    let c = |i: usize| as_number(&items[i], &format!("{path}[{i}]"));
    Ok(DVec3::new(c(0)?, c(1)?, c(2)?))
}

#[cfg(test)]
mod tests {
    use super::*;

    const EXAMPLE: &str = r#"{"model": "learnopengl", "frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3],
 "material": {"ambient": [1, 0.5, 0.31], "diffuse": [1, 0.5, 0.31], "specular": [0.5, 0.5, 0.5], "shininess": 32},
 "lights": [
   {"kind": "directional", "direction": [-0.2, -1, -0.3], "ambient": [0.05, 0.05, 0.05], "diffuse": [0.4, 0.4, 0.4], "specular": [0.5, 0.5, 0.5]},
   {"kind": "point", "position": [0.7, 0.2, 2], "constant": 1, "linear": 0.09, "quadratic": 0.032,
    "ambient": [0.05, 0.05, 0.05], "diffuse": [0.8, 0.8, 0.8], "specular": [1, 1, 1]},
   {"kind": "spot", "position": [0, 0, 3], "direction": [0, 0, -1], "cut_off_deg": 12.5, "outer_cut_off_deg": 15,
    "constant": 1, "linear": 0.09, "quadratic": 0.032, "ambient": [0, 0, 0], "diffuse": [1, 1, 1], "specular": [1, 1, 1]}]}"#;

    #[test]
    fn issue_example_matches_scene_terms() {
        let out = shade_line(&EXAMPLE.replace('\n', " ")).expect("example is valid");
        assert_eq!(out.lights.len(), 3);
        // The f32 and f64 paths agree to f32 rounding (a few ulps of values near 1).
        assert!((out.rgb.as_dvec3() - out.rgb_f64).abs().max_element() < 1e-5, "{:?} vs {:?}", out.rgb, out.rgb_f64);
    }

    #[test]
    fn errors_name_the_field() {
        let cases = [
            ("[1, 2]", "line: expected an object"),
            (r#"{"frag_pos": [0, 0]}"#, "frag_pos: expected an array of 3 numbers, got 2 elements"),
            (r#"{"model": "phong"}"#, "model: unknown model"),
            (r#"{"frag_pos": [0, 0, 0], "normal": [0, 0, 1]}"#, "view_pos: missing"),
            (r#"{"frag_pos": [0, 0, 1e39]}"#, "frag_pos[2]: not finite in f32"),
            (r#"{"frag_pos": [0, "a", 0]}"#, "frag_pos[1]: expected a number, got a string"),
            (r#"{"colour": 1}"#, "colour: unknown field"),
        ];
        for (input, expected) in cases {
            let err = shade_line(input).expect_err(input);
            assert!(err.starts_with(expected), "{input}: got {err:?}, expected {expected:?}");
        }
    }
}
