//! A small GLSL scanner: enough of the language to find a fragment shader's top-level
//! declarations (`in`, `uniform`, `out`, structs, interface blocks) and `main`.
//!
//! | piece | what it reads |
//! | --- | --- |
//! | [`blank_comments`] | `//` and `/* */` comments become spaces (newlines kept), so byte offsets and lines stay |
//! | [`tokenize`] | identifiers, numbers in every GLSL 3.30 literal form, single punctuation; preprocessor lines skipped |
//! | [`parse`] | declarations at brace depth 0, struct definitions, interface blocks, `void main(` |
//! | [`global_references`] | where a name can refer to a top-level declaration: not after `.`, not a same-named parameter or local in its scope |
//! | [`super::preprocess`] (before) | macros expanded, conditionals applied, lines kept: the checker parses and rewrites the preprocessed text, so `#define U uniform vec3`, `DECL(vec3, lightPos)`, `vec##3` and `#ifdef` branches are read as the driver reads them |
//!
//! Numbers (GLSL 3.30 §3.6 and §4.1.3–4.1.4): decimal, octal (`017`) and hexadecimal
//! (`0x1F`) integers with an optional `u`/`U`; floats with digits on either side of the
//! point or none (`1.`, `.5`, `1.5`, `1e5`, `1.5e-3`, `.5E+2`) and an optional `f`/`F` or
//! `lf`/`LF` suffix. A malformed number (`1e`, `0x`) is one token; the driver rejects it.
//!
//! Every step advances by at least one byte, so the scanner ends on any input; the
//! property tests in this file feed it random and mutated shaders.

use std::collections::BTreeMap;

/// One token: its text and byte range in the source.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Token {
    /// The text.
    pub text: String,
    /// First byte.
    pub start: usize,
    /// One past the last byte.
    pub end: usize,
}

/// Replaces comments by spaces (newlines kept) so byte offsets and lines stay the same.
/// An unterminated `/*` runs to the end of the text.
pub fn blank_comments(src: &str) -> String {
    blank_spans(src, &comment_spans(src))
}

/// The byte ranges of the comments of `src`, in order: `//` to the end of its line (the
/// line break excluded), `/*` to its `*/` included, or to the end of the text when it is
/// never closed. The one comment scanner ([`blank_comments`], the preprocessor's
/// directive lines).
pub(super) fn comment_spans(src: &str) -> Vec<std::ops::Range<usize>> {
    let b = src.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let start = i;
        match (b[i], b.get(i + 1)) {
            (b'/', Some(b'/')) => {
                i += b[i..].iter().take_while(|c| **c != b'\n').count();
            }
            (b'/', Some(b'*')) => {
                i = src[i + 2..].find("*/").map_or(b.len(), |k| i + 2 + k + 2);
            }
            _ => {
                i += 1;
                continue;
            }
        }
        spans.push(start..i);
    }
    spans
}

/// `src` with every byte of `spans` but line breaks made a space. Whole multi-byte
/// characters lie inside or outside a comment, so the result is UTF-8.
pub(super) fn blank_spans(src: &str, spans: &[std::ops::Range<usize>]) -> String {
    let mut out = src.as_bytes().to_vec();
    for span in spans {
        for byte in &mut out[span.clone()] {
            if *byte != b'\n' {
                *byte = b' ';
            }
        }
    }
    String::from_utf8(out).unwrap_or_default()
}

/// The end of the number starting at `i` (a digit, or a `.` followed by a digit).
fn number_end(b: &[u8], mut i: usize) -> usize {
    let digits = |b: &[u8], mut i: usize, ok: fn(&u8) -> bool| {
        while b.get(i).is_some_and(ok) {
            i += 1;
        }
        i
    };
    if b[i] == b'0' && matches!(b.get(i + 1), Some(b'x' | b'X')) {
        i = digits(b, i + 2, u8::is_ascii_hexdigit);
        if matches!(b.get(i), Some(b'u' | b'U')) {
            i += 1;
        }
        return i;
    }
    i = digits(b, i, u8::is_ascii_digit);
    let mut float = false;
    if b.get(i) == Some(&b'.') {
        float = true;
        i = digits(b, i + 1, u8::is_ascii_digit);
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
        if b.get(i + 1 + sign).is_some_and(u8::is_ascii_digit) {
            float = true;
            i = digits(b, i + 1 + sign, u8::is_ascii_digit);
        }
    }
    match (b.get(i), b.get(i + 1)) {
        // `1f` is not GLSL, but one token is what the driver should see and reject.
        (Some(b'f' | b'F'), _) => i + 1,
        (Some(b'l'), Some(b'f')) | (Some(b'L'), Some(b'F')) => i + 2,
        (Some(b'u' | b'U'), _) if !float => i + 1,
        _ => i,
    }
}

/// A word of GLSL text: a number or an identifier.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Word {
    /// Starts with a digit, or a `.` followed by a digit ([`number_end`]).
    Number,
    /// A letter or `_`, then letters, digits and `_`.
    Ident,
}

/// The word starting at `i` and its end, or `None` when `b[i]` starts no word (space or
/// punctuation). The one scanner of both the preprocessor and [`tokenize`].
pub(super) fn word_at(b: &[u8], i: usize) -> Option<(Word, usize)> {
    let c = *b.get(i)?;
    if c.is_ascii_digit() || c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit) {
        Some((Word::Number, number_end(b, i)))
    } else if c.is_ascii_alphabetic() || c == b'_' {
        let len = b[i..].iter().take_while(|c| c.is_ascii_alphanumeric() || **c == b'_').count();
        Some((Word::Ident, i + len))
    } else {
        None
    }
}

/// Identifiers, numbers and single punctuation characters; preprocessor lines are skipped.
/// Tokens are non-empty, in order and within the text.
pub fn tokenize(src: &str) -> Vec<Token> {
    let b = src.as_bytes();
    let mut tokens = Vec::new();
    let mut i = 0;
    let mut line_start = true;
    while i < b.len() {
        let c = b[i];
        let start = i;
        if c == b'\n' {
            line_start = true;
            i += 1;
            continue;
        } else if c.is_ascii_whitespace() {
            i += 1;
            continue;
        } else if c == b'#' && line_start {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
            continue;
        } else if let Some((_, end)) = word_at(b, i) {
            i = end;
        } else {
            // One character (a whole UTF-8 sequence for non-ASCII text).
            i += src[i..].chars().next().map_or(1, char::len_utf8);
        }
        tokens.push(Token { text: src[start..i].to_string(), start, end: i });
        line_start = false;
    }
    tokens
}

/// Where a declared variable lives.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Storage {
    /// `in` (a varying).
    In,
    /// `uniform`.
    Uniform,
    /// `out` (the colour).
    Out,
}

/// A top-level `in` / `uniform` / `out` declaration (one per declared name).
#[derive(Debug, Clone, PartialEq)]
pub struct Declaration {
    /// Storage qualifier.
    pub storage: Storage,
    /// Type name (a struct's name for a struct; the block name for an interface block).
    pub ty: String,
    /// Variable name; for a block without an instance name, empty.
    pub name: String,
    /// Array size, if any and known.
    pub array: Option<usize>,
    /// `layout(location = N)`, if given.
    pub location: Option<u32>,
    /// Byte ranges of the qualifier tokens (`layout(...)`, `flat`, `in`, `uniform`, `out`).
    pub qualifiers: Vec<(usize, usize)>,
    /// Byte range of the type token.
    pub type_span: (usize, usize),
    /// For an interface block: its members and the byte ranges to blank so the block
    /// becomes globals (an anonymous block) or a struct variable (a named instance).
    pub block: Option<Block>,
}

/// An interface block (`in VS_OUT { vec3 FragPos; } fs_in;`).
#[derive(Debug, Clone, PartialEq)]
pub struct Block {
    /// The members.
    pub members: Vec<Field>,
    /// Byte ranges of the block's braces, name and closing `;` (blanked for an anonymous
    /// block, whose members become globals).
    pub frame: Vec<(usize, usize)>,
    /// Byte ranges of qualifiers inside the block (blanked: a struct or global member
    /// cannot carry them).
    pub inner_qualifiers: Vec<(usize, usize)>,
}

/// A struct field or block member.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    /// Type name.
    pub ty: String,
    /// Field name.
    pub name: String,
    /// Array size, if any and known.
    pub array: Option<usize>,
    /// Byte range of the type token.
    pub type_span: (usize, usize),
}

/// What [`parse`] finds.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Parsed {
    /// Struct definitions by name.
    pub structs: BTreeMap<String, Vec<Field>>,
    /// Top-level declarations, in order.
    pub decls: Vec<Declaration>,
    /// Byte range of `main` in `void main(`.
    pub main: Option<(usize, usize)>,
    /// The largest array size written anywhere at the top level (declarations, struct
    /// fields, block members), known or not: the caller caps it before compiling.
    pub largest_array: usize,
    /// Byte range of the `#version` line, if any (a preprocessor line outside comments).
    pub version: Option<(usize, usize)>,
    /// Byte ranges of the `#extension` lines (preprocessor lines outside comments), which
    /// GLSL wants before any code: the rewrite moves them in front of its own.
    pub extensions: Vec<(usize, usize)>,
    /// How often each identifier occurs outside comments and preprocessor lines,
    /// declarations included: a member whose name occurs only where it is declared is
    /// never read (std140 padding).
    pub identifiers: BTreeMap<String, usize>,
    /// Top-level integer constants (`const int NR_POINT_LIGHTS = 2 * 2;`) by name, which
    /// array sizes may use.
    pub constants: BTreeMap<String, usize>,
    /// How often each identifier occurs where it can name a top-level declaration
    /// ([`global_references`]): as [`Parsed::identifiers`], less a member access
    /// (`x.lightPos`), a function's parameter and a local of the same name, and their uses.
    pub references: BTreeMap<String, usize>,
}

const QUALIFIERS: &[&str] = &["flat", "smooth", "noperspective", "centroid", "highp", "mediump", "lowp", "invariant"];

/// A GLSL integer literal's value (decimal, octal, hex; `u` suffix), saturating at
/// `usize::MAX`; `None` if it is not one.
pub(super) fn parse_int(text: &str) -> Option<usize> {
    let t = text.trim_end_matches(['u', 'U']);
    let (digits, radix) = if let Some(h) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        (h, 16)
    } else if t.len() > 1 && t.starts_with('0') {
        (&t[1..], 8)
    } else {
        (t, 10)
    };
    if digits.is_empty() || !digits.chars().all(|c| c.is_digit(radix)) {
        return None;
    }
    Some(usize::from_str_radix(digits, radix).unwrap_or(usize::MAX))
}

/// An array's `[size]` at `k`, moving `k` past the `]`: the size is a constant integer
/// expression ([`constant_expression`]: `4`, `2 * 2`, `(NR + 1)` with `const int NR`),
/// `None` when it cannot be worked out here (the driver still judges it).
fn parse_array(tokens: &[Token], k: &mut usize, parsed: &mut Parsed) -> Option<usize> {
    if tokens.get(*k).is_none_or(|t| t.text != "[") {
        return None;
    }
    let open = *k + 1;
    let mut depth = 0usize;
    *k = open;
    while let Some(t) = tokens.get(*k) {
        match t.text.as_str() {
            "[" => depth += 1,
            "]" if depth == 0 => break,
            "]" => depth -= 1,
            _ => {}
        }
        // Any integer inside the brackets counts towards the cap (`[100000 * 1000]`).
        if let Some(v) = parse_int(&t.text) {
            parsed.largest_array = parsed.largest_array.max(v);
        }
        *k += 1;
    }
    let n = constant_expression(&tokens[open..(*k).min(tokens.len())], &parsed.constants);
    *k += 1;
    if let Some(n) = n {
        parsed.largest_array = parsed.largest_array.max(n);
    }
    n
}

/// The value of a constant integer expression (GLSL 3.30 §4.3.3): integer literals, names
/// of `constants`, `+ - * / %`, unary `+ -` and parentheses, with C precedence. `None` for
/// anything else, a negative or overflowing value, or a division by zero.
pub(super) fn constant_expression(tokens: &[Token], constants: &BTreeMap<String, usize>) -> Option<usize> {
    let mut k = 0;
    let value = sum(tokens, &mut k, constants, 0)?;
    (k == tokens.len() && value >= 0).then_some(usize::try_from(value).ok()?)
}

/// How deep parentheses may nest in [`constant_expression`] (the recursion's bound).
const MAX_CONSTANT_DEPTH: usize = 64;

fn sum(t: &[Token], k: &mut usize, c: &BTreeMap<String, usize>, depth: usize) -> Option<i64> {
    let mut value = product(t, k, c, depth)?;
    while let Some(op) = t.get(*k).map(|t| t.text.as_str()).filter(|op| matches!(*op, "+" | "-")) {
        *k += 1;
        let rhs = product(t, k, c, depth)?;
        value = if op == "+" { value.checked_add(rhs)? } else { value.checked_sub(rhs)? };
    }
    Some(value)
}

fn product(t: &[Token], k: &mut usize, c: &BTreeMap<String, usize>, depth: usize) -> Option<i64> {
    let mut value = unary(t, k, c, depth)?;
    while let Some(op) = t.get(*k).map(|t| t.text.as_str()).filter(|op| matches!(*op, "*" | "/" | "%")) {
        *k += 1;
        let rhs = unary(t, k, c, depth)?;
        value = match op {
            "*" => value.checked_mul(rhs)?,
            "/" => value.checked_div(rhs)?,
            _ => value.checked_rem(rhs)?,
        };
    }
    Some(value)
}

fn unary(t: &[Token], k: &mut usize, c: &BTreeMap<String, usize>, depth: usize) -> Option<i64> {
    if depth > MAX_CONSTANT_DEPTH {
        return None;
    }
    let token = t.get(*k)?;
    *k += 1;
    match token.text.as_str() {
        "-" => unary(t, k, c, depth + 1)?.checked_neg(),
        "+" => unary(t, k, c, depth + 1),
        "(" => {
            let value = sum(t, k, c, depth + 1)?;
            (t.get(*k)?.text == ")").then(|| *k += 1)?;
            Some(value)
        }
        text => {
            let v = parse_int(text).or_else(|| c.get(text).copied())?;
            // parse_int saturates: a literal past i64 is refused, not wrapped
            i64::try_from(v).ok().filter(|_| v != usize::MAX)
        }
    }
}

/// `const int NAME = expression;` (or `uint`) at `start` (the `const` token), recorded in
/// `parsed.constants` when its value can be worked out; returns the index after its `;`.
fn parse_constant(tokens: &[Token], start: usize, parsed: &mut Parsed) -> usize {
    let mut k = start + 1;
    while tokens.get(k).is_some_and(|t| QUALIFIERS.contains(&t.text.as_str())) {
        k += 1;
    }
    let is_int = tokens.get(k).is_some_and(|t| t.text == "int" || t.text == "uint");
    let end = past_initializer(tokens, k);
    if is_int && tokens.get(k + 2).is_some_and(|t| t.text == "=") && tokens.get(end).is_some_and(|t| t.text == ";") {
        if let Some(v) = constant_expression(&tokens[k + 3..end], &parsed.constants) {
            parsed.constants.insert(tokens[k + 1].text.clone(), v);
        }
    }
    end + 1
}

/// Reads the declarations of `src` (see the module docs). Never fails: what it cannot
/// read it skips, and the driver's compiler judges the file. Macros are not expanded here:
/// the checker gives it the text [`super::preprocess::preprocess`] made, whose byte ranges
/// the rewrite then edits.
pub fn parse(src: &str) -> Parsed {
    let blanked = blank_comments(src);
    let tokens = tokenize(&blanked);
    let mut parsed = Parsed {
        version: directive_lines(&blanked, "version").first().copied(),
        extensions: directive_lines(&blanked, "extension"),
        ..Parsed::default()
    };
    for t in tokens.iter().filter(|t| is_identifier(&t.text)) {
        *parsed.identifiers.entry(t.text.clone()).or_insert(0) += 1;
    }
    let mut k = 0;
    // Brace and parenthesis depth: declarations are read only at the top level, so that
    // function parameters (`out vec3 x`) and locals are not taken for globals.
    let mut depth = 0i64;
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
        if t == "const" {
            k = parse_constant(&tokens, k, &mut parsed);
            continue;
        }
        k = parse_declaration(&tokens, k, &mut parsed);
    }
    parsed.references = global_references(&tokens, &parsed.structs);
    parsed
}

const PARAMETER_QUALIFIERS: &[&str] = &["in", "out", "inout", "const", "highp", "mediump", "lowp", "precise"];

/// Built-in type names a local declaration starts with (GLSL 3.30 §4.1).
const TYPE_NAMES: &[&str] = &[
    "float", "int", "uint", "bool", "vec2", "vec3", "vec4", "ivec2", "ivec3", "ivec4", "uvec2", "uvec3", "uvec4",
    "bvec2", "bvec3", "bvec4", "mat2", "mat3", "mat4", "mat2x2", "mat2x3", "mat2x4", "mat3x2", "mat3x3", "mat3x4",
    "mat4x2", "mat4x3", "mat4x4",
];

fn is_identifier(text: &str) -> bool {
    text.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
}

/// The parameter names of the parameter list `tokens[open + 1 .. close]`: in each
/// comma-separated part with a type and a name (`in vec3 lightPos`, `float w[2]`), the
/// last identifier before any `[`. A call's arguments (`max(a, 0.0)`) name no type, so
/// they give none, except a part of two bare identifiers, which a call cannot have.
fn parameter_names(tokens: &[Token]) -> Vec<String> {
    tokens
        .split(|t| t.text == ",")
        .filter_map(|part| {
            let head = part.split(|t| t.text == "[").next().unwrap_or(part);
            let names: Vec<&Token> = head
                .iter()
                .filter(|t| is_identifier(&t.text) && !PARAMETER_QUALIFIERS.contains(&t.text.as_str()))
                .collect();
            let plain = head.iter().all(|t| is_identifier(&t.text));
            (names.len() == 2 && plain).then(|| names[1].text.clone())
        })
        .collect()
}

/// Where a name can refer to a top-level declaration: each identifier's count, leaving out
///
/// - a member access (after `.`): `light.lightPos` reads a member, not `lightPos`;
/// - a function's parameters (in a definition or a prototype) and every use inside that
///   function's body: `vec3 shade(vec3 lightPos) { … lightPos … }` reads its argument;
/// - a local declaration (`vec3 lightPos = …;`, a built-in type or a struct's name after
///   `{`, `;`, `}`, `(` or a precision or `const`) and its uses, to the end of its block.
///
/// Scopes follow braces; a declaration in a `for` header counts to the end of the
/// enclosing block (an over-count of the shadow, never of a read).
pub fn global_references(tokens: &[Token], structs: &BTreeMap<String, Vec<Field>>) -> BTreeMap<String, usize> {
    let mut references = BTreeMap::new();
    // (brace depth the name belongs to, name): the names that shadow a top-level one
    let mut scopes: Vec<(usize, String)> = Vec::new();
    let mut pending: Vec<String> = Vec::new();
    let mut parameter_until = 0usize;
    let (mut braces, mut parens) = (0usize, 0usize);
    // inside a function's body (a top-level `{` after `)`), not a struct's or a block's
    let mut in_function = false;
    for (k, t) in tokens.iter().enumerate() {
        match t.text.as_str() {
            "{" => {
                if braces == 0 {
                    in_function = k > 0 && tokens[k - 1].text == ")";
                }
                braces += 1;
                scopes.extend(pending.drain(..).map(|n| (braces, n)));
            }
            "}" => {
                scopes.retain(|(d, _)| *d < braces);
                braces = braces.saturating_sub(1);
                in_function &= braces > 0;
            }
            "(" => {
                if braces == 0 && parens == 0 && k > 0 && is_identifier(&tokens[k - 1].text) {
                    if let Some(close) = matching_paren(tokens, k) {
                        let names = parameter_names(&tokens[k + 1..close]);
                        if !names.is_empty() {
                            parameter_until = close;
                            pending = names;
                        }
                    }
                }
                parens += 1;
            }
            ")" => parens = parens.saturating_sub(1),
            ";" if braces == 0 && parens == 0 => pending.clear(),
            _ => {}
        }
        if !is_identifier(&t.text) {
            continue;
        }
        if k > 0 && tokens[k - 1].text == "." {
            continue;
        }
        if k < parameter_until && pending.contains(&t.text) {
            continue;
        }
        if in_function && declares_local(tokens, k, structs) {
            scopes.push((braces, t.text.clone()));
            continue;
        }
        if scopes.iter().any(|(_, n)| *n == t.text) {
            continue;
        }
        *references.entry(t.text.clone()).or_insert(0) += 1;
    }
    references
}

/// The index of the `)` closing the `(` at `open`, if any.
fn matching_paren(tokens: &[Token], open: usize) -> Option<usize> {
    let mut depth = 0usize;
    for (k, t) in tokens.iter().enumerate().skip(open) {
        match t.text.as_str() {
            "(" => depth += 1,
            ")" => {
                depth -= 1;
                if depth == 0 {
                    return Some(k);
                }
            }
            _ => {}
        }
    }
    None
}

/// Whether identifier `tokens[k]` is the name of a local declaration: after a type (a
/// built-in one or a struct's name) that starts a statement, and before `=`, `;`, `,` or `[`.
fn declares_local(tokens: &[Token], k: usize, structs: &BTreeMap<String, Vec<Field>>) -> bool {
    let Some(ty) = k.checked_sub(1).map(|j| &tokens[j]) else { return false };
    let typed = TYPE_NAMES.contains(&ty.text.as_str()) || structs.contains_key(&ty.text);
    let starts =
        k < 2 || matches!(tokens[k - 2].text.as_str(), "{" | ";" | "}" | "(" | "const" | "highp" | "mediump" | "lowp");
    let ends = tokens.get(k + 1).is_some_and(|t| matches!(t.text.as_str(), "=" | ";" | "," | "["));
    typed && starts && ends
}

/// The lines of directive `name` (`version`, `extension`): lines whose first non-blank
/// character is `#` followed by `name` (comments already blanked), as byte ranges without
/// the line break.
fn directive_lines(blanked: &str, name: &str) -> Vec<(usize, usize)> {
    let mut start = 0;
    let mut found = Vec::new();
    for line in blanked.split_inclusive('\n') {
        let trimmed = line.trim_start();
        if let Some(rest) = trimmed.strip_prefix('#') {
            let after = rest.trim_start().strip_prefix(name);
            if after.is_some_and(|a| !a.starts_with(|c: char| c.is_ascii_alphanumeric() || c == '_')) {
                found.push((start, start + line.trim_end_matches('\n').len()));
            }
        }
        start += line.len();
    }
    found
}

/// `layout(location = N, ...)` starting at `k` (the `layout` token): (end token index,
/// location).
fn parse_layout(tokens: &[Token], mut k: usize) -> (usize, Option<u32>) {
    let mut location = None;
    while k < tokens.len() && tokens[k].text != ")" {
        if tokens[k].text == "location" && tokens.get(k + 1).is_some_and(|t| t.text == "=") {
            location = tokens.get(k + 2).and_then(|t| parse_int(&t.text)).and_then(|v| u32::try_from(v).ok());
        }
        k += 1;
    }
    (k, location)
}

/// One declaration with storage qualifiers starting at `k`; returns the next index.
fn parse_declaration(tokens: &[Token], start: usize, parsed: &mut Parsed) -> usize {
    let mut k = start;
    let mut qualifiers = Vec::new();
    let mut storage = None;
    let mut location = None;
    while let Some(tok) = tokens.get(k) {
        match tok.text.as_str() {
            "layout" => {
                let (close, loc) = parse_layout(tokens, k);
                location = loc.or(location);
                if let Some(close) = tokens.get(close) {
                    qualifiers.push((tok.start, close.end));
                }
                k = close + 1;
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
    let Some(storage) = storage else { return start + 1 };
    if k + 1 >= tokens.len() {
        return tokens.len();
    }
    let ty = tokens[k].clone();
    if tokens[k + 1].text == "{" {
        return parse_block(tokens, k, storage, qualifiers, location, parsed);
    }
    k += 1;
    while let Some(name) = tokens.get(k) {
        k += 1;
        let array = parse_array(tokens, &mut k, parsed);
        parsed.decls.push(Declaration {
            storage,
            ty: ty.text.clone(),
            name: name.text.clone(),
            array,
            location,
            qualifiers: qualifiers.clone(),
            type_span: (ty.start, ty.end),
            block: None,
        });
        if tokens.get(k).is_some_and(|t| t.text == "=") {
            k = past_initializer(tokens, k + 1);
        }
        if tokens.get(k).is_some_and(|t| t.text == ",") {
            k += 1;
        } else {
            break;
        }
    }
    while k < tokens.len() && tokens[k].text != ";" {
        k += 1;
    }
    k + 1
}

/// The index of the `,` or `;` that ends an initializer starting at `k` (`0.1`,
/// `vec3(1.0, 0.5, 0.2)`): commas inside parentheses, brackets or braces belong to it.
fn past_initializer(tokens: &[Token], mut k: usize) -> usize {
    let mut depth = 0usize;
    while let Some(t) = tokens.get(k) {
        match t.text.as_str() {
            "(" | "[" | "{" => depth += 1,
            ")" | "]" | "}" => depth = depth.saturating_sub(1),
            "," | ";" if depth == 0 => break,
            _ => {}
        }
        k += 1;
    }
    k
}

/// Fields up to the closing `}` from `k` (after the `{`): (fields, index of `}`, inner
/// qualifier ranges).
fn parse_fields(tokens: &[Token], mut k: usize, parsed: &mut Parsed) -> (Vec<Field>, usize, Vec<(usize, usize)>) {
    let mut fields = Vec::new();
    let mut inner = Vec::new();
    while k < tokens.len() && tokens[k].text != "}" {
        while k < tokens.len() && (QUALIFIERS.contains(&tokens[k].text.as_str()) || tokens[k].text == "layout") {
            if tokens[k].text == "layout" {
                let (close, _) = parse_layout(tokens, k);
                if let Some(c) = tokens.get(close) {
                    inner.push((tokens[k].start, c.end));
                }
                k = close + 1;
            } else {
                inner.push((tokens[k].start, tokens[k].end));
                k += 1;
            }
        }
        let Some(ty) = tokens.get(k).cloned() else { break };
        if ty.text == "}" {
            break;
        }
        k += 1;
        while let Some(field) = tokens.get(k).cloned() {
            k += 1;
            let array = parse_array(tokens, &mut k, parsed);
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
    (fields, k, inner)
}

fn parse_struct(tokens: &[Token], mut k: usize, parsed: &mut Parsed) -> usize {
    let Some(name) = tokens.get(k + 1).map(|t| t.text.clone()) else { return k + 1 };
    k += 2;
    if tokens.get(k).is_none_or(|t| t.text != "{") {
        return k;
    }
    let (fields, close, _) = parse_fields(tokens, k + 1, parsed);
    parsed.structs.insert(name, fields);
    close + 1
}

/// An interface block at `k` (its name token): `NAME { members } [instance [array]] ;`.
fn parse_block(
    tokens: &[Token],
    k: usize,
    storage: Storage,
    qualifiers: Vec<(usize, usize)>,
    location: Option<u32>,
    parsed: &mut Parsed,
) -> usize {
    let name = &tokens[k];
    let open = &tokens[k + 1];
    let (members, close, inner_qualifiers) = parse_fields(tokens, k + 2, parsed);
    let mut frame = vec![(name.start, name.end), (open.start, open.end)];
    if let Some(c) = tokens.get(close) {
        frame.push((c.start, c.end));
    }
    let mut j = close + 1;
    let mut instance = String::new();
    let mut array = None;
    if let Some(t) = tokens.get(j).filter(|t| t.text != ";") {
        instance = t.text.clone();
        j += 1;
        array = parse_array(tokens, &mut j, parsed);
    }
    while j < tokens.len() && tokens[j].text != ";" {
        j += 1;
    }
    if let Some(semi) = tokens.get(j) {
        frame.push((semi.start, semi.end));
    }
    parsed.decls.push(Declaration {
        storage,
        ty: name.text.clone(),
        name: instance,
        array,
        location,
        qualifiers,
        type_span: (name.start, name.end),
        block: Some(Block { members, frame, inner_qualifiers }),
    });
    j + 1
}

/// The number of `float` components a type takes (`float` 1 ... `mat4` 16; a struct the
/// sum of its fields); unknown types count 4.
pub fn components(ty: &str, structs: &BTreeMap<String, Vec<Field>>, depth: usize) -> usize {
    match ty {
        "float" | "int" | "uint" | "bool" | "sampler2D" => 1,
        "vec2" | "ivec2" | "uvec2" | "bvec2" => 2,
        "vec3" | "ivec3" | "uvec3" | "bvec3" => 3,
        "vec4" | "ivec4" | "uvec4" | "bvec4" | "mat2" => 4,
        "mat3" => 9,
        "mat4" => 16,
        other => match structs.get(other) {
            Some(fields) if depth < 8 => fields
                .iter()
                .map(|f| components(&f.ty, structs, depth + 1).saturating_mul(f.array.unwrap_or(1)))
                .fold(0usize, usize::saturating_add),
            _ => 4,
        },
    }
}

#[cfg(test)]
mod tests;
