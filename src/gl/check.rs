//! `lightlab check-shader`: run a user's complete fragment shader on llvmpipe over random
//! cases of a model and compare it with the model's `f64` reference.
//!
//! | step | what happens |
//! | --- | --- |
//! | compile | the file is compiled as it is; errors carry the line numbers of the file |
//! | parse | top-level `struct`s and `in` / `uniform` / `out` declarations are read (comments and preprocessor lines skipped) |
//! | map | each declared leaf (`lightPos`, `light.position`, `pointLights[2].constant`) is matched to a model quantity by the tutorials' name, or through the `--uniforms` TOML |
//! | rewrite | `in` and per-case `uniform` qualifiers are blanked (the variables become globals), `sampler2D` becomes `vec4` holding the case's texel and `texture(s, uv)` returns it, `main` is renamed; line numbers are kept |
//! | wrap | a generated `batch_main` loads every leaf from the batch inputs with `texelFetch`, calls the user's `main`, and writes the user's `out` variable |
//! | compare | per case and channel, `|llvmpipe - f64 reference|` against the model's bound ([`crate::gl::cases::bounds`]), undefined cases excluded |
//!
//! Quantities of the model that the shader does not declare are fixed to the chapter's
//! value (`ambientStrength` 0.1, `specularStrength` 0.5, `shininess` 32, ...), because a
//! shader that does not declare them hard-codes them; the TOML's `[values]` table overrides
//! them. The multiple-lights scene (`dirLight`, `pointLights[i]`, `spotLight`) stays a set
//! of real uniforms, one draw per scene.
//!
//! # The mapping file
//! ```toml
//! [names]            # shader name = model name (a struct or array name maps all its fields)
//! uLightPos = "lightPos"
//! uLight = "light"
//! [values]           # model quantities the shader hard-codes differently
//! shininess = 64.0
//! lightColor = [1.0, 1.0, 1.0]
//! ```

use std::collections::BTreeMap;
use std::fmt::Write as _;

use super::batch::{log_excerpt, Batch};
use super::cases::{self, CaseModel, Channels, Class, Group, QType, Quantity, Slot};
use super::context::{GlContext, GlError};
use super::oracle::{ulps, ErrorStats};

/// Why a check could not give a verdict, or the shader's compile error.
#[derive(Debug, Clone, PartialEq)]
pub enum CheckError {
    /// A usage error: unknown model, unreadable or invalid mapping, a name the model does
    /// not know, a type mismatch, no `out` variable. Exit status 2.
    Usage(String),
    /// The shader does not compile on llvmpipe: the driver's log (line numbers are the
    /// file's) and the numbered lines it names. Exit status 1.
    Compile {
        /// The info log.
        log: String,
        /// The file's lines the log points at.
        excerpt: String,
    },
    /// OpenGL is missing or a draw failed. Exit status 2.
    Gl(GlError),
}

impl std::fmt::Display for CheckError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CheckError::Usage(m) => write!(f, "{m}"),
            CheckError::Compile { log, excerpt } => {
                write!(f, "the shader does not compile on llvmpipe:\n{}\n{excerpt}", log.trim_end())
            }
            CheckError::Gl(e) => write!(f, "OpenGL: {e}"),
        }
    }
}

impl std::error::Error for CheckError {}

impl From<GlError> for CheckError {
    fn from(e: GlError) -> Self {
        CheckError::Gl(e)
    }
}

fn usage<T>(message: impl Into<String>) -> Result<T, CheckError> {
    Err(CheckError::Usage(message.into()))
}

/// The `--uniforms` mapping: shader names to model names, and fixed values.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Mapping {
    /// `shader name -> model name`.
    pub names: BTreeMap<String, String>,
    /// `model quantity -> value` (a float is stored in all three components).
    pub values: BTreeMap<String, [f32; 3]>,
}

/// Parses a mapping file (see the module docs).
///
/// Errors: [`CheckError::Usage`] naming the line and the key for invalid TOML, an unknown
/// table, a name that is not a string, a value that is not a number or a 3-number array.
pub fn parse_mapping(text: &str) -> Result<Mapping, CheckError> {
    let table: toml::Table = match text.parse() {
        Ok(t) => t,
        Err(e) => {
            let line = e.span().map(|s| text[..s.start.min(text.len())].lines().count().max(1));
            let at = line.map_or(String::new(), |l| format!(" at line {l}"));
            return usage(format!("invalid TOML{at}: {}", e.message()));
        }
    };
    let line_of = |key: &str| {
        text.lines()
            .position(|l| l.trim_start().starts_with(key))
            .map_or(String::new(), |i| format!("line {}: ", i + 1))
    };
    let mut mapping = Mapping::default();
    for (section, value) in &table {
        let Some(entries) = value.as_table() else {
            return usage(format!("{}`{section}` must be a table ([names] or [values])", line_of(section)));
        };
        for (key, v) in entries {
            match section.as_str() {
                "names" => match v.as_str() {
                    Some(s) => {
                        mapping.names.insert(key.clone(), s.to_string());
                    }
                    None => return usage(format!("{}names.{key} must be a string (a model name)", line_of(key))),
                },
                "values" => {
                    let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
                    let value = match (num(v), v.as_array()) {
                        (Some(x), _) => [x as f32; 3],
                        (None, Some(a)) if a.len() == 3 && a.iter().all(|x| num(x).is_some()) => {
                            let f = |i: usize| num(&a[i]).unwrap_or(0.0) as f32;
                            [f(0), f(1), f(2)]
                        }
                        _ => {
                            return usage(format!(
                                "{}values.{key} must be a number or an array of 3 numbers",
                                line_of(key)
                            ))
                        }
                    };
                    mapping.values.insert(key.clone(), value);
                }
                other => {
                    return usage(format!("{}unknown table [{other}] (expected [names] or [values])", line_of(other)))
                }
            }
        }
    }
    Ok(mapping)
}

// ---------------------------------------------------------------- a small GLSL scanner

#[derive(Debug, Clone)]
struct Token {
    text: String,
    start: usize,
    end: usize,
}

/// Replaces comments by spaces (newlines kept) so byte offsets and lines stay the same.
fn blank_comments(src: &str) -> String {
    let b = src.as_bytes();
    let mut out = b.to_vec();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                out[i] = b' ';
                i += 1;
            }
        } else if b[i] == b'/' && b.get(i + 1) == Some(&b'*') {
            while i < b.len() && !(b[i] == b'*' && b.get(i + 1) == Some(&b'/')) {
                if b[i] != b'\n' {
                    out[i] = b' ';
                }
                i += 1;
            }
            for byte in out.iter_mut().take((i + 2).min(b.len())).skip(i) {
                *byte = b' ';
            }
            i += 2;
        } else {
            i += 1;
        }
    }
    String::from_utf8(out).unwrap_or_default()
}

/// Identifiers, numbers and single punctuation characters; preprocessor lines are skipped.
fn tokenize(src: &str) -> Vec<Token> {
    let b = src.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    let mut line_start = true;
    while i < b.len() {
        let c = b[i];
        if c == b'\n' {
            line_start = true;
            i += 1;
        } else if c.is_ascii_whitespace() {
            i += 1;
        } else if c == b'#' && line_start {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
            let start = i;
            while i < b.len()
                && (b[i].is_ascii_alphanumeric() || b[i] == b'_' || b[i] == b'.' && b[start].is_ascii_digit())
            {
                i += 1;
            }
            tokens.push(Token { text: src[start..i].to_string(), start, end: i });
            line_start = false;
        } else {
            tokens.push(Token { text: (c as char).to_string(), start: i, end: i + 1 });
            i += 1;
            line_start = false;
        }
    }
    tokens
}

#[derive(Debug, Clone, PartialEq, Eq)]
enum Storage {
    In,
    Uniform,
    Out,
}

#[derive(Debug, Clone)]
struct Declaration {
    storage: Storage,
    ty: String,
    name: String,
    array: Option<usize>,
    /// Byte ranges of the qualifier tokens (`layout(...)`, `flat`, `in`, `uniform`, `out`).
    qualifiers: Vec<(usize, usize)>,
    /// Byte range of the type token.
    type_span: (usize, usize),
}

#[derive(Debug, Clone)]
struct Field {
    ty: String,
    name: String,
    array: Option<usize>,
    type_span: (usize, usize),
}

#[derive(Debug, Default)]
struct Parsed {
    structs: BTreeMap<String, Vec<Field>>,
    decls: Vec<Declaration>,
    /// Byte range of `main` in `void main(`.
    main: Option<(usize, usize)>,
    /// Integer macros, for array sizes.
    defines: BTreeMap<String, usize>,
}

const QUALIFIERS: &[&str] = &["flat", "smooth", "noperspective", "centroid", "highp", "mediump", "lowp", "invariant"];

/// Integer `#define`s (`#define NR_POINT_LIGHTS 4`), for array sizes.
fn integer_defines(src: &str) -> BTreeMap<String, usize> {
    src.lines()
        .filter_map(|line| {
            let mut words = line.trim_start().strip_prefix('#')?.split_whitespace();
            (words.next()? == "define").then_some(())?;
            let name = words.next()?.to_string();
            let value = words.next()?.parse().ok()?;
            Some((name, value))
        })
        .collect()
}

fn parse_array(tokens: &[Token], k: &mut usize, defines: &BTreeMap<String, usize>) -> Option<usize> {
    if tokens.get(*k).is_some_and(|t| t.text == "[") {
        let n = tokens.get(*k + 1).and_then(|t| t.text.parse().ok().or_else(|| defines.get(&t.text).copied()));
        while *k < tokens.len() && tokens[*k].text != "]" {
            *k += 1;
        }
        *k += 1;
        n
    } else {
        None
    }
}

fn parse(src: &str) -> Parsed {
    let tokens = tokenize(&blank_comments(src));
    let mut parsed = Parsed { defines: integer_defines(src), ..Parsed::default() };
    let mut k = 0;
    // Brace and parenthesis depth: declarations are read only at the top level, so that
    // function parameters (`out vec3 x`) and locals are not taken for globals.
    let mut depth = 0i32;
    while k < tokens.len() {
        let t = &tokens[k].text;
        match t.as_str() {
            "{" | "(" => depth += 1,
            "}" | ")" => depth -= 1,
            _ => {}
        }
        if depth != 0 || t == "}" || t == ")" {
            k += 1;
            continue;
        }
        if t == "struct" {
            k = parse_struct(&tokens, k, &mut parsed);
            continue;
        }
        if t == "void"
            && tokens.get(k + 1).is_some_and(|n| n.text == "main")
            && tokens.get(k + 2).is_some_and(|p| p.text == "(")
        {
            parsed.main = Some((tokens[k + 1].start, tokens[k + 1].end));
            k += 2;
            continue;
        }
        // A declaration with storage qualifiers.
        let start = k;
        let mut qualifiers = Vec::new();
        let mut storage = None;
        while let Some(tok) = tokens.get(k) {
            match tok.text.as_str() {
                "layout" => {
                    let from = tok.start;
                    while k < tokens.len() && tokens[k].text != ")" {
                        k += 1;
                    }
                    if let Some(close) = tokens.get(k) {
                        qualifiers.push((from, close.end));
                    }
                    k += 1;
                }
                "in" | "uniform" | "out" => {
                    storage = Some(match tok.text.as_str() {
                        "in" => Storage::In,
                        "uniform" => Storage::Uniform,
                        _ => Storage::Out,
                    });
                    qualifiers.push((tok.start, tok.end));
                    k += 1;
                }
                q if QUALIFIERS.contains(&q) => {
                    qualifiers.push((tok.start, tok.end));
                    k += 1;
                }
                _ => break,
            }
        }
        match storage {
            Some(storage) if k + 1 < tokens.len() => {
                let ty = tokens[k].clone();
                k += 1;
                while let Some(name) = tokens.get(k) {
                    k += 1;
                    let array = parse_array(&tokens, &mut k, &parsed.defines);
                    parsed.decls.push(Declaration {
                        storage: storage.clone(),
                        ty: ty.text.clone(),
                        name: name.text.clone(),
                        array,
                        qualifiers: qualifiers.clone(),
                        type_span: (ty.start, ty.end),
                    });
                    if tokens.get(k).is_some_and(|t| t.text == ",") {
                        k += 1;
                    } else {
                        break;
                    }
                }
                while k < tokens.len() && tokens[k].text != ";" {
                    k += 1;
                }
                k += 1;
            }
            _ => {
                k = start + 1;
            }
        }
    }
    parsed
}

fn parse_struct(tokens: &[Token], mut k: usize, parsed: &mut Parsed) -> usize {
    let Some(name) = tokens.get(k + 1).map(|t| t.text.clone()) else { return k + 1 };
    k += 2;
    if tokens.get(k).is_none_or(|t| t.text != "{") {
        return k;
    }
    k += 1;
    let mut fields = Vec::new();
    while k < tokens.len() && tokens[k].text != "}" {
        while k < tokens.len() && QUALIFIERS.contains(&tokens[k].text.as_str()) {
            k += 1;
        }
        let Some(ty) = tokens.get(k).cloned() else { break };
        k += 1;
        while let Some(field) = tokens.get(k).cloned() {
            k += 1;
            let array = parse_array(tokens, &mut k, &parsed.defines);
            fields.push(Field { ty: ty.text.clone(), name: field.text, array, type_span: (ty.start, ty.end) });
            if tokens.get(k).is_some_and(|t| t.text == ",") {
                k += 1;
            } else {
                break;
            }
        }
        while k < tokens.len() && tokens[k].text != ";" && tokens[k].text != "}" {
            k += 1;
        }
        if tokens.get(k).is_some_and(|t| t.text == ";") {
            k += 1;
        }
    }
    parsed.structs.insert(name, fields);
    k + 1
}

// ---------------------------------------------------------------- mapping leaves

/// One declared leaf of the user's shader and the model quantity it is.
#[derive(Debug, Clone)]
struct Leaf {
    /// The shader's expression (`light.position`, `pointLights[2].constant`).
    user: String,
    /// The model's name for it.
    model: String,
    /// The quantity (for case-scope and unused quantities).
    quantity: Option<Quantity>,
}

fn indices(array: Option<usize>) -> Vec<String> {
    match array {
        Some(n) => (0..n).map(|i| format!("[{i}]")).collect(),
        None => vec![String::new()],
    }
}

fn leaves_of(decl: &Declaration, structs: &BTreeMap<String, Vec<Field>>) -> Vec<(String, String, String)> {
    // (user leaf, declaration base + suffix, type)
    let mut out = Vec::new();
    for idx in indices(decl.array) {
        match structs.get(&decl.ty) {
            Some(fields) => {
                for f in fields {
                    for fidx in indices(f.array) {
                        let suffix = format!("{idx}.{}{fidx}", f.name);
                        out.push((format!("{}{suffix}", decl.name), suffix, f.ty.clone()));
                    }
                }
            }
            None => out.push((format!("{}{idx}", decl.name), idx.clone(), decl.ty.clone())),
        }
    }
    out
}

fn type_matches(glsl: &str, ty: QType) -> bool {
    matches!(
        (glsl, ty),
        ("float", QType::Float)
            | ("vec2", QType::Vec2)
            | ("vec3", QType::Vec3)
            | ("sampler2D", QType::Texel)
            | ("vec4", QType::Texel)
            | ("mat4", QType::Mat4)
    )
}

fn qtype_name(ty: QType) -> &'static str {
    match ty {
        QType::Float => "float",
        QType::Vec2 => "vec2",
        QType::Vec3 => "vec3",
        QType::Texel => "sampler2D",
        QType::Mat4 => "mat4",
    }
}

fn known_names(model: &CaseModel) -> String {
    model.quantities.iter().map(|q| q.name).collect::<Vec<_>>().join(", ")
}

fn map_leaves(model: &CaseModel, parsed: &Parsed, mapping: &Mapping) -> Result<Vec<(usize, Vec<Leaf>)>, CheckError> {
    let mut out = Vec::new();
    for (d, decl) in parsed.decls.iter().enumerate() {
        if decl.storage == Storage::Out {
            continue;
        }
        let base = mapping.names.get(&decl.name).cloned().unwrap_or_else(|| decl.name.clone());
        let mut leaves = Vec::new();
        for (user, suffix, ty) in leaves_of(decl, &parsed.structs) {
            let model_name = mapping.names.get(&user).cloned().unwrap_or_else(|| format!("{base}{suffix}"));
            let group = model.quantities.iter().find(|q| {
                q.slot == Slot::Group
                    && (model_name.starts_with(&format!("{}.", q.name))
                        || model_name.starts_with(&format!("{}[", q.name)))
            });
            if group.is_some() {
                leaves.push(Leaf { user, model: model_name, quantity: None });
                continue;
            }
            let Some(q) = model.quantities.iter().find(|q| q.name == model_name) else {
                return usage(format!(
                    "`{user}` is not a quantity of model {} (map it with --uniforms); the model knows: {}",
                    model.name,
                    known_names(model)
                ));
            };
            if !type_matches(&ty, q.ty) {
                return usage(format!(
                    "`{user}` is declared {ty}, but the model's `{}` is a {}",
                    q.name,
                    qtype_name(q.ty)
                ));
            }
            leaves.push(Leaf { user, model: model_name, quantity: Some(*q) });
        }
        out.push((d, leaves));
    }
    Ok(out)
}

// ---------------------------------------------------------------- rewrite and wrap

const PRELUDE: &str = "vec4 lightlab_sample(sampler2D s, vec2 uv) { return texture(s, uv); }
vec4 lightlab_sample(vec4 texel, vec2 uv) { return texel; }
vec4 lightlab_sample(vec4 texel, vec3 uv) { return texel; }
#define texture(s, uv) lightlab_sample(s, uv)
#define texture2D(s, uv) lightlab_sample(s, uv)
";

fn blank(bytes: &mut [u8], span: (usize, usize)) {
    for b in &mut bytes[span.0..span.1] {
        *b = b' ';
    }
}

/// The user's file rewritten (see the module docs), line for line.
fn rewrite(src: &str, parsed: &Parsed, case_decls: &[usize]) -> String {
    let mut bytes = src.as_bytes().to_vec();
    // The batch supplies its own #version line.
    if let Some(pos) = src.find("#version") {
        let end = src[pos..].find('\n').map_or(src.len(), |e| pos + e);
        blank(&mut bytes, (pos, end));
    }
    let mut replacements: Vec<((usize, usize), &str)> = Vec::new();
    for (d, decl) in parsed.decls.iter().enumerate() {
        let becomes_global = decl.storage != Storage::Uniform || case_decls.contains(&d);
        if becomes_global {
            for &q in &decl.qualifiers {
                blank(&mut bytes, q);
            }
            if decl.ty == "sampler2D" {
                replacements.push((decl.type_span, "vec4"));
            }
        }
    }
    for fields in parsed.structs.values() {
        for f in fields {
            if f.ty == "sampler2D" {
                replacements.push((f.type_span, "vec4"));
            }
        }
    }
    if let Some(main) = parsed.main {
        replacements.push((main, "lightlab_user_main"));
    }
    replacements.sort_by_key(|r| std::cmp::Reverse(r.0 .0));
    replacements.dedup_by_key(|r| r.0);
    let mut text = String::from_utf8(bytes).unwrap_or_default();
    for ((a, b), with) in replacements {
        text.replace_range(a..b, with);
    }
    text
}

fn load(leaf: &Leaf) -> Option<String> {
    let q = leaf.quantity?;
    let value = match (q.slot, q.ty) {
        (Slot::Unused, QType::Vec2) => "vec2(0.0)".to_string(),
        (Slot::Case { input, offset }, QType::Float) => format!("lightlab_v[{input}][{offset}]"),
        (Slot::Case { input, .. }, QType::Vec3) => format!("lightlab_v[{input}].xyz"),
        (Slot::Case { input, .. }, QType::Texel) => format!("lightlab_v[{input}]"),
        (Slot::Case { input, .. }, QType::Mat4) => {
            format!(
                "mat4(lightlab_v[{input}], lightlab_v[{}], lightlab_v[{}], lightlab_v[{}])",
                input + 1,
                input + 2,
                input + 3
            )
        }
        _ => return None,
    };
    Some(format!("    {} = {value};\n", leaf.user))
}

fn wrapper(leaves: &[Leaf], out: &Declaration) -> String {
    let mut s = String::from("\n#line 1 3\nvoid batch_main(in vec4 lightlab_v[LIGHTLAB_N_INPUTS], out vec4 lightlab_o[LIGHTLAB_N_OUTPUTS])\n{\n");
    for leaf in leaves {
        if let Some(line) = load(leaf) {
            s += &line;
        }
    }
    s += "    lightlab_user_main();\n";
    let color = match out.ty.as_str() {
        "vec3" => format!("vec4({}, 1.0)", out.name),
        "float" => format!("vec4(vec3({}), 1.0)", out.name),
        _ => format!("vec4({}.rgb, 1.0)", out.name),
    };
    let _ = writeln!(s, "    lightlab_o[0] = {color};\n}}");
    s
}

// ---------------------------------------------------------------- the check

/// The result of a check.
#[derive(Debug, Clone, PartialEq)]
pub struct CheckReport {
    /// Model name.
    pub model: &'static str,
    /// Cases run.
    pub cases: usize,
    /// Cases where the model is defined (the others are excluded from the verdict).
    pub defined: usize,
    /// The bound a correct shader stays within.
    pub bound: f64,
    /// The shader against the `f64` reference, defined cases.
    pub vs_f64: ErrorStats,
    /// Cases beyond the bound.
    pub failing: usize,
    /// The worst cases (at most 3), as printable blocks.
    pub counterexamples: Vec<String>,
    /// Notes: quantities fixed to the chapter's value, inactive uniforms.
    pub notes: Vec<String>,
}

impl CheckReport {
    /// Whether the shader agrees with the model on every defined case.
    pub fn agrees(&self) -> bool {
        self.failing == 0 && self.defined > 0
    }

    /// The report as text: verdict, statistics, notes, counterexamples.
    pub fn format(&self) -> String {
        let mut s = String::new();
        let verdict = if self.agrees() { "AGREES" } else { "DISAGREES" };
        let _ = writeln!(s, "verdict: {verdict} with model {}", self.model);
        let _ = writeln!(
            s,
            "cases: {} run, {} defined, {} beyond the bound {:.2e}",
            self.cases, self.defined, self.failing, self.bound
        );
        let v = &self.vs_f64;
        let _ = writeln!(
            s,
            "error vs the f64 reference: max {:.3e} ({:.1} ulps), mean {:.3e} ({:.2} ulps)",
            v.max_abs, v.max_ulps, v.mean_abs, v.mean_ulps
        );
        for n in &self.notes {
            let _ = writeln!(s, "note: {n}");
        }
        for (i, c) in self.counterexamples.iter().enumerate() {
            let _ = writeln!(s, "\ncounterexample {}:\n{c}", i + 1);
        }
        s
    }
}

fn quantity_value(q: &Quantity, row: &[[f32; 4]]) -> String {
    match (q.slot, q.ty) {
        (Slot::Case { input, offset }, QType::Float) => format!("{:?}", row[input][offset]),
        (Slot::Case { input, .. }, QType::Vec3) => {
            format!("({:?}, {:?}, {:?})", row[input][0], row[input][1], row[input][2])
        }
        (Slot::Case { input, .. }, QType::Texel) => format!("texel {:?}", row[input]),
        (Slot::Case { input, .. }, QType::Mat4) => {
            format!("columns {:?} {:?} {:?} {:?}", row[input], row[input + 1], row[input + 2], row[input + 3])
        }
        _ => "-".into(),
    }
}

fn describe_case(
    model: &CaseModel,
    leaves: &[Leaf],
    row: &[[f32; 4]],
    want: &[f64],
    got: &[f32],
    group: usize,
) -> String {
    let mut s = String::new();
    for leaf in leaves {
        if let Some(q) = &leaf.quantity {
            if q.slot != Slot::Unused {
                let _ = writeln!(s, "  {} = {}", leaf.user, quantity_value(q, row));
            }
        }
    }
    for q in model.quantities {
        let declared = leaves.iter().any(|l| l.quantity.is_some_and(|lq| lq.name == q.name));
        if !declared && matches!(q.slot, Slot::Case { .. }) {
            let _ = writeln!(s, "  (not declared) {} = {}", q.name, quantity_value(q, row));
        }
    }
    if model.kind == cases::Kind::MultipleLights {
        let _ = writeln!(s, "  scene: group {group} (0 = the chapter's lights)");
    }
    let _ = writeln!(s, "  expected (f64) = [{:.7}, {:.7}, {:.7}]", want[0], want[1], want[2]);
    let _ = write!(s, "  got (llvmpipe) = [{:.7}, {:.7}, {:.7}]", got[0], got[1], got[2]);
    s
}

/// The model `check-shader` compares with: every [`cases::CASE_MODELS`] entry but the
/// per-vertex `gouraud`. Errors: [`CheckError::Usage`] listing the models.
pub fn model_for_check(name: &str) -> Result<&'static CaseModel, CheckError> {
    match CaseModel::by_name(name) {
        Some(m) if m.kind != cases::Kind::Gouraud => Ok(m),
        Some(_) => usage("gouraud is a per-vertex model; check-shader checks fragment shaders"),
        None => {
            let names: Vec<&str> =
                cases::CASE_MODELS.iter().filter(|m| m.kind != cases::Kind::Gouraud).map(|m| m.name).collect();
            usage(format!("unknown model `{name}`; models: {}", names.join(", ")))
        }
    }
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
    /// Errors: [`CheckError::Usage`] when `n` is 0.
    pub fn generate(&self, n: usize, seed: u64) -> Result<Vec<Group>, CheckError> {
        if n == 0 {
            return usage("--cases must be at least 1");
        }
        Ok(cases::generate_cases(self.model, n, seed, &self.fixed)?)
    }

    /// The shader's output `outputs[group][case]` on `groups` (cases of [`Self::model`]).
    ///
    /// Errors: [`CheckError::Gl`] if a draw fails; [`CheckError::Usage`] for a uniform the
    /// group's scene does not have.
    pub fn run(&self, groups: &[Group]) -> Result<Vec<Vec<[f32; 4]>>, CheckError> {
        run_groups(&self.batch, self.model, groups, &self.leaves, &mut self.notes.borrow_mut())
    }

    /// Compares `outputs` (from [`Self::run`] on `groups`) with the `f64` reference.
    pub fn report(&self, groups: &[Group], outputs: &[Vec<[f32; 4]>]) -> CheckReport {
        compare(self.model, groups, outputs, &self.leaves, self.notes.borrow().clone())
    }
}

/// Compiles `source` (a complete fragment shader) for `model_name`: maps its declarations
/// to the model's quantities and fixes the ones it does not declare (see the module docs).
///
/// Errors: [`CheckError::Usage`] (unknown model, unmapped name, type mismatch, no `out`),
/// [`CheckError::Compile`] (with the file's line numbers), [`CheckError::Gl`].
pub fn compile_shader<'a>(
    ctx: &'a GlContext,
    source: &str,
    model_name: &str,
    mapping: &Mapping,
) -> Result<CompiledShader<'a>, CheckError> {
    let model = model_for_check(model_name)?;
    if let Err(e) = super::batch::compile_fragment(ctx, source) {
        return Err(match e {
            GlError::Compile { log, .. } => CheckError::Compile { excerpt: log_excerpt(source, &log), log },
            other => CheckError::Gl(other),
        });
    }
    let parsed = parse(source);
    let Some(out) = parsed.decls.iter().find(|d| d.storage == Storage::Out) else {
        return usage("the shader declares no `out` variable (its color)");
    };
    if parsed.main.is_none() {
        return usage("the shader has no `void main()`");
    }
    let mapped = map_leaves(model, &parsed, mapping)?;
    let case_decls: Vec<usize> =
        mapped.iter().filter(|(_, leaves)| leaves.iter().any(|l| l.quantity.is_some())).map(|(d, _)| *d).collect();
    let leaves: Vec<Leaf> = mapped.into_iter().flat_map(|(_, l)| l).collect();
    let mut notes = Vec::new();
    let mut fixed: Vec<(&'static str, [f32; 3])> = Vec::new();
    for q in model.quantities {
        let declared = leaves.iter().any(|l| l.quantity.is_some_and(|lq| lq.name == q.name));
        if let Some(v) = mapping.values.get(q.name) {
            if declared {
                return usage(format!("values.{} is fixed in the mapping but the shader declares it", q.name));
            }
            fixed.push((q.name, *v));
            let shown = if q.ty == QType::Float { format!("{}", v[0]) } else { format!("{v:?}") };
            notes.push(format!("{} fixed to {shown} by the mapping", q.name));
        } else if !declared {
            if let (Some(v), Slot::Case { .. }) = (q.default, q.slot) {
                fixed.push((q.name, v));
                let shown = if q.ty == QType::Float { format!("{}", v[0]) } else { format!("{v:?}") };
                notes.push(format!("{} is not declared by the shader: fixed to the chapter's {shown}", q.name));
            }
        }
    }
    for key in mapping.values.keys() {
        if !model.quantities.iter().any(|q| q.name == key) {
            return usage(format!(
                "values.{key}: model {} has no such quantity; it knows: {}",
                model.name,
                known_names(model)
            ));
        }
    }
    let body = format!("{PRELUDE}#line 1 1\n{}\n{}", rewrite(source, &parsed, &case_decls), wrapper(&leaves, out));
    let batch = match Batch::new(ctx, &body, model.n_inputs, 1) {
        Ok(b) => b,
        Err(GlError::Compile { log, .. }) => {
            return Err(CheckError::Gl(GlError::Gl {
                call: "compiling the rewritten shader (a lightlab limitation; please report)".into(),
                detail: format!("{log}\n{body}"),
            }))
        }
        Err(e) => return Err(e.into()),
    };
    Ok(CompiledShader { model, batch, leaves, fixed, notes: std::cell::RefCell::new(notes) })
}

/// Checks `source` (a complete fragment shader) against `model_name` on `n` cases from `seed`.
///
/// Errors: [`CheckError::Usage`] (unknown model, unmapped name, type mismatch, no `out`),
/// [`CheckError::Compile`] (with the file's line numbers), [`CheckError::Gl`].
pub fn check_shader(
    ctx: &GlContext,
    source: &str,
    model_name: &str,
    mapping: &Mapping,
    n: usize,
    seed: u64,
) -> Result<CheckReport, CheckError> {
    model_for_check(model_name)?;
    if n == 0 {
        return usage("--cases must be at least 1");
    }
    let shader = compile_shader(ctx, source, model_name, mapping)?;
    let groups = shader.generate(n, seed)?;
    let outputs = shader.run(&groups)?;
    Ok(shader.report(&groups, &outputs))
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
            match batch.set_uniform(&leaf.user, *value) {
                Ok(()) => {}
                Err(GlError::Input { .. }) => {
                    let note = format!("uniform {} is not used by the shader (inactive)", leaf.user);
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
    Ok(outputs)
}

fn compare(
    model: &'static CaseModel,
    groups: &[Group],
    outputs: &[Vec<[f32; 4]>],
    leaves: &[Leaf],
    notes: Vec<String>,
) -> CheckReport {
    let mut stats = ErrorStats::default();
    let (mut sum_abs, mut sum_ulps) = (0.0, 0.0);
    let mut failing = 0;
    let mut worst: Vec<(f64, usize, usize)> = Vec::new(); // (error, group, row)
    for (g, group) in groups.iter().enumerate() {
        let scene = group.scene.as_ref();
        for (i, row) in group.rows.iter().enumerate() {
            if model.classify(row, scene) != Class::Defined {
                continue;
            }
            let want: Channels<f64> = model.eval_f64(row, scene);
            let got = outputs[g][i];
            let mut abs = 0.0f64;
            let mut ulp = 0.0f64;
            for c in 0..3 {
                let d = (got[c] as f64 - want[c]).abs();
                abs = if d.is_nan() { f64::INFINITY } else { abs.max(d) };
                ulp = ulp.max(ulps(got[c] as f64, want[c]));
            }
            stats.count += 1;
            stats.max_abs = stats.max_abs.max(abs);
            stats.max_ulps = stats.max_ulps.max(ulp);
            sum_abs += abs;
            sum_ulps += ulp;
            if abs > model.bound {
                failing += 1;
            }
            worst.push((abs, g, i));
        }
    }
    if stats.count > 0 {
        stats.mean_abs = sum_abs / stats.count as f64;
        stats.mean_ulps = sum_ulps / stats.count as f64;
    }
    worst.sort_by(|a, b| b.0.total_cmp(&a.0));
    let counterexamples = worst
        .iter()
        .take(3)
        .filter(|w| w.0 > model.bound)
        .map(|&(_, g, i)| {
            let row = &groups[g].rows[i];
            let want = model.eval_f64(row, groups[g].scene.as_ref());
            describe_case(model, leaves, row, &want, &outputs[g][i], g)
        })
        .collect();
    CheckReport {
        model: model.name,
        cases: groups.iter().map(|g| g.rows.len()).sum(),
        defined: stats.count,
        bound: model.bound,
        vs_f64: stats,
        failing,
        counterexamples,
        notes,
    }
}
