//! The GLSL preprocessor (GLSL 3.30 §3.3, GLSL ES 3.00 §3.4): a learner's file as the
//! driver compiles it, line for line, so that [`super::glsl::parse`] reads the declarations
//! that macros write and the rewrite (`check::rewrite`) edits the expanded text.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | chunk | the lines between two directives: the macros cannot change inside it, so a call may span its lines |
//! | hide set | the macros a token came through; a name in its own token's hide set is not expanded again ("painted blue", C99 §6.10.3.4), so `#define a a + 1` ends |
//! | placemarker | an empty argument next to `##`: the other operand is kept as it is (C99 §6.10.3.3) |
//!
//! | piece | what it does |
//! | --- | --- |
//! | lines | the output has the input's line breaks, one for one: a directive becomes an empty line, except `#version`, `#extension` and `#pragma`, kept verbatim; a line the conditionals skip becomes empty; an expansion stays on the line of its macro's name (a call over several lines: the expansion on its first line, the line breaks after it). Compile errors and counterexamples keep the learner's line numbers |
//! | macros | object-like and function-like, `#undef`; arguments macro-expanded before substitution (not next to `##`), then the result rescanned; `##` pasting (GLSL has no `#` stringizing) |
//! | conditionals | `#if`, `#ifdef`, `#ifndef`, `#elif`, `#else`, `#endif`; `defined X` and `defined(X)`, also from an object-like macro's body (as Mesa and GCC do); integer `+ - * / % << >> < > <= >= == != & ^ \| && \|\| ! ~` and parentheses; a name left after expansion is 0 |
//! | predefined | `__LINE__`, `__FILE__` (0), `__VERSION__` (the `#version` line's, else 110), `GL_core_profile` (desktop 150 and later, not `compatibility`), `GL_compatibility_profile`, `GL_ES` and `GL_FRAGMENT_PRECISION_HIGH` (`es`) |
//! | bounds | at most [`MAX_EXPANDED_TOKENS`] tokens made by expansions, [`MAX_OUTPUT_BYTES`] of output and [`MAX_NESTING`] nested argument expansions or parentheses in `#if`: a macro bomb is an error in well under a second, never a hang |
//!
//! Comments are blanked first ([`super::glsl::blank_comments`]); a `\` at the end of a line
//! joins the next (its line break is put back after the joined line). Anything this cannot
//! read (an `#if` without `#endif`, a second `#else`, a malformed `#define`, a call without
//! its `)`, an unknown directive, `#error`) is a [`PreprocessError`], never a panic: the
//! checker compiles the original file on the driver first, which reports the learner's own
//! errors with their lines, and only a file the driver accepts meets this error
//! ([`super::compile_shader`]).
//!
//! Deviation: Mesa also defines a macro for every extension it supports (`GL_ARB_...`);
//! here they are undefined, so `#ifdef GL_ARB_...` takes its `#else`.

use std::collections::{BTreeMap, VecDeque};
use std::fmt;
use std::rc::Rc;

use super::glsl::{blank_spans, comment_spans, parse_int, word_at, Word};

/// The most tokens all macro expansions of one file may produce (the chapter's shaders
/// expand a few dozen; a macro doubling its previous one 40 times would make 2⁴⁰).
pub const MAX_EXPANDED_TOKENS: usize = 1 << 18;
/// The longest preprocessed text, and the longest file preprocessed: the checker's own
/// file limit ([`super::MAX_SOURCE_BYTES`]).
pub const MAX_OUTPUT_BYTES: usize = super::MAX_SOURCE_BYTES;
/// The deepest nesting of macro calls inside arguments, and of parentheses in `#if`.
pub const MAX_NESTING: usize = 200;

/// Why a file could not be preprocessed: the line (1-based, the file's) and what was wrong.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PreprocessError {
    /// The line of the directive or macro call.
    pub line: usize,
    /// What was wrong.
    pub message: String,
}

impl fmt::Display for PreprocessError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for PreprocessError {}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    Ident,
    Number,
    Punct,
    Space,
    Newline,
}

/// A hide set as a shared list: adding a name shares the rest.
#[derive(Debug)]
struct HideNode {
    name: Rc<str>,
    next: Hide,
}

type Hide = Option<Rc<HideNode>>;

fn hides(mut hide: &Hide, name: &str) -> bool {
    while let Some(node) = hide {
        if &*node.name == name {
            return true;
        }
        hide = &node.next;
    }
    false
}

fn with(hide: &Hide, name: &Rc<str>) -> Hide {
    Some(Rc::new(HideNode { name: name.clone(), next: hide.clone() }))
}

/// `a ∪ b`, sharing `b`.
fn union(a: &Hide, b: &Hide) -> Hide {
    let mut out = b.clone();
    let mut node = a;
    while let Some(n) = node {
        if !hides(b, &n.name) {
            out = with(&out, &n.name);
        }
        node = &n.next;
    }
    out
}

#[derive(Debug, Clone)]
struct Tok {
    kind: Kind,
    text: String,
    /// The file's line (1-based) the token is on, or its expansion's call is on.
    line: usize,
    /// Whitespace came before it (inside a directive or an argument).
    space: bool,
    /// It came out of an expansion (the output separates it from its neighbours).
    expanded: bool,
    hide: Hide,
}

impl Tok {
    fn is(&self, text: &str) -> bool {
        self.kind == Kind::Punct && self.text == text
    }
}

const PUNCT3: &[&str] = &["<<=", ">>="];
const PUNCT2: &[&str] = &[
    "##", "&&", "||", "^^", "<<", ">>", "<=", ">=", "==", "!=", "++", "--", "+=", "-=", "*=", "/=", "%=", "&=", "|=",
    "^=",
];

/// Preprocessing tokens of `text`, whose first line is `line`. Every step advances by at
/// least one byte.
fn lex(text: &str, mut line: usize) -> Vec<Tok> {
    let b = text.as_bytes();
    let mut toks = Vec::new();
    let mut i = 0;
    let mut space = false;
    while i < b.len() {
        let c = b[i];
        let start = i;
        let kind = if c == b'\n' {
            i += 1;
            Kind::Newline
        } else if c.is_ascii_whitespace() {
            while i < b.len() && b[i].is_ascii_whitespace() && b[i] != b'\n' {
                i += 1;
            }
            Kind::Space
        } else if let Some((word, end)) = word_at(b, i) {
            i = end;
            match word {
                Word::Number => Kind::Number,
                Word::Ident => Kind::Ident,
            }
        } else {
            let rest = &text[i..];
            i += PUNCT3
                .iter()
                .chain(PUNCT2)
                .find(|p| rest.starts_with(*p))
                .map_or_else(|| rest.chars().next().map_or(1, char::len_utf8), |p| p.len());
            Kind::Punct
        };
        toks.push(Tok { kind, text: text[start..i].to_owned(), line, space, expanded: false, hide: None });
        space = matches!(kind, Kind::Space | Kind::Newline);
        if kind == Kind::Newline {
            line += 1;
        }
    }
    toks
}

/// A macro: its parameters (`None` for an object-like one) and its body.
#[derive(Debug)]
struct Macro {
    name: Rc<str>,
    params: Option<Vec<String>>,
    body: Vec<Tok>,
}

/// One `#if` level: whether the text around it is active, whether its current branch is,
/// whether a branch was taken already, and whether `#else` was seen.
struct Conditional {
    outer: bool,
    active: bool,
    taken: bool,
    seen_else: bool,
    line: usize,
}

struct Preprocessor {
    macros: BTreeMap<String, Rc<Macro>>,
    conditionals: Vec<Conditional>,
    /// Tokens made by expansions so far.
    spent: usize,
    /// `__LINE__` minus the physical line (a `#line` moves it).
    line_shift: i64,
    /// The line being read, for errors.
    line: usize,
}

fn fail<T>(line: usize, message: impl Into<String>) -> Result<T, PreprocessError> {
    Err(PreprocessError { line, message: message.into() })
}

/// What a directive line becomes in the output.
enum Keep {
    Verbatim,
    Empty,
}

/// One logical line: its text (continuations joined), its first line number, and the line
/// breaks it took (0 for a last line without one).
struct Logical {
    text: String,
    first: usize,
    breaks: usize,
}

/// `blanked` (`src` with the comments `spans` blanked) with a `\` put before each line
/// break that lies inside a `/* */` comment begun on a directive line. GLSL replaces a
/// comment by one space before preprocessing (§3.3), so `#define ONE /* a⏎ b */ 1.0` is
/// one directive whose body is `1.0`; [`logical_lines`] then joins those lines like any
/// continuation and puts their breaks back. A comment in code is left alone: joining
/// would move code to another line for no change in meaning.
fn directive_comments_joined(blanked: &str, spans: &[std::ops::Range<usize>]) -> String {
    let on_directive = |at: usize| {
        let line_start = blanked[..at].rfind('\n').map_or(0, |k| k + 1);
        blanked[line_start..at].trim_start().starts_with('#')
    };
    let joins = spans
        .iter()
        .filter(|span| on_directive(span.start))
        .flat_map(|span| blanked[span.clone()].match_indices('\n').map(move |(k, _)| span.start + k));
    let mut out = String::with_capacity(blanked.len());
    let mut from = 0;
    for at in joins {
        out += &blanked[from..at];
        out.push('\\');
        from = at;
    }
    out + &blanked[from..]
}

fn logical_lines(text: &str) -> Vec<Logical> {
    let mut out: Vec<Logical> = Vec::new();
    let mut line = 1;
    let mut open: Option<Logical> = None;
    for piece in text.split_inclusive('\n') {
        let ends = piece.ends_with('\n');
        let body = piece.strip_suffix('\n').unwrap_or(piece);
        let trimmed = body.strip_suffix('\r').unwrap_or(body);
        let current = open.get_or_insert_with(|| Logical { text: String::new(), first: line, breaks: 0 });
        current.breaks += usize::from(ends);
        line += usize::from(ends);
        match trimmed.strip_suffix('\\') {
            Some(joined) if ends => current.text.push_str(joined),
            _ => {
                current.text.push_str(body);
                out.extend(open.take());
            }
        }
    }
    out.extend(open.take());
    out
}

/// `text` (a whole shader) preprocessed, line for line (see the module docs).
///
/// Errors: [`PreprocessError`] for a file larger than [`MAX_OUTPUT_BYTES`], an expansion
/// past the bounds, a malformed or unknown directive, unbalanced conditionals, a call
/// without its `)` or with the wrong number of arguments, a paste that is not one token,
/// a division by zero in `#if`, and `#error`.
pub fn preprocess(src: &str) -> Result<String, PreprocessError> {
    if src.len() > MAX_OUTPUT_BYTES {
        return fail(1, format!("the file is {} bytes, above {MAX_OUTPUT_BYTES}", src.len()));
    }
    let spans = comment_spans(src);
    let text = directive_comments_joined(&blank_spans(src, &spans), &spans);
    let mut pp = Preprocessor { macros: BTreeMap::new(), conditionals: Vec::new(), spent: 0, line_shift: 0, line: 1 };
    pp.predefine(110, "");
    let mut out = String::with_capacity(text.len());
    let mut chunk = String::new();
    let mut chunk_line = 1;
    for logical in logical_lines(&text) {
        pp.line = logical.first;
        let breaks = "\n".repeat(logical.breaks);
        let Some(directive) = logical.text.trim_start().strip_prefix('#') else {
            if pp.active() {
                if chunk.is_empty() {
                    chunk_line = logical.first;
                }
                chunk += &logical.text;
                chunk += &breaks;
            } else {
                out += &breaks;
            }
            continue;
        };
        pp.flush(&mut chunk, chunk_line, &mut out)?;
        match pp.directive(directive, logical.first + logical.breaks)? {
            Keep::Verbatim => out += &logical.text,
            Keep::Empty => {}
        }
        out += &breaks;
        if out.len() > MAX_OUTPUT_BYTES {
            return fail(logical.first, format!("the expanded text is longer than {MAX_OUTPUT_BYTES} bytes"));
        }
    }
    pp.flush(&mut chunk, chunk_line, &mut out)?;
    if let Some(c) = pp.conditionals.last() {
        return fail(c.line, "#if without #endif");
    }
    Ok(out)
}

fn number(value: i64, line: usize) -> Tok {
    Tok { kind: Kind::Number, text: value.to_string(), line, space: false, expanded: true, hide: None }
}

fn is_name(t: &Tok) -> bool {
    t.kind == Kind::Ident
}

/// Whether two characters would join into one token (or start a comment) if written side
/// by side.
fn would_join(a: char, b: char) -> bool {
    let word = |c: char| c.is_ascii_alphanumeric() || c == '_';
    let pair = format!("{a}{b}");
    (word(a) && word(b))
        || (a == '.' && b.is_ascii_digit())
        || (a.is_ascii_digit() && b == '.')
        || pair == "//"
        || pair == "/*"
        || PUNCT3.iter().chain(PUNCT2).any(|p| p.starts_with(&pair))
}

impl Preprocessor {
    fn active(&self) -> bool {
        self.conditionals.last().is_none_or(|c| c.active)
    }

    /// The predefined macros for `#version {version} {profile}`.
    fn predefine(&mut self, version: i64, profile: &str) {
        let es = profile == "es";
        for name in
            ["__VERSION__", "GL_core_profile", "GL_compatibility_profile", "GL_ES", "GL_FRAGMENT_PRECISION_HIGH"]
        {
            self.macros.remove(name);
        }
        let mut define = |name: &str, value: i64| {
            let body = vec![number(value, 0)];
            self.macros.insert(name.to_owned(), Rc::new(Macro { name: name.into(), params: None, body }));
        };
        define("__VERSION__", version);
        if es {
            define("GL_ES", 1);
            define("GL_FRAGMENT_PRECISION_HIGH", 1);
        } else if version >= 150 && profile != "compatibility" {
            define("GL_core_profile", 1);
        } else if profile == "compatibility" {
            define("GL_compatibility_profile", 1);
        }
    }

    fn spend(&mut self, n: usize, line: usize) -> Result<(), PreprocessError> {
        self.spent += n;
        if self.spent > MAX_EXPANDED_TOKENS {
            return fail(line, format!("the macros expand to more than {MAX_EXPANDED_TOKENS} tokens"));
        }
        Ok(())
    }

    /// Expands the pending lines into `out`.
    fn flush(&mut self, chunk: &mut String, first_line: usize, out: &mut String) -> Result<(), PreprocessError> {
        if chunk.is_empty() {
            return Ok(());
        }
        let toks = lex(chunk, first_line);
        let uses_macros = toks
            .iter()
            .any(|t| is_name(t) && (self.macros.contains_key(&t.text) || t.text == "__LINE__" || t.text == "__FILE__"));
        if uses_macros {
            let expanded = self.expand(toks.into(), 0)?;
            let mut joined = false;
            for t in expanded {
                if matches!(t.kind, Kind::Space | Kind::Newline) {
                    *out += &t.text;
                    joined = false;
                    continue;
                }
                let prev = out.chars().next_back().filter(|c| !c.is_whitespace());
                if let (Some(p), Some(c)) = (prev, t.text.chars().next()) {
                    if (t.expanded || joined) && (t.space || would_join(p, c)) {
                        out.push(' ');
                    }
                }
                *out += &t.text;
                joined = t.expanded;
                if out.len() > MAX_OUTPUT_BYTES {
                    return fail(t.line, format!("the expanded text is longer than {MAX_OUTPUT_BYTES} bytes"));
                }
            }
        } else {
            *out += chunk;
        }
        chunk.clear();
        Ok(())
    }

    /// Macro-expands `input` (C99 §6.10.3.4: each replacement is rescanned with the rest).
    fn expand(&mut self, mut input: VecDeque<Tok>, depth: usize) -> Result<Vec<Tok>, PreprocessError> {
        if depth > MAX_NESTING {
            return fail(self.line, format!("macro calls nest deeper than {MAX_NESTING}"));
        }
        let mut out = Vec::new();
        while let Some(t) = input.pop_front() {
            if !is_name(&t) || hides(&t.hide, &t.text) {
                out.push(t);
                continue;
            }
            match t.text.as_str() {
                "__LINE__" => {
                    let line = i64::try_from(t.line).unwrap_or(i64::MAX).saturating_add(self.line_shift);
                    out.push(Tok { space: t.space, ..number(line, t.line) });
                    continue;
                }
                "__FILE__" => {
                    out.push(Tok { space: t.space, ..number(0, t.line) });
                    continue;
                }
                _ => {}
            }
            let Some(m) = self.macros.get(&t.text).cloned() else {
                out.push(t);
                continue;
            };
            let hide = with(&t.hide, &m.name);
            let Some(params) = &m.params else {
                let body = self.substitute(&m, &[], &hide, &t, depth)?;
                for b in body.into_iter().rev() {
                    input.push_front(b);
                }
                continue;
            };
            let open = input.iter().position(|x| !matches!(x.kind, Kind::Space | Kind::Newline));
            if !open.is_some_and(|j| input[j].is("(")) {
                out.push(t);
                continue;
            }
            let mut breaks = 0;
            let mut args: Vec<Vec<Tok>> = vec![Vec::new()];
            let mut level = 0usize;
            let mut space = false;
            let mut seen_open = false;
            loop {
                let Some(mut x) = input.pop_front() else {
                    return fail(t.line, format!("the call of `{}` has no closing `)`", t.text));
                };
                match x.kind {
                    Kind::Newline => {
                        breaks += 1;
                        space = true;
                        continue;
                    }
                    Kind::Space => {
                        space = true;
                        continue;
                    }
                    _ => {}
                }
                if !seen_open {
                    seen_open = true;
                    space = false;
                    continue;
                }
                x.space = space;
                space = false;
                if x.is("(") {
                    level += 1;
                } else if x.is(")") {
                    if level == 0 {
                        break;
                    }
                    level -= 1;
                } else if x.is(",") && level == 0 {
                    args.push(Vec::new());
                    continue;
                }
                if let Some(last) = args.last_mut() {
                    last.push(x);
                }
            }
            if params.is_empty() && args.len() == 1 && args[0].is_empty() {
                args.clear();
            }
            if args.len() != params.len() {
                return fail(
                    t.line,
                    format!("`{}` takes {} arguments, the call gives {}", t.text, params.len(), args.len()),
                );
            }
            let body = self.substitute(&m, &args, &hide, &t, depth)?;
            for _ in 0..breaks {
                input.push_front(Tok {
                    kind: Kind::Newline,
                    text: "\n".into(),
                    line: t.line,
                    space: false,
                    expanded: false,
                    hide: None,
                });
            }
            for b in body.into_iter().rev() {
                input.push_front(b);
            }
        }
        Ok(out)
    }

    /// `m`'s body with `args` substituted and `##` applied, every token marked as coming
    /// from the call `call` and hidden from the macros in `hide`.
    fn substitute(
        &mut self,
        m: &Macro,
        args: &[Vec<Tok>],
        hide: &Hide,
        call: &Tok,
        depth: usize,
    ) -> Result<Vec<Tok>, PreprocessError> {
        let params: &[String] = m.params.as_deref().unwrap_or(&[]);
        let mut expanded_args: Vec<Option<Vec<Tok>>> = vec![None; args.len()];
        let mut out: Vec<Tok> = Vec::new();
        let mut paste = false;
        let mut previous_empty = false;
        for (i, b) in m.body.iter().enumerate() {
            if b.is("##") {
                paste = true;
                continue;
            }
            let next_pastes = m.body.get(i + 1).is_some_and(|n| n.is("##"));
            let mut piece: Vec<Tok> = match params.iter().position(|p| is_name(b) && *p == b.text) {
                Some(p) if paste || next_pastes => args[p].clone(),
                Some(p) => {
                    if expanded_args[p].is_none() {
                        expanded_args[p] = Some(self.expand(args[p].iter().cloned().collect(), depth + 1)?);
                    }
                    expanded_args[p].clone().unwrap_or_default()
                }
                None => vec![b.clone()],
            };
            if let Some(first) = piece.first_mut() {
                first.space = b.space;
            }
            self.spend(piece.len(), call.line)?;
            if paste && !previous_empty && !piece.is_empty() {
                let left = out.pop().map(|l| l.text).unwrap_or_default();
                let right = piece.remove(0);
                let text = format!("{left}{}", right.text);
                let toks = lex(&text, call.line);
                let [one] = &toks[..] else {
                    return fail(call.line, format!("pasting `{left}` and `{}` does not give one token", right.text));
                };
                out.push(Tok { space: out.is_empty() && b.space, ..one.clone() });
                out.extend(piece);
                previous_empty = false;
            } else if paste && piece.is_empty() {
                // the left operand stays as it is (an empty right operand)
            } else {
                previous_empty = piece.is_empty();
                out.extend(piece);
            }
            paste = false;
        }
        let first_space = call.space;
        for (k, t) in out.iter_mut().enumerate() {
            t.line = call.line;
            t.expanded = true;
            t.hide = if t.hide.is_none() { hide.clone() } else { union(&t.hide, hide) };
            if k == 0 {
                t.space = first_space;
            }
        }
        Ok(out)
    }

    /// Reads one directive (the text after `#`); `next_line` is the line after it.
    fn directive(&mut self, directive: &str, next_line: usize) -> Result<Keep, PreprocessError> {
        let line = self.line;
        let directive = directive.trim_start();
        let word_len = directive.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(directive.len());
        let (word, rest) = directive.split_at(word_len);
        let active = self.active();
        match word {
            "if" | "ifdef" | "ifndef" => {
                let cond = if active {
                    match word {
                        "if" => self.condition(rest)?,
                        _ => {
                            let name = self.one_name(rest, word)?;
                            self.macros.contains_key(&name) == (word == "ifdef")
                        }
                    }
                } else {
                    false
                };
                // an inactive level has taken its branch already: nothing in it runs
                self.conditionals.push(Conditional {
                    outer: active,
                    active: active && cond,
                    taken: !active || cond,
                    seen_else: false,
                    line,
                });
                return Ok(Keep::Empty);
            }
            "elif" | "else" | "endif" => {
                let Some(c) = self.conditionals.last() else { return fail(line, format!("#{word} without #if")) };
                if word == "endif" {
                    self.conditionals.pop();
                    return Ok(Keep::Empty);
                }
                if c.seen_else {
                    return fail(line, format!("#{word} after #else"));
                }
                let (outer, taken) = (c.outer, c.taken);
                let cond = if word == "else" {
                    true
                } else if outer && !taken {
                    self.condition(rest)?
                } else {
                    false
                };
                if let Some(c) = self.conditionals.last_mut() {
                    c.active = outer && !taken && cond;
                    c.taken = taken || cond;
                    c.seen_else = word == "else";
                }
                return Ok(Keep::Empty);
            }
            _ if !active => return Ok(Keep::Empty),
            _ => {}
        }
        match word {
            "" => Ok(Keep::Empty),
            "define" => {
                self.define(rest)?;
                Ok(Keep::Empty)
            }
            "undef" => {
                let name = self.one_name(rest, "undef")?;
                self.macros.remove(&name);
                Ok(Keep::Empty)
            }
            "version" => {
                let mut words = rest.split_whitespace();
                let version = words.next().and_then(parse_int).map_or(110, |v| i64::try_from(v).unwrap_or(i64::MAX));
                self.predefine(version, words.next().unwrap_or(""));
                Ok(Keep::Verbatim)
            }
            "extension" | "pragma" => Ok(Keep::Verbatim),
            "line" => {
                let toks = self.expand(lex(rest, line).into(), 0)?;
                let Some(n) = toks.iter().find(|t| t.kind != Kind::Space).and_then(|t| parse_int(&t.text)) else {
                    return fail(line, "#line needs a line number");
                };
                let n = i64::try_from(n).unwrap_or(i64::MAX);
                self.line_shift = n.saturating_sub(i64::try_from(next_line).unwrap_or(i64::MAX));
                Ok(Keep::Empty)
            }
            "error" => fail(line, format!("#error{rest}")),
            other => fail(line, format!("unknown directive #{other}")),
        }
    }

    /// The one identifier after `#ifdef`, `#ifndef` or `#undef`.
    fn one_name(&self, rest: &str, word: &str) -> Result<String, PreprocessError> {
        let toks: Vec<Tok> = lex(rest, self.line).into_iter().filter(|t| t.kind != Kind::Space).collect();
        match &toks[..] {
            [t] if is_name(t) => Ok(t.text.clone()),
            _ => fail(self.line, format!("#{word} takes one name")),
        }
    }

    fn define(&mut self, rest: &str) -> Result<(), PreprocessError> {
        let line = self.line;
        let toks = lex(rest, line);
        let mut k = toks.iter().position(|t| t.kind != Kind::Space).unwrap_or(toks.len());
        let Some(name) = toks.get(k).filter(|t| is_name(t)).map(|t| t.text.clone()) else {
            return fail(line, "#define needs a name");
        };
        if matches!(name.as_str(), "defined" | "__LINE__" | "__FILE__" | "__VERSION__") {
            return fail(line, format!("`{name}` cannot be defined"));
        }
        k += 1;
        let mut params = None;
        if toks.get(k).is_some_and(|t| t.is("(")) {
            let mut list = Vec::new();
            k += 1;
            loop {
                let mut next = || {
                    while toks.get(k).is_some_and(|t| t.kind == Kind::Space) {
                        k += 1;
                    }
                    k += 1;
                    toks.get(k - 1)
                };
                match next() {
                    Some(t) if t.is(")") && list.is_empty() => break,
                    Some(t) if is_name(t) && !list.contains(&t.text) => list.push(t.text.clone()),
                    _ => return fail(line, format!("the parameters of `{name}` are malformed")),
                }
                match next() {
                    Some(t) if t.is(")") => break,
                    Some(t) if t.is(",") => {}
                    _ => return fail(line, format!("the parameters of `{name}` are malformed")),
                }
            }
            params = Some(list);
        }
        let mut body: Vec<Tok> = Vec::new();
        for t in toks.into_iter().skip(k).filter(|t| t.kind != Kind::Space) {
            body.push(Tok { space: t.space && !body.is_empty(), ..t });
        }
        if body.first().is_some_and(|t| t.is("##")) || body.last().is_some_and(|t| t.is("##")) {
            return fail(line, format!("`##` cannot begin or end the body of `{name}`"));
        }
        self.macros.insert(name.clone(), Rc::new(Macro { name: name.into(), params, body }));
        Ok(())
    }

    /// `toks` with every object-like macro whose body holds `defined` (directly or through
    /// its macros, [`Self::brings_defined`]) replaced by its body, again until none is left
    /// (at most [`DEFINED_DEPTH`] rounds), except as the operand of `defined` itself.
    /// `#define HAS_SPEC defined(SPECULAR)` then `#if HAS_SPEC` is undefined behaviour in
    /// C, and Mesa's glcpp, like GCC, evaluates the `defined` the expansion brings: so does
    /// this. Inlining counts against [`MAX_EXPANDED_TOKENS`] like any expansion, so macros
    /// that multiply each other are an error, not a hang.
    fn defined_macros_inlined(&mut self, mut toks: Vec<Tok>) -> Result<Vec<Tok>, PreprocessError> {
        for _ in 0..DEFINED_DEPTH {
            let mut out = Vec::with_capacity(toks.len());
            let mut changed = false;
            for (k, t) in toks.iter().enumerate() {
                let operand = k >= 1 && toks[k - 1].text == "defined"
                    || k >= 2 && toks[k - 1].is("(") && toks[k - 2].text == "defined";
                let with_defined = self
                    .macros
                    .get(&t.text)
                    .filter(|m| is_name(t) && !operand && m.params.is_none())
                    .filter(|m| self.brings_defined(m));
                match with_defined.cloned() {
                    Some(m) => {
                        changed = true;
                        self.spend(m.body.len(), t.line)?;
                        out.extend(
                            m.body.iter().filter(|b| b.kind != Kind::Space).map(|b| Tok { line: t.line, ..b.clone() }),
                        );
                    }
                    None => out.push(t.clone()),
                }
            }
            toks = out;
            if !changed {
                break;
            }
        }
        Ok(toks)
    }

    /// Whether object-like macro `m`'s body holds `defined`, itself or through the
    /// object-like macros it names. Each macro is looked at once, so a web of macros that
    /// name each other costs its size, not its paths.
    fn brings_defined(&self, m: &Macro) -> bool {
        let mut seen = std::collections::HashSet::new();
        let mut todo = vec![m];
        while let Some(m) = todo.pop() {
            if !seen.insert(Rc::as_ptr(&m.name)) {
                continue;
            }
            for b in &m.body {
                if b.text == "defined" {
                    return true;
                }
                if let Some(inner) = self.macros.get(&b.text).filter(|inner| inner.params.is_none()) {
                    todo.push(inner);
                }
            }
        }
        false
    }

    /// The value of an `#if` or `#elif` expression.
    fn condition(&mut self, rest: &str) -> Result<bool, PreprocessError> {
        let line = self.line;
        let toks: Vec<Tok> = lex(rest, line).into_iter().filter(|t| t.kind != Kind::Space).collect();
        let toks = self.defined_macros_inlined(toks)?;
        let mut replaced = VecDeque::new();
        let mut k = 0;
        while let Some(t) = toks.get(k) {
            k += 1;
            if t.text != "defined" {
                replaced.push_back(t.clone());
                continue;
            }
            let parenthesized = toks.get(k).is_some_and(|t| t.is("("));
            let name = toks.get(k + usize::from(parenthesized)).filter(|t| is_name(t));
            let Some(name) = name else { return fail(line, "`defined` needs a name") };
            k += 1 + usize::from(parenthesized);
            if parenthesized {
                if !toks.get(k).is_some_and(|t| t.is(")")) {
                    return fail(line, "`defined(` needs its `)`");
                }
                k += 1;
            }
            let known = self.macros.contains_key(&name.text) || matches!(name.text.as_str(), "__LINE__" | "__FILE__");
            replaced.push_back(number(i64::from(known), line));
        }
        let expanded: Vec<Tok> =
            self.expand(replaced, 0)?.into_iter().filter(|t| !matches!(t.kind, Kind::Space | Kind::Newline)).collect();
        let mut e = Expr { toks: &expanded, k: 0, line, skipped: 0 };
        let value = e.binary(0, 0)?;
        if e.k != expanded.len() {
            return fail(line, "the #if expression has more after its end");
        }
        Ok(value != 0)
    }
}

/// How many times [`Preprocessor::defined_macros_inlined`] inlines: a macro that names
/// itself through `defined` stops there, and is then expanded as any other.
const DEFINED_DEPTH: usize = 16;

/// An `#if` expression, by precedence climbing over the expanded tokens.
struct Expr<'a> {
    toks: &'a [Tok],
    k: usize,
    line: usize,
    /// Inside the right operand of a decided `&&` or `||` (C: not evaluated, so a division
    /// by zero there is no error).
    skipped: usize,
}

fn precedence(op: &str) -> Option<u8> {
    Some(match op {
        "*" | "/" | "%" => 10,
        "+" | "-" => 9,
        "<<" | ">>" => 8,
        "<" | ">" | "<=" | ">=" => 7,
        "==" | "!=" => 6,
        "&" => 5,
        "^" => 4,
        "|" => 3,
        "&&" => 2,
        "||" => 1,
        _ => return None,
    })
}

impl Expr<'_> {
    fn binary(&mut self, min: u8, depth: usize) -> Result<i64, PreprocessError> {
        let mut lhs = self.unary(depth)?;
        loop {
            let Some(op) = self.toks.get(self.k).filter(|t| t.kind == Kind::Punct) else { return Ok(lhs) };
            let Some(p) = precedence(&op.text).filter(|p| *p > min) else { return Ok(lhs) };
            self.k += 1;
            let decided = (op.text == "&&" && lhs == 0) || (op.text == "||" && lhs != 0);
            self.skipped += usize::from(decided);
            let rhs = self.binary(p, depth + 1);
            self.skipped -= usize::from(decided);
            let rhs = rhs?;
            lhs = match op.text.as_str() {
                "*" => lhs.wrapping_mul(rhs),
                "/" | "%" if rhs == 0 && self.skipped > 0 => 0,
                "/" | "%" if rhs == 0 => return fail(self.line, "division by zero in #if"),
                "/" => lhs.wrapping_div(rhs),
                "%" => lhs.wrapping_rem(rhs),
                "+" => lhs.wrapping_add(rhs),
                "-" => lhs.wrapping_sub(rhs),
                "<<" => lhs.wrapping_shl(u32::try_from(rhs & 63).unwrap_or(0)),
                ">>" => lhs.wrapping_shr(u32::try_from(rhs & 63).unwrap_or(0)),
                "<" => i64::from(lhs < rhs),
                ">" => i64::from(lhs > rhs),
                "<=" => i64::from(lhs <= rhs),
                ">=" => i64::from(lhs >= rhs),
                "==" => i64::from(lhs == rhs),
                "!=" => i64::from(lhs != rhs),
                "&" => lhs & rhs,
                "^" => lhs ^ rhs,
                "|" => lhs | rhs,
                "&&" => i64::from(lhs != 0 && rhs != 0),
                _ => i64::from(lhs != 0 || rhs != 0),
            };
        }
    }

    fn unary(&mut self, depth: usize) -> Result<i64, PreprocessError> {
        if depth > MAX_NESTING {
            return fail(self.line, format!("the #if expression nests deeper than {MAX_NESTING}"));
        }
        let Some(t) = self.toks.get(self.k) else { return fail(self.line, "the #if expression ends early") };
        self.k += 1;
        match (t.kind, t.text.as_str()) {
            (Kind::Punct, "+") => self.unary(depth + 1),
            (Kind::Punct, "-") => Ok(self.unary(depth + 1)?.wrapping_neg()),
            (Kind::Punct, "!") => Ok(i64::from(self.unary(depth + 1)? == 0)),
            (Kind::Punct, "~") => Ok(!self.unary(depth + 1)?),
            (Kind::Punct, "(") => {
                let v = self.binary(0, depth + 1)?;
                if !self.toks.get(self.k).is_some_and(|t| t.is(")")) {
                    return fail(self.line, "a `(` in #if has no `)`");
                }
                self.k += 1;
                Ok(v)
            }
            (Kind::Number, text) => match parse_int(text) {
                Some(v) => Ok(i64::try_from(v).unwrap_or(i64::MAX)),
                None => fail(self.line, format!("`{text}` is not an integer")),
            },
            // a name no macro defines (C: 0)
            (Kind::Ident, _) => Ok(0),
            (_, text) => fail(self.line, format!("`{text}` in an #if expression")),
        }
    }
}

#[cfg(test)]
mod tests;
