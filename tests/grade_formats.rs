//! `lightlab grade`'s formats against the platforms' published fields, and a hostile
//! class folder graded without reading outside it.
//!
//! The fields checked come from Gradescope's "Autograder Specifications"
//! (gradescope-autograders.readthedocs.io/en/latest/specs/) and PrairieLearn's
//! `docs/externalGrading.md`; the module docs of `lightlab::cli::grade::formats` quote
//! them. Tests that need OpenGL print why and pass without it, unless
//! `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::common;
use crate::gl_common;

use common::{example_shader, lightlab};

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

const BIN: &str = env!("CARGO_BIN_EXE_lightlab");

fn temp_dir(name: &str) -> common::TempDir {
    common::temp_dir("formats", name)
}

fn example(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/class").join(name)
}

/// Cases per check: 2000 random cases find Blinn-Phong's and a reversed view direction's
/// differences on more than 100 of them (the example class's CSV), far from chance.
const CASES: &str = "2000";

fn grade(dir: &Path, extra: &[&str]) -> (i32, String, String) {
    let mut args = vec!["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--cases", CASES];
    args.extend_from_slice(extra);
    lightlab(&args)
}

#[test]
fn gradescope_results_have_the_specified_fields_and_values() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("gradescope");
    std::fs::write(dir.join("bob.frag"), example_shader("blinn_phong.frag")).unwrap();
    let (code, out, err) = grade(&dir, &["--format", "gradescope"]);
    assert_eq!(code, 1, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    assert!(v["score"].is_number() && v["execution_time"].is_number(), "{v}");
    // The feedback page is the submission's output, in HTML with the picture inside.
    assert_eq!(v["output_format"], "html");
    let page = v["output"].as_str().expect("output is a string");
    assert!(page.contains("<img src=\"data:image/png;base64,iVBORw0KGgo"), "a PNG data URL in the page: {page:.300}");
    assert!(page.contains("blinn-for-phong") && page.contains("A case where it differs:"), "{page:.2000}");
    assert!(["text", "html", "simple_format", "md", "ansi"].contains(&v["test_output_format"].as_str().unwrap()));
    let tests = v["tests"].as_array().expect("tests[]");
    assert_eq!(tests.len(), 1);
    for t in tests {
        assert!(t["name"].is_string() && t["output"].is_string(), "{t}");
        assert!(["text", "html", "simple_format", "md", "ansi"].contains(&t["output_format"].as_str().unwrap()), "{t}");
        let (score, max) = (t["score"].as_f64().unwrap(), t["max_score"].as_f64().unwrap());
        assert!((0.0..=max).contains(&score), "{t}");
        assert!(["passed", "failed"].contains(&t["status"].as_str().unwrap()), "{t}");
        assert!(["hidden", "after_due_date", "after_published", "visible"].contains(&t["visibility"].as_str().unwrap()));
    }
    assert_eq!(tests[0]["status"], "failed");
    assert!(tests[0]["output"].as_str().unwrap().contains("Blinn-Phong"), "the mistake is named: {v}");
    // The platform runs once per submission: a folder of two gets a score of 0 and a
    // message for the student (exit status 1), and a warning for the teacher.
    std::fs::write(dir.join("alice.frag"), example_shader("basic_lighting.frag")).unwrap();
    let (code, out, err) = grade(&dir, &["--format", "gradescope"]);
    assert_eq!(code, 1);
    assert!(err.contains("grades one submission") && err.contains("alice.frag, bob.frag"), "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["score"], 0.0, "{v}");
}

#[test]
fn prairielearn_scores_in_unit_range_and_a_compile_error_is_not_gradable() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("prairielearn");
    let file = dir.join("answer.frag");
    for (text, want) in [(example_shader("basic_lighting.frag"), Some(1.0)), (example_shader("blinn_phong.frag"), None)]
    {
        std::fs::write(&file, text).unwrap();
        let (_, out, err) = grade(&dir, &["--format", "prairielearn"]);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}{err}"));
        assert_eq!(v["gradable"], true);
        let score = v["score"].as_f64().unwrap();
        assert!((0.0..=1.0).contains(&score), "{v}");
        match want {
            Some(w) => assert_eq!(score, w),
            None => assert!(score < 1.0),
        }
        let url = v["tests"][0]["images"][0]["url"].as_str().unwrap_or("");
        assert!(url.starts_with("data:image/png;base64,iVBORw0KGgo"), "a PNG data URL: {}", &url[..url.len().min(40)]);
        for t in v["tests"].as_array().unwrap() {
            assert!(t["name"].is_string() && t["points"].is_number() && t["max_points"].is_number(), "{t}");
        }
        assert!(v["message"].is_string());
    }
    for bad in ["#version 330 core\nvoid main() { oops }\n", ""] {
        std::fs::write(&file, bad).unwrap();
        let (_, out, _) = grade(&dir, &["--format", "prairielearn"]);
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["gradable"], false, "{v}");
        assert!(!v["format_errors"].as_array().unwrap().is_empty(), "{v}");
    }
}

/// Splits a CSV line with no line breaks in its cells into its raw fields (quotes kept).
fn raw_fields(line: &str) -> Vec<&str> {
    let (mut out, mut start, mut quoted) = (Vec::new(), 0, false);
    for (i, c) in line.char_indices() {
        match c {
            '"' => quoted = !quoted,
            ',' if !quoted => {
                out.push(&line[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&line[start..]);
    out
}

#[test]
fn a_ukrainian_moodle_worksheet_changes_only_in_its_grade_and_feedback_cells() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let sheet = example("moodle-worksheet-uk.csv");
    let before = std::fs::read_to_string(&sheet).unwrap();
    let dir = temp_dir("moodle");
    let out = dir.join("filled.csv");
    // No --lang: the worksheet's Ukrainian header makes the class's language Ukrainian.
    let (code, _, err) = lightlab(&[
        "grade",
        example("submissions").to_str().unwrap(),
        "--exercise",
        "basic-move-light",
        "--cases",
        CASES,
        "--format",
        "moodle",
        "--worksheet",
        sheet.to_str().unwrap(),
        "--map",
        example("map.csv").to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("немає рядка") && err.contains("frank"), "unmatched students are named: {err}");
    let after = std::fs::read_to_string(&out).unwrap();
    assert!(after.starts_with('\u{feff}'), "the byte-order mark stays");
    let (b, a): (Vec<&str>, Vec<&str>) =
        (before.split_inclusive('\n').collect(), after.split_inclusive('\n').collect());
    assert_eq!(a.len(), b.len());
    assert_eq!(a[0], b[0], "the header row is byte for byte the same");
    // Columns 4 and 9 (0-based) are Moodle's Ukrainian "Оцінка" (gradenoun) and
    // "Відгук - коментарем" (assignfeedback_comments pluginname) in the header.
    let header = raw_fields(b[0].trim_end());
    assert!(header[4].contains("Оцінка") && header[9].contains("Відгук - коментарем"), "{header:?}");
    for (k, (la, lb)) in a.iter().zip(&b).enumerate().skip(1) {
        let (fa, fb) = (raw_fields(la.trim_end_matches('\n')), raw_fields(lb.trim_end_matches('\n')));
        assert_eq!(fa.len(), fb.len(), "line {k}");
        for (c, (x, y)) in fa.iter().zip(&fb).enumerate() {
            if c != 4 && c != 9 {
                assert_eq!(x.as_bytes(), y.as_bytes(), "line {k} column {c}");
            }
        }
        assert!(la.ends_with('\n') == lb.ends_with('\n'));
    }
    let rows: Vec<Vec<&str>> = a[1..].iter().map(|l| raw_fields(l.trim_end())).collect();
    // alice agrees: 100; bob's Blinn-Phong is named in the feedback, whose words are the
    // class's language (the verdict was English around a Ukrainian explanation).
    assert_eq!(rows[0][4], "100");
    assert!(rows[0][9].contains("basic-move-light: узгоджується (100/100)"), "{:?}", rows[0]);
    assert!(rows[1][9].contains("Blinn-Phong") && rows[1][9].contains(": не узгоджується ("), "{:?}", rows[1]);
    assert!(!after.contains("agrees"), "no English verdict in a Ukrainian worksheet: {after}");
}

fn endless_shader() -> String {
    // As in grade_cli.rs: llvmpipe ends any loop after 65 535 iterations, so the body is
    // 256 dependent `sin`s: about 1.7·10⁷ per fragment, far beyond the 5 s limit below.
    let body = "        x = sin(x + FragPos.x);\n".repeat(256);
    format!(
        "#version 330 core\nin vec3 FragPos;\nin vec3 Normal;\nout vec4 FragColor;\nuniform vec3 lightPos;\n\
         uniform vec3 viewPos;\nuniform vec3 lightColor;\nuniform vec3 objectColor;\nvoid main()\n{{\n    float x = 0.0;\n\
         while (true) {{\n{body}        if (x > 2.0) break;\n    }}\n    FragColor = vec4(x * lightColor * objectColor, 1.0);\n}}\n"
    )
}

/// Macros that double 34 times: 2^34 terms, far beyond any memory limit (issue 28's
/// reproducer grew a child to 3.9 GB in 60 s).
fn macro_bomb() -> String {
    let mut s = String::from(
        "#version 330 core\nin vec3 FragPos;\nin vec3 Normal;\nout vec4 FragColor;\n#define X0 (FragPos.x)\n",
    );
    for i in 1..=34 {
        s += &format!("#define X{i} (X{} + X{})\n", i - 1, i - 1);
    }
    s + "void main() { FragColor = vec4(X34); }\n"
}

#[test]
fn a_hostile_class_grades_one_row_per_submission_without_reading_outside() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("hostile");
    std::fs::write(dir.join("alice.frag"), example_shader("basic_lighting.frag")).unwrap();
    std::fs::write(dir.join("carol.frag"), example_shader("basic_lighting.frag")).unwrap();
    std::fs::write(dir.join("carol.vert"), example_shader("basic_lighting.vert")).unwrap();
    std::fs::create_dir(dir.join("dave")).unwrap();
    std::fs::write(dir.join("dave/lighting.frag"), example_shader("bug_reflect_sign.frag")).unwrap();
    std::fs::write(dir.join("endless.frag"), endless_shader()).unwrap();
    std::fs::write(dir.join("bomb.frag"), macro_bomb()).unwrap();
    std::fs::write(dir.join("empty.frag"), "").unwrap();
    std::fs::write(dir.join("README.txt"), "the class\n").unwrap();
    std::fs::write(dir.join("=HYPERLINK(1).frag"), example_shader("blinn_phong.frag")).unwrap();
    let bom_crlf = format!("\u{feff}{}", example_shader("basic_lighting.frag").replace('\n', "\r\n"));
    std::fs::write(dir.join("erin.frag"), bom_crlf).unwrap();
    std::os::unix::fs::symlink("/etc/passwd", dir.join("mallory.frag")).unwrap();
    assert!(Command::new("mkfifo").arg(dir.join("pipe.frag")).status().unwrap().success());
    let started = Instant::now();
    let out = dir.join("out.csv");
    // --memory 1024: a check of 2000 cases reserves about 620 MB of address space here
    // (child.rs, DEFAULT_MEMORY_MB), and the bomb reaches 1024 MB in under a second on a
    // quiet machine where it needs about 4.5 s to reach the default 2048 (measured). With
    // --timeout 5 it still hit the time limit first when two builds loaded both cores (CI,
    // 2026-11-25), so the limit is 20 s: room for a 20-fold slowdown, and the endless loop
    // still meets the time limit alone.
    let (code, _, err) = grade(&dir, &["--timeout", "20", "--memory", "1024", "-o", out.to_str().unwrap()]);
    println!("hostile class: {:.1} s", started.elapsed().as_secs_f64());
    assert_eq!(code, 1, "{err}");
    let csv = std::fs::read_to_string(&out).unwrap();
    let rows: Vec<&str> = csv.lines().skip(1).collect();
    let row = |name: &str| *rows.iter().find(|r| r.starts_with(name)).unwrap_or_else(|| panic!("{name}:\n{csv}"));
    // alice, =HYPERLINK, bomb, carol (pair), dave/, empty, endless, erin, mallory, pipe.
    assert_eq!(rows.len(), 10, "{csv}");
    assert!(rows.iter().any(|r| r.starts_with("alice.frag,agrees,100")), "{csv}");
    assert!(rows.iter().any(|r| r.starts_with("carol.frag + carol.vert,agrees,100")), "the pair is one row");
    assert!(row("dave/,disagrees").contains("view-dir-reversed"), "{csv}");
    assert!(rows.iter().any(|r| r.starts_with("erin.frag,agrees,100")), "a BOM and CRLF are accepted");
    assert!(row("endless.frag,error,0").contains("--timeout"), "{csv}");
    assert!(
        row("bomb.frag,ran out of memory,0").contains("ran out of memory: the limit is 1024 MiB (--memory)"),
        "{csv}"
    );
    assert!(row("empty.frag,error,0").contains("empty"), "{csv}");
    assert!(row("mallory.frag,error,0").contains("outside the class folder"), "{csv}");
    assert!(row("pipe.frag,error,0").contains("not a regular file"), "{csv}");
    assert!(rows.iter().any(|r| r.starts_with("'=HYPERLINK(1).frag,disagrees")), "formulas are defused:\n{csv}");
    assert!(!csv.contains("README") && err.contains("Not graded") && err.contains("README.txt"), "{err}");
    assert!(!csv.contains("root:"), "/etc/passwd was read:\n{csv}");
    assert!(err.contains("/10 ") && err.contains("alice.frag agrees"), "progress on stderr: {err}");
}

#[test]
fn limits_are_checked_by_clap_and_huge_timeouts_do_not_overflow() {
    let dir = temp_dir("limits");
    let file = dir.join("a.frag");
    std::fs::write(&file, example_shader("basic_lighting.frag")).unwrap();
    let f = file.to_str().unwrap();
    let (code, _, err) = lightlab(&["check-shader", f, "--model", "basic_lighting", "--timeout", "0"]);
    assert_eq!(code, 2, "{err}");
    let (code, _, _) = lightlab(&["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--timeout", "0"]);
    assert_eq!(code, 2);
    let (code, _, _) = lightlab(&["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--memory", "256"]);
    assert_eq!(code, 2, "--memory below 512 MB is refused");
    if gl_common::context_or_skip().is_none() {
        return;
    }
    // A shader saved by a Windows editor: a byte-order mark and CRLF line ends.
    let windows = dir.join("windows.frag");
    std::fs::write(&windows, format!("\u{feff}{}", example_shader("basic_lighting.frag").replace('\n', "\r\n")))
        .unwrap();
    let (code, out, err) =
        lightlab(&["check-shader", windows.to_str().unwrap(), "--model", "basic_lighting", "--cases", CASES]);
    assert_eq!(code, 0, "check-shader reads a BOM and CRLF: {out}{err}");
    let (code, out, err) =
        lightlab(&["exercise", "check", "basic-move-light", windows.to_str().unwrap(), "--cases", CASES]);
    assert_eq!(code, 0, "exercise check reads a BOM and CRLF: {out}{err}");
    let huge = u64::MAX.to_string();
    let (code, out, err) =
        lightlab(&["check-shader", f, "--model", "basic_lighting", "--cases", CASES, "--timeout", &huge]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn the_book_states_the_binarys_default_timeout() {
    let want = format!("{} s", lightlab::cli::child::DEFAULT_TIMEOUT_S);
    for page in ["book/src/12-exercises.md", "book/src/appendix-grading.md"] {
        let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(page)).unwrap();
        for line in text.lines().filter(|l| l.contains("by default") && l.contains("--timeout")) {
            assert!(line.contains(&want), "{page}: {line}");
        }
        assert!(text.contains(&want), "{page} states the default timeout ({want})");
    }
}

#[test]
fn feedback_pages_name_the_mistake_and_escape_the_students_text() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("feedback");
    let class = dir.join("class");
    std::fs::create_dir(&class).unwrap();
    std::fs::write(class.join("bob.frag"), example_shader("blinn_phong.frag")).unwrap();
    std::fs::write(class.join("<b>frank.frag"), example_shader("blinn_phong.frag").replace("spec", "shine")).unwrap();
    let pages = dir.join("pages");
    let (code, out, err) = grade(&class, &["--feedback", pages.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 1, "{err}");
    let md = std::fs::read_to_string(pages.join("bob.md")).unwrap();
    assert!(md.contains("**Mistake:** Blinn-Phong") && md.contains("**Hint:**"), "{md}");
    // The picture: student, reference and difference side by side, referenced by the page.
    let png = pages.join("bob-basic-move-light.png");
    let img = image::open(&png).expect("bob's picture is a PNG").to_rgb8();
    assert!(md.contains("(bob-basic-move-light.png)"), "{md}");
    // Three 160 × 120 panels with two 4-pixel gaps (picture.rs, PANEL).
    assert_eq!((img.width(), img.height()), (3 * 160 + 8, 120));
    let hot = (0..160)
        .flat_map(|x| (0..120).map(move |y| (x, y)))
        .filter(|&(x, y)| img.get_pixel(2 * 160 + 8 + x, y)[0] > 0)
        .count();
    assert!(hot > 100, "Blinn-Phong's wider highlight shows in the difference: {hot} pixels");
    let html = std::fs::read_to_string(pages.join("_b_frank.html")).unwrap();
    assert!(html.contains("&lt;b&gt;frank") && !html.contains("<b>frank"), "{html}");
    // bob and frank differ only in a name: flagged as near-identical (one exercise: the
    // JSON is the array of rows it has always been, each row naming its near-identical ones)
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rows = v.as_array().expect("one exercise: an array of rows");
    let flagged = rows.iter().filter(|r| r["similar_to"].as_array().is_some_and(|a| !a.is_empty())).count();
    assert_eq!(flagged, 2, "{v}");
}

#[test]
fn a_killed_grade_leaves_no_child() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("killed");
    std::fs::write(dir.join("endless.frag"), endless_shader()).unwrap();
    let mut grade = Command::new(BIN)
        .args(["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--timeout", "600"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let children = || -> Vec<String> {
        let mut found = Vec::new();
        for entry in std::fs::read_dir("/proc").unwrap().filter_map(Result::ok) {
            if let Ok(cmd) = std::fs::read(entry.path().join("cmdline")) {
                let cmd = String::from_utf8_lossy(&cmd).replace('\0', " ");
                if cmd.contains("--in-process") && cmd.contains(dir.to_str().unwrap()) {
                    found.push(cmd);
                }
            }
        }
        found
    };
    // The child starts within a second (context creation takes about 25 ms).
    let start = Instant::now();
    while children().is_empty() && start.elapsed().as_secs() < 10 {
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    assert!(!children().is_empty(), "the checking child started");
    grade.kill().unwrap();
    let _ = grade.wait();
    // The bound: no child 2 s after the parent's SIGKILL.
    std::thread::sleep(std::time::Duration::from_secs(2));
    assert!(children().is_empty(), "{:?}", children());
}

/// A student folder that is a symbolic link to another student's folder hands in the same
/// file: both rows are flagged for the teacher, whatever the verdict (the token-stream
/// comparison looks only at wrong shaders; this is an answer file, which it skips).
#[cfg(unix)]
#[test]
fn a_folder_linked_to_another_students_is_flagged() {
    let class = temp_dir("linked");
    std::fs::create_dir(class.join("alice")).unwrap();
    std::fs::write(class.join("alice/answer.txt"), "B\n").unwrap();
    std::fs::create_dir(class.join("bob")).unwrap();
    std::fs::write(class.join("bob/answer.txt"), "B\n").unwrap();
    std::os::unix::fs::symlink(class.join("alice"), class.join("carol")).unwrap();
    let (_, out, err) =
        lightlab(&["grade", class.to_str().unwrap(), "--exercise", "casters-swap-comparison", "--format", "json"]);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}\n{out}\n{err}"));
    let rows = v.as_array().expect("one exercise: an array of rows");
    let similar = |student: &str| {
        let row = rows.iter().find(|r| r["student"] == student).unwrap_or_else(|| panic!("{student}: {v}"));
        row["similar_to"].as_array().unwrap().iter().map(|s| s.as_str().unwrap().to_string()).collect::<Vec<_>>()
    };
    assert_eq!(similar("alice"), ["carol/"], "{v}");
    assert_eq!(similar("carol"), ["alice/"], "{v}");
    assert!(similar("bob").is_empty(), "the same answer in its own file is not flagged: {v}");
}
