//! The exercise catalogue: every exercise of the four texts, and our own, each with a
//! statement, a starter, a reference solution and a check.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | shader check | the learner's fragment shader against a model's `f64` reference ([`crate::checker::check`]), diagnosed with the mistake catalogue |
//! | variant check | the learner's shader against the model's function file with an exercise's edits applied (run on llvmpipe, within `2·bound`) |
//! | numeric check | a number the crate computes; the learner's answer must be within a stated tolerance |
//! | choice check | a question whose right choice the crate computes |
//!
//! Reference solutions and starters are generated from the verified function files
//! ([`crate::checker::complete`]); only the numeric and choice answers are computed here, each
//! by the crate function named in its doc.

pub mod answer_text;
mod book;
mod catalogue;
pub mod change;
mod check;
pub mod export;

pub use book::{book_markdown, chapter_page_of, CHAPTERS};
pub use catalogue::{answer_choice, answer_number, EXERCISES};
pub use check::{
    check_exercise, check_submission, choice_verdict, text_of, ExerciseError, ExerciseResult, NumberFinding,
    NumberTexts, FILE_EMPTY, FILE_TEXTS, GIVEN,
};

use crate::checker::check::pair::{reference_pair, PairModel};
use crate::checker::complete;
use crate::checker::mistakes::{apply_steps, Edit};
use crate::gl::ModelId;

/// How an exercise is checked.
#[derive(Debug, Clone, Copy)]
pub enum Check {
    /// A fragment shader against `model`'s reference; `mapping` is a `--uniforms` TOML
    /// (empty: the shader uses the model's names).
    Shader {
        /// The model.
        model: ModelId,
        /// The mapping TOML.
        mapping: &'static str,
    },
    /// A fragment shader against `model`'s function file with `steps` applied.
    Variant {
        /// The model.
        model: ModelId,
        /// The edits (as in [`crate::checker::mistakes`]).
        steps: &'static [&'static [Edit]],
        /// The mapping TOML.
        mapping: &'static str,
    },
    /// A vertex and a fragment shader checked together against `model`'s pair reference,
    /// as `check-shader --vertex` does ([`crate::checker::check::pair`]).
    Pair {
        /// The pair model (`gouraud`: Phong per vertex).
        model: PairModel,
    },
    /// A number: the answer file holds one number.
    Numeric {
        /// The crate's answer.
        answer: fn() -> f64,
        /// Accepted distance from the answer (its reason is in the statement's doc).
        tolerance: f64,
        /// The unit, for messages.
        unit: &'static str,
    },
    /// A choice: the answer file holds one letter (`a`, `b`, ...).
    Choice {
        /// The choices, in order.
        choices: &'static [&'static str],
        /// The crate's answer (an index into `choices`).
        answer: fn() -> usize,
    },
}

/// One exercise.
#[derive(Debug, Clone, Copy)]
pub struct Exercise {
    /// Stable id, kebab-case.
    pub id: &'static str,
    /// The book chapter (`basic-lighting`, `materials`, `lighting-maps`, `light-casters`,
    /// `multiple-lights`, `ogldev19`, `opengl-tutorial8`, or `own` for ours).
    pub chapter: &'static str,
    /// Where it comes from (the text and its section, or "lightlab").
    pub source: &'static str,
    /// A short title.
    pub title: &'static str,
    /// The statement, in Markdown.
    pub statement: &'static str,
    /// How it is checked.
    pub check: Check,
    /// For `Shader` checks with no function file (`normal_matrix`): the solution's text.
    pub solution_text: Option<&'static str>,
    /// For `Shader` checks: a function of the reference to leave as a stub in the starter
    /// (`CalcSpotLight`); `None` keeps only the declarations.
    pub stub: Option<&'static str>,
}

impl Exercise {
    /// Looks an exercise up by id.
    pub fn by_id(id: &str) -> Option<&'static Exercise> {
        EXERCISES.iter().find(|e| e.id == id)
    }

    /// The model a shader exercise is checked against; `None` for numeric and choice ones.
    pub fn model(&self) -> Option<ModelId> {
        match self.check {
            Check::Shader { model, .. } | Check::Variant { model, .. } => Some(model),
            Check::Pair { model } => Some(model.model()),
            _ => None,
        }
    }

    /// The function file the learner's shader must match: the model's, with the variant's
    /// edits applied. `None` for non-shader checks or models without a function file.
    pub fn functions(&self) -> Option<String> {
        match self.check {
            Check::Shader { model, .. } => model.shader().map(|s| s.functions().to_string()),
            Check::Variant { model, steps, .. } => apply_steps(steps, model.shader()?.functions()).ok(),
            _ => None,
        }
    }

    /// The reference solution: a complete shader for shader checks, the answer with its
    /// unit for numeric ones, the right choice for choice ones.
    pub fn solution(&self) -> String {
        if let Some(text) = self.solution_text {
            return text.to_string();
        }
        match self.check {
            Check::Pair { model } => reference_pair(model).1.to_string(),
            Check::Shader { model, .. } | Check::Variant { model, .. } => {
                self.functions().and_then(|f| complete::complete_with(model, &f)).unwrap_or_default()
            }
            Check::Numeric { answer, unit, .. } => format!("{} {unit}", format_number(answer())).trim_end().to_string(),
            Check::Choice { choices, answer } => {
                let k = answer();
                format!("({}) {}", letter(k), choices.get(k).copied().unwrap_or(""))
            }
        }
    }

    /// The starter: for shader checks, the declarations of the solution with an empty
    /// `main` (or the solution with one function stubbed); for the others, the question
    /// and how to answer.
    pub fn starter(&self) -> String {
        match self.check {
            Check::Pair { model } => reference_pair(starter_model(model)).1.to_string(),
            Check::Shader { .. } | Check::Variant { .. } => {
                let solution = self.solution();
                match self.stub {
                    Some(name) => stub_function(&solution, name),
                    None => declarations_only(&solution),
                }
            }
            Check::Numeric { .. } | Check::Choice { .. } => self.answer_starter(|msgid| msgid.to_string()),
        }
    }

    /// The starter of an exercise answered in a text file, each sentence and choice passed
    /// through `tr` (the command line's language; `{}` in [`STARTER_NUMBER_UNIT`] is the
    /// unit). Empty for a shader exercise.
    pub fn answer_starter(&self, tr: impl Fn(&str) -> String) -> String {
        match self.check {
            Check::Numeric { unit: "", .. } => format!("{}\n", tr(STARTER_NUMBER)),
            Check::Numeric { unit, .. } => format!("{}\n", tr(STARTER_NUMBER_UNIT).replacen("{}", unit, 1)),
            Check::Choice { choices, .. } => {
                let mut s = format!("{}\n", tr(STARTER_CHOICE));
                for (k, c) in choices.iter().enumerate() {
                    s += &format!("  ({}) {}\n", letter(k), tr(c));
                }
                s
            }
            _ => String::new(),
        }
    }
}

/// The starters of exercises answered in a text file (msgids).
pub const STARTER_NUMBER: &str = "Write one number in a text file.";
/// See [`STARTER_NUMBER`]; `{}` is the unit.
pub const STARTER_NUMBER_UNIT: &str = "Write one number ({}) in a text file.";
/// See [`STARTER_NUMBER`].
pub const STARTER_CHOICE: &str = "Write the letter of your choice in a text file:";

impl Exercise {
    /// A pair exercise's reference vertex shader (the verified pair of its model,
    /// `src/gl/shaders/examples/`); `None` for every other exercise.
    pub fn vertex_solution(&self) -> Option<&'static str> {
        match self.check {
            Check::Pair { model } => Some(reference_pair(model).0),
            _ => None,
        }
    }

    /// A pair exercise's starting vertex shader: the other model's verified vertex shader
    /// (see `starter_model`); `None` for every other exercise.
    pub fn vertex_starter(&self) -> Option<&'static str> {
        match self.check {
            Check::Pair { model } => Some(reference_pair(starter_model(model)).0),
            _ => None,
        }
    }
}

/// The pair a pair exercise starts from: the other model's verified pair, so the reader
/// moves the lighting between the stages (Gouraud starts from the chapter's per-fragment
/// pair, which the check names `phong-for-gouraud`).
fn starter_model(model: PairModel) -> PairModel {
    match model {
        PairModel::PerVertex => PairModel::PerFragment,
        PairModel::PerFragment => PairModel::PerVertex,
    }
}

/// `a`, `b`, `c`, ... for choice `k`.
pub fn letter(k: usize) -> char {
    (b'a' + (k % 26) as u8) as char
}

/// A number with the digits that matter (at most 4 decimals, trailing zeros dropped).
pub fn format_number(x: f64) -> String {
    let s = format!("{x:.4}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// Whether a line (at brace depth 0) opens a function definition: `type name(`.
fn opens_function(line: &str) -> bool {
    let t = line.trim_start();
    if t.starts_with("//") || t.starts_with('#') || t.starts_with("struct") || t.starts_with("uniform") {
        return false;
    }
    let Some(paren) = t.find('(') else { return false };
    let head: Vec<&str> = t[..paren].split_whitespace().collect();
    head.len() == 2 && head.iter().all(|w| w.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
}

/// The shader without its function bodies and comments: `#version`, `#define`s, structs
/// and declarations, then `void main()` that writes 0 to the `out` variable.
fn declarations_only(shader: &str) -> String {
    let mut out = String::new();
    let mut skipping = false;
    let mut depth = 0i32;
    let mut out_var = None;
    for line in shader.lines() {
        let t = line.trim_start();
        if !skipping && depth == 0 && opens_function(line) {
            skipping = true;
        }
        if skipping {
            depth += line.matches('{').count() as i32 - line.matches('}').count() as i32;
            if depth == 0 && line.contains('}') {
                skipping = false;
            }
            continue;
        }
        if t.starts_with("//") {
            continue;
        }
        if let Some(rest) = t.strip_prefix("out ") {
            let mut words = rest.trim_end_matches(';').split_whitespace();
            if let (Some(ty), Some(name)) = (words.next(), words.next()) {
                out_var = Some((ty.to_string(), name.to_string()));
            }
        }
        if t.is_empty() && out.ends_with("\n\n") {
            continue;
        }
        out += line;
        out.push('\n');
    }
    let (ty, name) = out_var.unwrap_or(("vec4".into(), "FragColor".into()));
    let zero = if ty == "vec3" { "vec3(0.0)" } else { "vec4(0.0, 0.0, 0.0, 1.0)" };
    out += &format!("\nvoid main()\n{{\n    // TODO: your lighting here\n    {name} = {zero};\n}}\n");
    out
}

/// The shader with the body of function `name` replaced by a TODO returning zero.
fn stub_function(shader: &str, name: &str) -> String {
    let Some(start) = shader.find(&format!(" {name}(")) else { return shader.to_string() };
    let Some(open) = shader[start..].find('{').map(|o| start + o) else { return shader.to_string() };
    let mut depth = 0;
    for (k, c) in shader[open..].char_indices() {
        match c {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    let close = open + k;
                    return format!(
                        "{}{{\n    // TODO: write {name} (see the statement)\n    return vec3(0.0);\n}}{}",
                        &shader[..open],
                        &shader[close + 1..]
                    );
                }
            }
            _ => {}
        }
    }
    shader.to_string()
}
