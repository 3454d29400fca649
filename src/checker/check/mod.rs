//! `lightlab check-shader`: run a user's complete fragment shader on llvmpipe over random
//! cases of a model and compare it with the model's `f64` reference.
//!
//! | step | what happens |
//! | --- | --- |
//! | preprocess | macros are expanded and conditionals applied, line for line ([`preprocess`]); the scanner and the rewrite read that text, the driver's first compile the file itself |
//! | parse | top-level `struct`s, `in` / `uniform` / `out` declarations and interface blocks are read ([`glsl`]: comments and preprocessor lines skipped, every GLSL literal form) |
//! | limits | arrays over [`MAX_ARRAY`], uniform storage over [`MAX_UNIFORM_COMPONENTS`] and files over [`MAX_SOURCE_BYTES`] are refused before the driver sees them |
//! | compile | the file is compiled as it is; errors carry the line numbers of the file |
//! | colour | the `out` at `layout(location = 0)`, else the only `out`, else the only `vec4` `out` |
//! | map | each declared leaf (`lightPos`, `light.position`, `pointLights[2].constant`) is matched to a model quantity by the tutorials' name, or through the `--uniforms` TOML |
//! | rewrite | the `#version` line is blanked; `in` and per-case `uniform` qualifiers are blanked (the variables become globals; an anonymous interface block's members become globals, a named one becomes a struct variable), `sampler2D` becomes `vec4` holding the case's texel and `texture(s, uv)` returns it, `main` is renamed; line numbers are kept |
//! | wrap | a generated `batch_main` loads every leaf from the batch inputs with `texelFetch`, calls the user's `main`, and writes the user's `out` variable |
//! | compare | per case and channel, `|llvmpipe - f64 reference|` against the model's bound ([`crate::oracle::cases::bounds`]), undefined cases excluded |
//!
//! Quantities of the model that the shader does not declare are fixed to the chapter's
//! value (`ambientStrength` 0.1, `specularStrength` 0.5, `shininess` 32, the casters'
//! attenuation 1, 0.09, 0.032 and the spotlight's cut-offs cos 12.5°, cos 17.5°, ...),
//! because a shader that does not declare them hard-codes them; one the chapter gives no
//! value stays random, and the report's notes say which. A quantity the cases vary that
//! the shader declares and never reads (`uniform vec3 lightPos;` beside a constant lamp)
//! gets a note of its own, first: the colour cannot follow it. The TOML's `[values]` table fixes
//! any quantity, declared or not (a declared one receives the value as its uniform). The
//! same policy holds for every model. The multiple-lights scene (`dirLight`, `pointLights[i]`, `spotLight`) stays a set
//! of real uniforms, one draw per scene.
//!
//! Every entry of `[names]` must match a name the shader declares, every entry of
//! `[values]` a quantity of the model (declared by the shader or not), and values must be
//! finite: one number for a float quantity (`shininess = [1, 2, 3]` is an error, not 1),
//! one number or an array of 3 for a vector (one number fills all three); messages name
//! the line.
//!
//! # The mapping file
//! ```toml
//! [names]            # shader name = model name (a struct or array name maps all its fields)
//! uLightPos = "lightPos"
//! uLight = "light"
//! [values]           # model quantities fixed in every case (hard-coded, or the lab's uniforms)
//! shininess = 64.0
//! lightColor = [1.0, 1.0, 1.0]
//! ```

use crate::checker::texts;
use crate::gl::batch::{log_excerpt, Batch, Uniform};
use crate::gl::context::{GlContext, GlError};
use crate::gl::layout::Layout;
use crate::gl::model_id::ModelId;
use crate::oracle::cases::{self, CaseModel, Group, QType, Slot};

pub mod characters;
pub mod glsl;
pub mod loops;
mod mapping;
pub mod pair;
pub mod preprocess;
pub mod report;
mod rewrite;

pub use mapping::{parse_mapping, Mapping};
pub use report::CheckReport;

use glsl::{Declaration, Parsed, Storage};
use mapping::{known_names, map_leaves, Leaf};
pub use mapping::{RULE_FORBIDDEN, RULE_REQUIRED};

/// Largest array size `check-shader` accepts in a top-level declaration, struct field or
/// block member (the shipped shaders use 4): a larger one is refused before compiling,
/// because the driver allocates the storage while it compiles.
pub const MAX_ARRAY: usize = 4096;

/// Most `float` components of `uniform` storage accepted (llvmpipe's
/// `GL_MAX_FRAGMENT_UNIFORM_COMPONENTS` is 16 384; GL 3.3 guarantees 1 024).
pub const MAX_UNIFORM_COMPONENTS: usize = 16_384;

/// Largest shader accepted, in bytes (4 MiB; the tutorials' shaders are under 4 KiB).
pub const MAX_SOURCE_BYTES: usize = 4 << 20;

/// Why a check could not give a verdict, or the shader's compile error.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CheckError {
    /// A usage or input error: a model check-shader does not check (`gouraud` without a
    /// vertex shader), a count out of range, unreadable or invalid mapping, a name the
    /// model does not know, a type mismatch, no colour output, storage above the limits.
    /// Exit status 2.
    #[error("{0}")]
    Usage(String),
    /// The shader does not compile on llvmpipe: the driver's log (line numbers are the
    /// file's) and the numbered lines it names. Exit status 1.
    #[error("the shader does not compile on llvmpipe:\n{}\n{excerpt}", log.trim_end())]
    Compile {
        /// The info log.
        log: String,
        /// The file's lines the log points at.
        excerpt: String,
    },
    /// The vertex shader of a pair does not compile: as [`CheckError::Compile`], with the
    /// vertex file's line numbers. Exit status 1.
    #[error("the vertex shader does not compile on llvmpipe:\n{}\n{excerpt}", log.trim_end())]
    VertexCompile {
        /// The info log.
        log: String,
        /// The vertex file's lines the log points at.
        excerpt: String,
    },
    /// A loop ran past the loop guard's cap ([`loops::LOOP_CAP`] iterations) in `cases` of
    /// the `of` cases run: on a GPU the shader would hang, so its output is not graded.
    /// Exit status 1.
    #[error("does not terminate: a loop ran past {cap} iterations in {cases} of {of} cases (on a GPU this shader would hang; llvmpipe ends every loop after 65 535 iterations, so its output only looked finished)", cap = loops::LOOP_CAP)]
    DoesNotTerminate {
        /// Cases whose loops reached the cap.
        cases: usize,
        /// Cases run.
        of: usize,
    },
    /// The shader breaks a rule of the exercise's mapping (`[rules]`: it declares a
    /// quantity the exercise forbids, or not one it requires): the msgid
    /// ([`mapping::RULE_FORBIDDEN`] or [`mapping::RULE_REQUIRED`]) and the model's name.
    /// Its output is not graded. Exit status 1.
    #[error("{}", rule.0.replace("{}", &rule.1))]
    BreaksRule {
        /// The msgid and the name it is filled with.
        rule: (&'static str, String),
    },
    /// OpenGL is missing, a draw failed, or lightlab's rewrite of a shader that compiles
    /// did not compile (a lightlab defect). Exit status 3.
    #[error("OpenGL: {0}")]
    Gl(#[from] GlError),
}

fn usage<T>(message: impl Into<String>) -> Result<T, CheckError> {
    Err(CheckError::Usage(message.into()))
}

/// The cases `check-shader` compares a fragment shader with: those of every model but the
/// per-vertex `gouraud`. Errors: [`CheckError::Usage`] for `gouraud`.
pub fn model_for_check(model: ModelId) -> Result<&'static CaseModel, CheckError> {
    match model {
        ModelId::Gouraud => usage("gouraud is a per-vertex model; check-shader checks fragment shaders"),
        ModelId::BasicLighting
        | ModelId::Materials
        | ModelId::LightingMaps
        | ModelId::Directional
        | ModelId::Point
        | ModelId::Spot
        | ModelId::MultipleLights
        | ModelId::OpenGLTutorial8
        | ModelId::Ogldev19
        | ModelId::NormalMatrix
        | ModelId::BlinnPhong
        | ModelId::LightingMapsEmission => Ok(model.case_model()),
    }
}

/// Checks the counts before anything is allocated: `n` in `1..=`[`cases::MAX_CASES`].
/// Errors: [`CheckError::Usage`] naming `--cases`.
pub fn check_cases(n: usize) -> Result<(), CheckError> {
    if n == 0 || n > cases::MAX_CASES {
        return usage(format!("--cases must be in 1..={} (got {n})", cases::MAX_CASES));
    }
    Ok(())
}

fn line_of(src: &str, byte: usize) -> usize {
    src.as_bytes()[..byte.min(src.len())].iter().filter(|&&b| b == b'\n').count() + 1
}

/// Refuses sources the driver would spend unbounded memory on: a file over
/// [`MAX_SOURCE_BYTES`], an array over [`MAX_ARRAY`], uniform storage over
/// [`MAX_UNIFORM_COMPONENTS`].
fn check_storage(src: &str, parsed: &Parsed) -> Result<(), CheckError> {
    if src.len() > MAX_SOURCE_BYTES {
        return usage(format!("the shader is {} bytes, above the limit of {MAX_SOURCE_BYTES}", src.len()));
    }
    if parsed.largest_array > MAX_ARRAY {
        return usage(format!(
            "an array of {} elements is declared; check-shader accepts at most {MAX_ARRAY}",
            parsed.largest_array
        ));
    }
    let mut total = 0usize;
    for d in parsed.decls.iter().filter(|d| d.storage == Storage::Uniform) {
        let one = match &d.block {
            Some(b) => b
                .members
                .iter()
                .map(|m| glsl::components(&m.ty, &parsed.structs, 0).saturating_mul(m.array.unwrap_or(1)))
                .fold(0usize, usize::saturating_add),
            None => glsl::components(&d.ty, &parsed.structs, 0),
        };
        total = total.saturating_add(one.saturating_mul(d.array.unwrap_or(1)));
        if total > MAX_UNIFORM_COMPONENTS {
            return usage(format!(
                "line {}: the uniforms take more than {MAX_UNIFORM_COMPONENTS} float components",
                line_of(src, d.type_span.0)
            ));
        }
    }
    Ok(())
}

/// The colour a fragment shader writes, as the batch's wrapper reads it.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Colour {
    /// The expression holding it after [`Colour::find`]'s renaming (`FragColor`, `lightlab_fc0`).
    pub name: String,
    /// Its GLSL type (`vec4`, `vec3` or `float`).
    pub ty: String,
    /// A global the batch body declares for it (the legacy built-ins' stand-in), or nothing.
    pub declaration: &'static str,
}

/// The legacy built-in colours, each with a stand-in identifier of the same length (so
/// every offset the parse found stays right), the colour read from it, and its declaration.
const LEGACY_COLOURS: [(&str, &str, &str, &str); 2] = [
    ("gl_FragColor", "lightlab_fc0", "lightlab_fc0", "vec4 lightlab_fc0;\n"),
    ("gl_FragData", "lightlab_fd", "lightlab_fd[0]", "vec4 lightlab_fd[8];\n"),
];

impl Colour {
    /// The colour output: the `out` at `layout(location = 0)`, else the only `out`, else
    /// the only `vec4` `out`. A shader with no `out` that the driver compiled may write the
    /// legacy `gl_FragColor` or `gl_FragData[0]` (GLSL 1.10–1.30, and drivers that keep them
    /// in later versions): those are renamed in `text` to a global the batch declares, since
    /// a shader cannot write a built-in colour and the batch's own outputs at once.
    ///
    /// Errors: [`CheckError::Usage`] when there is none or it is ambiguous.
    pub(super) fn find(parsed: &Parsed, text: &mut String) -> Result<Colour, CheckError> {
        let outs: Vec<&Declaration> = parsed.decls.iter().filter(|d| d.storage == Storage::Out).collect();
        let declared = |d: &Declaration| Colour { name: d.name.clone(), ty: d.ty.clone(), declaration: "" };
        if let Some(d) = outs.iter().find(|d| d.location == Some(0)) {
            return Ok(declared(d));
        }
        match outs[..] {
            [] => {
                for (builtin, stand_in, read, declaration) in LEGACY_COLOURS {
                    if let Some(renamed) = rename_identifier(text, builtin, stand_in) {
                        *text = renamed;
                        return Ok(Colour { name: read.to_owned(), ty: "vec4".to_owned(), declaration });
                    }
                }
                usage(texts::tr(texts::NO_COLOUR_OUTPUT))
            }
            [one] => Ok(declared(one)),
            _ => {
                let vec4: Vec<&&Declaration> = outs.iter().filter(|d| d.ty == "vec4").collect();
                match vec4[..] {
                    [one] => Ok(declared(one)),
                    _ => {
                        let names: Vec<&str> = outs.iter().map(|d| d.name.as_str()).collect();
                        usage(texts::tr_fill(texts::SEVERAL_OUTPUTS, &[&names.join(", ")]))
                    }
                }
            }
        }
    }
}

/// `text` with every whole identifier `from` replaced by `to` (of the same length), or
/// `None` when `from` does not occur as an identifier.
fn rename_identifier(text: &str, from: &str, to: &str) -> Option<String> {
    debug_assert_eq!(from.len(), to.len(), "a stand-in keeps every offset");
    let is_ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let (mut done, mut found) = (0, false);
    for (at, _) in text.match_indices(from) {
        let before = at.checked_sub(1).map(|k| bytes[k]);
        let after = bytes.get(at + from.len()).copied();
        if before.is_some_and(is_ident) || after.is_some_and(is_ident) {
            continue;
        }
        out.push_str(&text[done..at]);
        out.push_str(to);
        done = at + from.len();
        found = true;
    }
    out.push_str(&text[done..]);
    found.then_some(out)
}

/// The quantities fixed for the check (`(name, value)`), with a note for each. One policy
/// for every model:
/// - a `[values]` entry fixes its quantity, declared by the shader or not (a declared one
///   then receives that value in every case: a teacher tests with the lab's uniforms);
/// - a per-case quantity the shader does not declare is fixed to the chapter's value
///   ([`crate::gl::layout::Quantity::default`]), because the shader hard-codes it;
/// - one without a chapter value (a position, a colour the chapter varies) stays random,
///   and the note says so: the model's answer depends on it and the shader's cannot.
///
/// `silent` names quantities whose absence needs no note (the pair check's `viewPos`: its
/// eye is the camera's, so a shader lighting in view space has it at the origin).
fn fixed_quantities(
    model: &Layout,
    leaves: &[Leaf],
    mapping: &Mapping,
    silent: &[&str],
    notes: &mut Vec<String>,
) -> Result<Vec<(&'static str, [f32; 3])>, CheckError> {
    for key in mapping.values.keys() {
        if !model.quantities.iter().any(|q| q.name == key) {
            return usage(format!(
                "{}values.{key}: model {} has no such quantity; it knows: {}",
                mapping.at("values", key),
                model.id,
                known_names(model)
            ));
        }
    }
    let mut fixed = Vec::new();
    for q in model.quantities {
        let declared = leaves.iter().any(|l| l.quantity.is_some_and(|lq| lq.name == q.name));
        let shown = |v: &[f32; 3]| if q.ty == QType::Float { format!("{}", v[0]) } else { format!("{v:?}") };
        if let Some(v) = mapping.values.get(q.name) {
            if q.ty == QType::Float && mapping.vectors.contains(q.name) {
                return usage(format!(
                    "{}values.{}: {} is a float: give one number, not an array of 3",
                    mapping.at("values", q.name),
                    q.name,
                    q.name
                ));
            }
            // a quantity the cases never draw below 0 (a colour, a strength, the shininess, an
            // attenuation constant) refuses a negative value: no shader is right or wrong on it
            if let Some(bad) = q.range.filter(|(lo, _)| *lo >= 0.0).and(v.iter().find(|x| **x < 0.0)) {
                return usage(format!(
                    "{}values.{}: {} is negative; {} is never below 0 (the cases draw it from {:?})",
                    mapping.at("values", q.name),
                    q.name,
                    bad,
                    q.name,
                    q.range.unwrap_or_default()
                ));
            }
            fixed.push((q.name, *v));
            let how = if declared { texts::tr(texts::NOTE_FIXED_RECEIVED) } else { String::new() };
            notes.push(texts::tr_fill(texts::NOTE_FIXED_BY_MAPPING, &[q.name, &texts::number(&shown(v)), &how]));
        } else if !declared {
            let note = match (q.default, q.slot) {
                (Some(v), Slot::Case { .. }) => {
                    fixed.push((q.name, v));
                    Some(texts::tr_fill(texts::NOTE_NOT_DECLARED_FIXED, &[q.name, &texts::number(&shown(&v))]))
                }
                (None, Slot::Case { .. }) => Some(texts::tr_fill(texts::NOTE_NOT_DECLARED_RANDOM, &[q.name])),
                _ => None,
            };
            notes.extend(note.filter(|_| !silent.contains(&q.name)));
        }
    }
    Ok(fixed)
}

/// A user's shader compiled against a model, ready to run on any cases of that model
/// (`check-shader` runs it once; the diagnosis runs it again on cases with terms or lights
/// switched off).
#[derive(Debug)]
pub struct CompiledShader<'a> {
    model: &'static CaseModel,
    batch: Batch<'a>,
    leaves: Vec<Leaf>,
    fixed: Vec<(&'static str, [f32; 3])>,
    /// Notes so far: fixed quantities, then inactive uniforms met by [`Self::run`].
    notes: std::cell::RefCell<Vec<String>>,
}

impl CompiledShader<'_> {
    /// The model the shader is checked against.
    pub fn model(&self) -> &'static CaseModel {
        self.model
    }

    /// Model quantities fixed for this shader (not declared, or fixed by the mapping).
    pub fn fixed(&self) -> &[(&'static str, [f32; 3])] {
        &self.fixed
    }

    /// Whether the shader declares the model quantity `name` (a case input or, for
    /// `multiple_lights`, a scene uniform such as `dirLight.diffuse`).
    pub fn declares(&self, name: &str) -> bool {
        self.leaves.iter().any(|l| l.model == name || l.quantity.is_some_and(|q| q.name == name))
    }

    /// `n` cases from `seed`, with this shader's fixed quantities.
    ///
    /// Errors: [`CheckError::Usage`] when `n` is outside `1..=`[`cases::MAX_CASES`].
    pub fn generate(&self, n: usize, seed: u64) -> Result<Vec<Group>, CheckError> {
        check_cases(n)?;
        Ok(cases::generate_cases(self.model, n, seed, &self.fixed)?)
    }

    /// The shader's output `outputs[group][case]` on `groups` (cases of [`Self::model`]).
    ///
    /// Errors: [`CheckError::Gl`] if a draw fails; [`CheckError::Usage`] for a uniform the
    /// group's scene does not have.
    pub fn run(&self, groups: &[Group]) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
        run_groups(&self.batch, self.model, groups, &self.leaves, &mut self.notes.borrow_mut())
    }

    /// Case `i` of group `g` as a counterexample block in the shader's own names
    /// (`lightPos`, `light.position`): its inputs, then `expected (<expected>) = want` and
    /// `got (llvmpipe) = got`. The exercises' variant check uses it with the reference
    /// solution's colour as `want`.
    pub fn describe(
        &self,
        groups: &[Group],
        (g, i): (usize, usize),
        want: &[f64],
        expected: &str,
        got: &[f32],
    ) -> String {
        report::describe_case(self.model, &self.leaves, &groups[g].rows[i], (want, expected), got, g)
    }

    /// Compares `outputs` (from [`Self::run`] on `groups`) with the `f64` reference.
    pub fn report(&self, groups: &[Group], outputs: &[Vec<[f32; 4]>]) -> CheckReport {
        report::compare(self.model, groups, outputs, &self.leaves, self.notes.borrow().clone())
    }

    /// The whole check: [`Self::generate`] `n` cases from `seed`, [`Self::run`] the shader
    /// on them and [`Self::report`]; the cases and outputs come back too, so a diagnosis
    /// can look at the same cases.
    ///
    /// Errors: as [`Self::generate`] and [`Self::run`].
    pub fn check(&self, n: usize, seed: u64) -> Result<Checked, CheckError> {
        let groups = self.generate(n, seed)?;
        let outputs = self.run(&groups)?;
        let report = self.report(&groups, &outputs);
        Ok(Checked { groups, outputs, report })
    }
}

/// What a check ran and found: [`CompiledShader::check`] on groups of cases, and the pair
/// check ([`pair::CompiledPair::check`]) on groups of triangles.
#[derive(Debug)]
pub struct Checked<G = Group> {
    /// The cases (or triangles), in groups sharing uniforms.
    pub groups: Vec<G>,
    /// The shader's output `outputs[group][case]`.
    pub outputs: Vec<Vec<[f32; 4]>>,
    /// The verdict and statistics.
    pub report: CheckReport,
}

/// A non-ASCII character outside the comments of `source` ([`characters`]) as the
/// compile error Mesa does not give: [`CheckError::Compile`], or
/// [`CheckError::VertexCompile`] for a `vertex` shader.
pub(crate) fn pasted_characters(source: &str, vertex: bool) -> Result<(), CheckError> {
    match characters::log(source) {
        None => Ok(()),
        Some(log) if vertex => Err(CheckError::VertexCompile { excerpt: log_excerpt(source, &log), log }),
        Some(log) => Err(CheckError::Compile { excerpt: log_excerpt(source, &log), log }),
    }
}

/// The learner's `source` as the checker reads it, preprocessed ([`preprocess`]: macros
/// expanded, conditionals applied, lines kept), and the declarations read from that text.
/// When it cannot be preprocessed, the declarations of the original text (for the limits
/// checked before the driver compiles the file) and the error, which [`preprocessed`]
/// reports once the driver has compiled the original: the learner's own errors come from
/// the driver, with their lines.
pub(crate) fn read(source: &str) -> (Result<String, preprocess::PreprocessError>, Parsed) {
    let text = preprocess::preprocess(source);
    let parsed = glsl::parse(text.as_deref().unwrap_or(source));
    (text, parsed)
}

/// The preprocessed text of [`read`], once the driver compiled the original. Errors:
/// [`CheckError::Usage`] for a file the driver compiles but [`preprocess`] cannot read (a
/// macro expanding past its bounds, a directive it does not know).
pub(crate) fn preprocessed(
    text: Result<String, preprocess::PreprocessError>,
    vertex: bool,
) -> Result<String, CheckError> {
    text.map_err(|e| {
        let which = if vertex { "vertex shader" } else { "shader" };
        CheckError::Usage(format!(
            "the {which}'s preprocessor lines could not be expanded ({e}); the driver compiles them, so this is a \
             lightlab limitation: please report it, or write the declarations without macros"
        ))
    })
}

/// Compiles `source` (a complete fragment shader) for `model`: maps its declarations
/// to the model's quantities and fixes the ones it does not declare (see the module docs).
///
/// Compiles the user's file as it is on the driver, in the calling process.
///
/// Errors: [`CheckError::Usage`] (`gouraud`, which is per vertex, storage above the
/// limits, unmapped name, type mismatch, no colour output), [`CheckError::Compile`] (with the file's line
/// numbers), [`CheckError::Gl`].
pub fn compile_shader<'a>(
    ctx: &'a GlContext,
    source: &str,
    model: ModelId,
    mapping: &Mapping,
) -> Result<CompiledShader<'a>, CheckError> {
    let model = model_for_check(model)?;
    pasted_characters(source, false)?;
    let (text, parsed) = read(source);
    check_storage(text.as_deref().unwrap_or(source), &parsed)?;
    if let Err(e) = crate::gl::batch::compile_fragment(ctx, source) {
        return Err(match e {
            GlError::Compile { log, .. } => CheckError::Compile { excerpt: log_excerpt(source, &log), log },
            other => CheckError::Gl(other),
        });
    }
    let mut text = preprocessed(text, false)?;
    let out = Colour::find(&parsed, &mut text)?;
    if parsed.main.is_none() {
        return usage(texts::tr(texts::NO_MAIN));
    }
    let mapped = map_leaves(model.layout, &parsed, mapping, &[Storage::In, Storage::Uniform])?;
    let case_decls: Vec<usize> =
        mapped.iter().filter(|(_, leaves)| leaves.iter().any(|l| l.quantity.is_some())).map(|(d, _)| *d).collect();
    let leaves: Vec<Leaf> = mapped.into_iter().flat_map(|(_, l)| l).collect();
    if let Some(rule) = mapping::broken_rule(model.layout, mapping, &leaves)? {
        return Err(CheckError::BreaksRule { rule });
    }
    let mut notes = Vec::new();
    let fixed = fixed_quantities(model.layout, &leaves, mapping, &[], &mut notes)?;
    // first: a quantity the shader ignores explains more than one it fixes
    notes.splice(0..0, mapping::never_read_notes(&leaves, &fixed));
    let body = format!(
        "{}{}{}#line 1 1\n{}\n{}",
        rewrite::extensions(&text, &parsed),
        rewrite::prelude(),
        out.declaration,
        rewrite::rewrite(&text, &parsed, &case_decls),
        rewrite::wrapper(&leaves, "", &out)
    );
    let batch = match Batch::new(ctx, &body, model.n_inputs, 1) {
        Ok(b) => b,
        Err(GlError::Compile { log, .. }) => {
            // Mesa's log only: the rewritten text is lightlab's, and in `grade` this
            // message reaches the student's row.
            return Err(CheckError::Gl(GlError::Gl {
                call: "compiling the rewritten shader (a lightlab limitation; please report)".into(),
                detail: log,
            }));
        }
        Err(e) => return Err(e.into()),
    };
    Ok(CompiledShader { model, batch, leaves, fixed, notes: std::cell::RefCell::new(notes) })
}

fn run_groups(
    batch: &Batch<'_>,
    model: &CaseModel,
    groups: &[Group],
    leaves: &[Leaf],
    notes: &mut Vec<String>,
) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
    let mut outputs = Vec::with_capacity(groups.len());
    for group in groups {
        for leaf in leaves.iter().filter(|l| l.quantity.is_none()) {
            let Some((_, value)) = group.uniforms.iter().find(|(name, _)| *name == leaf.model) else {
                return usage(format!(
                    "`{}` maps to `{}`, which the model's scene does not have",
                    leaf.user, leaf.model
                ));
            };
            let value = match *value {
                Uniform::Vec3([x, y, z]) if leaf.carries_vec3 => {
                    Uniform::Vec4([x, y, z, mapping::carried_w(&leaf.model)])
                }
                other => other,
            };
            match batch.set_uniform(&leaf.user, value) {
                Ok(()) => {}
                // a uniform never read has its note already (mapping::never_read_notes)
                Err(GlError::Input { .. }) if !leaf.read => {}
                Err(GlError::Input { .. }) => {
                    let note = texts::tr_fill(texts::NOTE_INACTIVE, &[&leaf.user]);
                    if !notes.contains(&note) {
                        notes.push(note);
                    }
                }
                Err(e) => return Err(e.into()),
            }
        }
        let mut out = batch.run(&group.columns(model.n_inputs))?;
        outputs.push(out.swap_remove(0));
    }
    terminated(&outputs)?;
    Ok(outputs)
}

/// Errors: [`CheckError::DoesNotTerminate`] when any case of `outputs` carries the loop
/// guard's mark.
pub(crate) fn terminated(outputs: &[Vec<[f32; 4]>]) -> Result<(), CheckError> {
    let of = outputs.iter().map(Vec::len).sum();
    let cases = outputs.iter().flatten().filter(|c| loops::marked(c)).count();
    if cases == 0 {
        Ok(())
    } else {
        Err(CheckError::DoesNotTerminate { cases, of })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_whole_identifiers_are_renamed() {
        let text = "gl_FragColor = c; my_gl_FragColor = d; gl_FragColorX = e; (gl_FragColor).rgb";
        let renamed = rename_identifier(text, "gl_FragColor", "lightlab_fc0").unwrap();
        assert_eq!(renamed, "lightlab_fc0 = c; my_gl_FragColor = d; gl_FragColorX = e; (lightlab_fc0).rgb");
        assert_eq!(renamed.len(), text.len(), "offsets kept");
        assert_eq!(rename_identifier("my_gl_FragColor = d;", "gl_FragColor", "lightlab_fc0"), None);
    }
}
