//! The user's shader rewritten into a batch body, line for line, and the generated
//! `batch_main` that loads every leaf from the batch inputs.

use std::fmt::Write as _;

use super::glsl::{Declaration, Parsed, Storage};
use super::mapping::Leaf;
use crate::gl::layout::{QType, Slot};

/// Lets `texture(s, uv)` return the case's texel once `sampler2D` became `vec4`.
const SAMPLING: &str = "vec4 lightlab_sample(sampler2D s, vec2 uv) { return texture(s, uv); }
vec4 lightlab_sample(vec4 texel, vec2 uv) { return texel; }
vec4 lightlab_sample(vec4 texel, vec3 uv) { return texel; }
#define texture(s, uv) lightlab_sample(s, uv)
#define texture2D(s, uv) lightlab_sample(s, uv)
";

/// What every rewritten shader is preceded by: the sampling overloads, then the loop
/// guard's counter ([`super::loops`]).
pub(super) fn prelude() -> String {
    format!("{SAMPLING}{}", super::loops::loop_header())
}

fn blank(bytes: &mut [u8], span: (usize, usize)) {
    for b in &mut bytes[span.0..span.1] {
        if *b != b'\n' {
            *b = b' ';
        }
    }
}

/// The user's `#extension` lines, each ending in a line break: the batch body starts with
/// them, and [`crate::gl::batch::fragment_source`] puts them right after its `#version`
/// (GLSL allows them only before any code, and the batch's declarations come first).
pub(super) fn extensions(src: &str, parsed: &Parsed) -> String {
    parsed.extensions.iter().map(|&(a, b)| format!("{}\n", src[a..b].trim())).collect()
}

/// The user's file rewritten, line for line: the `#version` and `#extension` lines blanked
/// (the batch has its own version, and [`extensions`] moves the others), `in`/`out` and per-case `uniform` qualifiers blanked (the variables become
/// globals), interface blocks turned into globals (anonymous) or a struct variable (with
/// an instance name), `sampler2D` into `vec4`, `main` renamed, and every loop condition
/// counting iterations ([`super::loops::guard_loops`]).
pub(super) fn rewrite(src: &str, parsed: &Parsed, case_decls: &[usize]) -> String {
    let mut bytes = src.as_bytes().to_vec();
    for &span in parsed.version.iter().chain(&parsed.extensions) {
        blank(&mut bytes, span);
    }
    let mut replacements: Vec<((usize, usize), String)> = Vec::new();
    for (d, decl) in parsed.decls.iter().enumerate() {
        let becomes_global = decl.storage != Storage::Uniform || case_decls.contains(&d);
        if !becomes_global {
            continue;
        }
        for &q in &decl.qualifiers {
            blank(&mut bytes, q);
        }
        match &decl.block {
            Some(block) => rewrite_block(&mut bytes, &mut replacements, decl, block),
            None if decl.ty == "sampler2D" => replacements.push((decl.type_span, "vec4".into())),
            None => {}
        }
    }
    for fields in parsed.structs.values() {
        for f in fields.iter().filter(|f| f.ty == "sampler2D") {
            replacements.push((f.type_span, "vec4".into()));
        }
    }
    if let Some(main) = parsed.main {
        replacements.push((main, "lightlab_user_main".into()));
    }
    replacements.sort_by_key(|r| std::cmp::Reverse(r.0 .0));
    replacements.dedup_by_key(|r| r.0);
    // Only ASCII bytes were blanked, and only whole tokens, so this is still UTF-8.
    let mut text = String::from_utf8(bytes).unwrap_or_default();
    for ((a, b), with) in replacements {
        text.replace_range(a..b, &with);
    }
    super::loops::guard_loops(&text).0
}

fn rewrite_block(
    bytes: &mut [u8],
    replacements: &mut Vec<((usize, usize), String)>,
    decl: &Declaration,
    block: &super::glsl::Block,
) {
    for &q in &block.inner_qualifiers {
        blank(bytes, q);
    }
    for m in block.members.iter().filter(|m| m.ty == "sampler2D") {
        replacements.push((m.type_span, "vec4".into()));
    }
    if decl.name.is_empty() {
        // `in Block { vec3 a; };` -> `vec3 a;`: the members become globals.
        for &span in &block.frame {
            blank(bytes, span);
        }
    } else {
        // `in Block { vec3 a; } b;` -> `struct Block { vec3 a; } b;`.
        replacements.push((decl.type_span, format!("struct {}", decl.ty)));
    }
}

pub(super) fn load(leaf: &Leaf) -> Option<String> {
    let q = leaf.quantity?;
    let value = match (q.slot, q.ty) {
        (Slot::Unused, QType::Vec2) => "vec2(0.0)".to_string(),
        (Slot::Case { input, offset }, QType::Float) => format!("lightlab_v[{input}][{offset}]"),
        (Slot::Case { input, .. }, QType::Vec3) if leaf.carries_vec3 => {
            format!("vec4(lightlab_v[{input}].xyz, {:.1})", super::mapping::carried_w(&leaf.model))
        }
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

/// The generated `batch_main`: loads the leaves (then runs the lines `more_loads`), calls
/// the user's `main` with the loop counter at 0, writes `out`, or the loop guard's mark on
/// every channel when the cap stopped a loop ([`super::loops`]).
pub(super) fn wrapper(leaves: &[Leaf], more_loads: &str, out: &super::Colour) -> String {
    let mut s = String::from("\n#line 1 3\nvoid batch_main(in vec4 lightlab_v[LIGHTLAB_N_INPUTS], out vec4 lightlab_o[LIGHTLAB_N_OUTPUTS])\n{\n");
    for leaf in leaves {
        if let Some(line) = load(leaf) {
            s += &line;
        }
    }
    s += more_loads;
    s += "    lightlab_loops = 0;\n    lightlab_user_main();\n";
    let color = match out.ty.as_str() {
        "vec3" => format!("vec4({}, 1.0)", out.name),
        "float" => format!("vec4(vec3({}), 1.0)", out.name),
        _ => format!("vec4({}.rgb, 1.0)", out.name),
    };
    let _ = writeln!(
        s,
        "    lightlab_o[0] = lightlab_loops > {cap} ? vec4({mark:.1}) : {color};\n}}",
        cap = super::loops::LOOP_CAP,
        mark = super::loops::LOOP_MARK
    );
    s
}
