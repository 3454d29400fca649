//! `lightlab check-shader` end to end: the binary on the shipped example shaders.
//!
//! - the correct shaders pass (exit 0);
//! - the two classic bugs are caught (exit 1) with a counterexample: specular from
//!   `reflect(lightDir, norm)`, and the normal moved by `mat3(model)` under non-uniform scale;
//! - usage errors exit 2 and name what is wrong; a compile error exits 1 with the file's line.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

mod gl_common;

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
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab")).args(args).output().expect("run lightlab");
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

fn temp_file(name: &str, text: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("lightlab-{}-{name}", std::process::id()));
    std::fs::write(&path, text).unwrap();
    path
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
    format!("#version 330 core\n{}\n{}", lightlab::gl::models::MULTIPLE_LIGHTS.functions, main.replace("WHICH", which))
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
        assert!(first.contains(&format!("| {model} | 2000 |")), "{model} row");
    }
    let (_, second, _) = lightlab(&args);
    assert_eq!(first, second, "deterministic output");
    let (code, _, _) = lightlab(&["oracle", "--cases", "0"]);
    assert_eq!(code, 2);
}
