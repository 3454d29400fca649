//! Issue 28's runner reproducers, in every command that reads a shader (`exercise check`,
//! `check-shader`, `grade`): a child that runs out of memory has its own verdict, a
//! no-break space is a compile error at its line, and `grade`'s output paths are checked
//! before the work.
//!
//! Tests that need OpenGL print why and pass without it, unless `LIGHTLAB_REQUIRE_GL=1`.
#![cfg(all(feature = "gl", feature = "book"))]

use crate::common;
use crate::gl_common;

use std::time::Instant;

use common::{example_shader, huge_array, lightlab};

fn temp_dir(name: &str) -> common::TempDir {
    common::temp_dir("hostile", name)
}

/// The child's own witness (issue 28's flaky run): Mesa's compiler dies by `SIGSEGV`
/// with no message when an allocation fails, and the parent's 10 ms sampling of `/proc`
/// can miss the peak on a loaded machine. Run straight under the limit, with no parent
/// sampling at all, the child must still say on standard error that it ran out of memory,
/// for both commands that run as a checking child.
#[cfg(target_os = "linux")]
#[test]
fn a_child_that_faults_at_its_memory_limit_says_it_ran_out_of_memory() {
    use std::os::unix::process::ExitStatusExt;
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("fault-at-limit");
    let file = dir.join("huge.frag");
    std::fs::write(&file, huge_array(4_000_000)).unwrap();
    let f = file.to_str().unwrap();
    for args in [
        vec!["check-shader", f, "--model", "basic_lighting", "--in-process"],
        vec!["exercise", "check", "basic-move-light", f, "--in-process"],
    ] {
        // `ulimit -v` is the same RLIMIT_AS as `--memory 512` sets (524 288 KiB)
        let out = std::process::Command::new("sh")
            .arg("-c")
            .arg("ulimit -v 524288 && exec \"$0\" \"$@\"")
            .arg(env!("CARGO_BIN_EXE_lightlab"))
            .args(&args)
            .env("LIGHTLAB_LANG", "en")
            .output()
            .expect("run lightlab under sh");
        let stderr = String::from_utf8_lossy(&out.stderr);
        // Mesa runs out in one of three places (all seen here): its compiler dies by SIGSEGV
        // (before the fix, with an empty standard error), LLVM's bad_alloc aborts the
        // child (SIGABRT, "Rust cannot catch foreign exceptions"), or a texture allocation
        // fails with GL_OUT_OF_MEMORY and the child exits with its message. Every way, the
        // child's standard error must say so.
        if let Some(signal) = out.status.signal() {
            assert!([libc::SIGSEGV, libc::SIGABRT].contains(&signal), "{args:?}: {:?} {stderr}", out.status);
            assert!(stderr.contains(lightlab::cli::child::FAULT_AT_LIMIT.trim_end()), "{args:?}: {stderr}");
        }
        assert!(lightlab::cli::child::out_of_memory(&stderr), "{args:?}: {:?} {stderr}", out.status);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn running_out_of_memory_is_its_own_verdict_not_a_compile_error() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("memory");
    let file = dir.join("huge.frag");
    std::fs::write(&file, huge_array(4_000_000)).unwrap();
    let f = file.to_str().unwrap();
    let want = "ran out of memory: the limit is 512 MiB (--memory)";
    for args in [
        vec!["exercise", "check", "basic-move-light", f, "--memory", "512", "--timeout", "60"],
        vec!["check-shader", f, "--model", "basic_lighting", "--memory", "512", "--timeout", "60"],
    ] {
        let (code, out, err) = lightlab(&args);
        assert_eq!(code, 4, "{args:?}: its own exit status: {out}{err}");
        assert!(out.contains("verdict: RAN OUT OF MEMORY") && out.contains(want), "{args:?}:\n{out}{err}");
        assert!(!out.contains("DOES NOT COMPILE") && !out.contains("driver crashed"), "{out}");
        let mut json = args.clone();
        json.extend(["--format", "json"]);
        let (code, out, _) = lightlab(&json);
        assert_eq!(code, 4, "{out}");
        let v: serde_json::Value = serde_json::from_str(out.trim()).expect("one JSON object");
        assert_eq!(v["verdict"], "ran out of memory", "{out}");
    }
    // in the learner's language, the verdict and the sentence; JSON stays English
    use lightlab::cli::child::{OUT_OF_MEMORY, VERDICT_LINE};
    use lightlab::i18n::{tr, Lang};
    let uk_why = tr(Lang::Uk, OUT_OF_MEMORY).replacen("{}", "512", 1);
    let uk_verdict = tr(Lang::Uk, VERDICT_LINE).replacen("{}", &tr(Lang::Uk, "RAN OUT OF MEMORY"), 1);
    assert!(!uk_why.starts_with("ran out"), "po/uk.po translates the sentence");
    let args = ["exercise", "check", "basic-move-light", f, "--memory", "512", "--timeout", "60", "--lang", "uk"];
    let (code, out, err) = lightlab(&args);
    assert_eq!(code, 4, "{out}{err}");
    assert!(out.contains(&uk_verdict) && out.contains(&uk_why), "{out}{err}");
    let (code, csv, err) = lightlab(&[
        "grade",
        dir.to_str().unwrap(),
        "--exercise",
        "basic-move-light",
        "--memory",
        "512",
        "--timeout",
        "60",
    ]);
    assert_eq!(code, 1, "{err}");
    let row = csv.lines().find(|l| l.starts_with("huge.frag,")).unwrap_or_else(|| panic!("{csv}"));
    assert!(row.starts_with("huge.frag,ran out of memory,0,") && row.contains(want), "{row}");
    assert!(!row.contains("does not compile"), "{row}");
}

#[test]
fn a_no_break_space_does_not_compile_at_its_line_in_every_command() {
    if gl_common::context_or_skip().is_none() {
        return;
    }
    let dir = temp_dir("nbsp");
    let good = example_shader("basic_lighting.frag");
    let line = 1 + good.lines().position(|l| l.starts_with("uniform")).unwrap();
    let text: Vec<String> = good
        .lines()
        .enumerate()
        .map(|(k, l)| if k + 1 == line { format!("\u{a0}{l}") } else { l.to_string() })
        .collect();
    let file = dir.join("pasted.frag");
    std::fs::write(&file, text.join("\n") + "\n").unwrap();
    let f = file.to_str().unwrap();
    let want = format!("U+00A0 no-break space at line {line}, column 1: replace it with a space");
    for args in [
        vec!["exercise", "check", "basic-move-light", f, "--cases", "500"],
        vec!["check-shader", f, "--model", "basic_lighting", "--cases", "500"],
    ] {
        let (code, out, err) = lightlab(&args);
        assert_eq!(code, 1, "{args:?}: never an internal error (3): {out}{err}");
        assert!(out.contains("verdict: DOES NOT COMPILE") && out.contains(&want), "{args:?}:\n{out}{err}");
        assert!(out.contains(&format!("{line:4} | \u{a0}uniform")), "the line is shown:\n{out}");
    }
    let (code, csv, err) =
        lightlab(&["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light", "--cases", "500"]);
    assert_eq!(code, 1, "{err}");
    assert!(csv.lines().any(|r| r.starts_with("pasted.frag,error,0,") && r.contains(&want)), "{csv}");
    // In a comment, any character is fine.
    std::fs::write(&file, format!("// lumière\u{a0}spéculaire\n{good}")).unwrap();
    let (code, out, err) = lightlab(&["check-shader", f, "--model", "basic_lighting", "--cases", "500"]);
    assert_eq!(code, 0, "{out}{err}");
}

#[test]
fn grade_checks_its_output_paths_before_any_shader() {
    let dir = temp_dir("outputs");
    let class = dir.join("class");
    std::fs::create_dir_all(&class).unwrap();
    std::fs::write(class.join("alice.frag"), example_shader("basic_lighting.frag")).unwrap();
    let missing = dir.join("missing/x.csv");
    let blocker = dir.join("a-file");
    std::fs::write(&blocker, "not a folder").unwrap();
    let cases: [(Vec<String>, String); 4] = [
        (vec!["-o".into(), missing.display().to_string()], missing.display().to_string()),
        // /proc holds no new files, even for root: the write would fail after the work.
        (vec!["-o".into(), "/proc/grades.csv".into()], "/proc".into()),
        (vec!["--feedback".into(), "/proc/sys".into()], "--feedback /proc/sys".into()),
        (vec!["--feedback".into(), blocker.join("pages").display().to_string()], blocker.display().to_string()),
    ];
    for (extra, named) in cases {
        let mut args = vec!["grade", class.to_str().unwrap(), "--exercise", "basic-move-light", "--timeout", "60"];
        args.extend(extra.iter().map(String::as_str));
        let t = Instant::now();
        let (code, out, err) = lightlab(&args);
        assert_eq!(code, 2, "{extra:?}: {out}{err}");
        assert!(err.contains(&named), "{extra:?}: the error names the path: {err}");
        assert!(!err.contains("1/1"), "{extra:?}: a shader was checked before the error: {err}");
        assert!(out.is_empty(), "{out}");
        assert!(t.elapsed().as_secs() < 20, "{extra:?}: took {:?}", t.elapsed());
    }
}
