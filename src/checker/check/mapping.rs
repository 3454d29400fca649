//! The `--uniforms` mapping file, and the matching of a shader's declared leaves to the
//! model's quantities.

use std::collections::{BTreeMap, BTreeSet};

use super::glsl::{Declaration, Field, Parsed, Storage};
use super::CheckError;
use crate::checker::texts;
use crate::gl::layout::{Layout, QType, Quantity, Slot};

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
    /// The `[values]` keys given as an array of 3 numbers (the others were one number):
    /// a float quantity given an array is an error, not its first element.
    pub vectors: BTreeSet<String>,
    /// The line of each `names.KEY` / `values.KEY` entry in the file (`"names.uLight"`), for
    /// messages; empty for a mapping built in code.
    pub lines: BTreeMap<String, usize>,
    /// `[rules] forbid`: model quantities the shader must not declare (an exercise's own
    /// rule, such as `viewPos` in view space); a light's name forbids all its fields.
    pub forbid: Vec<String>,
    /// `[rules] require`: model quantities the shader must declare.
    pub require: Vec<String>,
    /// `[names]` keys a shader may leave undeclared: in `grade`, the teacher's file is one
    /// mapping for a whole class, and a student who keeps the chapter's names declares
    /// none of the renamed ones (elsewhere a key that names nothing is an error: a typo).
    pub optional_names: BTreeSet<String>,
    /// The file the mapping was read from, for messages (`None` for a mapping built in code
    /// or an exercise's own).
    pub file: Option<String>,
}

impl Mapping {
    /// `"FILE: line N: "` for the entry `table.key` (without the file when the mapping has
    /// none), or nothing when the line is unknown.
    pub fn at(&self, table: &str, key: &str) -> String {
        let file = self.file.as_ref().map_or(String::new(), |f| format!("{f}: "));
        self.lines.get(&format!("{table}.{key}")).map_or(String::new(), |l| format!("{file}line {l}: "))
    }
}

/// The line (1-based) of `key = ...` inside `[section]`, matched exactly (a bare or quoted
/// key), or of the `[section]` header when `key` is `None`.
fn key_line(text: &str, section: &str, key: Option<&str>) -> Option<usize> {
    let mut current = String::new();
    for (i, line) in text.lines().enumerate() {
        let t = line.trim();
        if let Some(header) = t.strip_prefix('[').and_then(|h| h.split(']').next()) {
            current = header.trim().to_string();
            if key.is_none() && current == section {
                return Some(i + 1);
            }
            continue;
        }
        let Some(key) = key else { continue };
        if current != section {
            continue;
        }
        let Some((lhs, _)) = t.split_once('=') else { continue };
        let lhs = lhs.trim();
        let unquoted = lhs.strip_prefix('"').and_then(|l| l.strip_suffix('"')).unwrap_or(lhs);
        if unquoted == key {
            return Some(i + 1);
        }
    }
    None
}

fn prefix(line: Option<usize>) -> String {
    line.map_or(String::new(), |l| format!("line {l}: "))
}

/// Parses a mapping file (see [`crate::checker::check`]).
///
/// Errors: [`CheckError::Usage`] naming the line and the key for invalid TOML, an unknown
/// table, a name that is not a string, a value that is not a finite number or an array of
/// 3 finite numbers.
pub fn parse_mapping(text: &str) -> Result<Mapping, CheckError> {
    let table: toml::Table = match text.parse() {
        Ok(t) => t,
        Err(e) => {
            let line = e.span().map(|s| text[..s.start.min(text.len())].lines().count().max(1));
            let at = line.map_or(String::new(), |l| format!(" at line {l}"));
            return usage(format!("invalid TOML{at}: {}", e.message()));
        }
    };
    let mut mapping = Mapping::default();
    for (section, value) in &table {
        let Some(entries) = value.as_table() else {
            let line = key_line(text, "", Some(section));
            return usage(format!("{}`{section}` must be a table ([names] or [values])", prefix(line)));
        };
        if section == "rules" {
            parse_rules(text, entries, &mut mapping)?;
            continue;
        }
        if section != "names" && section != "values" {
            let line = key_line(text, section, None);
            return usage(format!("{}unknown table [{section}] (expected [names], [values] or [rules])", prefix(line)));
        }
        for (key, v) in entries {
            let line = key_line(text, section, Some(key));
            if let Some(l) = line {
                mapping.lines.insert(format!("{section}.{key}"), l);
            }
            if section == "names" {
                match v.as_str() {
                    Some(s) => {
                        mapping.names.insert(key.clone(), s.to_string());
                    }
                    None => return usage(format!("{}names.{key} must be a string (a model name)", prefix(line))),
                }
                continue;
            }
            let num = |v: &toml::Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
            let value = match (num(v), v.as_array()) {
                (Some(x), _) => [x; 3],
                (None, Some(a)) if a.len() == 3 && a.iter().all(|x| num(x).is_some()) => {
                    mapping.vectors.insert(key.clone());
                    let f = |i: usize| num(&a[i]).unwrap_or(f64::NAN);
                    [f(0), f(1), f(2)]
                }
                _ => return usage(format!("{}values.{key} must be a number or an array of 3 numbers", prefix(line))),
            };
            if let Some(bad) = value.iter().find(|x| !x.is_finite() || !(**x as f32).is_finite()) {
                return usage(format!("{}values.{key} must be finite (got {bad})", prefix(line)));
            }
            mapping.values.insert(key.clone(), value.map(|x| x as f32));
        }
    }
    Ok(mapping)
}

/// The `[rules]` table: `forbid` and `require`, each an array of model quantity names.
fn parse_rules(text: &str, entries: &toml::Table, mapping: &mut Mapping) -> Result<(), CheckError> {
    for (key, v) in entries {
        let line = key_line(text, "rules", Some(key));
        let list = match key.as_str() {
            "forbid" => &mut mapping.forbid,
            "require" => &mut mapping.require,
            _ => return usage(format!("{}rules.{key}: unknown rule (expected forbid or require)", prefix(line))),
        };
        let names =
            v.as_array().and_then(|a| a.iter().map(|x| x.as_str().map(String::from)).collect::<Option<Vec<_>>>());
        match names {
            Some(names) => list.extend(names),
            None => return usage(format!("{}rules.{key} must be an array of model names", prefix(line))),
        }
    }
    Ok(())
}

/// What the exercise's `[rules]` say the shader must not or must declare, and it did or
/// did not (English msgids of `po/messages.pot`; `{}`: the model's name for it).
pub const RULE_FORBIDDEN: &str = "the exercise asks you not to declare `{}` (see its statement)";
/// See [`RULE_FORBIDDEN`].
pub const RULE_REQUIRED: &str = "the exercise asks you to declare `{}` (see its statement)";

/// The first rule of `mapping` that `leaves` break, as `(msgid, name)`; a rule naming no
/// quantity of `model` is a usage error (the mapping is wrong, not the shader).
pub(super) fn broken_rule(
    model: &Layout,
    mapping: &Mapping,
    leaves: &[Leaf],
) -> Result<Option<(&'static str, String)>, CheckError> {
    let covers = |rule: &str, name: &str| {
        name == rule || name.starts_with(&format!("{rule}.")) || name.starts_with(&format!("{rule}["))
    };
    for rule in mapping.forbid.iter().chain(&mapping.require) {
        if !model.quantities.iter().any(|q| covers(rule, q.name) || covers(q.name, rule)) {
            return usage(format!(
                "rules: `{rule}` is not a quantity of model {}; the model knows: {}",
                model.id,
                known_names(model)
            ));
        }
    }
    let declared = |rule: &str| leaves.iter().any(|l| covers(rule, &l.model));
    if let Some(rule) = mapping.forbid.iter().find(|r| declared(r)) {
        return Ok(Some((RULE_FORBIDDEN, rule.clone())));
    }
    Ok(mapping.require.iter().find(|r| !declared(r)).map(|rule| (RULE_REQUIRED, rule.clone())))
}

/// One declared leaf of the user's shader and the model quantity it is.
#[derive(Debug, Clone)]
pub(super) struct Leaf {
    /// The shader's expression (`light.position`, `pointLights[2].constant`, `fs_in.FragPos`).
    pub user: String,
    /// The model's name for it.
    pub model: String,
    /// The quantity (for case-scope and unused quantities); `None` for a group uniform.
    pub quantity: Option<Quantity>,
    /// A `vec4` carrying a `vec3` quantity (an engine's std140 block): loaded with `w` =
    /// [`carried_w`].
    pub carries_vec3: bool,
    /// Whether the shader reads it: false when its name occurs only where it is declared
    /// (`never_read`: whole identifiers outside comments, so `// lightPos` and
    /// `lightPosition` do not count).
    pub read: bool,
}

/// The notes for the leaves among `leaves` that the cases drive but the shader never reads
/// ([`texts::NOTE_NEVER_READ`]): a per-case quantity or a scene uniform, declared and never
/// read, so the colour cannot follow it (a learner who declares `lightPos` and writes a
/// constant position instead). Left out: a quantity `fixed` by the mapping's `[values]`
/// (the cases do not vary it), one the model does not use (texture coordinates), and one
/// that another leaf of the same model name reads (the other stage of a pair). Array
/// elements share their name, so they are read or not together: one note stands for all
/// (`pointLights[i].position`).
pub(super) fn never_read_notes(leaves: &[Leaf], fixed: &[(&'static str, [f32; 3])]) -> Vec<String> {
    let driven = |l: &Leaf| match l.quantity {
        None => true,
        Some(q) => matches!(q.slot, Slot::Case { .. }) && !fixed.iter().any(|(name, _)| *name == q.name),
    };
    let mut notes = Vec::new();
    for leaf in leaves.iter().filter(|l| !l.read && driven(l)) {
        if leaves.iter().any(|other| other.read && other.model == leaf.model) {
            continue;
        }
        let note = texts::tr_fill(texts::NOTE_NEVER_READ, &[&any_index(&leaf.user), &any_index(&leaf.model)]);
        if !notes.contains(&note) {
            notes.push(note);
        }
    }
    notes
}

/// `name` with every array index written `[i]` (`pointLights[2].position` →
/// `pointLights[i].position`).
fn any_index(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    let mut inside = false;
    for c in name.chars() {
        match c {
            '[' => {
                inside = true;
                out.push_str("[i]");
            }
            ']' => inside = false,
            _ if inside => {}
            c => out.push(c),
        }
    }
    out
}

/// The `w` a `vec4` carrying the `vec3` quantity `model` gets: 0 for a direction (a
/// homogeneous direction), 1 for a position or a colour (a point, an opaque colour).
#[must_use]
pub(super) fn carried_w(model: &str) -> f32 {
    if model.to_ascii_lowercase().contains("direction") {
        0.0
    } else {
        1.0
    }
}

fn indices(array: Option<usize>) -> Vec<String> {
    match array {
        Some(n) => (0..n).map(|i| format!("[{i}]")).collect(),
        None => vec![String::new()],
    }
}

/// A candidate leaf: the shader's expression, the model name it maps to, its GLSL type,
/// and the mapping key that renamed it (if one did).
struct Candidate {
    user: String,
    model: String,
    ty: String,
    renamed_by: Option<String>,
}

fn rename(mapping: &Mapping, key: &str, fallback: String) -> (String, Option<String>) {
    match mapping.names.get(key) {
        Some(m) => (m.clone(), Some(key.to_string())),
        None => (fallback, None),
    }
}

/// How deep structs may nest inside one declaration (GLSL forbids a struct containing
/// itself, but the scanner reads any text, so the walk is bounded).
const MAX_NESTING: usize = 8;

/// The leaves under `user` (mapped to `model`) of GLSL type `ty`: itself, or, for a
/// struct, every field's leaves (`surface.params.ka`), each renamed by the mapping when a
/// key names it.
fn expand(
    c: Candidate,
    structs: &BTreeMap<String, Vec<Field>>,
    mapping: &Mapping,
    depth: usize,
    out: &mut Vec<Candidate>,
) {
    let Some(fields) = structs.get(&c.ty).filter(|_| depth < MAX_NESTING) else {
        out.push(c);
        return;
    };
    for f in fields {
        for fidx in indices(f.array) {
            let user = format!("{}.{}{fidx}", c.user, f.name);
            let (model, by) = rename(mapping, &user, format!("{}.{}{fidx}", c.model, f.name));
            let field = Candidate { user, model, ty: f.ty.clone(), renamed_by: by.or(c.renamed_by.clone()) };
            expand(field, structs, mapping, depth + 1, out);
        }
    }
}

fn candidates(decl: &Declaration, structs: &BTreeMap<String, Vec<Field>>, mapping: &Mapping) -> Vec<Candidate> {
    let mut out = Vec::new();
    if let Some(block) = &decl.block {
        for idx in indices(decl.array) {
            for m in &block.members {
                for fidx in indices(m.array) {
                    let user = if decl.name.is_empty() {
                        format!("{}{fidx}", m.name)
                    } else {
                        format!("{}{idx}.{}{fidx}", decl.name, m.name)
                    };
                    let (base, by) = rename(mapping, &m.name, m.name.clone());
                    let (model, by2) = rename(mapping, &user, format!("{base}{fidx}"));
                    let member = Candidate { user, model, ty: m.ty.clone(), renamed_by: by2.or(by) };
                    expand(member, structs, mapping, 0, &mut out);
                }
            }
        }
        return out;
    }
    let (base, base_by) = rename(mapping, &decl.name, decl.name.clone());
    for idx in indices(decl.array) {
        let user = format!("{}{idx}", decl.name);
        let (model, by) = rename(mapping, &user, format!("{base}{idx}"));
        let top = Candidate { user, model, ty: decl.ty.clone(), renamed_by: by.or(base_by.clone()) };
        expand(top, structs, mapping, 0, &mut out);
    }
    out
}

/// Whether a declared GLSL type can hold a quantity of type `ty`; a `vec4` holds a `vec3`
/// quantity too (see [`Leaf::carries_vec3`]).
fn type_matches(glsl: &str, ty: QType) -> bool {
    matches!(
        (glsl, ty),
        ("float", QType::Float)
            | ("vec2", QType::Vec2)
            | ("vec3", QType::Vec3)
            | ("vec4", QType::Vec3)
            | ("sampler2D", QType::Texel)
            | ("vec4", QType::Texel)
            | ("mat4", QType::Mat4)
    )
}

fn qtype_name(ty: QType) -> &'static str {
    match ty {
        QType::Texel => "sampler2D",
        other => other.name(),
    }
}

/// The model's quantity names, comma-separated, for messages.
pub(super) fn known_names(model: &Layout) -> String {
    model.quantities.iter().map(|q| q.name).collect::<Vec<_>>().join(", ")
}

/// Every `[names]` key must name something the shader declares: a variable, a block
/// member, or a leaf (`light.position`, `pointLights[0].constant`). One message per key
/// that names nothing.
fn unused_names(parsed: &Parsed, mapping: &Mapping, all: &[&Candidate]) -> Vec<String> {
    let mut declared: BTreeSet<&str> = BTreeSet::new();
    for d in &parsed.decls {
        declared.insert(&d.name);
        if let Some(b) = &d.block {
            declared.extend(b.members.iter().map(|m| m.name.as_str()));
        }
    }
    declared.extend(all.iter().map(|c| c.user.as_str()));
    let shown: Vec<&str> = parsed.decls.iter().map(|d| d.name.as_str()).filter(|n| !n.is_empty()).collect();
    mapping
        .names
        .keys()
        .filter(|key| !declared.contains(key.as_str()) && !mapping.optional_names.contains(*key))
        .map(|key| {
            format!(
                "{}names.{key}: the shader declares no `{key}` (it declares: {})",
                mapping.at("names", key),
                shown.join(", ")
            )
        })
        .collect()
}

/// Whether the last name of `user` (`_pad0` in `surface.params._pad0`) occurs in the
/// shader only where it is declared: a member the shader never reads, such as std140
/// padding, which needs no quantity. A top-level name counts only where it can refer to
/// the declaration ([`Parsed::references`]): a same-named parameter or local, or a member
/// access, reads something else (as the driver's list of active uniforms says in the page).
fn never_read(user: &str, parsed: &Parsed) -> bool {
    let member = user.contains('.');
    let name = user.rsplit('.').next().unwrap_or(user);
    let name = name.split('[').next().unwrap_or(name);
    let counts = if member { &parsed.identifiers } else { &parsed.references };
    let declared = parsed.decls.iter().filter(|d| d.name == name).count()
        + parsed
            .decls
            .iter()
            .filter_map(|d| d.block.as_ref())
            .flat_map(|b| &b.members)
            .filter(|m| m.name == name)
            .count()
        + parsed.structs.values().flatten().filter(|f| f.name == name).count();
    counts.get(name).copied().unwrap_or(0) <= declared
}

/// Why candidate `c` is no quantity of `model`: blaming the mapping entry that renamed it,
/// or offering the closest free quantity, with its mapping line (`uLightPos = "lightPos"`)
/// for the one `[names]` block [`map_leaves`] prints after every message.
fn unknown_leaf(c: &Candidate, model: &Layout, mapping: &Mapping, taken: &BTreeSet<&str>) -> (String, Option<String>) {
    if let Some(key) = &c.renamed_by {
        // a name close to a quantity's (`objectColour`, `lightPosition`, `lightpos`): offer it
        let guess = closest_quantity(&c.model, &c.ty, model, taken)
            .map_or(String::new(), |name| format!("; did you mean `{name}`? ({key} = \"{name}\")"));
        let why = format!(
            "{}names.{key} maps `{}` to `{}`, which is not a quantity of model {}{guess}; the model knows: {}",
            mapping.at("names", key),
            c.user,
            c.model,
            model.id,
            known_names(model)
        );
        return (why, None);
    }
    let guess = closest_quantity(&c.user, &c.ty, model, taken);
    let hint = guess.map_or(String::new(), |name| format!("; did you mean `{name}`?"));
    let line = guess.map(|name| format!("{} = \"{name}\"", toml_key(&c.user)));
    let stage = if matches!(c.model.as_str(), "view" | "projection") {
        format!(
            "; `{}` is a vertex-stage uniform: check this shader together with its vertex shader (--vertex FILE.vert)",
            c.model
        )
    } else {
        String::new()
    };
    let why = format!(
        "`{}` is not a quantity of model {} (map it with --uniforms); the model knows: {}{hint}{stage}",
        c.user,
        model.id,
        known_names(model)
    );
    (why, line)
}

/// Two leaves of the shader mapped to one model quantity: one message per quantity.
fn mapped_twice(leaves: &[(usize, Vec<Leaf>)], mapping: &Mapping) -> Vec<String> {
    let mut by_model: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for leaf in leaves.iter().flat_map(|(_, l)| l) {
        by_model.entry(leaf.model.as_str()).or_default().push(leaf.user.as_str());
    }
    by_model
        .into_iter()
        .filter(|(_, users)| users.len() > 1)
        .map(|(model, users)| {
            let lines: Vec<String> = users
                .iter()
                .filter_map(|u| mapping.lines.get(&format!("names.{u}")))
                .map(|l| format!("line {l}"))
                .collect();
            let at = if lines.is_empty() { String::new() } else { format!(" (mapping {})", lines.join(", ")) };
            let names: Vec<String> = users.iter().map(|u| format!("`{u}`")).collect();
            format!("{} all map to the model's `{model}`{at}: map each quantity once", names.join(" and "))
        })
        .collect()
}

/// Matches every declared leaf whose storage is in `mapped` (`in` and `uniform` for a
/// fragment shader checked alone; `uniform` only when its inputs come from a vertex shader)
/// to a model quantity: `(declaration index, its leaves)`. A member the shader never reads
/// and the model does not know (std140 padding) is left out.
///
/// Errors: [`CheckError::Usage`] listing, one per line, every leaf the model does not know
/// (blaming the mapping entry when one renamed it), every type mismatch, every `[names]`
/// entry that matches nothing, and every quantity two leaves map to.
pub(super) fn map_leaves(
    model: &Layout,
    parsed: &Parsed,
    mapping: &Mapping,
    mapped: &[Storage],
) -> Result<Vec<(usize, Vec<Leaf>)>, CheckError> {
    let per_decl: Vec<(usize, Vec<Candidate>)> = parsed
        .decls
        .iter()
        .enumerate()
        .filter(|(_, decl)| mapped.contains(&decl.storage))
        .map(|(d, decl)| (d, candidates(decl, &parsed.structs, mapping)))
        .collect();
    let all: Vec<&Candidate> = per_decl.iter().flat_map(|(_, c)| c).collect();
    let taken: BTreeSet<&str> = all.iter().map(|o| o.model.as_str()).collect();
    let mut errors = unused_names(parsed, mapping, &all);
    let mut suggested: Vec<String> = Vec::new();
    let mut out = Vec::new();
    for (d, cands) in &per_decl {
        let decl = &parsed.decls[*d];
        let mut leaves = Vec::new();
        for c in cands {
            let group = model.quantities.iter().find(|q| {
                q.slot == Slot::Group
                    && (c.model == q.name
                        || c.model.starts_with(&format!("{}.", q.name))
                        || c.model.starts_with(&format!("{}[", q.name)))
            });
            if group.is_some() {
                if decl.block.is_some() {
                    errors.push(format!(
                        "`{}` is a scene light inside an interface block; declare the lights as plain uniforms",
                        c.user
                    ));
                }
                let carries_vec3 = c.ty == "vec4";
                let read = !never_read(&c.user, parsed);
                leaves.push(Leaf { user: c.user.clone(), model: c.model.clone(), quantity: None, carries_vec3, read });
                continue;
            }
            let Some(q) = model.quantities.iter().find(|q| q.name == c.model) else {
                if c.renamed_by.is_some() || !never_read(&c.user, parsed) {
                    let (why, line) = unknown_leaf(c, model, mapping, &taken);
                    errors.push(why);
                    suggested.extend(line);
                }
                continue;
            };
            if !type_matches(&c.ty, q.ty) {
                errors.push(format!(
                    "`{}` is declared {}, but the model's `{}` is a {}",
                    c.user,
                    c.ty,
                    q.name,
                    qtype_name(q.ty)
                ));
                continue;
            }
            let carries_vec3 = c.ty == "vec4" && q.ty == QType::Vec3;
            let read = !never_read(&c.user, parsed);
            leaves.push(Leaf { user: c.user.clone(), model: c.model.clone(), quantity: Some(*q), carries_vec3, read });
        }
        out.push((*d, leaves));
    }
    errors.extend(mapped_twice(&out, mapping));
    if !suggested.is_empty() {
        // one block, so the lines paste into a file as they are (a `[names]` per line
        // would be a duplicate table)
        errors.push(format!(
            "Add these lines to a mapping file and pass it with --uniforms:\n[names]\n{}",
            suggested.join("\n")
        ));
    }
    if errors.is_empty() {
        Ok(out)
    } else {
        usage(errors.join("\n"))
    }
}

/// The model quantity a renamed uniform most likely stands for: among the quantities of a
/// matching type that no other declaration already maps to, the one with the smallest
/// edit distance between lower-cased names (`uLightPosition` → `lightPos`), counting a
/// name contained in the other as close. `None` when nothing is within half the longer
/// name's length, or the name (without its `u`/`a`/`v`/`g`/`_` prefix) is under three
/// letters, so a wild guess is never offered.
fn closest_quantity<'m>(user: &str, glsl_ty: &str, model: &'m Layout, taken: &BTreeSet<&str>) -> Option<&'m str> {
    let leaf = user.rsplit(['.', ']']).next().unwrap_or(user).to_lowercase();
    let trimmed = leaf.trim_start_matches(['u', 'a', 'v', 'g', '_']);
    // Two letters (`wp`, `kd`) say too little to guess from: `wp` was once offered `viewPos`.
    if trimmed.chars().count() < 3 {
        return None;
    }
    model
        .quantities
        .iter()
        .filter(|q| q.slot != Slot::Group && !taken.contains(q.name) && type_matches(glsl_ty, q.ty))
        .filter_map(|q| {
            let name = q.name.rsplit('.').next().unwrap_or(q.name).to_lowercase();
            let contained = leaf.contains(&name) || name.contains(trimmed);
            let d = if contained { leaf.len().abs_diff(name.len()) / 2 } else { edit_distance(&leaf, &name) };
            (d * 2 <= leaf.len().max(name.len())).then_some((d, q.name))
        })
        .min()
        .map(|(_, name)| name)
}

/// Levenshtein distance between two strings, counted in characters.
fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut diag = row[0];
        row[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let next = (row[j + 1] + 1).min(row[j] + 1).min(diag + usize::from(ca != cb));
            diag = row[j + 1];
            row[j + 1] = next;
        }
    }
    row[b.len()]
}

/// A TOML key for `name`: bare when it is only letters, digits, `_` and `-`, else quoted.
fn toml_key(name: &str) -> String {
    if !name.is_empty() && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-') {
        name.to_string()
    } else {
        format!("\"{}\"", name.replace('\\', "\\\\").replace('"', "\\\""))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::oracle::cases::CaseModel;

    fn basic() -> &'static CaseModel {
        crate::gl::ModelId::BasicLighting.case_model()
    }

    #[test]
    fn edit_distance_counts_single_edits() {
        assert_eq!(edit_distance("lightpos", "lightpos"), 0);
        assert_eq!(edit_distance("lightpos", "lighpos"), 1);
        assert_eq!(edit_distance("kitten", "sitting"), 3);
        assert_eq!(edit_distance("", "abc"), 3);
    }

    #[test]
    fn a_renamed_uniform_gets_the_closest_free_quantity_of_its_type() {
        let none = BTreeSet::new();
        assert_eq!(closest_quantity("lightPosition", "vec3", basic().layout, &none), Some("lightPos"));
        assert_eq!(closest_quantity("uLightPos", "vec3", basic().layout, &none), Some("lightPos"));
        assert_eq!(closest_quantity("shinyness", "float", basic().layout, &none), Some("shininess"));
        // the type decides: a float named like a vector quantity is not offered it
        assert_ne!(closest_quantity("lightPosition", "float", basic().layout, &none), Some("lightPos"));
        // a quantity another declaration already maps to is not offered twice
        let taken = BTreeSet::from(["lightPos"]);
        assert_ne!(closest_quantity("lightPosition", "vec3", basic().layout, &taken), Some("lightPos"));
        // nothing close: no wild guess
        assert_eq!(closest_quantity("zzzzzzzzzzzz", "vec3", basic().layout, &none), None);
    }

    #[test]
    fn toml_keys_are_quoted_when_they_must_be() {
        assert_eq!(toml_key("uLight"), "uLight");
        assert_eq!(toml_key("light.positon"), "\"light.positon\"");
        let parsed = parse_mapping(&format!("[names]\n{} = \"light.position\"\n", toml_key("light.positon")));
        assert_eq!(parsed.expect("valid TOML").names.get("light.positon").map(String::as_str), Some("light.position"));
    }

    fn mapped(src: &str, toml: &str) -> Result<Vec<Leaf>, CheckError> {
        let parsed = crate::checker::check::glsl::parse(src);
        let mapping = parse_mapping(toml).expect("valid mapping");
        let leaves = map_leaves(basic().layout, &parsed, &mapping, &[Storage::In, Storage::Uniform])?;
        Ok(leaves.into_iter().flat_map(|(_, l)| l).collect())
    }

    fn usage_text(r: Result<Vec<Leaf>, CheckError>) -> String {
        match r {
            Err(CheckError::Usage(m)) => m,
            other => panic!("expected a usage error, got {other:?}"),
        }
    }

    const HEAD: &str = "#version 330 core\nin vec3 FragPos;\nin vec3 Normal;\nout vec4 FragColor;\n";

    /// Several renamed uniforms get one `[names]` block after every message, which pastes
    /// into a mapping file as it is and then maps them all.
    #[test]
    fn the_suggested_lines_are_one_mapping_file() {
        let src = format!(
            "{HEAD}uniform vec3 uLightPos;\nuniform vec3 uLightColor;\nuniform vec3 uObjectColor;\n\
             void main() {{ FragColor = vec4(uLightPos + uLightColor + uObjectColor, 1.0); }}\n"
        );
        let m = usage_text(mapped(&src, ""));
        assert_eq!(m.matches("[names]").count(), 1, "{m}");
        let block = &m[m.find("[names]").unwrap()..];
        let file = parse_mapping(block).unwrap_or_else(|e| panic!("{e:?}:\n{block}"));
        assert_eq!(file.names.len(), 3, "{block}");
        let leaves = mapped(&src, block).unwrap_or_else(|e| panic!("{e:?}"));
        let models: BTreeSet<&str> = leaves.iter().map(|l| l.model.as_str()).collect();
        assert!(["lightPos", "lightColor", "objectColor"].iter().all(|q| models.contains(q)), "{models:?}");
    }

    #[test]
    fn every_unmatched_name_is_reported_in_one_run() {
        let src = format!("{HEAD}uniform vec3 uSunPos;\nuniform vec3 uTint;\nvoid main() {{ FragColor = vec4(uSunPos + uTint, 1.0); }}\n");
        let m = usage_text(mapped(&src, "[names]\nnothere = \"lightPos\"\n"));
        assert!(m.contains("`uSunPos` is not a quantity"), "{m}");
        assert!(m.contains("`uTint` is not a quantity"), "{m}");
        assert!(m.contains("line 2: names.nothere"), "{m}");
        assert_eq!(m.lines().filter(|l| !l.starts_with('[') && !l.contains(" = \"")).count(), 3, "{m}");
    }

    /// A `[names]` value close to a quantity's name (a spelling, a longer name, the case
    /// only) gets a guess, and a file's name leads the message (item 22 of the red-team report).
    #[test]
    fn a_mapped_name_close_to_a_quantity_gets_a_guess_and_the_file() {
        let src = format!("{HEAD}uniform vec3 uAlbedo;\nuniform vec3 uLightPos;\nvoid main() {{ FragColor = vec4(uAlbedo + uLightPos, 1.0); }}\n");
        for (toml, guess) in [
            ("[names]\nuAlbedo = \"objectColour\"\nuLightPos = \"lightPos\"\n", "objectColor"),
            ("[names]\nuAlbedo = \"objectColor\"\nuLightPos = \"lightPosition\"\n", "lightPos"),
            ("[names]\nuAlbedo = \"objectColor\"\nuLightPos = \"lightpos\"\n", "lightPos"),
        ] {
            let m = usage_text(mapped(&src, toml));
            assert!(m.contains(&format!("did you mean `{guess}`?")), "{toml}: {m}");
        }
        let parsed = crate::checker::check::glsl::parse(&src);
        let mapping = Mapping {
            file: Some("class.toml".into()),
            ..parse_mapping("[names]\nuAlbedo = \"objectColour\"\nuLightPos = \"lightPos\"\n").unwrap()
        };
        let m = usage_text(
            map_leaves(basic().layout, &parsed, &mapping, &[Storage::In, Storage::Uniform]).map(|_| Vec::new()),
        );
        assert!(m.starts_with("class.toml: line 2: names.uAlbedo"), "{m}");
    }

    #[test]
    fn two_letter_names_get_no_guess() {
        let none = BTreeSet::new();
        assert_eq!(closest_quantity("wp", "vec3", basic().layout, &none), None);
        assert_eq!(closest_quantity("u_wp", "vec3", basic().layout, &none), None);
        let src = format!("{HEAD}uniform vec3 wp;\nvoid main() {{ FragColor = vec4(wp, 1.0); }}\n");
        let m = usage_text(mapped(&src, ""));
        assert!(m.contains("`wp` is not a quantity") && !m.contains("did you mean"), "{m}");
    }

    #[test]
    fn two_names_mapped_to_one_quantity_are_flagged() {
        let src =
            format!("{HEAD}uniform vec3 uA;\nuniform vec3 uB;\nvoid main() {{ FragColor = vec4(uA + uB, 1.0); }}\n");
        let m = usage_text(mapped(&src, "[names]\nuA = \"lightPos\"\nuB = \"lightPos\"\n"));
        assert!(m.contains("`uA` and `uB` all map to the model's `lightPos` (mapping line 2, line 3)"), "{m}");
    }

    #[test]
    fn an_engine_block_with_padding_vec4s_and_a_struct_maps() {
        let src = format!(
            "{HEAD}struct P {{ vec4 col; float k; float _pad0; }};\n\
             layout(std140) uniform Frame {{ vec4 uLight; vec4 uEye; float _pad1; }};\n\
             layout(std140) uniform S {{ P p; }} s;\n\
             void main() {{ FragColor = vec4(uLight.xyz + uEye.xyz + s.p.col.rgb * s.p.k, 1.0); }}\n"
        );
        let toml = "[names]\nuLight = \"lightPos\"\nuEye = \"viewPos\"\n\"s.p.col\" = \"objectColor\"\n\"s.p.k\" = \"shininess\"\n";
        let leaves = mapped(&src, toml).expect("maps");
        let find = |u: &str| leaves.iter().find(|l| l.user == u);
        assert!(find("uLight").is_some_and(|l| l.carries_vec3 && l.model == "lightPos"));
        assert!(find("s.p.col").is_some_and(|l| l.carries_vec3 && l.model == "objectColor"));
        assert!(find("s.p.k").is_some_and(|l| !l.carries_vec3 && l.model == "shininess"));
        // the padding is never read, so it needs no quantity and is left out
        assert!(find("_pad1").is_none() && find("s.p._pad0").is_none());
        // read padding is a leaf like any other: the model does not know it
        let read = src.replace("* s.p.k", "* s.p.k * s.p._pad0");
        let m = usage_text(mapped(&read, toml));
        assert!(m.contains("`s.p._pad0` is not a quantity"), "{m}");
    }

    /// A uniform the cases drive that the shader declares and never reads gets a note, by
    /// whole identifiers outside comments: its name in a comment, or inside a longer
    /// identifier, is no read. A quantity fixed by `[values]` is not driven, so it gets none.
    #[test]
    fn a_driven_uniform_never_read_gets_a_note() {
        let src = format!(
            "{HEAD}uniform vec3 uLamp; // uLamp: the host sets it; we use LAMP below (uLamp ignored)\n\
             uniform vec3 viewPos;\nuniform float shininess;\n\
             /* uLamp */ const vec3 LAMP = vec3(1.2, 1.0, 2.0);\n\
             void main() {{ vec3 uLampDir = normalize(LAMP - FragPos);\n\
             FragColor = vec4(uLampDir * dot(Normal, normalize(viewPos - FragPos)) * shininess, 1.0); }}\n"
        );
        let toml = "[names]\nuLamp = \"lightPos\"\n";
        let leaves = mapped(&src, toml).expect("maps");
        assert_eq!(leaves.iter().filter(|l| !l.read).map(|l| l.user.as_str()).collect::<Vec<_>>(), ["uLamp"]);
        let notes = never_read_notes(&leaves, &[]);
        let want = texts::tr_fill(texts::NOTE_NEVER_READ, &["uLamp", "lightPos"]);
        assert_eq!(notes, [want]);
        assert!(
            notes[0].starts_with("`uLamp` is declared but never read") && notes[0].contains("lightPos"),
            "{notes:?}"
        );
        // fixed by the mapping's [values]: the cases do not vary it
        assert!(never_read_notes(&leaves, &[("lightPos", [1.2, 1.0, 2.0])]).is_empty());
        // read once, anywhere in the code: no note
        let read = src.replace("normalize(LAMP - FragPos)", "normalize(LAMP + 0.0 * uLamp - FragPos)");
        assert!(never_read_notes(&mapped(&read, toml).expect("maps"), &[]).is_empty());
    }

    /// A name that refers to something else is no read of the uniform: a function's
    /// parameter of the same name (and its uses in that function), a local of the same name
    /// to the end of its block, a member access. The uniform used once outside those
    /// scopes, after the local's block closed, is read. (The page asks the driver, which
    /// keeps only the uniforms the code reads: the two sides give the same note.)
    #[test]
    fn a_same_named_parameter_local_or_member_is_no_read() {
        let body = |extra: &str| {
            format!(
                "{HEAD}uniform vec3 lightPos;\nuniform vec3 viewPos;\nuniform float shininess;\n\
                 struct Lamp {{ vec3 lightPos; }};\n\
                 vec3 lit(vec3 n);\n\
                 vec3 shade(in vec3 lightPos, vec3 n) {{ return normalize(lightPos - FragPos) * dot(n, n); }}\n\
                 vec3 lit(vec3 n) {{ if (n.x > 2.0) {{ vec3 lightPos = vec3(0.0); return lightPos; }} {extra} return n; }}\n\
                 void main() {{ Lamp lamp = Lamp(vec3(1.2, 1.0, 2.0)); vec3 lightPos2 = lamp.lightPos;\n\
                 FragColor = vec4(shade(lightPos2, lit(Normal)) * dot(Normal, normalize(viewPos - FragPos)) * shininess, 1.0); }}\n"
            )
        };
        let unread = mapped(&body(""), "").expect("maps");
        assert_eq!(unread.iter().filter(|l| !l.read).map(|l| l.user.as_str()).collect::<Vec<_>>(), ["lightPos"]);
        assert_eq!(never_read_notes(&unread, &[]).len(), 1);
        // the uniform itself, after the local's block closed: read
        let read = mapped(&body("n += 0.0 * lightPos;"), "").expect("maps");
        assert!(read.iter().all(|l| l.read), "{:?}", read.iter().map(|l| (&l.user, l.read)).collect::<Vec<_>>());
        assert!(never_read_notes(&read, &[]).is_empty());
    }

    #[test]
    fn array_indices_are_written_i() {
        assert_eq!(any_index("pointLights[2].position"), "pointLights[i].position");
        assert_eq!(any_index("a[0].b[13]"), "a[i].b[i]");
        assert_eq!(any_index("lightPos"), "lightPos");
        assert_eq!(any_index("broken[1"), "broken[i]");
    }

    #[test]
    fn a_carried_vec3_gets_w_0_for_a_direction_and_1_otherwise() {
        assert_eq!(carried_w("light.direction"), 0.0);
        assert_eq!(carried_w("dirLight.direction"), 0.0);
        assert_eq!(carried_w("lightPos"), 1.0);
        assert_eq!(carried_w("light.diffuse"), 1.0);
    }

    #[test]
    fn rules_parse_and_name_their_line() {
        let m = parse_mapping("[rules]\nforbid = [\"viewPos\"]\nrequire = [\"lightPos\", \"light\"]\n").expect("valid");
        assert_eq!(m.forbid, vec!["viewPos"]);
        assert_eq!(m.require, vec!["lightPos", "light"]);
        let bad = |text: &str| match parse_mapping(text) {
            Err(CheckError::Usage(m)) => m,
            other => panic!("{other:?}"),
        };
        assert!(bad("[rules]\nforbid = \"viewPos\"\n").starts_with("line 2: rules.forbid must be an array"));
        assert!(bad("\n[rules]\nallow = []\n").starts_with("line 3: rules.allow: unknown rule"));
    }

    #[test]
    fn a_rule_covers_a_quantity_or_a_whole_light() {
        let src = format!("{HEAD}uniform vec3 lightPos;\nuniform vec3 viewPos;\nvoid main() {{ FragColor = vec4(lightPos + viewPos, 1.0); }}\n");
        let leaves = mapped(&src, "").expect("maps");
        let rules = |toml: &str| broken_rule(basic().layout, &parse_mapping(toml).expect("valid"), &leaves);
        assert_eq!(rules("[rules]\nforbid = [\"viewPos\"]\n").ok().flatten(), Some((RULE_FORBIDDEN, "viewPos".into())));
        assert_eq!(
            rules("[rules]\nrequire = [\"shininess\"]\n").ok().flatten(),
            Some((RULE_REQUIRED, "shininess".into()))
        );
        assert_eq!(rules("[rules]\nrequire = [\"lightPos\"]\nforbid = [\"shininess\"]\n").ok().flatten(), None);
        assert!(matches!(rules("[rules]\nforbid = [\"eye\"]\n"), Err(CheckError::Usage(_))));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig {
            cases: std::env::var("LIGHTLAB_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(512),
            ..proptest::prelude::ProptestConfig::default()
        })]

        /// Any text, and any mutation of a valid mapping file, parses or is a usage error:
        /// never a panic.
        #[test]
        fn mapping_files_never_panic(text in "(\\[names\\]|\\[values\\]|[a-zA-Z_.\\[\\]]{1,12} ?= ?|\"[a-z.]{0,8}\"|-?[0-9.e]{1,6}|nan|inf|\\[|\\]|,|\n|#| ){0,40}") {
            let _ = parse_mapping(&text);
        }

        #[test]
        fn arbitrary_text_never_panics(text in "\\PC{0,200}") {
            let _ = parse_mapping(&text);
        }
    }
}
