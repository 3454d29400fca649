//! Vertex + fragment pairs (`check-shader FRAG --vertex VERT`): the reference pairs agree,
//! per-vertex and per-fragment lighting are told apart, every vertex-stage mistake is
//! diagnosed from its own mutant and from hand-written variants in other styles, and bad
//! input gets a clear message.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::gl_common;

use std::process::Command;

use lightlab::checker::check::pair::{self, PairModel};
use lightlab::checker::check::{CheckError, Mapping};
use lightlab::checker::diagnose::Submission;
use lightlab::checker::mistakes::VERTEX_CATALOGUE;
use lightlab::gl::{GlContext, ModelId};

const EXAMPLES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/gl/shaders/examples");

/// 3 000 triangles: every mistake here changes hundreds of them; a correct pair stays
/// within the bound on all.
const N: usize = 3000;
const SEED: u64 = 7;

fn example(name: &str) -> String {
    std::fs::read_to_string(format!("{EXAMPLES}/{name}")).unwrap()
}

fn diagnosed(ctx: &GlContext, vertex: &str, fragment: &str, model: ModelId) -> lightlab::checker::diagnose::Diagnosed {
    let submission = Submission { fragment, vertex: Some(vertex) };
    lightlab::checker::diagnose::check_and_diagnose(ctx, submission, model, &Mapping::default(), N, SEED)
        .unwrap_or_else(|e| panic!("{e}"))
}

fn ids(d: &lightlab::checker::diagnose::Diagnosed) -> Vec<&str> {
    d.diagnosis.iter().map(|f| f.id.as_str()).collect()
}

#[test]
fn the_reference_pairs_agree_and_the_two_models_are_told_apart() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    for model in [PairModel::PerFragment, PairModel::PerVertex] {
        let (v, f) = pair::reference_pair(model);
        let d = diagnosed(&ctx, v, f, model.model());
        assert!(d.agrees(), "{}", d.format());
        // The bound is a worst case (see bounds::VERTEX_PAIR); the correct pairs stay far
        // inside it, so a real mistake is not hidden by it.
        assert!(d.report.vs_f64.max_abs < d.report.bound / 100.0, "{}", d.format());
        let other = if model == PairModel::PerFragment { ModelId::Gouraud } else { ModelId::BasicLighting };
        let crossed = diagnosed(&ctx, v, f, other);
        assert!(!crossed.agrees(), "{other} must tell per-vertex from per-fragment lighting");
        let expected = if model == PairModel::PerFragment { "phong-for-gouraud" } else { "gouraud-for-phong" };
        assert_eq!(ids(&crossed), [expected], "{}", crossed.format());
    }
}

#[test]
fn every_vertex_mistake_is_diagnosed_from_its_own_mutant() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    for model in [PairModel::PerFragment, PairModel::PerVertex] {
        for pair::MutantPair { mistake, vertex, fragment } in pair::pair_mistakes(model).unwrap() {
            let d = diagnosed(&ctx, &vertex, &fragment, model.model());
            assert!(!d.agrees(), "{} on {}: the mutant must disagree", mistake.id, model.model());
            assert!(ids(&d).contains(&mistake.id), "{} on {}: {}", mistake.id, model.model(), d.format());
        }
    }
}

/// Every verified pair agrees with its model, and a Gouraud vertex shader with a lighting
/// mistake (Blinn-Phong, no ambient: red-team 3, M2, once "could not be narrowed") is named,
/// as every vertex-stage mistake is: each mistake applying to a model is in its list.
#[test]
fn lighting_mistakes_in_a_gouraud_vertex_shader_are_named() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    for model in [PairModel::PerFragment, PairModel::PerVertex] {
        for (v, f) in pair::verified_pairs(model) {
            let d = diagnosed(&ctx, v, f, model.model());
            assert!(d.agrees(), "{v}\n{}", d.format());
        }
        let listed: Vec<&str> = pair::pair_mistakes(model).unwrap().iter().map(|m| m.mistake.id).collect();
        for m in VERTEX_CATALOGUE.iter().filter(|m| m.applies_to(model.model())) {
            assert!(listed.contains(&m.id), "{} on {}", m.id, model.model());
        }
    }
    let listed: Vec<&str> = pair::pair_mistakes(PairModel::PerVertex).unwrap().iter().map(|m| m.mistake.id).collect();
    for id in ["blinn-for-phong", "ambient-missing", "specular-missing", "light-dir-reversed", "diffuse-no-clamp"] {
        assert!(listed.contains(&id), "{id}: {listed:?}");
    }
    assert!(!pair::pair_mistakes(PairModel::PerFragment).unwrap().iter().any(|m| m.mistake.id == "blinn-for-phong"));
    // The learner's own Gouraud shader (the reference's names, not LearnOpenGL's) with
    // Blinn-Phong's half vector: named all the same, by its colours.
    let (v, f) = pair::reference_pair(PairModel::PerVertex);
    let blinn = v.replace(
        "float spec = pow(max(dot(toEye, reflect(-toLight, n)), 0.0), 32.0);",
        "float spec = pow(max(dot(n, normalize(toLight + toEye)), 0.0), 32.0);",
    );
    assert_ne!(blinn, v);
    let d = diagnosed(&ctx, &blinn, f, ModelId::Gouraud);
    assert!(ids(&d).contains(&"blinn-for-phong"), "{}", d.format());
}

/// A view-space pair in the style of LearnOpenGL's exercise (interface blocks, `view *
/// model`, the eye at the origin): right, and with each vertex mistake written its way.
#[test]
fn view_space_pairs_agree_and_their_mistakes_are_named() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let (v, f) = (example("view_space.vert"), example("view_space.frag"));
    let d = diagnosed(&ctx, &v, &f, ModelId::BasicLighting);
    assert!(d.agrees(), "{}", d.format());
    let variants = [
        ("mat3(transpose(inverse(modelView))) * aNormal", "mat3(modelView) * aNormal", "normal-matrix-missing"),
        ("mat3(transpose(inverse(modelView))) * aNormal", "mat3(view) * aNormal", "normal-not-transformed"),
        ("vec3(modelView * vec4(aPos, 1.0))", "vec3(view * vec4(aPos, 1.0))", "position-not-transformed"),
    ];
    for (from, to, id) in variants {
        assert!(v.contains(from));
        let d = diagnosed(&ctx, &v.replace(from, to), &f, ModelId::BasicLighting);
        assert!(ids(&d).contains(&id), "{to}: {}", d.format());
    }
}

/// Other names (through a mapping), a hand-written normal matrix, a `flat`-free block on
/// one side only: still right.
#[test]
fn a_correct_pair_written_differently_agrees() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let vertex = "#version 330 core
in vec3 position;
in vec3 normal;
out vec3 vWorld;
out vec3 vNormal;
uniform mat4 uModel, uView, uProj;
void main() {
    vec4 w = uModel * vec4(position, 1.0);
    mat3 m = mat3(uModel);
    mat3 normalMatrix = inverse(transpose(m));
    vWorld = w.xyz;
    vNormal = normalMatrix * normal;
    gl_Position = uProj * uView * w;
}";
    let fragment = "#version 330 core
in vec3 vWorld;
in vec3 vNormal;
layout(location = 0) out vec4 color;
uniform vec3 uLight, uEye, uLightColor, uAlbedo;
void main() {
    vec3 n = normalize(vNormal);
    vec3 l = normalize(uLight - vWorld);
    vec3 e = normalize(uEye - vWorld);
    vec3 r = 2.0 * dot(n, l) * n - l;
    float s = pow(max(dot(e, r), 0.0), 32.0);
    color = vec4(uAlbedo * uLightColor * (0.1 + max(dot(n, l), 0.0) + 0.5 * s), 1.0);
}";
    let mapping = lightlab::checker::check::parse_mapping(
        "[names]\nposition = \"aPos\"\nnormal = \"aNormal\"\nuModel = \"model\"\nuView = \"view\"\nuProj = \"projection\"\n\
         uLight = \"lightPos\"\nuEye = \"viewPos\"\nuLightColor = \"lightColor\"\nuAlbedo = \"objectColor\"\n",
    )
    .unwrap();
    let checked =
        pair::compile_pair(&ctx, vertex, fragment, ModelId::BasicLighting, &mapping).unwrap().check(N, SEED).unwrap();
    assert!(checked.report.agrees(), "{}", checked.report.format());
    assert!(!checked.report.notes.iter().any(|n| n.contains("gl_Position")), "{:?}", checked.report.notes);
}

#[test]
fn a_wrong_gl_position_is_a_note_not_a_verdict() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let (v, f) = pair::reference_pair(PairModel::PerFragment);
    let v = v.replace("gl_Position = projection * view * vec4(FragPos, 1.0);", "gl_Position = vec4(aPos, 1.0);");
    let checked =
        pair::compile_pair(&ctx, &v, f, ModelId::BasicLighting, &Mapping::default()).unwrap().check(200, SEED).unwrap();
    assert!(checked.report.agrees(), "{}", checked.report.format());
    assert!(
        checked.report.notes.iter().any(|n| n.starts_with("gl_Position is not projection")),
        "{:?}",
        checked.report.notes
    );
}

#[test]
fn bad_pairs_get_clear_errors() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let (v, f) = pair::reference_pair(PairModel::PerFragment);
    let run = |v: &str, f: &str, model: ModelId| {
        pair::compile_pair(&ctx, v, f, model, &Mapping::default()).and_then(|p| p.check(10, SEED))
    };
    // A vertex compile error carries the vertex file's line (line 17: the normal).
    let broken = v.replace("Normal = mat3(transpose(inverse(model))) * aNormal;", "Normal = mat3(model) * aNormal +;");
    match run(&broken, f, ModelId::BasicLighting) {
        Err(CheckError::VertexCompile { log, excerpt }) => {
            assert!(excerpt.contains("17"), "{log}\n{excerpt}");
        }
        other => panic!("expected a vertex compile error, got {other:?}"),
    }
    // The fragment shader reads what the vertex shader does not write (Mesa links it, the
    // value being undefined; the check refuses it).
    let unlinked = v.replace("out vec3 Normal;", "out vec3 Normal2;").replace("Normal = ", "Normal2 = ");
    match run(&unlinked, f, ModelId::BasicLighting) {
        Err(CheckError::Usage(m)) => assert!(m.contains("`Normal`, which the vertex shader does not write"), "{m}"),
        other => panic!("expected a usage error, got {other:?}"),
    }
    // Types that differ between the stages do not link.
    let mistyped =
        f.replace("in vec3 Normal;", "in vec4 Normal;").replace("normalize(Normal)", "normalize(Normal.xyz)");
    match run(v, &mistyped, ModelId::BasicLighting) {
        Err(CheckError::Usage(m)) => assert!(m.contains("do not link") || m.contains("vec4"), "{m}"),
        other => panic!("expected a usage error, got {other:?}"),
    }
    match run(v, f, ModelId::Spot) {
        Err(CheckError::Usage(m)) => assert!(m.contains("basic_lighting") && m.contains("gouraud"), "{m}"),
        other => panic!("expected a usage error, got {other:?}"),
    }
}

#[test]
fn the_command_line_checks_a_pair_and_names_the_files() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let run = |vertex: &str, fragment: &str, extra: &[&str]| {
        let mut cmd = Command::new(env!("CARGO_BIN_EXE_lightlab"));
        cmd.env("LIGHTLAB_LANG", "en");
        cmd.args(["check-shader", &format!("{EXAMPLES}/{fragment}"), "--vertex", &format!("{EXAMPLES}/{vertex}")]);
        cmd.args(["--model", "basic_lighting", "--cases", "2000"]).args(extra);
        let out = cmd.output().unwrap();
        (out.status.code(), String::from_utf8_lossy(&out.stdout).into_owned())
    };
    let (code, out) = run("basic_lighting.vert", "basic_lighting.frag", &[]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("basic_lighting.vert") && out.contains("AGREES"), "{out}");
    let (code, out) = run("bug_normal_matrix_missing.vert", "basic_lighting.frag", &["--format", "json"]);
    assert_eq!(code, Some(1), "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["verdict"], "disagrees");
    assert_eq!(v["diagnosis"][0]["id"], "normal-matrix-missing", "{out}");
}

/// A view-space pair declares no `viewPos` (its eye is the origin), so no note says that
/// viewPos is missing, in any language (the note was once dropped by its English text alone).
#[test]
fn a_view_space_pair_has_no_eye_note_in_any_language() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    for lang in ["en", "fr", "uk"] {
        let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
            .env("LIGHTLAB_LANG", lang)
            .args(["check-shader", &format!("{EXAMPLES}/view_space.frag")])
            .args(["--vertex", &format!("{EXAMPLES}/view_space.vert"), "--model", "basic_lighting", "--cases", "500"])
            .output()
            .unwrap();
        let out = String::from_utf8_lossy(&out.stdout);
        assert!(!out.contains("viewPos"), "{lang}:\n{out}");
    }
}

/// `example(name)` with each `(from, to)` replaced; panics if a pattern is missing (the
/// example changed and the test would no longer test anything).
fn edited(name: &str, edits: &[(&str, &str)]) -> String {
    let mut text = example(name);
    for (from, to) in edits {
        assert!(text.contains(from), "{name} no longer contains {from:?}");
        text = text.replace(from, to);
    }
    text
}

/// Issue 25 item 9: a Gouraud vertex shader that takes the strengths as uniforms (the
/// check fills them with random values) is still named `gouraud-for-phong`, and so is one
/// of them taken as a uniform with the others hard-coded.
#[test]
fn a_gouraud_pair_with_the_strengths_as_uniforms_is_named() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let declare = (
        "uniform vec3 lightColor;",
        "uniform vec3 lightColor;\nuniform float ambientStrength;\nuniform float specularStrength;\nuniform float shininess;",
    );
    let all = edited(
        "gouraud.vert",
        &[
            declare,
            ("0.1 * lightColor", "ambientStrength * lightColor"),
            ("0.5 * spec", "specularStrength * spec"),
            (", 32.0)", ", shininess)"),
        ],
    );
    let one = edited(
        "gouraud.vert",
        &[
            ("uniform vec3 lightColor;", "uniform vec3 lightColor;\nuniform float shininess;"),
            (", 32.0)", ", shininess)"),
        ],
    );
    let f = example("gouraud.frag");
    for v in [all, one] {
        let right = diagnosed(&ctx, &v, &f, ModelId::Gouraud);
        assert!(right.agrees(), "the same pair checked as Gouraud: {}", right.format());
        let d = diagnosed(&ctx, &v, &f, ModelId::BasicLighting);
        assert_eq!(ids(&d), ["gouraud-for-phong"], "{}", d.format());
    }
}

/// Issue 25 item 9: a view-space pair that leaves the light in world space is named,
/// written either way (the vertex shader passing `lightPos` unmoved, or the fragment
/// shader reading the `lightPos` uniform itself).
#[test]
fn a_view_space_pair_with_the_light_in_world_space_is_named() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let moved = "vs_out.LightPos = vec3(view * vec4(lightPos, 1.0));";
    let passed = edited("view_space.vert", &[(moved, "vs_out.LightPos = lightPos;")]);
    let f = example("view_space.frag");
    let d = diagnosed(&ctx, &passed, &f, ModelId::BasicLighting);
    assert_eq!(ids(&d), ["light-not-in-view-space"], "{}", d.format());
    let read = edited(
        "view_space.frag",
        &[
            ("    vec3 LightPos;\n", ""),
            ("uniform vec3 lightColor;", "uniform vec3 lightColor;\nuniform vec3 lightPos;"),
            ("fs_in.LightPos", "lightPos"),
        ],
    );
    let vertex = edited("view_space.vert", &[("    vec3 LightPos;\n", ""), (moved, "")]);
    let d = diagnosed(&ctx, &vertex, &read, ModelId::BasicLighting);
    assert_eq!(ids(&d), ["light-not-in-view-space"], "{}", d.format());
}

/// When nothing is named, the finding says what was tried, never an empty sentence.
#[test]
fn a_pair_nothing_names_says_what_was_tried() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    // Two mistakes at once, one in each shader: the normal through mat3(model), and the
    // specular term left out.
    let v = edited("basic_lighting.vert", &[("mat3(transpose(inverse(model))) * aNormal", "mat3(model) * aNormal")]);
    let f = edited("basic_lighting.frag", &[("(ambient + diffuse + specular)", "(ambient + diffuse)")]);
    let d = diagnosed(&ctx, &v, &f, ModelId::BasicLighting);
    assert_eq!(ids(&d), ["isolated"], "{}", d.format());
    let title = &d.diagnosis[0].title;
    assert!(title.contains("vertex-stage mistakes") && title.contains("neither of your shaders"), "{title}");
}

/// The page's pair data (`lightlab::live::pair`) decides as `check-shader --vertex --cases
/// N_PAIR_CASES --seed SEED` does: for the reference pair and every vertex mutant, the
/// page's rule (each triangle's colour against the exported `expected` within the exported
/// `bound`) on llvmpipe's colours fails the same triangles the command line fails, and on
/// these few triangles the command line still names each mutant.
#[test]
fn the_page_pair_data_gives_the_command_lines_verdicts() {
    use lightlab::checker::diagnose::case_fails;
    use lightlab::live::pair::{pair_json, N_PAIR_CASES};
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let seed = lightlab::live::exercises::SEED;
    for model in [PairModel::PerFragment, PairModel::PerVertex] {
        let data = pair_json(model).unwrap();
        let bound = data["verdict"]["bound"].as_f64().unwrap();
        let mut programs = vec![(String::from("reference"), data["reference"].clone())];
        for m in data["mutants"].as_array().unwrap() {
            programs.push((m["id"].as_str().unwrap().to_string(), m.clone()));
        }
        for (id, p) in programs {
            let (v, f) = (p["vertex"].as_str().unwrap(), p["fragment"].as_str().unwrap());
            let compiled = pair::compile_pair(&ctx, v, f, model.model(), &Mapping::default()).unwrap();
            let checked = compiled.check(N_PAIR_CASES, seed).unwrap();
            let mut page_failing = 0;
            for (g, group) in data["groups"].as_array().unwrap().iter().enumerate() {
                for i in 0..group["triangles"].as_array().unwrap().len() {
                    let want: Vec<f64> =
                        data["expected"][g][i].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
                    page_failing +=
                        usize::from(case_fails(&checked.outputs[g][i], &[want[0], want[1], want[2]], bound));
                }
            }
            assert_eq!(page_failing, checked.report.failing, "{id} on {}", model.model());
            assert_eq!(id == "reference", checked.report.agrees(), "{id} on {}", model.model());
            if id != "reference" {
                let found = pair::diagnose_pair(&ctx, (v, f), model, &Mapping::default(), &checked).unwrap().findings;
                assert!(found.iter().any(|x| x.id == id), "{id} on {}: {found:?}", model.model());
            }
        }
    }
}

/// The chapter's pair with both shaders' declarations written through macros (a two-word
/// macro, a function-like one over two lines, `##`, `gl_Position` through a macro): the
/// checker reads the preprocessed text, so every uniform and attribute is found and set,
/// and the pair agrees.
#[test]
fn a_pair_declared_through_macros_agrees() {
    let Some(ctx) = gl_common::context_or_skip() else { return };
    let vertex = example("basic_lighting.vert")
        .replace(
            "layout (location = 0) in vec3 aPos;",
            "#define ATTR(loc, name) layout (location = loc) in vec3 a##name;\nATTR(0,\n     Pos)",
        )
        .replace("layout (location = 1) in vec3 aNormal;", "ATTR(1, Normal)")
        .replace("uniform mat4 ", "M4 ")
        .replace("out vec3 FragPos;", "#define M4 uniform mat4\n#define POSITION gl_Position\nout vec3 FragPos;")
        .replace("gl_Position =", "POSITION =");
    assert_eq!(vertex.matches("M4 ").count(), 4, "{vertex}");
    let fragment =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/macro_shaders/function_like.frag"))
            .unwrap();
    let d = diagnosed(&ctx, &vertex, &fragment, ModelId::BasicLighting);
    assert!(d.agrees(), "{}\n{vertex}", d.format());
}
