//! `lightlab shade`: evaluate fragments given as JSON lines, print what each should be.
//!
//! | item | meaning |
//! | --- | --- |
//! | input line | one JSON object: `model`, the fragment (`frag_pos`, `normal`, `view_pos`) and the model's fields |
//! | `rgb` | the `f32` shader path (lightlab's core modules), unclamped linear RGB |
//! | `rgb_f64` | the same fragment in `f64` ([`crate::reference`]), unclamped |
//! | `lights` | each light's `ambient`, `diffuse`, `specular` terms (`f32`) |
//! | exit status | 0: every line succeeded; 1: some line failed; 2: usage or input error (bad argument, unreadable file, a line over [`MAX_LINE_BYTES`]); 3: internal failure (output cannot be written) |
//!
//! A bad line produces `{"line": N, "field": "...", "error": "...", "column": C}` naming
//! the field and what is wrong with it; the other lines are still processed. Blank
//! lines and lines starting with `#` are skipped (they still count in `line`).
//!
//! The input is read with `#[derive(Deserialize)]` types, one per model and per light
//! kind: unknown fields, duplicate keys, `null` for a number,
//! vectors of the wrong length and numbers not finite in `f32` are errors.

mod eval;
mod input;

use std::io::{BufRead, Write};
use std::path::PathBuf;

use glam::{DVec3, Vec3};
use serde::Serialize;

use super::{output, CliError, CliResult, Outcome};
use crate::phong::{BasicLighting, Terms};

/// The longest input line `shade` reads, in bytes (1 MiB; a case is well under 10 KiB).
/// A longer line (`lightlab shade /dev/zero`) ends the run with an input error
/// naming its line number, before more memory is taken.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// The models and their fields, printed by `lightlab shade --help`.
pub fn models_help() -> String {
    let b = BasicLighting::learnopengl();
    let v = |x: Vec3| format!("[{}, {}, {}]", x.x, x.y, x.z);
    format!(
        "\
INPUT: one JSON object per line (blank lines and lines starting with # are skipped).
Every model but basic_lighting takes frag_pos, normal and view_pos ([x, y, z], world space);
normal need not be unit length (it is normalized, as the shader does), but its length, like
every direction's, must be within 1.08e-19..1.84e19: f32 normalizes it through its squared
length, which must be a normal f32 number (smaller vectors are an error, not a wrong color).
Unknown fields and repeated keys are errors, so a misspelt optional field is not silently
ignored. Lines are at most {max} bytes.

model \"learnopengl\" (the default) and \"blinn-phong\":
  material  {{\"ambient\": [r,g,b], \"diffuse\": [r,g,b], \"specular\": [r,g,b], \"shininess\": s >= 0}}
            or {{\"name\": \"emerald\"}}, a row of the classic materials table (shininess x 128)
  lights    array of lights, each with ambient, diffuse, specular [r,g,b] and a kind:
    {{\"kind\": \"directional\", \"direction\": [x,y,z]}}        direction FROM the light, non-zero
    {{\"kind\": \"point\", \"position\": [x,y,z], \"constant\": Kc, \"linear\": Kl, \"quadratic\": Kq}}
    {{\"kind\": \"spot\", \"position\", \"direction\", \"cut_off_deg\", \"outer_cut_off_deg\",
     \"constant\", \"linear\", \"quadratic\"}}                  angles in [0, 90], inner <= outer
  LearnOpenGL Multiple lights: point and spot terms x attenuation 1/(Kc + Kl d + Kq d^2),
  spot terms also x clamp((theta - cos outer)/(cos inner - cos outer), 0, 1); specular
  pow(max(view_dir . reflect_dir, 0), s), not gated by n . l. blinn-phong uses
  pow(max(n . halfway, 0), s) instead.

model \"opengl-tutorial\" (opengl-tutorial 8, one point light, power / d^2):
  light_pos [x,y,z] (required), diffuse [r,g,b] (required, MaterialDiffuseColor),
  light_color [r,g,b] (default [1, 1, 1]), light_power (default 50),
  specular [r,g,b] (default [0.3,0.3,0.3]), ambient_factor (default 0.1: ambient = 0.1 x diffuse),
  exponent (default 5). A fragment at light_pos (d = 0) is an error (infinite result).

model \"ogldev\" (ogldev 19, one directional light; defaults from tutorial19.cpp):
  color [r,g,b] (default [1, 1, 1]), ambient_intensity (default 0), diffuse_intensity (default 0.2),
  direction [x,y,z] FROM the light (default [0, 0, 1]; normalized in f32, as the tutorial's CPU code does),
  specular_intensity (default 1), specular_power (default 32), texture_color [r,g,b] (default [1, 1, 1]).
  Specular only where n . l > 0; pow is taken before its > 0 test (a negative base gives no specular).


model \"basic_lighting\" (LearnOpenGL Basic lighting, in the chapter's own names):
  FragPos [x,y,z] and Normal [x,y,z] (required), viewPos (default {view_pos}),
  lightPos (default {light_pos}), lightColor (default {light_color}),
  objectColor (default {object_color}), ambientStrength (default {ambient}),
  specularStrength (default {specular}), shininess (default {shininess}).
  result = (ambientStrength*lightColor + diff*lightColor + specularStrength*spec*lightColor) * objectColor.
  How the names map onto the light and material fields of model \"learnopengl\" (Materials
  chapter), which gives the same color up to f32 rounding:
    one light {{\"kind\": \"point\", \"position\": lightPos, \"constant\": 1, \"linear\": 0, \"quadratic\": 0,
      \"ambient\": ambientStrength*lightColor, \"diffuse\": lightColor, \"specular\": specularStrength*lightColor}}
    material {{\"ambient\": objectColor, \"diffuse\": objectColor, \"specular\": objectColor, \"shininess\": shininess}}
    view_pos = viewPos, frag_pos = FragPos, normal = Normal.

OUTPUT: one JSON line per input line:
  {{\"line\": N, \"rgb\": [r,g,b], \"rgb_f64\": [r,g,b], \"lights\": [{{\"ambient\": [..], \"diffuse\": [..], \"specular\": [..]}}, ..]}}
  or {{\"line\": N, \"field\": \"lights[0].linear\", \"error\": \"lights[0].linear: what is wrong\", \"column\": C}}.
  rgb and rgb_f64 are unclamped linear RGB.
EXIT STATUS: 0 all lines succeeded, 1 some line failed, 2 usage or input error (bad argument,
unreadable file, a line over {max} bytes), 3 internal failure (standard output full).",
        max = MAX_LINE_BYTES,
        view_pos = v(b.view_pos),
        light_pos = v(b.light_pos),
        light_color = v(b.light_color),
        object_color = v(b.object_color),
        ambient = b.ambient_strength,
        specular = b.specular_strength,
        shininess = b.shininess,
    )
}

/// Arguments of `lightlab shade`.
#[derive(clap::Args, Clone, Debug, PartialEq, Eq)]
#[command(after_help = models_help())]
pub struct ShadeArgs {
    /// JSON-lines file to read; standard input when absent or `-`.
    pub input: Option<PathBuf>,
}

/// Run `lightlab shade`: read the input, print one JSON line per case.
///
/// `Success` when every line succeeded, `Problems` when some line failed, an input
/// error when the input cannot be opened or read or has a line over
/// [`MAX_LINE_BYTES`], an internal error when the output cannot be written (a closed
/// pipe stops quietly).
pub fn run(args: &ShadeArgs) -> CliResult {
    let mut out = output::stdout();
    let ok = match args.input.as_deref() {
        None => process(std::io::stdin().lock(), out.writer(), "standard input")?,
        Some(p) if p.as_os_str() == "-" => process(std::io::stdin().lock(), out.writer(), "standard input")?,
        Some(path) => {
            let file = std::fs::File::open(path)
                .map_err(|e| CliError::Input(format!("cannot open {}: {e}", path.display())))?;
            process(std::io::BufReader::new(file), out.writer(), &path.display().to_string())?
        }
    };
    out.finish()?;
    Ok(Outcome::from_ok(ok))
}

/// What [`read_line_capped`] found.
#[derive(Debug, PartialEq, Eq)]
enum LineRead {
    /// End of input, nothing read.
    End,
    /// A line (its `\n`, if any, included).
    Line,
    /// More than `cap` bytes before the next `\n`.
    TooLong,
}

/// Read up to and including the next `\n` into `buf`, but never more than `cap` bytes
/// of line content.
fn read_line_capped(input: &mut impl BufRead, buf: &mut Vec<u8>, cap: usize) -> std::io::Result<LineRead> {
    loop {
        let available = match input.fill_buf() {
            Ok(bytes) => bytes,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if available.is_empty() {
            return Ok(if buf.is_empty() { LineRead::End } else { LineRead::Line });
        }
        let (take, done) = match available.iter().position(|&b| b == b'\n') {
            Some(i) => (i + 1, true),
            None => (available.len(), false),
        };
        let content = take - usize::from(done);
        if buf.len() + content > cap {
            return Ok(LineRead::TooLong);
        }
        buf.extend_from_slice(&available[..take]);
        input.consume(take);
        if done {
            return Ok(LineRead::Line);
        }
    }
}

/// Shade every line of `input` (named `source` in errors), writing one JSON line per
/// case to `out`.
///
/// Returns `Ok(true)` when every case succeeded and `Ok(false)` when some line
/// produced an error object. A line that is not valid UTF-8 is an error line. A read
/// error or a line over [`MAX_LINE_BYTES`] is [`CliError::Input`] naming `source` and
/// the line; a write error is mapped by [`output::stdout_error`].
pub fn process(mut input: impl BufRead, out: &mut impl Write, source: &str) -> Result<bool, CliError> {
    let mut all_ok = true;
    let mut bytes = Vec::new();
    let mut line_no = 0usize;
    loop {
        bytes.clear();
        let read = read_line_capped(&mut input, &mut bytes, MAX_LINE_BYTES)
            .map_err(|e| CliError::Input(format!("{source}: line {}: cannot read: {e}", line_no + 1)))?;
        match read {
            LineRead::End => break,
            LineRead::TooLong => {
                out.flush().map_err(output::stdout_error)?;
                return Err(CliError::Input(format!(
                    "{source}: line {}: longer than {MAX_LINE_BYTES} bytes (is this a JSON-lines file?)",
                    line_no + 1
                )));
            }
            LineRead::Line => {}
        }
        line_no += 1;
        let result = match std::str::from_utf8(&bytes) {
            Err(e) => Some(Err(LineError {
                field: "line".into(),
                reason: "not valid UTF-8".into(),
                column: Some(e.valid_up_to() + 1),
            })),
            Ok(text) => {
                let text = text.trim();
                if text.is_empty() || text.starts_with('#') {
                    None
                } else {
                    Some(shade_line(text))
                }
            }
        };
        let json = match result {
            None => continue,
            Some(Ok(shaded)) => shaded.to_json(line_no),
            Some(Err(error)) => {
                all_ok = false;
                error.to_json(line_no)
            }
        };
        writeln!(out, "{json}").map_err(output::stdout_error)?;
    }
    Ok(all_ok)
}

/// What is wrong with one input line: the field path (`lights[1].cut_off_deg`, or
/// `line` for the line as a whole), the reason, and the 1-based column when known.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{field}: {reason}")]
pub struct LineError {
    /// The field path, as written in the input.
    pub field: String,
    /// What is wrong, in the input's own words.
    pub reason: String,
    /// The byte column in the line (1-based) where the reader stopped, when known.
    pub column: Option<usize>,
}

impl LineError {
    fn new(field: impl Into<String>, reason: impl Into<String>) -> LineError {
        LineError { field: field.into(), reason: reason.into(), column: None }
    }

    /// The output line for input line `line`.
    pub fn to_json(&self, line: usize) -> String {
        let message = self.to_string();
        let json = ErrorJson { line, field: &self.field, error: &message, column: self.column };
        serde_json::to_string(&json)
            .unwrap_or_else(|_| format!("{{\"line\": {line}, \"error\": \"unprintable error\"}}"))
    }
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
    field: &'a str,
    error: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    column: Option<usize>,
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
        serde_json::to_string(&json).unwrap_or_else(|e| LineError::new("output", e.to_string()).to_json(line))
    }
}

/// Parse and shade one JSON case.
///
/// Errors name the field (`lights[1].cut_off_deg: ...`): invalid JSON, a
/// missing field, a wrong type, `null`, a number that is not finite in `f32`, an
/// unknown field, model or material, a repeated key, an inverted spot cone,
/// invalid attenuation, a zero normal or direction, or a result that is not finite.
pub fn shade_line(text: &str) -> Result<ShadeOutput, LineError> {
    let case = input::parse_case(text)?;
    let (rgb, lights) = case.shade_f32();
    let rgb_f64 = eval::shade_f64(&case);
    let finite = rgb.is_finite()
        && rgb_f64.is_finite()
        && lights.iter().all(|t| t.ambient.is_finite() && t.diffuse.is_finite() && t.specular.is_finite());
    if !finite {
        let reason = match case.model {
            eval::ModelCase::OpenGLTutorial(_) => {
                "not finite (frag_pos at light_pos gives light_power / 0, or inputs overflow f32)"
            }
            _ => "not finite (inputs overflow f32)",
        };
        return Err(LineError::new("result", reason));
    }
    Ok(ShadeOutput { rgb, rgb_f64, lights })
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
    fn example_matches_scene_terms() {
        let out = shade_line(&EXAMPLE.replace('\n', " ")).expect("example is valid");
        assert_eq!(out.lights.len(), 3);
        // The f32 and f64 paths agree to f32 rounding (a few ulps of values near 1).
        assert!((out.rgb.as_dvec3() - out.rgb_f64).abs().max_element() < 1e-5, "{:?} vs {:?}", out.rgb, out.rgb_f64);
    }

    #[test]
    fn duplicate_keys_inside_lights_and_materials_are_errors() {
        let line = EXAMPLE.replace('\n', " ");
        let dup_light = line.replacen(r#""cut_off_deg": 12.5"#, r#""cut_off_deg": 12.5, "cut_off_deg": 13"#, 1);
        let err = shade_line(&dup_light).expect_err("duplicate in a light");
        assert_eq!(
            (err.field.as_str(), err.reason.starts_with("duplicate key")),
            ("lights[2].cut_off_deg", true),
            "{err}"
        );
        // The column points into the line, past the first cut_off_deg.
        let first = dup_light.find("cut_off_deg").expect("present");
        assert!(err.column.is_some_and(|c| c > first), "{err:?}");
        let dup_material = line.replacen(r#""shininess": 32"#, r#""shininess": 32, "shininess": 8"#, 1);
        assert_eq!(shade_line(&dup_material).expect_err("dup").field, "material.shininess");
    }

    #[test]
    fn capped_reader_stops_at_the_cap() {
        let mut input = std::io::Cursor::new(b"abc\ndefgh\nij".to_vec());
        let mut buf = Vec::new();
        assert_eq!(read_line_capped(&mut input, &mut buf, 4).expect("read"), LineRead::Line);
        assert_eq!(buf, b"abc\n");
        buf.clear();
        assert_eq!(read_line_capped(&mut input, &mut buf, 4).expect("read"), LineRead::TooLong);
        let mut input = std::io::Cursor::new(b"abcd\nij".to_vec());
        buf.clear();
        // Exactly `cap` bytes of content is allowed; the newline is not counted.
        assert_eq!(read_line_capped(&mut input, &mut buf, 4).expect("read"), LineRead::Line);
        buf.clear();
        assert_eq!(read_line_capped(&mut input, &mut buf, 4).expect("read"), LineRead::Line);
        assert_eq!(buf, b"ij");
        buf.clear();
        assert_eq!(read_line_capped(&mut input, &mut buf, 4).expect("read"), LineRead::End);
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
            (r#"{"frag_pos": [0, 0, 0], "frag_pos": [0, 0, 1]}"#, "frag_pos: duplicate key"),
            (r#"{"model": "ogldev", "model": "ogldev"}"#, "model: duplicate key"),
            (r#"{"frag_pos": null}"#, "frag_pos: expected an array of 3 numbers, got null"),
            (r#"{"lights": {}}"#, "lights: expected an array, got an object"),
            (r#"{"material": [1, 2]}"#, "material: expected an object, got an array"),
            (r#"{"frag_pos": [0, 0, 0, 0]}"#, "frag_pos: expected an array of 3 numbers, got 4 elements"),
            (
                r#"{"model": "basic_lighting", "frag_pos": [0, 0, 0]}"#,
                "frag_pos: unknown field for model \"basic_lighting\"",
            ),
            (r#"{"model": "basic_lighting", "FragPos": [0, 0, 0]}"#, "Normal: missing"),
            (r#"{} x"#, "line: invalid JSON"),
        ];
        for (input, expected) in cases {
            let err = shade_line(input).expect_err(input).to_string();
            assert!(err.starts_with(expected), "{input}: got {err:?}, expected {expected:?}");
        }
    }
}
