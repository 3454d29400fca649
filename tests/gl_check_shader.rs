//! `lightlab check-shader` end to end: the binary on the shipped example shaders.
//!
//! - the correct shaders pass (exit 0);
//! - the two classic bugs are caught (exit 1) with a counterexample: specular from
//!   `reflect(lightDir, norm)`, and the normal moved by `mat3(model)` under non-uniform scale;
//! - usage errors exit 2 and name what is wrong; a compile error exits 1 with the file's line.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::gl_common;

use std::path::{Path, PathBuf};
use std::process::Command;

const EXAMPLES: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/gl/shaders/examples");

/// 20 000 cases keep each run short in a debug build; the bugs fail thousands of them.
const CASES: &str = "20000";

fn example(name: &str) -> PathBuf {
    Path::new(EXAMPLES).join(name)
}

/// Runs the binary; returns (exit code, stdout, stderr).
fn lightlab(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .env("LIGHTLAB_LANG", "en")
        .args(args)
        .output()
        .expect("run lightlab");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    println!("$ lightlab {}\n{stdout}{stderr}", args.join(" "));
    (out.status.code().unwrap_or(-1), stdout, stderr)
}

fn check(file: &Path, model: &str, extra: &[&str]) -> (i32, String, String) {
    let file = file.to_str().unwrap();
    let mut args = vec!["check-shader", file, "--model", model, "--cases", CASES];
    args.extend_from_slice(extra);
    lightlab(&args)
}

fn gl_available() -> bool {
    gl_common::context_or_skip().is_some()
}

fn temp_file(name: &str, text: &str) -> crate::common::TempFile {
    crate::common::TempFile::new(name, text)
}

#[test]
fn the_correct_basic_lighting_shader_agrees() {
    if !gl_available() {
        return;
    }
    let (code, out, _) = check(&example("basic_lighting.frag"), "basic_lighting", &[]);
    assert_eq!(code, 0);
    assert!(out.contains("verdict: AGREES"), "{out}");
    assert!(out.contains("0 beyond the bound"), "{out}");
}

#[test]
fn the_reflect_sign_bug_is_caught() {
    if !gl_available() {
        return;
    }
    let (code, out, _) = check(&example("bug_reflect_sign.frag"), "basic_lighting", &[]);
    assert_eq!(code, 1);
    assert!(out.contains("verdict: DISAGREES"), "{out}");
    assert!(out.contains("counterexample 1:"), "{out}");
    assert!(out.contains("expected (f64) = [") && out.contains("got (llvmpipe) = ["), "{out}");
    assert!(out.contains("lightPos = ("), "the inputs are printed with the shader's names: {out}");
}

/// Two mistakes with the same output (`reflect-sign`, `view-dir-reversed`) come in the
/// order of the learner's text: the one whose edit the shader contains first.
#[test]
fn equivalent_mistakes_are_ordered_by_the_learners_text() {
    if !gl_available() {
        return;
    }
    let (code, out, _) = check(&example("bug_reflect_sign.frag"), "basic_lighting", &[]);
    assert_eq!(code, 1);
    let first = out.lines().find(|l| l.starts_with("  - ")).unwrap_or_default();
    assert!(first.contains("[reflect-sign]"), "{out}");
    let view = temp_file(
        "view_dir_reversed.frag",
        &basic_lighting_with("normalize(viewPos - FragPos)", "normalize(FragPos - viewPos)"),
    );
    let (code, out, _) = check(&view, "basic_lighting", &[]);
    assert_eq!(code, 1);
    let first = out.lines().find(|l| l.starts_with("  - ")).unwrap_or_default();
    assert!(first.contains("[view-dir-reversed]"), "{out}");
}

#[test]
fn the_normal_matrix_shader_agrees_and_the_model_matrix_bug_is_caught() {
    if !gl_available() {
        return;
    }
    let (code, out, _) = check(&example("normal_matrix.frag"), "normal_matrix", &[]);
    assert_eq!(code, 0, "{out}");
    let (code, out, _) = check(&example("bug_model_matrix_normal.frag"), "normal_matrix", &[]);
    assert_eq!(code, 1);
    assert!(out.contains("counterexample 1:") && out.contains("model = columns"), "{out}");
    // the mistake is named: the normal-matrix model has the normal-matrix mistakes
    let first = out.lines().find(|l| l.starts_with("  - ")).unwrap_or_default();
    assert!(first.contains("[normal-matrix-missing]"), "{out}");
}

#[test]
fn a_mapping_file_renames_and_fixes_values() {
    if !gl_available() {
        return;
    }
    let shader = example("renamed_uniforms.frag");
    let toml = example("renamed_uniforms.toml");
    let (code, out, _) = check(&shader, "basic_lighting", &["--uniforms", toml.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("shininess fixed to 64 by the mapping"), "{out}");
    // Without the mapping the names are unknown: a usage error naming the first one.
    let (code, _, err) = check(&shader, "basic_lighting", &[]);
    assert_eq!(code, 2);
    assert!(err.contains("`vWorldPos` is not a quantity of model basic_lighting"), "{err}");
}

#[test]
fn a_compile_error_is_reported_with_the_line_of_the_file() {
    if !gl_available() {
        return;
    }
    let text = "#version 330 core\nin vec3 FragPos;\nin vec3 Normal;\nout vec4 FragColor;\nuniform vec3 lightPos;\nvoid main() {\n    vec3 d = normalize(lightPos - FragPos)\n    FragColor = vec4(d, 1.0);\n}\n";
    let path = temp_file("broken.frag", text);
    let (code, out, _) = check(&path, "basic_lighting", &[]);
    assert_eq!(code, 1);
    assert!(out.contains("DOES NOT COMPILE"), "{out}");
    // Mesa reports the error where the statement runs on: line 7 or 8 of the file.
    assert!(out.contains("   8 |     FragColor") || out.contains("   7 |     vec3 d"), "{out}");
}

#[test]
fn usage_errors_exit_2() {
    // No GL needed: these fail before a context is created.
    let shader = example("basic_lighting.frag");
    let (code, _, err) = check(&shader, "no_such_model", &[]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown model `no_such_model`") && err.contains("basic_lighting"), "{err}");
    let (code, _, err) = check(&shader, "gouraud", &[]);
    assert_eq!(code, 2);
    assert!(err.contains("per-vertex"), "{err}");
    let (code, _, err) = check(Path::new("/nonexistent/shader.frag"), "basic_lighting", &[]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot read shader"), "{err}");
    let (code, _, _) = lightlab(&["check-shader", shader.to_str().unwrap()]);
    assert_eq!(code, 2, "--model is required");
    let (code, _, _) = check(&shader, "basic_lighting", &["--cases", "0"]);
    assert_eq!(code, 2);
}

#[test]
fn bad_mapping_files_exit_2_naming_line_and_field() {
    let shader = example("basic_lighting.frag");
    let bad_toml = temp_file("bad.toml", "[names]\nuLight = \"lightPos\"\nuEye = \n");
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", bad_toml.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("invalid TOML at line 3"), "{err}");
    let not_a_string = temp_file("num.toml", "[names]\nuLight = 3\n");
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", not_a_string.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 2: names.uLight must be a string"), "{err}");
    let bad_value = temp_file("val.toml", "[values]\nshininess = \"high\"\n");
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", bad_value.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 2: values.shininess must be a number"), "{err}");
    // a value out of the quantity's range is refused, naming the file, the line and the field
    let negative = temp_file("neg.toml", "[values]\nambientStrength = 0.2\nshininess = -5.0\n");
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", negative.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    let at = format!("{}: line 3: values.shininess: -5 is negative", negative.display());
    assert!(err.contains(&at), "{err}");
}

#[test]
fn the_other_shipped_examples_give_their_documented_verdict() {
    if !gl_available() {
        return;
    }
    // The interpolated normal used without normalize(): its length scales the light.
    let (code, _, _) = check(&example("bug_unnormalized_normal.frag"), "basic_lighting", &[]);
    assert_eq!(code, 1);
    // opengl-tutorial 8 as printed: the ';' after the diffuse line drops the specular term.
    let (code, out, _) = check(&example("ot8_printed_semicolon.frag"), "opengl_tutorial8", &[]);
    assert_eq!(code, 1);
    assert!(out.contains("counterexample 1:"), "{out}");
}

/// A multiple-lights shader written around the crate's function file, with the chapter's
/// `Material` struct of samplers and the lights as uniforms.
fn multiple_lights_shader(with_spot: bool) -> String {
    let main = "struct Material {\n    sampler2D diffuse;\n    sampler2D specular;\n    float shininess;\n};\n\
in vec3 FragPos;\nin vec3 Normal;\nin vec2 TexCoords;\nout vec4 FragColor;\nuniform vec3 viewPos;\nuniform Material material;\n\
void main()\n{\n    vec3 withoutSpot;\n\
    vec3 result = multiple_lights(FragPos, Normal, viewPos, vec3(texture(material.diffuse, TexCoords)),\n\
        vec3(texture(material.specular, TexCoords)), material.shininess, withoutSpot);\n\
    FragColor = vec4(WHICH, 1.0);\n}\n";
    let which = if with_spot { "result" } else { "withoutSpot" };
    format!(
        "#version 330 core\n{}\n{}",
        lightlab::gl::models::MULTIPLE_LIGHTS.functions(),
        main.replace("WHICH", which)
    )
}

#[test]
fn multiple_lights_with_sampler_structs_and_light_uniforms() {
    if !gl_available() {
        return;
    }
    let path = temp_file("multi.frag", &multiple_lights_shader(true));
    let (code, out, _) = check(&path, "multiple_lights", &[]);
    assert_eq!(code, 0, "{out}");
    // The chapter's listing leaves the spotlight commented out: the model includes it.
    let path = temp_file("multi-nospot.frag", &multiple_lights_shader(false));
    let (code, out, _) = check(&path, "multiple_lights", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("scene: group"), "{out}");
}

#[test]
fn the_oracle_subcommand_prints_the_same_table_on_every_run() {
    if !gl_available() {
        return;
    }
    let args = ["oracle", "--cases", "2000", "--format", "markdown"];
    let (code, first, _) = lightlab(&args);
    assert_eq!(code, 0);
    assert!(first.contains("| model | cases | defined | f32 vs f64 max |"), "{first}");
    for model in ["basic_lighting", "gouraud", "multiple_lights", "opengl_tutorial8", "ogldev19"] {
        assert!(first.contains(&format!("| `{model}` | 2000 |")), "{model} row");
    }
    let (_, second, _) = lightlab(&args);
    assert_eq!(first, second, "deterministic output");
    let (code, _, _) = lightlab(&["oracle", "--cases", "0"]);
    assert_eq!(code, 2);
}

// ---------------------------------------------------------------- hostile and unusual input

fn basic_lighting_with(from: &str, to: &str) -> String {
    let src = std::fs::read_to_string(example("basic_lighting.frag")).unwrap();
    assert!(src.contains(from), "the example contains {from:?}");
    src.replacen(from, to, 1)
}

#[test]
fn a_leading_dot_float_gets_a_verdict() {
    // The old scanner never advanced on `.1` and grew until the process aborted.
    if !gl_available() {
        return;
    }
    let path =
        temp_file("dot.frag", &basic_lighting_with("float ambientStrength = 0.1;", "float ambientStrength = .1;"));
    let (code, out, _) = check(&path, "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("verdict: AGREES"), "{out}");
}

#[test]
fn every_float_literal_form_is_accepted() {
    if !gl_available() {
        return;
    }
    let src = basic_lighting_with(
        "float specularStrength = 0.5;",
        "float specularStrength = 5e-1 + 0.0f + .0 + 0. + 1.5e-3 * 0.0 + float(0x0 + 00) + float(0u);",
    );
    let (code, out, _) = check(&temp_file("literals.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}");
}

#[test]
fn a_version_inside_a_leading_comment_is_fine() {
    // The old rewrite blanked the comment's `#version` and left the real one mid-file.
    if !gl_available() {
        return;
    }
    let src = format!(
        "// written for #version 330 core\n/* #version 100 */\n{}",
        std::fs::read_to_string(example("basic_lighting.frag")).unwrap()
    );
    let (code, out, err) = check(&temp_file("comment-version.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn the_colour_is_the_output_at_location_0() {
    // The old checker took the first `out` declared, here a bright-pass output left black.
    if !gl_available() {
        return;
    }
    let src = basic_lighting_with(
        "out vec4 FragColor;",
        "layout(location = 1) out vec4 Bright;\nlayout(location = 0) out vec4 FragColor;",
    )
    .replacen("FragColor = vec4(", "Bright = vec4(0.0);\n    FragColor = vec4(", 1);
    let (code, out, _) = check(&temp_file("two-outs.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}");
    // Two outputs and no location: the only vec4 one is the colour.
    let src = basic_lighting_with("out vec4 FragColor;", "out float Depth;\nout vec4 FragColor;").replacen(
        "FragColor = vec4(",
        "Depth = 0.0;\n    FragColor = vec4(",
        1,
    );
    let (code, out, _) = check(&temp_file("vec4-out.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}");
}

#[test]
fn interface_blocks_are_inputs() {
    // The old parser read `in VS_OUT {` as a variable named `{` and then found no `out`.
    if !gl_available() {
        return;
    }
    let named = basic_lighting_with(
        "in vec3 FragPos;\nin vec3 Normal;",
        "in VS_OUT {\n    vec3 FragPos;\n    vec3 Normal;\n} fs_in;",
    )
    .replace("- FragPos", "- fs_in.FragPos")
    .replace("normalize(Normal)", "normalize(fs_in.Normal)");
    let (code, out, err) = check(&temp_file("block.frag", &named), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}{err}");
    let anonymous = basic_lighting_with(
        "in vec3 FragPos;\nin vec3 Normal;",
        "in VS_OUT {\n    vec3 FragPos;\n    flat vec3 Normal;\n};",
    );
    let (code, out, err) = check(&temp_file("anon-block.frag", &anonymous), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn an_expression_that_crashes_the_driver_does_not_compile() {
    // Mesa's compiler overflows its stack on 100 000 terms; before, lightlab died with it.
    if !gl_available() {
        return;
    }
    let terms = " + FragPos.x * 0.0".repeat(100_000);
    let src = basic_lighting_with("FragColor = vec4(", &format!("float z = 0.0{terms};\n    FragColor = z + vec4("));
    let (code, out, _) = check(&temp_file("huge.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("verdict: DOES NOT COMPILE"), "{out}");
}

#[test]
fn a_check_past_its_time_limit_took_too_long() {
    if !gl_available() {
        return;
    }
    // `--timeout 0` is refused (issue 28), so a runaway shader takes the path: an endless
    // loop whose body is 256 dependent `sin`s (llvmpipe ends any loop after 65 535
    // iterations; this body still costs about 1.7·10⁷ `sin`s per fragment), under 1 s.
    let (code, _, _) = check(&example("basic_lighting.frag"), "basic_lighting", &["--timeout", "0"]);
    assert_eq!(code, 2, "--timeout 0 is a usage error");
    let body = "x = sin(x + FragPos.x);\n".repeat(256);
    let endless = format!(
        "float x = 0.0;\n    while (true) {{\n{body}    if (x > 2.0) break;\n    }}\n    FragColor = x + vec4("
    );
    let src = basic_lighting_with("FragColor = vec4(", &endless);
    let (code, out, _) = check(&temp_file("endless.frag", &src), "basic_lighting", &["--timeout", "1"]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("verdict: TOOK TOO LONG"), "{out}");
}

#[test]
fn huge_counts_and_storage_are_refused_before_allocating() {
    // No GL needed: refused before a context is made.
    let shader = example("basic_lighting.frag");
    let file = shader.to_str().unwrap();
    let (code, _, err) = lightlab(&["check-shader", file, "--model", "basic_lighting", "--cases", "1000000000000"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--cases") && err.contains("1..=1000000"), "{err}");
    let (code, _, err) = lightlab(&["oracle", "--cases", "1000000000000"]);
    assert_eq!(code, 2, "{err}");
    let big =
        basic_lighting_with("uniform vec3 objectColor;", "uniform vec3 objectColor;\nuniform vec4 big[100000000];");
    let (code, _, err) = check(&temp_file("big.frag", &big), "basic_lighting", &[]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("an array of 100000000 elements"), "{err}");
    let many = basic_lighting_with(
        "uniform vec3 objectColor;",
        "uniform vec3 objectColor;\nuniform mat4 bones[4000];\nuniform mat4 more[4000];",
    );
    let (code, _, err) = check(&temp_file("many.frag", &many), "basic_lighting", &[]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("float components"), "{err}");
}

#[test]
fn mapping_values_must_be_finite_and_names_must_match() {
    let shader = example("renamed_uniforms.frag");
    let base = std::fs::read_to_string(example("renamed_uniforms.toml")).unwrap();
    let nan = temp_file("nan.toml", &base.replace("shininess = 64.0", "shininess = nan"));
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", nan.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("values.shininess must be finite"), "{err}");
    let inf = temp_file("inf.toml", &base.replace("shininess = 64.0", "shininess = [1.0, inf, 1.0]"));
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", inf.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    if !gl_available() {
        return;
    }
    let stray = temp_file("stray.toml", &base.replacen("[names]\n", "[names]\nuNotInTheShader = \"lightPos\"\n", 1));
    let text = std::fs::read_to_string(&stray).unwrap();
    let line = text.lines().position(|l| l.starts_with("uNotInTheShader")).unwrap() + 1;
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", stray.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(
        err.contains(&format!("line {line}: names.uNotInTheShader: the shader declares no `uNotInTheShader`")),
        "{err}"
    );
}

#[test]
fn a_mapping_to_an_unknown_name_blames_the_mapping() {
    if !gl_available() {
        return;
    }
    let shader = example("renamed_uniforms.frag");
    let base = std::fs::read_to_string(example("renamed_uniforms.toml")).unwrap();
    let (key, target) = base
        .lines()
        .find_map(|l| l.split_once(" = \"").map(|(k, v)| (k.trim().to_string(), v.trim_end_matches('"').to_string())))
        .expect("a [names] entry");
    let typo = temp_file("typo.toml", &base.replacen(&format!("\"{target}\""), "\"lightPosition\"", 1));
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", typo.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(&format!("names.{key} maps `{key}` to `lightPosition`")), "{err}");
}

#[test]
fn a_bad_entry_is_found_on_its_own_line_not_a_prefix() {
    let shader = example("basic_lighting.frag");
    let toml = temp_file("prefix.toml", "[values]\nshininessFactor = 2.0\nshininess = \"high\"\n");
    let (code, _, err) = check(&shader, "basic_lighting", &["--uniforms", toml.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("line 3: values.shininess must be a number"), "{err}");
}

#[test]
fn a_missing_opengl_is_an_internal_failure() {
    // A libEGL.so.1 that is not a library: the context fails; that is exit 3, not 2.
    let dir = crate::common::temp_dir("fake-egl", "lib");
    std::fs::write(dir.join("libEGL.so.1"), b"not a library").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .env("LIGHTLAB_LANG", "en")
        .args(["check-shader", example("basic_lighting.frag").to_str().unwrap(), "--model", "basic_lighting"])
        .env("LD_LIBRARY_PATH", dir.path())
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{err}");
    assert!(err.contains("no OpenGL context"), "{err}");
}

#[test]
fn blinn_phong_agrees_with_its_model_and_phong_does_not() {
    if !gl_available() {
        return;
    }
    let (code, out, _) = check(&example("blinn_phong.frag"), "blinn_phong", &[]);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("verdict: AGREES") && out.contains("0 beyond the bound"), "{out}");
    // The Phong shader is the same but for the specular lobe: it must be told apart.
    let (code, out, _) = check(&example("basic_lighting.frag"), "blinn_phong", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("verdict: DISAGREES"), "{out}");
    // And the other way round.
    let (code, out, _) = check(&example("blinn_phong.frag"), "basic_lighting", &[]);
    assert_eq!(code, 1, "{out}");
}

/// The shipped spot bug disagrees only because of its cut-offs: it hard-codes them instead of
/// declaring uniforms, so they are fixed to the chapter's cosines (the note says so), and with
/// the cosines typed in it agrees. (Fixing
/// the model's cut-offs to the degrees through `[values]` does not make it agree: the model
/// validates the cone, and 12.5 > 1 is no cosine.)
#[test]
fn the_spot_degrees_bug_disagrees_only_through_its_cut_offs() {
    if !gl_available() {
        return;
    }
    let file = example("bug_spot_degrees.frag");
    let (code, out, _) = check(&file, "spot", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("note: light.cutOff is not declared by the shader: fixed to the chapter's 0.976296"), "{out}");
    assert!(out.contains("(not declared) light.outerCutOff = 0.95371693"), "{out}");
    let source = std::fs::read_to_string(&file).unwrap();
    let fixed = source
        .replace("const float cutOff = 12.5;", "const float cutOff = cos(radians(12.5));")
        .replace("const float outerCutOff = 17.5;", "const float outerCutOff = cos(radians(17.5));");
    assert_ne!(fixed, source);
    let (code, out, _) = check(&temp_file("spot_cosines.frag", &fixed), "spot", &[]);
    assert_eq!(code, 0, "{out}");
}

/// `[values]` may fix a quantity the shader declares (its uniform receives the value), and a
/// quantity the chapter gives no value stays random when undeclared, with a note.
#[test]
fn values_fix_declared_quantities_and_undeclared_ones_follow_one_policy() {
    if !gl_available() {
        return;
    }
    let shader = example("basic_lighting.frag");
    let white = temp_file("white.toml", "[values]\nlightColor = [1.0, 1.0, 1.0]\n");
    let (code, out, _) = check(&shader, "basic_lighting", &["--uniforms", white.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}");
    assert!(
        out.contains("lightColor fixed to [1.0, 1.0, 1.0] by the mapping (the shader's uniform receives it)"),
        "{out}"
    );
    // Hard-code the chapter's coral: objectColor has no chapter value in the model, so it
    // stays random (and the shader disagrees) until [values] gives the shader's colour.
    let source = std::fs::read_to_string(&shader).unwrap();
    let coral = source.replace("uniform vec3 objectColor;", "const vec3 objectColor = vec3(1.0, 0.5, 0.31);");
    let coral = temp_file("coral.frag", &coral);
    let (code, out, _) = check(&coral, "basic_lighting", &[]);
    assert_eq!(code, 1, "{out}");
    assert!(
        out.contains("objectColor is not declared by the shader and the chapter gives it no value: it stays random"),
        "{out}"
    );
    let values = temp_file("coral.toml", "[values]\nobjectColor = [1.0, 0.5, 0.31]\n");
    let (code, out, _) = check(&coral, "basic_lighting", &["--uniforms", values.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}");
}

/// A loop that never ends is reported as not terminating by `check-shader`, `exercise
/// check` and `grade`, never graded: llvmpipe ends every loop after 65 535 iterations, so
/// before the loop guard this shader scored "agrees, 100". A loop that ends under the cap
/// still agrees.
#[test]
fn a_loop_that_reaches_the_cap_does_not_terminate_everywhere() {
    if !gl_available() {
        return;
    }
    let spin = "float k = 1.0;\n    while (k > 0.0) k += 1.0;\n    FragColor = 0.0 * k + vec4(";
    let endless = temp_file("spin.frag", &basic_lighting_with("FragColor = vec4(", spin));
    let (code, out, _) = check(&endless, "basic_lighting", &[]);
    assert_eq!(code, 1, "{out}");
    let every = format!("{CASES} of {CASES} cases");
    assert!(out.contains("verdict: DOES NOT TERMINATE") && out.contains(&every), "{out}");

    // 5·10⁴ iterations, under the cap of 6·10⁴ (src/checker/check/loops.rs LOOP_CAP).
    let long = "float k = 0.0;\n    for (int i = 0; i < 50000; i++) k += 1.0;\n    FragColor = 0.0 * k + vec4(";
    let finite = temp_file("long.frag", &basic_lighting_with("FragColor = vec4(", long));
    let (code, out, _) = check(&finite, "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}");

    let file = endless.to_str().unwrap();
    let (code, out, _) =
        lightlab(&["exercise", "check", "basic-move-light", file, "--cases", "300", "--format", "json"]);
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["verdict"], "does not terminate", "{out}");

    let class = endless.parent().unwrap().join("class-spin");
    let _ = std::fs::remove_dir_all(&class);
    std::fs::create_dir_all(&class).unwrap();
    std::fs::copy(&endless, class.join("alice.frag")).unwrap();
    std::fs::copy(&finite, class.join("bob.frag")).unwrap();
    let dir = class.to_str().unwrap();
    let (_, csv, err) = lightlab(&["grade", dir, "--exercise", "basic-move-light", "--cases", "300"]);
    assert!(csv.contains("alice.frag,does not terminate,0,"), "{csv}\n{err}");
    assert!(csv.contains("bob.frag,agrees,100,"), "{csv}\n{err}");
}

/// The same for a vertex + fragment pair: a loop that never ends in the vertex shader (one
/// case of the vertex stage per vertex) or in the fragment shader is reported as not
/// terminating by `check-shader --vertex`, `exercise check --vertex` and `grade` of a pair
/// exercise, never graded.
#[test]
fn a_pair_whose_loop_reaches_the_cap_does_not_terminate_everywhere() {
    if !gl_available() {
        return;
    }
    let read = |name: &str| std::fs::read_to_string(example(name)).unwrap();
    let colour = "    LightingColor = ambient + diffuse + specular;";
    let spin = "    float k = 1.0;\n    while (k > 0.0) k += 1.0;\n    LightingColor = 0.0 * k + ambient + diffuse + specular;";
    assert!(read("gouraud.vert").contains(colour));
    let endless_vertex = temp_file("spin.vert", &read("gouraud.vert").replacen(colour, spin, 1));
    let fragment = example("gouraud.frag");
    let vertex_arg = endless_vertex.to_str().unwrap();
    // 300 triangles: 900 vertices of 6·10⁴ iterations each
    let pair = |fragment: &Path, vertex: &str| {
        let fragment = fragment.to_str().unwrap();
        lightlab(&["check-shader", fragment, "--vertex", vertex, "--model", "gouraud", "--cases", "300"])
    };
    let (code, out, _) = pair(&fragment, vertex_arg);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("verdict: DOES NOT TERMINATE") && out.contains("300 of 300 cases"), "{out}");

    // the loop in the fragment shader of the pair
    let frag = read("gouraud.frag");
    let write = "    FragColor = vec4(LightingColor * objectColor, 1.0);";
    assert!(frag.contains(write));
    let looped = "    float k = 1.0;\n    while (k > 0.0) k += 1.0;\n    FragColor = 0.0 * k + vec4(LightingColor * objectColor, 1.0);";
    let endless_fragment = temp_file("spin-pair.frag", &frag.replacen(write, looped, 1));
    let (code, out, _) = pair(&endless_fragment, example("gouraud.vert").to_str().unwrap());
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("verdict: DOES NOT TERMINATE"), "{out}");

    let file = fragment.to_str().unwrap();
    let args = ["exercise", "check", "basic-gouraud-pair", file, "--vertex", vertex_arg, "--cases", "300"];
    let (code, out, _) = lightlab(&[&args[..], &["--format", "json"]].concat());
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["verdict"], "does not terminate", "{out}");

    let class = endless_vertex.parent().unwrap().join(format!("class-spin-pair-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&class);
    std::fs::create_dir_all(&class).unwrap();
    std::fs::copy(&fragment, class.join("alice.frag")).unwrap();
    std::fs::copy(&endless_vertex, class.join("alice.vert")).unwrap();
    std::fs::copy(&fragment, class.join("bob.frag")).unwrap();
    std::fs::copy(example("gouraud.vert"), class.join("bob.vert")).unwrap();
    let dir = class.to_str().unwrap();
    let (_, csv, err) = lightlab(&["grade", dir, "--exercise", "basic-gouraud-pair", "--cases", "300"]);
    let row = |who: &str| csv.lines().find(|l| l.starts_with(who)).unwrap_or_default().to_string();
    assert!(row("alice").contains(",does not terminate,0,"), "{csv}\n{err}");
    assert!(row("bob").contains(",agrees,100,"), "{csv}\n{err}");
    let _ = std::fs::remove_dir_all(&class);
}

/// Red-team finding: `#extension` must come before any code, and the rewrite put its own
/// declarations first, so a correct shader with an `#extension` line was an internal error
/// (exit 3) whose message carried lightlab's whole rewritten text. Now the line moves in
/// front of the batch's declarations, for a fragment shader alone and for a pair.
#[test]
fn a_shader_with_an_extension_line_is_checked() {
    if !gl_available() {
        return;
    }
    let ext = "#version 330 core\n#extension GL_ARB_gpu_shader5 : enable";
    let src = basic_lighting_with("#version 330 core", ext);
    assert!(src.contains("GL_ARB_gpu_shader5"), "the example starts with its #version line");
    let (code, out, err) = check(&temp_file("extension.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("verdict: AGREES"), "{out}");
    let with_ext = |name: &str| {
        let text = std::fs::read_to_string(example(name)).unwrap().replacen("#version 330 core", ext, 1);
        assert!(text.contains("GL_ARB_gpu_shader5"), "{name} starts with its #version line");
        temp_file(name, &text)
    };
    let (frag, vert) = (with_ext("gouraud.frag"), with_ext("gouraud.vert"));
    let (code, out, err) = check(&frag, "gouraud", &["--vertex", vert.to_str().unwrap()]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(
        !out.contains("lightlab_sample") && !err.contains("lightlab_sample"),
        "no rewritten text shown: {out}{err}"
    );
}

/// Red-team finding 15: `#version 460 core` (editors' templates) does not compile on
/// Mesa llvmpipe; the verdict says which versions it reads, not only Mesa's list.
#[test]
fn a_shader_for_glsl_460_is_told_which_version_to_write() {
    if !gl_available() {
        return;
    }
    let src = basic_lighting_with("#version 330 core", "#version 460 core");
    let (code, out, err) = check(&temp_file("v460.frag", &src), "basic_lighting", &[]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("DOES NOT COMPILE") && out.contains("GLSL up to 4.50"), "{out}{err}");
}

/// Red-team finding 10c: a shader in the chapter's own style (strengths written as
/// numbers) with one wrong term. The isolation step cannot switch those terms off, and its
/// hints said the difference was in what every term shares; now they say which terms could
/// not be switched off and why.
#[test]
fn hard_coded_strengths_are_named_as_what_the_isolation_could_not_switch_off() {
    if !gl_available() {
        return;
    }
    let src = basic_lighting_with("normalize(viewPos - FragPos)", "normalize(viewPos)");
    assert!(src.contains("float specularStrength = 0.5;"), "the example writes its strengths as numbers");
    let (code, out, err) = check(&temp_file("hard-coded.frag", &src), "basic_lighting", &["--hints"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("could not be switched off") && out.contains("the specular term"), "{out}{err}");
    assert!(!out.contains("enter every term"), "the shared-inputs hint is not given: {out}");
}

/// Declarations written through one-word macros (`#define U uniform`, `#define VEC vec3`)
/// are read as the preprocessor reads them: the shader agrees, as its expanded text does
/// (the scanner once missed the uniforms and left them at 0: "disagrees").
#[test]
fn uniforms_declared_through_macros_are_checked_as_declared() {
    if !gl_available() {
        return;
    }
    let src = std::fs::read_to_string(example("basic_lighting.frag")).unwrap();
    let src =
        src.replacen("in vec3 FragPos;", "#define U uniform\n#define VEC V3\n#define V3 vec3\nin VEC FragPos;", 1);
    let src = src.replace("uniform vec3 ", "U VEC ");
    assert_eq!(src.matches("U VEC ").count(), 4, "{src}");
    let file = temp_file("macro-declarations.frag", &src);
    let (code, out, err) = check(&file, "basic_lighting", &[]);
    assert_eq!(code, 0, "{out}{err}");
    assert!(out.contains("verdict: AGREES"), "{out}");
    for name in ["FragPos", "lightPos", "viewPos", "lightColor", "objectColor"] {
        assert!(!out.contains(&format!("{name} is not declared")), "{name} is declared through the macros:\n{out}");
    }
}

/// A shader that declares the light's position and never reads it (a constant lamp in its
/// place), in a style unlike the tutorial's: its own names mapped with `--uniforms`, the
/// uniform's name in comments and inside a longer identifier. The report says, in the
/// learner's language, that the uniform is never read; the same shader reading it agrees,
/// with no such note.
#[test]
fn a_light_position_declared_and_never_read_is_noted() {
    use lightlab::checker::texts::NOTE_NEVER_READ;
    use lightlab::i18n::{tr, Lang};
    if !gl_available() {
        return;
    }
    let ignored = "#version 330 core
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 uLamp;      // uLamp = lightPos in the C++ code; see LAMP below
uniform vec3 uEye;
uniform vec3 uLampRgb;
uniform vec3 uAlbedo;
/* the lamp stays where the tutorial's screenshot has it (uLamp not used) */
const vec3 LAMP = vec3(1.2, 1.0, 2.0);

void main()
{
    vec3 uLampDir = normalize(LAMP - FragPos);
    vec3 N = normalize(Normal);
    vec3 toEye = normalize(uEye - FragPos);
    float lambert = max(dot(N, uLampDir), 0.0);
    float phong = pow(max(dot(toEye, reflect(-uLampDir, N)), 0.0), 32.0);
    FragColor = vec4((0.1 + lambert + 0.5 * phong) * uLampRgb * uAlbedo, 1.0);
}
";
    let names =
        "[names]\nuLamp = \"lightPos\"\nuEye = \"viewPos\"\nuLampRgb = \"lightColor\"\nuAlbedo = \"objectColor\"\n";
    let map = temp_file("never_read.toml", names);
    let map_arg = map.to_str().unwrap();
    let shader = temp_file("never_read.frag", ignored);
    for (lang, code) in [(Lang::En, "en"), (Lang::Fr, "fr"), (Lang::Uk, "uk")] {
        let (status, out, err) = check(&shader, "basic_lighting", &["--uniforms", map_arg, "--lang", code]);
        assert_eq!(status, 1, "{out}{err}");
        let note = lightlab::blanks::fill(&tr(lang, NOTE_NEVER_READ), &["uLamp", "lightPos"]);
        assert!(lang == Lang::En || note != lightlab::blanks::fill(NOTE_NEVER_READ, &["uLamp", "lightPos"]), "{code}");
        assert!(out.contains(&note), "{code}: no «{note}» in\n{out}");
        // the other uniforms are read: one note of this kind
        let template = tr(lang, NOTE_NEVER_READ);
        let piece = template.split("{}").max_by_key(|p| p.len()).unwrap_or_default();
        assert_eq!(out.matches(piece).count(), 1, "{code}: «{piece}» in\n{out}");
    }
    let reads = ignored.replace("normalize(LAMP - FragPos)", "normalize(uLamp - FragPos)");
    let shader = temp_file("reads.frag", &reads);
    let (status, out, err) = check(&shader, "basic_lighting", &["--uniforms", map_arg]);
    assert_eq!(status, 0, "{out}{err}");
    assert!(!out.contains("never read"), "{out}");
}
