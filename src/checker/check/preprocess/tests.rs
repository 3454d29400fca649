//! The preprocessor on every macro form the red-team wrote, the conditionals, the line
//! count, the bounds, and fuzzed with proptest: random directive soup and mutated shaders
//! (`LIGHTLAB_FUZZ_CASES` cases per property, default 256, a fixed seed).

use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

use super::*;

fn pp(src: &str) -> String {
    let out = preprocess(src).unwrap_or_else(|e| panic!("{e}\n{src}"));
    assert_eq!(out.matches('\n').count(), src.matches('\n').count(), "the line count is kept:\n{src}\n---\n{out}");
    out
}

/// The output's words (whitespace collapsed), for comparisons that ignore spacing.
fn words(src: &str) -> String {
    pp(src).split_whitespace().collect::<Vec<_>>().join(" ")
}

/// A comment is one space before preprocessing, so a comment over two lines inside a
/// `#define` keeps the directive going; in code it changes nothing (red-team 3, H2: the
/// second line was read as code and the rewritten shader did not compile).
#[test]
fn a_comment_over_lines_in_a_directive_continues_it() {
    let src = "#define ONE /* a\n b */ 1.0\nfloat x = ONE;\nfloat y = /* c\n d */ 2.0;\n";
    let out = pp(src);
    let lines: Vec<&str> = out.split('\n').collect();
    assert_eq!(lines[0].trim(), "", "{out}");
    assert_eq!(lines[1].trim(), "", "the comment's second line belongs to the directive:\n{out}");
    assert_eq!(lines[2].split_whitespace().collect::<Vec<_>>(), ["float", "x", "=", "1.0;"], "{out}");
    assert_eq!(lines[3].split_whitespace().collect::<Vec<_>>(), ["float", "y", "="], "code keeps its lines:\n{out}");
    assert_eq!(lines[4].split_whitespace().collect::<Vec<_>>(), ["2.0;"], "{out}");
}

#[test]
fn lines_are_kept_and_directives_become_empty_lines() {
    let src =
        "#version 330 core\n#extension GL_ARB_x : enable\n#pragma optimize(off)\n#define A 1\nfloat a = A;\n#undef A\n\
               #if 0\nfloat gone;\n#endif\nfloat b;";
    let out = pp(src);
    let lines: Vec<&str> = out.split('\n').collect();
    assert_eq!(lines[0], "#version 330 core");
    assert_eq!(lines[1], "#extension GL_ARB_x : enable");
    assert_eq!(lines[2], "#pragma optimize(off)");
    assert_eq!(lines[3], "");
    assert_eq!(lines[4], "float a = 1;");
    assert_eq!(lines[5..9], ["", "", "", ""]);
    assert_eq!(lines[9], "float b;", "{out}");
    // a text without macros comes out as it went in (comments blanked)
    let plain = "in vec3 FragPos; // the position\nvoid main() {\n\tx = 1.0;\r\n}\n";
    assert_eq!(pp(plain), crate::checker::check::glsl::blank_comments(plain));
}

#[test]
fn object_like_macros_of_any_length_expand() {
    assert_eq!(words("#define UV uniform vec3\nUV lightPos;\n"), "uniform vec3 lightPos;");
    assert_eq!(words("#define HIGHP\n#define U uniform HIGHP\nU vec3 lightPos;\n"), "uniform vec3 lightPos;");
    assert_eq!(words("#define A B\n#define B uniform\nA vec3 x;\n"), "uniform vec3 x;", "a chain");
    assert_eq!(words("#define INC(x) x += 1\nINC(a);\n"), "a += 1;", "`+=` stays one token");
}

#[test]
fn function_like_macros_take_their_arguments() {
    assert_eq!(words("#define DECL(t, n) uniform t n;\nDECL(vec3, lightPos)\n"), "uniform vec3 lightPos;");
    assert_eq!(words("#define F(a, b) a(b, (1, 2))\nF(max, min(x, y))\n"), "max(min(x, y), (1, 2))");
    assert_eq!(words("#define F(x) [x]\nF()\n"), "[]", "an empty argument");
    assert_eq!(words("#define Z() 0\nZ() + Z ( )\n"), "0 + 0");
    assert_eq!(words("#define F(x) x\nfloat F;\n"), "float F;", "a name without `(` is not a call");
    // a call over three lines: the expansion on its first line, the breaks after it
    let out = pp("#define DECL(t, n) uniform t n;\nDECL(vec3,\n  light\n  )\nfloat y;\n");
    let lines: Vec<&str> = out.split('\n').collect();
    assert_eq!(lines[1].split_whitespace().collect::<Vec<_>>(), ["uniform", "vec3", "light;"], "{out}");
    assert_eq!(lines[2..5], ["", "", "float y;"], "{out}");
}

#[test]
fn token_pasting_makes_one_token() {
    assert_eq!(words("#define T(n) vec##n\nuniform T(3) lightPos;\n"), "uniform vec3 lightPos;");
    assert_eq!(words("#define LIGHT(x) light##x\nuniform vec3 LIGHT(Pos);\n"), "uniform vec3 lightPos;");
    assert_eq!(words("#define CAT(a, b) a ## b\nCAT(, x) CAT(y, ) CAT(1, 0)\n"), "x y 10", "placemarkers");
    assert_eq!(words("#define AB done\n#define CAT(a, b) a##b\nCAT(A, B)\n"), "done", "a pasted name is rescanned");
    // the argument next to `##` is not expanded first
    assert_eq!(words("#define N 3\n#define V(n) vec##n\n#define W(n) V(n)\nV(N) W(N)\n"), "vecN vec3");
    assert!(preprocess("#define P(a, b) a##b\nP(+, x)\n").is_err(), "`+x` is not one token");
    assert!(preprocess("#define P ## x\n").is_err());
}

#[test]
fn undef_then_redefine_takes_the_new_body() {
    let src = "#define STRENGTH uniform float\nSTRENGTH a;\n#undef STRENGTH\n#define STRENGTH const float\nSTRENGTH b = 0.5;\nSTRENGTH\n";
    assert_eq!(words(src), "uniform float a; const float b = 0.5; const float");
    assert_eq!(words("#define X 1\n#undef X\nX\n"), "X");
}

#[test]
fn conditionals_choose_the_branch_the_driver_compiles() {
    let choose = |head: &str| {
        words(&format!("{head}\n#define PARAM uniform float\n#else\n#define PARAM const float\n#endif\nPARAM a;\n"))
    };
    assert_eq!(choose("#define TWEAKABLE\n#ifdef TWEAKABLE"), "uniform float a;");
    assert_eq!(choose("#ifdef TWEAKABLE"), "const float a;");
    assert_eq!(choose("#ifndef FIXED"), "uniform float a;");
    assert_eq!(choose("#define FIXED\n#ifndef FIXED"), "const float a;");
    assert_eq!(choose("#define TWEAKABLE\n#if defined(TWEAKABLE) && 1"), "uniform float a;");
    assert_eq!(choose("#define TWEAKABLE\n#if defined TWEAKABLE && 0"), "const float a;");
    assert_eq!(choose("#if !defined(TWEAKABLE)"), "uniform float a;");
    // `defined` brought by a macro's body is evaluated, as Mesa and GCC do (red-team 3).
    assert_eq!(choose("#define TWEAKABLE\n#define HAS defined(TWEAKABLE)\n#if HAS"), "uniform float a;");
    assert_eq!(choose("#define HAS defined TWEAKABLE\n#if HAS"), "const float a;");
    assert_eq!(choose("#define T\n#define HAS defined(T)\n#define BOTH HAS && 1\n#if BOTH"), "uniform float a;");
    assert_eq!(choose("#define HAS defined(HAS)\n#if HAS"), "uniform float a;", "it is defined");
    // A web of macros naming each other, one of them bringing `defined`: each macro is
    // looked at once (path by path it would be 4^16 steps and never end here).
    let web = "#define A B B B C\n#define B A A A A\n#define C defined(A)\n#if A\n#endif\n";
    assert!(preprocess(web).is_err(), "`#if 1 1 ...` has more after its end");
    let nested = "#if 1\n#if 0\na\n#elif 1\nb\n#else\nc\n#endif\n#else\n#if 1\nd\n#endif\n#endif\n";
    assert_eq!(words(nested), "b");
    assert_eq!(
        words("#if 0\n#bogus directive\n#if 1\nx\n#endif\n#else\ny\n#endif\n"),
        "y",
        "skipped lines are not read"
    );
}

#[test]
fn if_arithmetic_follows_c_precedence() {
    let truth = |expr: &str| {
        words(&format!("#define TWO 2\n#define F(x) (x * 10)\n#if {expr}\nyes\n#else\nno\n#endif\n")) == "yes"
    };
    for expr in [
        "1 + 2 * 3 == 7",
        "(1 + 2) * 3 == 9",
        "TWO << 3 == 16",
        "-TWO < 0",
        "~0 == -1",
        "10 / 3 == 3 && 10 % 3 == 1",
        "F(TWO) == 20",
        "0x10 == 16 && 010 == 8",
        "1 || 1 / 0",
        "(5 & 3) == 1 && (5 | 3) == 7 && (5 ^ 3) == 6",
        "3 > 2 && 2 >= 2 && 2 <= 2 && 1 != 2",
        "UNDEFINED == 0",
        "__VERSION__ == 110 && !defined(GL_core_profile)",
        "__LINE__ == 3",
        "defined(__LINE__)",
    ] {
        assert!(truth(expr), "{expr}");
    }
    assert!(!truth("1 - 1"), "1 - 1");
    assert!(!truth("2 < 1"), "2 < 1");
    assert_eq!(
        words("#version 330 core\n#if __VERSION__ == 330 && GL_core_profile\nyes\n#endif\n"),
        "#version 330 core yes"
    );
    assert_eq!(words("#version 300 es\n#if GL_ES && !defined(GL_core_profile)\nyes\n#endif\n"), "#version 300 es yes");
    assert_eq!(words("#if __VERSION__ == 110\nyes\n#endif\n"), "yes", "no #version: 110");
    assert_eq!(words("\n\n#line 10\n__LINE__ __FILE__\n"), "10 0");
    assert!(preprocess("#if 1 / 0\n#endif\n").is_err());
}

#[test]
fn a_self_referential_macro_ends() {
    assert_eq!(words("#define a a + 1\na\n"), "a + 1");
    assert_eq!(words("#define x y\n#define y x\nx y\n"), "x y");
    assert_eq!(words("#define f(a) a + f(a)\nf(f(z))\n"), "z + f(z) + f(z + f(z))");
}

/// Each macro doubles the previous one: 2⁴⁰ tokens, refused within the bound.
#[test]
fn a_macro_bomb_is_bounded() {
    let mut src = String::from("#version 330 core\nout vec4 FragColor;\n#define A0 1.0\n");
    for i in 1..=40 {
        src += &format!("#define A{i} (A{} + A{})\n", i - 1, i - 1);
    }
    src += "void main() { FragColor = vec4(A40); }\n";
    let started = std::time::Instant::now();
    let err = preprocess(&src).expect_err("the bomb is refused");
    assert!(err.message.contains("more than"), "{err}");
    assert_eq!(err.line, 44, "{err}");
    // function-like, each argument used twice
    let mut src = String::from("#define F0(x) x x\n");
    for i in 1..=40 {
        src += &format!("#define F{i}(x) F{}(F{}(x))\n", i - 1, i - 1);
    }
    src += "F40(y)\n";
    assert!(preprocess(&src).is_err());
    let deep = format!("#define G(x) x\n{}1{}\n", "G(".repeat(5000), ")".repeat(5000));
    assert!(preprocess(&deep).is_err(), "nesting past the bound");
    assert!(started.elapsed().as_secs_f64() < 20.0, "{:?}", started.elapsed());
    if let Ok(file) = std::fs::read_to_string("/tmp/redteam/cases/hostile_macro_bomb.frag") {
        assert!(preprocess(&file).is_err());
    }
}

#[test]
fn bad_directives_are_errors() {
    for src in [
        "#if 1\nx\n",
        "#endif\n",
        "#if 1\n#else\n#else\n#endif\n",
        "#if 1\n#else\n#elif 1\n#endif\n",
        "#define\n",
        "#define 1 2\n",
        "#define F(a, a) a\n",
        "#define F(a b) a\n",
        "#define F(a,\n",
        "#define F(x) x\nF(1, 2)\n",
        "#define F(x) x\nF((1)\n",
        "#ifdef\n#endif\n",
        "#include <x>\n",
        "#error stop\n",
        "#if (1\n#endif\n",
        "#if 1 2\n#endif\n",
        "#if\n#endif\n",
        "#if defined(\n#endif\n",
        "#line\n",
    ] {
        assert!(preprocess(src).is_err(), "{src}");
    }
}

#[test]
fn a_continued_line_keeps_the_line_count() {
    let src = "#define LONG uniform \\\n  vec3\nLONG lightPos;\nfloat a = 1.0 + \\\n 2.0;\n";
    let out = pp(src);
    assert_eq!(
        out.split('\n').collect::<Vec<_>>()[2].split_whitespace().collect::<Vec<_>>(),
        ["uniform", "vec3", "lightPos;"]
    );
}

/// A file this cannot preprocess is read from its original text for the limits checked
/// before the driver compiles it, and refused with its line only after (the driver reports
/// the learner's own errors first: [`crate::checker::check::compile_shader`]).
#[test]
fn a_file_that_cannot_be_preprocessed_keeps_its_limits_and_is_refused_with_its_line() {
    use crate::checker::check::{preprocessed, read, CheckError};
    let src =
        "#version 330 core\nuniform float big[5000];\n#define U uniform\n#include <x>\nout vec4 c;\nvoid main() {}\n";
    let (text, parsed) = read(src);
    assert_eq!(text.as_ref().map_err(|e| e.line), Err(4));
    assert_eq!(parsed.largest_array, 5000, "the original's arrays still meet the cap");
    match preprocessed(text, true) {
        Err(CheckError::Usage(m)) => assert!(m.contains("vertex shader") && m.contains("line 4"), "{m}"),
        other => panic!("{other:?}"),
    }
    let (text, parsed) = read("#define N 5000\nuniform float big[N];\n");
    assert!(text.is_ok());
    assert_eq!(parsed.largest_array, 5000, "a size through a macro meets the cap");
}

fn fuzz_config() -> Config {
    let cases = std::env::var("LIGHTLAB_FUZZ_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(256);
    Config { cases, rng_seed: RngSeed::Fixed(0x7070_7270), failure_persistence: None, ..Config::default() }
}

const PIECES: &[&str] = &[
    "#define ",
    "#undef ",
    "#if ",
    "#ifdef ",
    "#ifndef ",
    "#elif ",
    "#else",
    "#endif",
    "#line ",
    "#version 330\n",
    "#pragma x",
    "#",
    "\n",
    " ",
    "\\\n",
    "(",
    ")",
    ",",
    "##",
    "defined",
    "A",
    "B",
    "F",
    "G(x)",
    "x",
    "1",
    "0",
    "+",
    "/",
    "*",
    "<<",
    "&&",
    "!",
    "uniform",
    "vec3",
    ";",
    "/*",
    "*/",
    "//",
    "é",
    "__LINE__",
];

/// Whatever the text: no panic, and when it is preprocessed the line count is kept.
fn preprocessed_or_refused(src: &str) -> Result<(), TestCaseError> {
    if let Ok(out) = preprocess(src) {
        prop_assert_eq!(out.matches('\n').count(), src.matches('\n').count());
        prop_assert!(out.len() <= MAX_OUTPUT_BYTES);
    }
    Ok(())
}

proptest! {
    #![proptest_config(fuzz_config())]

    #[test]
    fn random_directive_soup_never_panics(pieces in prop::collection::vec(prop::sample::select(PIECES), 0..120)) {
        preprocessed_or_refused(&pieces.concat())?;
    }

    #[test]
    fn mutated_macro_shaders_never_panic(
        edits in prop::collection::vec((0usize..400, prop::sample::select(PIECES), 0usize..3), 1..10)
    ) {
        let mut src = String::from("#version 330 core\n#define T(n) vec##n\n#define F(a, b) a(b)\n#ifdef X\n#define U uniform\n#else\n\
                                    #define U uniform highp\n#endif\nU T(3) lightPos;\nvoid main() { F(max, (1, 2)); }\n");
        for (at, piece, cut) in edits {
            let mut at = at.min(src.len());
            while !src.is_char_boundary(at) {
                at -= 1;
            }
            let mut end = (at + cut).min(src.len());
            while !src.is_char_boundary(end) {
                end += 1;
            }
            src.replace_range(at..end, piece);
        }
        preprocessed_or_refused(&src)?;
    }

    #[test]
    fn arbitrary_text_never_panics(src in "\\PC{0,300}") {
        preprocessed_or_refused(&src)?;
    }
}
