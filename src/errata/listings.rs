//! The printed code listings the errata check, quoted as the seeds print them (the
//! Ukrainian text prints one line per code block; the lines are joined here), and the
//! small parsers the checks use. The listings themselves are the files under `quoted/`.
//!
//! `tests/gl_errata.rs` compiles these listings on OpenGL: the ones the table flags fail
//! to compile, their counterparts in the other text compile.
//!
//! Sources: `shared/seeds/000` (French LearnOpenGL), `001` (opengl-tutorial 8), `002`
//! (ogldev 19), `003` (Ukrainian lab); line numbers on each constant.

/// One quoted listing: `quoted/NAME.txt`, byte for byte as the seed prints it (kept out of
/// the Rust source so that rustfmt and the reader see it as data, not code).
macro_rules! quoted {
    ($name:literal) => {
        include_str!(concat!("quoted/", $name, ".txt"))
    };
}

/// 000 l.1062-1067: the flashlight's `Light` struct (the `...` line left out).
pub const FR_SPOT_STRUCT: &str = quoted!("fr_spot_struct");

/// 000 l.1083-1090: the cone test, French text.
pub const FR_SPOT_TEST: &str = quoted!("fr_spot_test");

/// 003 l.1674-1700: the cone test, Ukrainian text.
pub const UK_SPOT_TEST: &str = quoted!("uk_spot_test");

/// 000 l.1192-1205 (and 003 l.1812-1864): the multiple-lights skeleton.
pub const OUTPUT_SKELETON: &str = quoted!("output_skeleton");

/// 000 l.1216-1225: `DirLight`, French text, with the label line the listing prints.
pub const FR_DIRLIGHT: &str = quoted!("fr_dirlight");

/// 000 l.1229-1231: the prototype, French text, with its label line.
pub const FR_DIRLIGHT_PROTOTYPE: &str = quoted!("fr_dirlight_prototype");

/// 003 l.1878-1896: `DirLight` and the prototype, Ukrainian text.
pub const UK_DIRLIGHT: &str = quoted!("uk_dirlight");

/// 000 l.990-998: the point light's `Light` struct, French text.
pub const FR_POINT_STRUCT: &str = quoted!("fr_point_struct");

/// 003 l.1495-1527: the same struct, Ukrainian text.
pub const UK_POINT_STRUCT: &str = quoted!("uk_point_struct");

/// 000 l.1267-1277 (= 003 l.1966-2006): `PointLight` and the array of four.
pub const POINT_LIGHT_STRUCT: &str = quoted!("point_light_struct");

/// 000 l.1357-1368: `pointLightPositions`, French text, as its two code blocks print it.
pub const FR_POINT_LIGHT_POSITIONS: &str = quoted!("fr_point_light_positions");

/// 003 l.2184-2204: `pointLightPositions`, Ukrainian text.
pub const UK_POINT_LIGHT_POSITIONS: &str = quoted!("uk_point_light_positions");

/// 000 l.527-534 (= 003 l.704-732): the `Material` struct.
pub const MATERIAL_STRUCT: &str = quoted!("material_struct");

/// 001 l.294-300: opengl-tutorial 8's final color, as printed.
pub const OPENGL_TUTORIAL_COLOR: &str = quoted!("opengl_tutorial_color");

/// 002 l.202-208: ogldev 19's specular term.
pub const OGLDEV_SPECULAR: &str = quoted!("ogldev_specular");

/// 002 l.211: the last line of the shader ogldev 19's l.214 describes.
pub const OGLDEV_FRAGMENT_OUTPUT: &str = quoted!("ogldev_fragment_output");

/// 002 l.129-137: ogldev 19's vertex shader excerpt.
pub const OGLDEV_VERTEX: &str = quoted!("ogldev_vertex");

/// 002 l.106-114: the new members of `LightingTechnique`.
pub const OGLDEV_TECHNIQUE: &str = quoted!("ogldev_technique");

/// 002 l.182-184: the fragment shader's new uniforms.
pub const OGLDEV_UNIFORMS: &str = quoted!("ogldev_uniforms");

/// The field names of the first `struct NAME { … }` in `source`, in order; empty when
/// there is none. Declarations are `TYPE NAME;` with one name each, as in the tutorials.
pub fn struct_fields(source: &str) -> Vec<String> {
    let Some(open) = source.find('{') else { return Vec::new() };
    let body = &source[open + 1..];
    let body = &body[..body.find('}').unwrap_or(body.len())];
    body.split(';')
        .filter_map(|decl| {
            let decl = decl.lines().filter(|l| !l.trim_start().starts_with("//")).collect::<Vec<_>>().join(" ");
            decl.split_whitespace().last().map(|name| name.to_string())
        })
        .collect()
}

/// The identifiers written as `light.NAME` in `source`.
pub fn light_members_used(source: &str) -> Vec<String> {
    source
        .match_indices("light.")
        .map(|(i, m)| {
            source[i + m.len()..].chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect::<String>()
        })
        .collect()
}

/// The elements of the first brace initializer `= { … };` in `source`: the text
/// between the first `{` and the first `}` that closes it, split on top-level commas,
/// empty items dropped.
pub fn initializer_items(source: &str) -> Vec<String> {
    let Some(open) = source.find('{') else { return Vec::new() };
    let mut depth = 0usize;
    let mut items = Vec::new();
    let mut current = String::new();
    for ch in source[open + 1..].chars() {
        match ch {
            '(' => {
                depth += 1;
                current.push(ch);
            }
            ')' => {
                depth = depth.saturating_sub(1);
                current.push(ch);
            }
            ',' if depth == 0 => items.push(std::mem::take(&mut current)),
            '}' if depth == 0 => break,
            _ => current.push(ch),
        }
    }
    items.push(current);
    items.into_iter().map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect()
}

/// Whether the braces of `source` balance (every `}` closes an open `{`, none left open).
pub fn braces_balance(source: &str) -> bool {
    let mut depth = 0i64;
    for ch in source.chars() {
        match ch {
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth < 0 {
                    return false;
                }
            }
            _ => {}
        }
    }
    depth == 0
}

/// Words GLSL 3.30 reserves for future use (GLSL 3.30 spec §3.6), the ones the tutorials'
/// code could meet.
pub const GLSL_RESERVED: [&str; 12] = [
    "output",
    "input",
    "common",
    "partition",
    "active",
    "filter",
    "sizeof",
    "cast",
    "namespace",
    "using",
    "public",
    "static",
];

/// The reserved words of [`GLSL_RESERVED`] that `source` uses as identifiers.
pub fn reserved_words_used(source: &str) -> Vec<&'static str> {
    let words: Vec<&str> = source.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).collect();
    GLSL_RESERVED.iter().copied().filter(|r| words.contains(r)).collect()
}
