//! The scanner on every GLSL literal form, on the declarations `check-shader` relies on,
//! and fuzzed with proptest: random token soup and mutated valid shaders.
//!
//! The fuzz runs `LIGHTLAB_FUZZ_CASES` cases per property (default 256, a fixed seed, so
//! CI runs the same slice every time). More locally:
//! `LIGHTLAB_FUZZ_CASES=100000 cargo test --release --lib checker::check::glsl`.

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

use super::*;
use crate::checker::check::rewrite;

fn texts(src: &str) -> Vec<String> {
    tokenize(src).into_iter().map(|t| t.text).collect()
}

#[test]
fn every_literal_form_is_one_token() {
    for lit in [
        "1", "017", "0x1F", "0XaBu", "42u", "7U", "1.", "1.5", ".5", ".1", "1e5", "1E5", "1e+5", "1e-5", "1.5e-3",
        ".5E+2", "1.5f", "1.5F", ".1f", "1e5f", "2.0lf", "2.0LF", "3.lf",
    ] {
        assert_eq!(texts(&format!("x = {lit};")), vec!["x", "=", lit, ";"], "literal {lit}");
    }
}

#[test]
fn a_leading_dot_float_ends() {
    // The old scanner never advanced on `.1` and grew its token list without end.
    assert_eq!(texts("float a = .1;"), vec!["float", "a", "=", ".1", ";"]);
    assert_eq!(texts(".1"), vec![".1"]);
    assert_eq!(texts("v.x"), vec!["v", ".", "x"]);
    assert_eq!(texts("1.0.x"), vec!["1.0", ".", "x"]);
}

#[test]
fn a_version_in_a_leading_comment_is_not_the_directive() {
    let src = "// #version 100\n/* #version 200 */\n  #version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
    let parsed = parse(src);
    let (a, b) = parsed.version.expect("the directive is found");
    assert_eq!(&src[a..b], "  #version 330 core");
}

#[test]
fn extension_lines_are_found_outside_comments_only() {
    let src = "#version 330 core\n#extension GL_ARB_gpu_shader5 : enable\n/*\n#extension GL_x : require\n*/\n  # extension GL_y : enable\n#extensions_are_not_this\nout vec4 c;\n";
    let parsed = parse(src);
    let found: Vec<&str> = parsed.extensions.iter().map(|&(a, b)| &src[a..b]).collect();
    assert_eq!(found, vec!["#extension GL_ARB_gpu_shader5 : enable", "  # extension GL_y : enable"]);
    // the rewrite blanks them in place (line numbers stay) and hands them over separately
    let out = rewrite::rewrite(src, &parsed, &[]);
    assert_eq!(out.lines().count(), src.lines().count());
    assert!(!out.contains("GL_ARB_gpu_shader5") && !out.contains("GL_y"), "{out}");
    assert_eq!(
        rewrite::extensions(src, &parsed),
        "#extension GL_ARB_gpu_shader5 : enable\n# extension GL_y : enable\n"
    );
}

#[test]
fn every_declarator_is_read_past_initializers() {
    // red-team finding 23: the second name after an initializer was missed
    let p = parse("uniform float ambientStrength = 0.1, specularStrength = 0.5;\nuniform vec3 a = vec3(1.0, 2.0, 3.0), b, c[2] = vec3[2](vec3(0.0), vec3(1.0));\n");
    let names: Vec<&str> = p.decls.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, vec!["ambientStrength", "specularStrength", "a", "b", "c"]);
}

#[test]
fn outputs_carry_their_location() {
    let p = parse("layout(location = 1) out vec4 bright;\nlayout(location = 0) out vec4 color;\nout vec3 other;\n");
    let locs: Vec<(String, Option<u32>)> = p.decls.iter().map(|d| (d.name.clone(), d.location)).collect();
    assert_eq!(
        locs,
        vec![("bright".to_string(), Some(1)), ("color".to_string(), Some(0)), ("other".to_string(), None)]
    );
}

#[test]
fn interface_blocks_are_read_with_their_members() {
    let p =
        parse("in VS_OUT {\n    vec3 FragPos;\n    flat vec3 Normal;\n} fs_in;\nuniform Light { vec3 lightPos; };\n");
    assert_eq!(p.decls.len(), 2);
    let named = &p.decls[0];
    assert_eq!((named.ty.as_str(), named.name.as_str()), ("VS_OUT", "fs_in"));
    let members: Vec<&str> = named.block.as_ref().unwrap().members.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(members, vec!["FragPos", "Normal"]);
    let anon = &p.decls[1];
    assert_eq!((anon.storage, anon.name.as_str()), (Storage::Uniform, ""));
    assert_eq!(anon.block.as_ref().unwrap().members[0].name, "lightPos");
}

/// An array's size is a constant expression: arithmetic, parentheses and earlier `const
/// int`s, as `multi-calc-spot` answers write `pointLights[NR_POINT_LIGHTS]` (red-team 3,
/// H1: `[2*2]` was read as 2, and a correct shader disagreed).
#[test]
fn array_sizes_are_constant_expressions() {
    let size = |src: &str| parse(src).decls.last().and_then(|d| d.array);
    assert_eq!(size("uniform vec3 p[2*2];"), Some(4));
    assert_eq!(size("uniform vec3 p[2+2];"), Some(4));
    assert_eq!(size("uniform vec3 p[(4)];"), Some(4));
    assert_eq!(size("uniform vec3 p[(1 + 1) * (5 - 3)];"), Some(4));
    assert_eq!(size("const int N = 4;\nuniform vec3 p[N];"), Some(4));
    assert_eq!(size("const int TWO = 2;\nconst highp int N = TWO * TWO;\nuniform vec3 p[N];"), Some(4));
    assert_eq!(size("uniform vec3 p[9 / 2 % 3];"), Some(1));
    // not constant here, or not a size: left to the driver
    assert_eq!(size("uniform vec3 p[M];"), None);
    assert_eq!(size("uniform vec3 p[1 / 0];"), None);
    assert_eq!(size("uniform vec3 p[2 - 3];"), None);
    assert_eq!(size("uniform vec3 p[(((2)];"), None);
    let deep = format!("uniform vec3 p[{}1{}];", "(".repeat(500), ")".repeat(500));
    assert_eq!(size(&deep), None, "nesting is bounded, not a stack overflow");
}

#[test]
fn array_sizes_in_every_integer_form_count_towards_the_cap() {
    assert_eq!(parse("uniform vec4 big[100000000];").largest_array, 100_000_000);
    assert_eq!(parse("uniform vec4 big[0x10000];").largest_array, 65_536);
    // a macro's size counts once preprocessed, as the checker reads the file
    let text = crate::checker::check::preprocess::preprocess("#define N 5000\nuniform float a[N];").unwrap();
    assert_eq!(parse(&text).largest_array, 5000);
    assert_eq!(parse("uniform float a[1000 * 1000];").largest_array, 1_000_000, "the size is the product");
    assert_eq!(parse("struct S { vec4 v[9000]; };").largest_array, 9000);
}

#[test]
fn components_of_structs_and_arrays() {
    let p = parse("struct L { vec3 p; float k[4]; };");
    assert_eq!(components("L", &p.structs, 0), 7);
    assert_eq!(components("mat4", &p.structs, 0), 16);
}

// ---------------------------------------------------------------- fuzz

fn fuzz_config() -> Config {
    let cases = std::env::var("LIGHTLAB_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(256);
    Config { cases, rng_seed: RngSeed::Fixed(0x6c69_6768), failure_persistence: None, ..Config::default() }
}

const PIECES: &[&str] = &[
    "#version 330 core\n",
    "in",
    "out",
    "uniform",
    "layout",
    "(",
    ")",
    "location",
    "=",
    "0",
    "1",
    "{",
    "}",
    "[",
    "]",
    ";",
    ",",
    ".",
    ".1",
    "1.",
    "1e5",
    "1.5e-3f",
    "0x1F",
    "017u",
    "2.0lf",
    "vec3",
    "vec4",
    "float",
    "mat4",
    "sampler2D",
    "struct",
    "void",
    "main",
    "flat",
    "FragPos",
    "Normal",
    "lightPos",
    "fs_in",
    "VS_OUT",
    "//",
    "/*",
    "*/",
    "\n",
    " ",
    "#define N 4\n",
    "é",
    "\u{1F600}",
    "\"",
    "\\",
    "e",
    "+",
    "-",
    "*",
    "/",
];

const VALID: &str = include_str!("../../../gl/shaders/examples/basic_lighting.frag");

/// Checks what must hold for any text: tokens are non-empty, ordered and on character
/// boundaries; parse and rewrite end; the rewrite keeps the line count.
fn scan_everything(src: &str) -> Result<(), TestCaseError> {
    let tokens = tokenize(src);
    let mut last = 0;
    for t in &tokens {
        prop_assert!(t.start < t.end && t.start >= last && t.end <= src.len(), "token {t:?}");
        prop_assert!(src.is_char_boundary(t.start) && src.is_char_boundary(t.end));
        last = t.end;
    }
    let blanked = blank_comments(src);
    prop_assert_eq!(blanked.len(), src.len());
    prop_assert_eq!(blanked.lines().count(), src.lines().count());
    let parsed = parse(src);
    let all: Vec<usize> = (0..parsed.decls.len()).collect();
    let out = rewrite::rewrite(src, &parsed, &all);
    prop_assert_eq!(out.matches('\n').count(), src.matches('\n').count());
    // the checker's path: the preprocessed text, parsed and rewritten, keeps the lines too
    if let Ok(text) = crate::checker::check::preprocess::preprocess(src) {
        prop_assert_eq!(text.matches('\n').count(), src.matches('\n').count());
        let parsed = parse(&text);
        let all: Vec<usize> = (0..parsed.decls.len()).collect();
        let out = rewrite::rewrite(&text, &parsed, &all);
        prop_assert_eq!(out.matches('\n').count(), src.matches('\n').count());
    }
    Ok(())
}

proptest! {
    #![proptest_config(fuzz_config())]

    #[test]
    fn random_token_soup_is_scanned(pieces in prop::collection::vec(prop::sample::select(PIECES), 0..80)) {
        scan_everything(&pieces.concat())?;
    }

    #[test]
    fn mutated_valid_shaders_are_scanned(
        edits in prop::collection::vec((0usize..4000, prop::sample::select(PIECES), 0usize..3), 1..8)
    ) {
        let mut src = VALID.to_string();
        for (at, piece, kind) in edits {
            let mut at = at % (src.len() + 1);
            while !src.is_char_boundary(at) {
                at -= 1;
            }
            match kind {
                0 => src.insert_str(at, piece),
                1 => {
                    let mut end = (at + piece.len()).min(src.len());
                    while !src.is_char_boundary(end) {
                        end += 1;
                    }
                    src.replace_range(at..end, "");
                }
                _ => {
                    let mut end = (at + 1).min(src.len());
                    while !src.is_char_boundary(end) {
                        end += 1;
                    }
                    src.replace_range(at..end, piece);
                }
            }
        }
        scan_everything(&src)?;
    }

    #[test]
    fn arbitrary_text_is_scanned(src in "\\PC{0,300}") {
        scan_everything(&src)?;
    }
}

/// The scanner reads the preprocessed text ([`crate::checker::check::preprocess`]):
/// declarations written through macros of any form are read as the driver reads them, and
/// the byte ranges point into that text.
#[test]
fn declarations_through_macros_are_read_in_the_preprocessed_text() {
    let src = "#version 330 core\n#define U uniform\n#define VEC VEC3\n  #  define VEC3 vec3\n#define F(x) x\n\
               #define TWO uniform vec3\n#define SELF SELF\nin VEC FragPos;\nU VEC lightPos;\nSELF vec3 odd;\n\
               TWO viewPos;\nF(uniform) F(vec3) lightColor;\n";
    let text = crate::checker::check::preprocess::preprocess(src).expect("preprocessed");
    let p = parse(&text);
    let found: Vec<(Storage, &str, &str)> =
        p.decls.iter().map(|d| (d.storage, d.ty.as_str(), d.name.as_str())).collect();
    assert_eq!(
        found,
        [
            (Storage::In, "vec3", "FragPos"),
            (Storage::Uniform, "vec3", "lightPos"),
            (Storage::Uniform, "vec3", "viewPos"),
            (Storage::Uniform, "vec3", "lightColor")
        ],
        "{text}"
    );
    let light = &p.decls[1];
    assert_eq!(&text[light.type_span.0..light.type_span.1], "vec3");
}

#[test]
fn declarations_the_preprocessor_skips_are_not_read() {
    let src = "#version 330 core\n#define USE_MAPS 0\n#if 0\nuniform float shininess;\n#endif\n\
               #ifdef NEVER\nuniform vec3 gone;\n#else\nuniform vec3 kept;\n#endif\n\
               #if USE_MAPS\nuniform sampler2D map;\n#elif defined(USE_MAPS)\nuniform vec3 elif_taken;\n#endif\n\
               #ifndef NEVER\nuniform vec3 ifndef_taken;\n#endif\n#if WIDTH * 2 > 3\nuniform vec3 unknown_is_zero;\n#endif\n\
               #define X 1\n#undef X\n#if X\nuniform vec3 undefined_is_zero;\n#endif\nconst float shininess = 32.0;\n";
    let text = crate::checker::check::preprocess::preprocess(src).expect("preprocessed");
    assert_eq!(text.lines().count(), src.lines().count());
    let names: Vec<String> = parse(&text).decls.into_iter().map(|d| d.name).collect();
    assert_eq!(names, ["kept", "elif_taken", "ifndef_taken"], "{text}");
}
