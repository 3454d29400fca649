//! `lightlab exercise` and `lightlab grade` end to end, and `check-shader --format json`.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::common;
use crate::gl_common;

use common::{example_shader, lightlab};

use std::path::Path;
use std::process::Command;

use lightlab::checker::{complete, mistakes::Mistake};
use lightlab::exercises::Exercise;
use lightlab::gl::ModelId;

fn temp_dir(name: &str) -> common::TempDir {
    common::temp_dir("grade", name)
}

#[test]
fn exercise_list_json_has_every_exercise() {
    let (code, out, _) = lightlab(&["exercise", "list", "--format", "json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let list = v.as_array().unwrap();
    assert!(list.len() >= 15);
    for item in list {
        for key in ["id", "chapter", "title", "model"] {
            assert!(item.get(key).is_some(), "{item}");
        }
    }
}

#[test]
fn exercise_show_prints_statement_and_starter_and_unknown_ids_are_usage_errors() {
    let (code, out, _) = lightlab(&["exercise", "show", "multi-calc-spot"]);
    assert_eq!(code, 0);
    assert!(out.contains("Write `CalcSpotLight`") && out.contains("TODO: write CalcSpotLight"), "{out}");
    let (code, _, err) = lightlab(&["exercise", "show", "no-such"]);
    assert_eq!(code, 2);
    assert!(err.contains("unknown exercise `no-such`"), "{err}");
}

#[test]
fn check_shader_json_is_one_object_with_a_diagnosis() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("json");
    let m = Mistake::by_id("ambient-missing").unwrap();
    let file = dir.join("a.frag");
    std::fs::write(&file, complete::with_mistake(ModelId::Point, m).unwrap()).unwrap();
    let (code, out, _) =
        lightlab(&["check-shader", file.to_str().unwrap(), "--model", "point", "--cases", "3000", "--format", "json"]);
    assert_eq!(code, 1);
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["verdict"], "disagrees");
    assert_eq!(v["diagnosis"][0]["id"], "ambient-missing");
    for key in ["title", "evidence", "link"] {
        assert!(v["diagnosis"][0][key].as_str().is_some_and(|s| !s.is_empty()), "{key}");
    }
    assert!(v["stats"]["failing"].as_u64().unwrap() > 0);
    let (code, out, _) = lightlab(&["check-shader", file.to_str().unwrap(), "--model", "point", "--cases", "3000"]);
    assert_eq!(code, 1);
    assert!(out.lines().next().unwrap().contains("Your shader disagrees"), "{out}");
    assert!(out.contains("ambient term left out"), "{out}");
}

#[test]
fn grade_writes_one_row_per_file_and_survives_bad_files() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("class");
    let e = Exercise::by_id("own-point-attenuation").unwrap();
    std::fs::write(dir.join("alice.frag"), e.solution()).unwrap();
    let m = Mistake::by_id("attenuation-quadratic-uses-d").unwrap();
    std::fs::write(dir.join("bob.frag"), complete::with_mistake(ModelId::Point, m).unwrap()).unwrap();
    std::fs::write(dir.join("carol.frag"), "#version 330 core\nvoid main() { oops }\n").unwrap();
    std::fs::write(dir.join("dave.frag"), "").unwrap();
    std::fs::write(dir.join("erin.png"), [0x89u8, b'P', b'N', b'G', 0, 0, 1]).unwrap();
    let out_file = dir.join("out").with_extension("csv");
    let (code, _, err) = lightlab(&[
        "grade",
        dir.to_str().unwrap(),
        "--exercise",
        "own-point-attenuation",
        "--cases",
        "3000",
        "--output",
        out_file.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    let csv = std::fs::read_to_string(&out_file).unwrap();
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(rows[0], "file,verdict,score,diagnosis,counterexample,error,mistake,explanation,similar_to");
    // erin.png is not a submission: named on stderr, not a row.
    assert_eq!(rows.len(), 1 + 4, "{csv}");
    assert!(err.contains("Not graded") && err.contains("erin.png"), "{err}");
    let row = |name: &str| *rows.iter().find(|r| r.starts_with(name)).unwrap();
    assert_eq!(row("alice.frag"), "alice.frag,agrees,100,,,,,,");
    assert!(row("bob.frag,disagrees,").contains("attenuation-quadratic-uses-d"), "{csv}");
    assert!(row("carol.frag,error,0").contains("does not compile"), "{csv}");
    assert!(row("dave.frag,error,0").contains("empty"), "{csv}");
    assert!(row("bob.frag").contains("quadratic"), "the row names the mistake's title: {csv}");
    let bob_score: u32 = row("bob.frag").split(',').nth(2).unwrap().parse().unwrap();
    assert!(bob_score < 90, "a shader that disagrees scores below 90: {bob_score}");
    assert!(!Path::new(&dir.join(".out.csv.tmp")).exists());
}

#[test]
fn exercise_check_numeric_exit_codes() {
    let dir = temp_dir("numeric");
    let right = dir.join("right.txt");
    let answer = lightlab::exercises::answer_number("own-attenuation-half").unwrap();
    std::fs::write(&right, format!("{answer}\n")).unwrap();
    let (code, out, _) =
        lightlab(&["exercise", "check", "own-attenuation-half", right.to_str().unwrap(), "--format", "json"]);
    assert_eq!(code, 0, "{out}");
    let wrong = dir.join("wrong.txt");
    std::fs::write(&wrong, format!("{}\n", answer + 1.0)).unwrap();
    let (code, out, _) = lightlab(&["exercise", "check", "own-attenuation-half", wrong.to_str().unwrap()]);
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("too high"), "{out}");
    let bad = dir.join("bad.txt");
    std::fs::write(&bad, "about ten").unwrap();
    let (code, _, err) = lightlab(&["exercise", "check", "own-attenuation-half", bad.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(err.contains("`about` is not a number"), "{err}");
}

/// A fragment shader that never ends in a test's time: an endless loop whose body is 256
/// dependent `sin` calls. (llvmpipe stops any loop after 65 535 iterations, so a bare
/// `while (true)` ends; with this body one fragment still costs about 1.7·10⁷ `sin`s.)
/// The rest is the Basic lighting exercise's declarations.
fn endless_shader() -> String {
    let body = "        x = sin(x + FragPos.x);\n".repeat(256);
    format!(
        "{}void main()
{{
    float x = 0.0;
    while (true) {{
{body}        if (x > 2.0) break;
    }}
    FragColor = vec4(x * lightColor * objectColor, 1.0);
}}
",
        common::BASIC_LIGHTING_HEAD
    )
}

#[test]
fn an_endless_loop_takes_too_long_in_exercise_check_and_in_grade() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("endless");
    let endless = dir.join("endless.frag");
    std::fs::write(&endless, endless_shader()).unwrap();
    let file = endless.to_str().unwrap();
    let (code, out, err) = lightlab(&["exercise", "check", "basic-move-light", file, "--timeout", "2"]);
    assert_eq!(code, 1, "{out}{err}");
    assert!(out.contains("verdict: TOOK TOO LONG") && out.contains("--timeout"), "{out}");
    let (code, out, _) =
        lightlab(&["exercise", "check", "basic-move-light", file, "--timeout", "2", "--format", "json"]);
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).expect("one JSON object");
    assert_eq!(v["verdict"], "took too long", "{out}");
    let good = Exercise::by_id("basic-move-light").unwrap().solution();
    std::fs::write(dir.join("good.frag"), good).unwrap();
    let (code, out, err) = lightlab(&[
        "grade",
        dir.to_str().unwrap(),
        "--exercise",
        "basic-move-light",
        "--timeout",
        "2",
        "--cases",
        "2000",
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(out.lines().any(|r| r.starts_with("endless.frag,error,0,") && r.contains("--timeout")), "{out}");
    assert!(out.lines().any(|r| r == "good.frag,agrees,100,,,,,,"), "the run goes on after the timeout:\n{out}");
}

/// The three numbers after `label = [` in a counterexample.
fn color_after(text: &str, label: &str) -> [f64; 3] {
    let start = text.find(label).unwrap_or_else(|| panic!("no `{label}` in {text}")) + label.len();
    let rest = &text[start..];
    let inner = &rest[rest.find('[').unwrap() + 1..rest.find(']').unwrap()];
    let v: Vec<f64> = inner.split(',').map(|x| x.trim().parse().unwrap()).collect();
    [v[0], v[1], v[2]]
}

#[test]
fn the_row_carries_the_worst_counterexample_in_the_shaders_names() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    // Phong handed in for the Blinn-Phong variant: hundreds of cases differ, by different amounts.
    let dir = temp_dir("worst");
    let phong = Exercise::by_id("basic-move-light").unwrap().solution();
    std::fs::write(dir.join("phong.frag"), phong).unwrap();
    let file = dir.join("phong.frag");
    let (code, out, _) = lightlab(&[
        "exercise",
        "check",
        "own-blinn-phong",
        file.to_str().unwrap(),
        "--cases",
        "2000",
        "--format",
        "json",
    ]);
    assert_eq!(code, 1, "{out}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    let max_abs = v["stats"]["max_abs"].as_f64().unwrap();
    let diff = |c: &str| {
        let (want, got) = (color_after(c, "expected ("), color_after(c, "got ("));
        (0..3).map(|k| (want[k] - got[k]).abs()).fold(0.0, f64::max)
    };
    let list: Vec<&str> = v["counterexamples"].as_array().unwrap().iter().map(|c| c.as_str().unwrap()).collect();
    assert_eq!(list.len(), 3, "{out}");
    // The worst case with typical inputs comes first, then the raw worst (issue 25 item 8:
    // a counterexample at shininess 0 says nothing about Blinn against Phong).
    let shininess = |c: &str| -> f64 {
        let line = c.lines().find(|l| l.trim_start().starts_with("shininess = ")).expect("a shininess line");
        line.split('=').nth(1).unwrap().trim().parse().unwrap()
    };
    let worst_at = list.iter().position(|c| (diff(c) - max_abs).abs() < 1e-6);
    match worst_at {
        Some(0) => {}
        Some(1) => {
            let s = shininess(list[0]);
            // src/checker/check/report.rs TYPICAL_SHININESS_MIN and _MAX
            assert!((8.0..=128.0).contains(&s), "the first is typical: shininess {s}\n{}", list[0]);
        }
        other => panic!("the raw worst is first or second, not {other:?}: {list:?}"),
    }
    assert!(diff(list[1]) >= diff(list[2]), "after the two, the rest worst first: {list:?}");
    let (code, csv, err) = lightlab(&[
        "grade",
        dir.to_str().unwrap(),
        "--exercise",
        "own-blinn-phong",
        "--cases",
        "2000",
        "--format",
        "json",
    ]);
    assert_eq!(code, 1, "{err}");
    let rows: serde_json::Value = serde_json::from_str(csv.trim()).unwrap();
    let row = rows[0]["counterexample"].as_str().unwrap();
    assert!(row.contains("lightPos = (") && row.contains("viewPos = ("), "the shader's names: {row}");
    let first_line = list[0].lines().next().unwrap_or_default();
    assert!(row.contains(first_line.trim()), "the row carries the check's first counterexample: {row}");
}

#[test]
fn feedback_pages_are_in_the_class_language_and_the_command_line_wins() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("lang");
    let class = dir.join("class");
    std::fs::create_dir_all(&class).unwrap();
    std::fs::write(class.join("bob.frag"), example_shader("blinn_phong.frag")).unwrap();
    let pages = dir.join("pages");
    let (code, _, err) = lightlab(&[
        "grade",
        "--lang",
        "uk",
        class.to_str().unwrap(),
        "--exercise",
        "basic-move-light",
        "--cases",
        "2000",
        "--feedback",
        pages.to_str().unwrap(),
    ]);
    assert_eq!(code, 1, "{err}");
    let html = std::fs::read_to_string(pages.join("bob.html")).unwrap();
    for uk in ["<html lang=\"uk\">", "Відгук: bob", "Вердикт: не узгоджується — оцінка", "Помилка:", "Підказка:"]
    {
        assert!(html.contains(uk), "`{uk}` missing from the Ukrainian page:\n{html}");
    }
    assert!(html.contains("Випадок, у якому результат відрізняється:"), "{html}");
    for en in ["Feedback:", "Verdict:", "Hint:", "A case where it differs"] {
        assert!(!html.contains(en), "English `{en}` left in the Ukrainian page:\n{html}");
    }
    // The assignment's `lang` sets the class language; `--lang` on the command line wins.
    let assignment = dir.join("lab.toml");
    std::fs::write(&assignment, "lang = \"fr\"\n[[exercise]]\nid = \"basic-move-light\"\n").unwrap();
    for (flag, want, not) in [(None, "Indice\u{a0}:", "Hint:"), (Some("en"), "Hint:", "Indice\u{a0}:")] {
        let mut args = vec!["grade"];
        if let Some(l) = flag {
            args.extend(["--lang", l]);
        }
        args.extend([
            class.to_str().unwrap(),
            "--assignment",
            assignment.to_str().unwrap(),
            "--cases",
            "2000",
            "--feedback",
            pages.to_str().unwrap(),
        ]);
        let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
            .args(&args)
            .env("LIGHTLAB_LANG", "uk")
            .output()
            .expect("run lightlab");
        assert_eq!(out.status.code(), Some(1), "{}", String::from_utf8_lossy(&out.stderr));
        let md = std::fs::read_to_string(pages.join("bob.md")).unwrap();
        assert!(md.contains(want) && !md.contains(not), "--lang {flag:?}: want `{want}`:\n{md}");
    }
    std::fs::write(&assignment, "lang = \"de\"\n[[exercise]]\nid = \"basic-move-light\"\n").unwrap();
    let (code, _, err) = lightlab(&["grade", class.to_str().unwrap(), "--assignment", assignment.to_str().unwrap()]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("line 1: lang: unknown language `de`"), "{err}");
}

/// A LearnOpenGL project holds its lamp shader beside the lighting one: without `--files`
/// the folder is an error row that says how to name the answer; with `--files` the pattern
/// picks it in each student's folder (not the project's vertex shader, which it names too),
/// and a bad pattern is a usage error naming the option.
#[test]
fn files_picks_the_answer_in_a_project_folder_with_a_lamp_shader() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let class = temp_dir("files-option");
    let e = Exercise::by_id("own-point-attenuation").unwrap();
    let lamp = "#version 330 core\nout vec4 FragColor;\nvoid main() { FragColor = vec4(1.0); }\n";
    for student in ["ana", "ben"] {
        let folder = class.join(student).join("src");
        std::fs::create_dir_all(&folder).unwrap();
        std::fs::write(folder.join("2.1.lighting.fs"), e.solution()).unwrap();
        std::fs::write(folder.join("2.1.light_cube.fs"), lamp).unwrap();
        // the project's vertex shader matches the pattern too: a fragment pattern skips it
        std::fs::write(folder.join("2.1.lighting.vs"), "#version 330 core\nvoid main() { gl_Position = vec4(0.0); }\n")
            .unwrap();
    }
    let dir = class.to_str().unwrap();
    let grade = |extra: &[&str]| {
        let mut args = vec!["grade", dir, "--exercise", "own-point-attenuation", "--cases", "2000"];
        args.extend_from_slice(extra);
        lightlab(&args)
    };
    let (code, csv, err) = grade(&[]);
    assert_eq!(code, 1, "{err}");
    assert!(csv.contains("ana/,error,0") && csv.contains("--files"), "the error says how to name the answer:\n{csv}");
    let (code, csv, err) = grade(&["--files", "*lighting*"]);
    assert_eq!(code, 0, "{err}\n{csv}");
    assert!(
        csv.contains("ana/src/2.1.lighting.fs,agrees,100") && csv.contains("ben/src/2.1.lighting.fs,agrees,100"),
        "{csv}"
    );
    let (code, _, err) = grade(&["--files", "[ab]*.fs"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--files `[ab]*.fs`"), "{err}");
    let (code, _, err) = grade(&["--vertex", "*.vs"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--files"), "{err}");
}

/// `--files` and `--vertex` in project folders as students hand them in: a capitalised
/// name is found, a vertex pattern never takes a fragment shader, two patterns that name
/// one file say so, a pair without its vertex shader is "not handed in", the student is
/// the row's key whatever the outcome, and a shader exercise checked with its vertex
/// shader still names the fragment shader's mistake. Options that cannot fit the exercise
/// are usage errors.
#[test]
fn project_patterns_pick_each_students_files_and_key_the_rows_by_student() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let class = temp_dir("project-patterns");
    let e = Exercise::by_id("basic-move-light").unwrap();
    let solution = e.solution();
    let no_ambient = solution.replace("(ambient + diffuse + specular)", "(diffuse + specular)");
    assert_ne!(no_ambient, solution, "the mutant must differ from the solution");
    let vertex =
        lightlab::checker::check::pair::reference_pair(lightlab::checker::check::pair::PairModel::PerFragment).0;
    let put = |path: &str, text: &str| {
        let p = class.join(path);
        std::fs::create_dir_all(p.parent().unwrap()).unwrap();
        std::fs::write(p, text).unwrap();
    };
    put("ana/src/lighting.frag", &no_ambient);
    put("ana/src/lighting.vert", vertex);
    put("ben/Shaders/Lighting.FRAG", &solution); // only the case differs from the pattern
    put("ben/Shaders/Lighting.VERT", vertex);
    put("cy/src/lighting.frag", &solution); // no vertex shader: `*lighting*` names the fragment one only
    put("di/lighting.glsl", &solution); // both patterns name this one file
    let dir = class.to_str().unwrap();
    let (code, csv, err) = lightlab(&[
        "grade",
        dir,
        "--exercise",
        "basic-move-light",
        "--files",
        "*lighting*",
        "--vertex",
        "*lighting*",
        "--cases",
        "2000",
    ]);
    assert_eq!(code, 1, "{err}\n{csv}");
    let row = |student: &str| {
        csv.lines().find(|l| l.starts_with(&format!("{student},basic-move-light,"))).unwrap_or_else(|| panic!("{csv}"))
    };
    assert!(csv.starts_with("student,exercise,weight,points,file,"), "the student is the key:\n{csv}");
    assert!(row("ana").contains("ana/src/lighting.frag + src/lighting.vert,disagrees"), "{csv}");
    assert!(
        row("ana").contains(",ambient-missing,"),
        "the pair's difference is in the fragment shader, which is then diagnosed alone:\n{csv}"
    );
    assert!(row("ben").contains("Shaders/Lighting.FRAG + Shaders/Lighting.VERT,agrees,100"), "{csv}");
    assert!(row("cy").contains("cy/,error,0") && row("cy").contains("no vertex shader matches `*lighting*`"), "{csv}");
    assert!(row("di").contains("di/,error,0") && row("di").contains("pick the same file (lighting.glsl)"), "{csv}");
    // usage errors, before anything is graded
    let (code, _, err) = lightlab(&["grade", dir, "--exercise", "basic-gouraud-pair", "--files", "*lighting*"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("checked as a pair") && err.contains("--vertex"), "{err}");
    let (code, _, err) =
        lightlab(&["grade", dir, "--exercise", "casters-swap-comparison", "--files", "*.txt", "--vertex", "*.vert"]);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("--vertex") && err.contains("takes no vertex shader"), "{err}");
}

/// `exercise show` and `exercise list` speak the learner's language: the starter of an
/// answer file (its sentence and choices) and the titles, not only the statement.
#[test]
fn exercise_show_and_list_are_in_the_learners_language() {
    let (code, out, err) = lightlab(&["exercise", "show", "casters-swap-comparison", "--lang", "uk"]);
    assert_eq!(code, 0, "{err}");
    assert!(!out.contains("Write the letter") && !out.contains("those inside the cone"), "{out}");
    assert!(out.contains("Запишіть літеру") && out.contains("(a) ті, що всередині конуса"), "{out}");
    let (code, out, err) = lightlab(&["exercise", "show", "casters-swap-comparison", "--starter", "--lang", "fr"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("Écrivez la lettre"), "{out}");
    let (code, out, err) = lightlab(&["exercise", "list", "--lang", "fr"]);
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("Déplacer la lumière au fil du temps") && !out.contains("Move the light over time"), "{out}");
}
