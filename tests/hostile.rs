//! Issue 28's replay suite: one test per reproducer of items 6 ("no silent wrong answers")
//! and 7 ("old defects"), named for what it proves. Each failed on the code before the
//! fix and passes after; they go through the command line, as the audit did.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::common;
use crate::gl_common;

use std::fs;
use std::path::{Path, PathBuf};

use common::{lightlab, lightlab_with_input};

fn temp_dir(name: &str) -> common::TempDir {
    common::temp_dir("replay", name)
}

/// `shade`'s one output line for one input line (exit status, the line as JSON).
fn shade(line: &str) -> (i32, serde_json::Value) {
    let (code, out, err) = lightlab_with_input(&["shade"], &format!("{line}\n"));
    let v = serde_json::from_str(out.trim()).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
    (code, v)
}

// ---------------------------------------------------------------------------
// Item 6: no silent wrong answers.

#[test]
fn shade_refuses_a_normal_too_short_for_f32_instead_of_two_answers() {
    // Issue 28: exit 0 with f32 rgb 0.02 against f64 rgb_f64 0.065.
    for normal in ["[0, 0, 1e-46]", "[0, 0, 1e-20]", "[1e-30, 0, 0]"] {
        let line = format!(r#"{{"model": "basic_lighting", "FragPos": [0, 0, 0], "Normal": {normal}}}"#);
        let (_, v) = shade(&line);
        assert_eq!(v["field"], "Normal", "{normal}: {v}");
        let error = v["error"].as_str().unwrap_or("");
        assert!(error.contains("has length") && error.contains("f32"), "{normal}: {v}");
        assert!(v.get("rgb").is_none(), "{normal}: an error, not a colour: {v}");
    }
    // A short normal f32 can still normalize is answered, and both paths agree.
    let (code, v) = shade(r#"{"model": "basic_lighting", "FragPos": [0, 0, 0], "Normal": [0, 0, 1e-15]}"#);
    assert_eq!(code, 0, "{v}");
    let (f32_rgb, f64_rgb) = (v["rgb"][0].as_f64().unwrap(), v["rgb_f64"][0].as_f64().unwrap());
    // 1e-5: a few f32 ulps of a value below 2 (the shade tests' own bound is tighter).
    assert!((f32_rgb - f64_rgb).abs() < 1e-5, "{v}");
}

#[test]
fn shade_refuses_a_light_direction_too_short_for_f32() {
    // Issue 28: a direction of [0, 0, -1e-100] gave two different colours.
    let line = r#"{"frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3], "material": {"name": "emerald"}, "lights": [{"kind": "directional", "direction": [0, 0, -1e-100], "ambient": [0.05, 0.05, 0.05], "diffuse": [0.4, 0.4, 0.4], "specular": [0.5, 0.5, 0.5]}]}"#;
    let (_, v) = shade(line);
    assert_eq!(v["field"], "lights[0].direction", "{v}");
    assert!(v["error"].as_str().unwrap_or("").contains("has length 1e-100"), "{v}");
    let ogldev = r#"{"model": "ogldev", "frag_pos": [0, 0, 0], "normal": [0, 0, 1], "view_pos": [0, 0, 3], "direction": [0, 0, -1e-100]}"#;
    let (_, v) = shade(ogldev);
    assert_eq!(v["field"], "direction", "{v}");
}

/// A basic-lighting shader that agrees with the model (the example class's right answer).
fn right_shader(dir: &Path) -> PathBuf {
    let file = dir.join("right.frag");
    fs::write(&file, common::example_shader("basic_lighting.frag")).unwrap();
    file
}

#[test]
fn a_float_value_given_as_an_array_is_an_error_naming_key_and_line() {
    // Issue 28: `shininess = [1,2,3]` was accepted and its first element used.
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("values-array");
    let shader = right_shader(&dir);
    let mapping = dir.join("m.toml");
    fs::write(&mapping, "# a teacher's values\n[values]\nshininess = [1, 2, 3]\n").unwrap();
    let (s, m) = (shader.to_str().unwrap(), mapping.to_str().unwrap());
    let check = || lightlab(&["check-shader", s, "--model", "basic_lighting", "--uniforms", m, "--cases", "100"]);
    let (code, out, err) = check();
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("line 3") && err.contains("values.shininess"), "{err}");
    // One number is still accepted.
    fs::write(&mapping, "[values]\nshininess = 32\n").unwrap();
    let (code, out, err) = check();
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn cases_above_the_documented_maximum_are_a_usage_error_everywhere() {
    // Issue 28: `exercise export --cases 4294967296` printed `"models": {}` and exited 0;
    // 10^6 aborted at 4 GB. No OpenGL is needed: clap refuses before anything runs.
    let dir = temp_dir("cases");
    let shader = right_shader(&dir);
    let f = shader.to_str().unwrap();
    let commands: [Vec<&str>; 6] = [
        vec!["exercise", "export", "--cases", "4294967296"],
        vec!["exercise", "export", "--cases", "1000000"],
        vec!["exercise", "check", "basic-move-light", f, "--cases", "1000001"],
        vec!["check-shader", f, "--model", "basic_lighting", "--cases", "1000001"],
        vec!["oracle", "--cases", "1000001"],
        vec!["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--cases", "1000001"],
    ];
    for args in commands {
        let (code, out, err) = lightlab(&args);
        assert_eq!(code, 2, "{args:?}: {out}{err}");
        assert!(err.contains("--cases") && err.contains("1.."), "{args:?}: {err}");
        assert!(out.is_empty(), "{args:?}: nothing printed: {out}");
    }
    let (code, _, err) = lightlab(&["exercise", "export", "--cases", "0"]);
    assert_eq!(code, 2, "{err}");
}

#[test]
fn json_calls_a_compile_error_does_not_compile_not_disagrees() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("json-compile");
    let file = dir.join("broken.frag");
    fs::write(&file, format!("{}void main() {{ FragColor = vec4(lightColor 1.0); }}\n", common::BASIC_LIGHTING_HEAD))
        .unwrap();
    let f = file.to_str().unwrap();
    for args in [
        vec!["check-shader", f, "--model", "basic_lighting", "--cases", "100", "--format", "json"],
        vec!["exercise", "check", "basic-move-light", f, "--cases", "100", "--format", "json"],
    ] {
        let (code, out, err) = lightlab(&args);
        assert_eq!(code, 1, "{args:?}: {out}{err}");
        let v: serde_json::Value = serde_json::from_str(out.trim()).expect("one JSON object");
        assert_eq!(v["verdict"], "does not compile", "{args:?}: {out}");
        assert!(v["compile_error"]["log"].as_str().is_some_and(|l| !l.is_empty()), "{out}");
        let (_, text, _) = lightlab(&args[..args.len() - 2]);
        assert!(text.contains("verdict: DOES NOT COMPILE"), "the text output names it so: {text}");
    }
}

#[test]
fn nan_and_inf_answers_are_not_a_number_on_the_command_line_as_in_the_page() {
    // Issue 28: "too low" / "too high" on the CLI, "not a number" in the page (whose rule
    // is `isFinite`, lightlab-exercise.js answerVerdict).
    let dir = temp_dir("nan");
    for token in ["nan", "NaN", "inf", "-inf", "infinity", "1e999"] {
        let file = dir.join("answer.txt");
        fs::write(&file, format!("{token}\n")).unwrap();
        let (code, out, err) = lightlab(&["exercise", "check", "own-attenuation-half", file.to_str().unwrap()]);
        assert_eq!(code, 2, "{token}: {out}{err}");
        assert!(err.contains("is not a number"), "{token}: {err}");
        assert!(!out.contains("too low") && !out.contains("too high"), "{token}: {out}");
    }
}

/// A copy of the book (with the crate sources its chapters include) in `dir`; returns its
/// root (the folder holding `book.toml`).
fn copy_book(dir: &Path) -> PathBuf {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    for sub in ["src", "examples", "po", "book"] {
        common::copy_book_tree(&crate_dir.join(sub), &dir.join(sub));
    }
    dir.join("book")
}

#[test]
fn the_book_draws_the_study_csvs_on_disk_and_names_a_missing_one() {
    // Issue 28: after `lightlab study` rewrote the CSVs, `lightlab --force` drew the old
    // charts (compiled in with include_str!).
    let dir = temp_dir("book-csv");
    let root = copy_book(&dir);
    let csv = root.join("data/study/sphere-multi.csv");
    let text = fs::read_to_string(&csv).unwrap();
    let cpu = text.lines().next().unwrap().to_owned();
    assert!(cpu.starts_with("# cpu: "), "{cpu}");
    fs::write(&csv, text.replacen(&cpu, "# cpu: Replayed CPU 9000", 1)).unwrap();
    let r = root.to_str().unwrap();
    let (code, out, err) = lightlab(&["book", "--force", "-q", "--root", r]);
    assert_eq!(code, 0, "{out}{err}");
    let machine = fs::read_to_string(root.join("src/generated/tables/study-machine.md")).unwrap();
    assert!(machine.contains("Replayed CPU 9000"), "the table shows the CSV on disk:\n{machine}");

    fs::remove_file(&csv).unwrap();
    let (code, out, err) = lightlab(&["book", "-q", "--root", r]);
    assert_ne!(code, 0, "{out}{err}");
    assert!(err.contains("data/study/sphere-multi.csv"), "the error names the file: {err}");
}

// ---------------------------------------------------------------------------
// Item 7: old defects.

/// A scene file of `n` tori at `detail`.
fn tori(n: usize, detail: u32) -> String {
    let mut s = String::from("shading = \"phong\"\n");
    for i in 0..n {
        s += &format!("\n[[object]]\nmesh = \"torus\"\ndetail = {detail}\ntranslate = [{}.0, 0.0, 0.0]\n", i % 7);
    }
    s
}

#[test]
fn a_scene_of_200_fine_tori_is_refused_up_front_naming_object_and_line() {
    // Issue 28: 200 tori at detail 1024 aborted at 2.6 GB (exit 134).
    let dir = temp_dir("tori");
    let scene = dir.join("tori.toml");
    fs::write(&scene, tori(200, 1024)).unwrap();
    let out = dir.join("out.png");
    let started = std::time::Instant::now();
    let (code, stdout, err) =
        lightlab(&["render", "--scene", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--size", "64x48"]);
    assert_eq!(code, 2, "{stdout}{err}");
    // object[4] is the first past 2^22 triangles (each torus at 1024 has 1 048 576).
    assert!(err.contains("object[4].detail") && err.contains("line ") && err.contains("triangles"), "{err}");
    // Up front: refused in far less than making one mesh of this scene would take.
    assert!(started.elapsed().as_secs() < 10, "{:?}", started.elapsed());
    assert!(!out.exists());
    // Four fit.
    fs::write(&scene, tori(4, 1024)).unwrap();
    let (code, _, err) =
        lightlab(&["render", "--scene", scene.to_str().unwrap(), "-o", out.to_str().unwrap(), "--size", "64x48"]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn a_scene_of_too_many_objects_is_refused_naming_the_count() {
    let dir = temp_dir("many");
    let scene = dir.join("many.toml");
    let mut text = String::new();
    for _ in 0..1025 {
        text += "[[object]]\nmesh = \"cube\"\n";
    }
    fs::write(&scene, text).unwrap();
    let out = dir.join("out.png");
    let (code, _, err) = lightlab(&["render", "--scene", scene.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("1025") && err.contains("1024") && err.contains("object"), "{err}");
}

#[test]
fn a_regular_file_at_book_build_is_refused_before_building() {
    // Issue 28: the new book rendered, then exit 3 and a `.build-old-PID` left behind.
    let dir = temp_dir("build-file");
    let root = copy_book(&dir);
    fs::write(root.join("build"), "not a folder").unwrap();
    let (code, out, err) = lightlab(&["book", "-q", "--root", root.to_str().unwrap()]);
    assert_eq!(code, 2, "a user error: {out}{err}");
    assert!(err.contains("build") && err.contains("not a directory"), "{err}");
    assert!(!root.join("src/generated").exists(), "refused before any work");
    let left: Vec<String> = fs::read_dir(&root)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(".build-"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    assert_eq!(fs::read_to_string(root.join("build")).unwrap(), "not a folder");
}

#[test]
fn a_missing_include_fails_the_build_naming_chapter_and_path() {
    // Issue 28: mdBook printed an ERROR and the build exited 0.
    let dir = temp_dir("include");
    let root = copy_book(&dir);
    let chapter = root.join("src/03-materials.md");
    let mut text = fs::read_to_string(&chapter).unwrap();
    text += "\n{{#include ../../examples/no_such_example.rs}}\n";
    fs::write(&chapter, text).unwrap();
    let (code, out, err) = lightlab(&["book", "-q", "--root", root.to_str().unwrap()]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("03-materials.md") && err.contains("no_such_example.rs"), "{err}");
    assert!(!root.join("build").exists(), "no book installed");
}

#[test]
fn bench_save_errors_name_the_path() {
    let dir = temp_dir("bench-save");
    let file = dir.join("a-file");
    fs::write(&file, "x").unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) = lightlab(&["bench", "quad-single", "--runs", "1", "--frames", "1", "--save", f]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains(f), "{err}");
    assert!(out.is_empty(), "checked before the first scene: {out}");
}

#[test]
fn bench_csv_is_checked_before_the_work() {
    let dir = temp_dir("bench-csv");
    let csv = dir.join("no-such-dir").join("roofline.csv");
    let c = csv.to_str().unwrap();
    let (code, out, err) =
        lightlab(&["bench", "quad-single", "--runs", "1", "--frames", "1", "--roofline", "--csv", c]);
    assert_eq!(code, 2, "{out}{err}");
    // outfile names the missing directory
    assert!(err.contains(csv.parent().unwrap().to_str().unwrap()), "{c}: {err}");
    assert!(out.is_empty(), "no scene measured before the refusal: {out}");
}

#[test]
fn study_outputs_are_checked_before_the_work() {
    let dir = temp_dir("study-out");
    // A folder where the first CSV goes: unwritable as a file.
    fs::create_dir_all(dir.join("sphere-multi.csv")).unwrap();
    let (code, out, err) = lightlab(&["study", "--quick", "--out", dir.to_str().unwrap()]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("sphere-multi.csv"), "{err}");
    assert!(!err.contains(" s]  1."), "refused before the first step of the study: {err}");
}

#[test]
fn render_output_is_checked_before_drawing() {
    let dir = temp_dir("render-out");
    // Two planes at the finest detail (4.2 M triangles, inside the budget) on the largest
    // frame: making and drawing them took 4.1 s here before the output was checked.
    let scene = dir.join("planes.toml");
    fs::write(&scene, "[[object]]\nmesh = \"plane\"\ndetail = 1024\n\n[[object]]\nmesh = \"plane\"\ndetail = 1024\n")
        .unwrap();
    let out = dir.join("no-such-dir").join("out.png");
    let o = out.to_str().unwrap();
    let started = std::time::Instant::now();
    let (code, _, err) = lightlab(&["render", "--scene", scene.to_str().unwrap(), "-o", o, "--size", "8192x8192"]);
    // 2 s: half the 4.1 s the drawing took; the check alone takes milliseconds.
    assert!(started.elapsed().as_secs_f64() < 2.0, "refused before drawing: {:?}", started.elapsed());
    assert_eq!(code, 2, "{err}");
    assert!(err.contains(out.parent().unwrap().to_str().unwrap()), "{o}: {err}");
}

// ---------------------------------------------------------------------------
// Leftovers.

#[test]
fn running_out_of_memory_has_its_own_exit_status() {
    // Issue 28: a child out of memory exited 1, like a wrong shader; now 4 (README's table).
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("oom-status");
    let file = dir.join("huge.frag");
    fs::write(&file, common::huge_array(4_000_000)).unwrap();
    let f = file.to_str().unwrap();
    let (code, out, err) =
        lightlab(&["check-shader", f, "--model", "basic_lighting", "--memory", "512", "--timeout", "60"]);
    assert_eq!(code, 4, "{out}{err}");
    assert!(out.contains("verdict: RAN OUT OF MEMORY"), "{out}");
    let (_, help, _) = lightlab(&["check-shader", "--help"]);
    assert!(help.contains("4  a checked shader ran out of memory"), "--help documents it:\n{help}");
}

#[test]
fn a_malformed_study_csv_is_a_user_error_naming_the_file() {
    let dir = temp_dir("book-bad-csv");
    let root = copy_book(&dir);
    let csv = root.join("data/bench/scaling.csv");
    let mut text = fs::read_to_string(&csv).unwrap();
    text += "lights,oops,not,a,row\n";
    fs::write(&csv, text).unwrap();
    let (code, out, err) = lightlab(&["book", "-q", "--root", root.to_str().unwrap()]);
    assert_eq!(code, 2, "a user error, not an internal one: {out}{err}");
    assert!(err.contains("data/bench/scaling.csv") && !err.contains("please report"), "{err}");
    assert!(!root.join("src/generated").exists(), "refused before generating");
}
