//! `grade --uniforms`: the teacher's mapping file is one for the whole class (red-team
//! finding 2). A student who keeps the chapter's names declares none of the renamed ones;
//! before, every such student got an error row citing the teacher's TOML lines, and 0.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::common::{example_shader, lightlab, TempDir};
use crate::gl_common;

#[test]
fn one_mapping_grades_renamed_and_chapter_named_shaders_alike() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let class = TempDir::new("grade-mapping", "class");
    let chapter = example_shader("basic_lighting.frag");
    assert!(chapter.contains("lightPos"), "the example declares the chapter's lightPos");
    std::fs::write(class.join("keeps.frag"), &chapter).unwrap();
    std::fs::write(class.join("renames.frag"), chapter.replace("lightPos", "uLightPos")).unwrap();
    let toml = TempDir::new("grade-mapping", "toml");
    let map = toml.join("class.toml");
    std::fs::write(&map, "[names]\nuLightPos = \"lightPos\"\n").unwrap();
    let args = |dir: &std::path::Path| {
        let mut a =
            vec!["grade".to_string(), dir.display().to_string(), "--exercise".into(), "basic-move-light".into()];
        a.extend(["--uniforms".into(), map.display().to_string(), "--cases".into(), "2000".into()]);
        a
    };
    let a = args(&class);
    let (code, csv, err) = lightlab(&a.iter().map(String::as_str).collect::<Vec<_>>());
    assert_eq!(code, 0, "{csv}{err}");
    for student in ["keeps.frag", "renames.frag"] {
        assert!(csv.lines().any(|r| r.starts_with(&format!("{student},agrees,100,"))), "{student}:\n{csv}{err}");
    }
    // a single check keeps the error: there the key is most likely a typo
    let file = class.join("keeps.frag");
    let (code, out, err) = lightlab(&[
        "exercise",
        "check",
        "basic-move-light",
        file.to_str().unwrap(),
        "--uniforms",
        map.to_str().unwrap(),
        "--cases",
        "2000",
    ]);
    assert_eq!(code, 2, "{out}{err}");
    assert!(err.contains("names.uLightPos") && err.contains("declares no"), "{out}{err}");
}
