//! One meaning per exit status, across every subcommand:
//! 0 success, 1 the work ran and found a problem, 2 usage or input error,
//! 3 internal failure (a panic included, never 101), 4 a checked shader ran out of
//! memory (`tests/hostile.rs` runs that one: it needs OpenGL). A closed standard output
//! ends a run quietly; a full one is an internal failure with a message.
//!
//! Runs the binary, as a user would.
#![cfg(feature = "book")]

use std::path::Path;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_lightlab");

fn data(name: &str) -> String {
    format!("{}/tests/data/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A fresh empty directory outside any lightlab checkout.
fn scratch(name: &str) -> crate::common::TempDir {
    crate::common::TempDir::new("cli-exit", name)
}

fn run_in(dir: Option<&Path>, args: &[&str]) -> Output {
    let mut cmd = Command::new(BIN);
    cmd.env("LIGHTLAB_LANG", "en");
    cmd.args(args).stdin(Stdio::null()).stdout(Stdio::piped()).stderr(Stdio::piped());
    if let Some(dir) = dir {
        cmd.current_dir(dir);
    }
    cmd.output().expect("lightlab runs")
}

fn status(args: &[&str]) -> (Option<i32>, String) {
    let out = run_in(None, args);
    (out.status.code(), String::from_utf8_lossy(&out.stderr).into_owned())
}

#[track_caller]
fn assert_status(args: &[&str], want: i32) -> String {
    let (code, stderr) = status(args);
    assert_eq!(code, Some(want), "lightlab {args:?}: stderr {stderr}");
    stderr
}

#[test]
fn help_and_version_exit_0_and_document_the_table() {
    let out = run_in(None, &["--help"]);
    assert_eq!(out.status.code(), Some(0));
    let help = String::from_utf8_lossy(&out.stdout);
    for needle in ["EXIT STATUS", "1  the work ran", "2  usage or input error", "3  internal failure"] {
        assert!(help.contains(needle), "lightlab --help lacks {needle:?}:\n{help}");
    }
    assert_status(&["--version"], 0);
    let mut subcommands = vec!["book", "shade", "render", "bench", "study"];
    if cfg!(feature = "gl") {
        subcommands.extend(["check-shader", "oracle"]);
    }
    for sub in subcommands {
        let out = run_in(None, &[sub, "--help"]);
        assert_eq!(out.status.code(), Some(0), "{sub} --help");
        let help = String::from_utf8_lossy(&out.stdout);
        assert!(help.contains("EXIT STATUS"), "lightlab {sub} --help lacks the exit-status table");
    }
}

#[test]
fn usage_errors_exit_2_in_every_subcommand() {
    // Unknown options: clap's usage errors.
    for sub in ["book", "shade", "render", "bench", "study", "check-shader", "oracle"] {
        if !cfg!(feature = "gl") && (sub == "check-shader" || sub == "oracle") {
            continue;
        }
        assert_status(&[sub, "--no-such-option"], 2);
    }
    assert_status(&["no-such-subcommand"], 2);
    // Bad values that only the subcommand can judge (these exited 1 before).
    let stderr = assert_status(&["render", "--preset", "no-such-preset", "-o", "/tmp/x.png"], 2);
    assert!(stderr.contains("no-such-preset"), "{stderr}");
    assert_status(&["render", "--preset", "quad-single", "--size", "0x0", "-o", "/tmp/x.png"], 2);
    assert_status(&["render"], 2);
    let stderr = assert_status(&["bench", "no-such-scene"], 2);
    assert!(stderr.contains("no-such-scene"), "{stderr}");
    assert_status(&["book", "--root", "/nonexistent/lightlab-book"], 2);
    assert_status(&["shade", "/nonexistent/cases.jsonl"], 2);
    // --out names a regular file, not a directory.
    let dir = scratch("study-out");
    let file = dir.join("file");
    std::fs::write(&file, "x").expect("write");
    assert_status(&["study", "--quick", "--out", file.to_str().expect("utf-8")], 2);
}

#[cfg(all(feature = "gl", unix))]
#[test]
fn oracle_into_a_full_or_closed_stdout_does_not_panic() {
    if lightlab::gl::GlContext::new().is_err() {
        eprintln!("no OpenGL here; skipped");
        return;
    }
    assert_status(&["oracle", "--cases", "10"], 0);
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        return;
    };
    // `lightlab oracle --cases 10 > /dev/full` panicked.
    let out = Command::new(BIN).args(["oracle", "--cases", "10"]).stdout(full).output().expect("runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("standard output") && !stderr.contains("panicked"), "{stderr}");
    let out = Command::new(BIN).args(["oracle", "--cases", "10"]).stdout(closed_pipe()).output().expect("runs");
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
}

#[cfg(feature = "gl")]
#[test]
fn gl_usage_errors_exit_2() {
    assert_status(&["oracle", "--cases", "0"], 2);
    assert_status(&["check-shader", "/nonexistent.frag", "--model", "basic_lighting"], 2);
}

#[test]
fn problems_found_exit_1() {
    assert_status(&["shade", &data("malformed.jsonl")], 1);
}

#[test]
fn success_exits_0() {
    assert_status(&["shade", &data("example.jsonl")], 0);
    assert_status(&["render", "--list"], 0);
}

#[test]
fn a_panic_is_an_internal_error_with_status_3() {
    let out = Command::new(BIN).arg("render").arg("--list").env("LIGHTLAB_TEST_PANIC", "1").output().expect("runs");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "stderr: {stderr}");
    assert!(stderr.contains("internal error") && stderr.contains("please report"), "{stderr}");
}

/// Standard output whose reader is already gone: every write fails with EPIPE.
#[cfg(unix)]
fn closed_pipe() -> std::io::PipeWriter {
    let (reader, writer) = std::io::pipe().expect("pipe");
    drop(reader);
    writer
}

#[cfg(unix)]
#[test]
fn closed_stdout_stops_quietly() {
    // `lightlab render --list | true` panicked with exit 101 before.
    let cases: &[&[&str]] = &[&["render", "--list"], &["shade", &data("example.jsonl")], &["--help"]];
    for args in cases {
        let out = Command::new(BIN)
            .args(*args)
            .stdin(Stdio::null())
            .stdout(closed_pipe())
            .stderr(Stdio::piped())
            .output()
            .expect("runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(0), "lightlab {args:?}: {stderr}");
        assert!(!stderr.contains("panicked") && !stderr.contains("internal error"), "lightlab {args:?}: {stderr}");
    }
}

#[cfg(unix)]
#[test]
fn full_stdout_is_an_internal_error_with_a_message() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        eprintln!("no /dev/full here; skipped");
        return;
    };
    let cases: &[&[&str]] = &[&["render", "--list"], &["shade", &data("example.jsonl")]];
    for args in cases {
        let out = Command::new(BIN)
            .args(*args)
            .stdin(Stdio::null())
            .stdout(full.try_clone().expect("clone"))
            .stderr(Stdio::piped())
            .output()
            .expect("runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(3), "lightlab {args:?}: {stderr}");
        assert!(stderr.contains("standard output") && !stderr.contains("panicked"), "lightlab {args:?}: {stderr}");
    }
}

#[test]
fn no_default_root_outside_a_project() {
    // Run from a directory with no book/book.toml above it: the book and the study's
    // default output refuse (exit 2, naming --root / --out) instead of writing into the
    // checkout the binary was built from.
    let dir = scratch("no-root");
    let out = run_in(Some(&dir), &["book"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--root"), "{stderr}");
    let out = run_in(Some(&dir), &["study", "--quick"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--out"), "{stderr}");
}

#[test]
fn the_root_is_found_from_a_subdirectory() {
    let found = lightlab::cli::find_book_dir_from(&Path::new(env!("CARGO_MANIFEST_DIR")).join("src").join("cli"));
    assert_eq!(found, Some(Path::new(env!("CARGO_MANIFEST_DIR")).join("book")));
    assert_eq!(lightlab::cli::find_book_dir_from(&scratch("no-root-lib")), None);
}

#[test]
fn readme_repeats_the_exit_status_table() {
    let readme = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).expect("README");
    let rows: Vec<(&str, &str)> =
        lightlab::cli::EXIT_STATUS_HELP.lines().skip(1).filter_map(|l| l.trim().split_once("  ")).collect();
    assert_eq!(rows.len(), 5, "{}", lightlab::cli::EXIT_STATUS_HELP);
    for (status, meaning) in rows {
        let row = format!("| {status} | {} |", meaning.trim());
        assert!(readme.contains(&row), "README lacks the row {row:?}");
    }
}

/// `--lang` and `--hints` are global: before the subcommand as after it (`lightlab --lang
/// fr exercise list`, as the top-level help lists them). The book's own options before a
/// subcommand are a usage error naming the option.
#[test]
fn global_options_come_before_the_subcommand_and_book_options_do_not() {
    let out = run_in(None, &["--lang", "fr", "exercise", "list"]);
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    assert!(stdout.contains("Déplacer la lumière au fil du temps"), "{stdout}");
    let out = run_in(None, &["--root", "/nonexistent", "exercise", "list"]);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("--root") && stderr.contains("`book`"), "{stderr}");
}

/// A file that cannot be read is refused in the learner's language: what it is, and why
/// (`cli/input.rs`'s msgids; the system's own reason stays as the system words it).
#[test]
fn unreadable_inputs_are_refused_in_the_learners_language() {
    let dir = scratch("unreadable");
    let folder = dir.join("answer.txt");
    std::fs::create_dir(&folder).unwrap();
    let folder = folder.to_str().unwrap();
    for (lang, kind, why) in [
        ("en", "a directory", "only regular files are read"),
        ("fr", "un dossier", "seuls les fichiers ordinaires sont lus"),
        ("uk", "тека", "читаються лише звичайні файли"),
    ] {
        let out = run_in(None, &["--lang", lang, "exercise", "check", "casters-swap-comparison", folder]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{lang}: {stderr}");
        assert!(stderr.contains(kind) && stderr.contains(why), "{lang}: {stderr}");
    }
}

/// The error line itself, and an unknown exercise's message, are in the learner's
/// language too (they were English around a translated reason).
#[test]
fn the_error_line_and_an_unknown_exercise_are_in_the_learners_language() {
    for (lang, line, unknown) in [
        ("en", "lightlab exercise: error: ", "unknown exercise `no-such`; exercises: basic-move-light"),
        (
            "fr",
            "lightlab exercise\u{a0}: erreur\u{a0}: ",
            "exercice inconnu `no-such`\u{a0}; exercices\u{a0}: basic-move-light",
        ),
        ("uk", "lightlab exercise: помилка: ", "невідома вправа `no-such`; вправи: basic-move-light"),
    ] {
        let out = run_in(None, &["--lang", lang, "exercise", "show", "no-such"]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{lang}: {stderr}");
        assert!(stderr.starts_with(&format!("{line}{unknown}")), "{lang}: {stderr}");
    }
}

/// clap's usage errors are in the learner's language too (`cli/usage_error.rs`): an
/// unknown option with clap's suggestion, a refused value with the possible ones, an
/// unknown subcommand. English stays clap's own, word for word; every one exits 2.
#[test]
fn usage_errors_are_in_the_learners_language() {
    use lightlab::i18n::Lang;
    let cases: [(&[&str], [&str; 2]); 3] = [
        (&["bench", "--rums", "3"], ["--rums", "--runs"]),
        (&["--lang", "de", "bench"], ["de", "en, fr, uk"]),
        (&["benhc"], ["benhc", "bench"]),
    ];
    for (args, pieces) in cases {
        let en = run_in(None, args);
        let en_text = String::from_utf8_lossy(&en.stderr).into_owned();
        assert_eq!(en.status.code(), Some(2), "{args:?}: {en_text}");
        assert!(en_text.starts_with("error: ") && en_text.contains("For more information, try '--help'."), "{en_text}");
        for lang in [Lang::Fr, Lang::Uk] {
            let out = Command::new(BIN).env("LIGHTLAB_LANG", lang.code()).args(args).output().expect("runs");
            let text = String::from_utf8_lossy(&out.stderr).into_owned();
            assert_eq!(out.status.code(), Some(2), "{lang:?} {args:?}: {text}");
            for piece in pieces {
                assert!(text.contains(piece), "{lang:?} {args:?}: {piece} is named:\n{text}");
            }
            assert!(text.contains(&lang.quoted(pieces[0])), "{lang:?}: quoted as the language quotes:\n{text}");
            for english in ["error:", "Usage:", "For more information", "unexpected", "invalid value", "tip:"] {
                assert!(!text.contains(english), "{lang:?} {args:?}: {english} is left:\n{text}");
            }
        }
    }
}

/// `--help` is in the reader's language: clap's headings and every help text of the
/// command (its about, each argument's help, a possible value's help), with the defaults
/// and possible values that clap would have printed in English. English is clap's own.
#[test]
fn the_help_is_in_the_readers_language() {
    use lightlab::cli::help::{DEFAULT, POSSIBLE, USAGE};
    use lightlab::i18n::{catalog::tr_fill, tr, Lang};
    let english = lightlab::cli::args::command(Lang::En);
    let grade = english.find_subcommand("grade").expect("grade exists");
    let helps: Vec<String> = grade
        .get_arguments()
        .filter(|a| !a.is_hide_set())
        .filter_map(|a| a.get_help())
        .map(|h| h.to_string())
        .collect();
    assert!(helps.len() >= 10, "grade has {} documented arguments", helps.len());
    let check = english.find_subcommand("exercise").and_then(|e| e.find_subcommand("check")).expect("exercise check");
    let cases_arg = check.get_arguments().find(|a| a.get_id() == "cases").expect("--cases");
    let default_cases = cases_arg.get_default_values()[0].to_string_lossy().into_owned();
    let en = String::from_utf8_lossy(&run_in(None, &["--lang", "en", "grade", "-h"]).stdout).into_owned();
    assert!(en.contains("Usage: lightlab grade") && en.contains("Options:"), "{en}");
    for lang in [Lang::Fr, Lang::Uk] {
        let code = lang.code();
        // LIGHTLAB_LANG or --lang, before or after the subcommand: the same help
        let out = run_in(None, &["grade", "--lang", code, "-h"]);
        assert_eq!(out.status.code(), Some(0), "{code}");
        let help = String::from_utf8_lossy(&out.stdout).into_owned();
        let usage = tr(lang, USAGE);
        assert_ne!(usage, USAGE, "{code}: `Usage:` is translated");
        assert!(help.contains(&format!("{usage} lightlab grade")), "{code}:\n{help}");
        assert!(help.contains(&*tr(lang, grade.get_about().unwrap().to_string().as_str())), "{code}:\n{help}");
        for h in &helps {
            let translated = tr(lang, h);
            assert!(help.contains(&*translated), "{code}: {h:?} is not shown as {translated:?}:\n{help}");
            assert!(translated == *h || !help.contains(h.as_str()), "{code}: {h:?} is still English:\n{help}");
        }
        for english_word in ["Usage:", "[default:", "[possible values:", "Possible values:"] {
            assert!(!help.contains(english_word), "{code}: {english_word} is left:\n{help}");
        }
        let cases =
            String::from_utf8_lossy(&run_in(None, &["--lang", code, "exercise", "check", "-h"]).stdout).into_owned();
        assert!(cases.contains(&tr_fill(lang, DEFAULT, &[&default_cases])), "{code}:\n{cases}");
        assert!(cases.contains(&tr_fill(lang, POSSIBLE, &["text, json"])), "{code}:\n{cases}");
        // the positionals keep their order (clap sorts a headed list by display order)
        assert!(cases.find("<ID>").unwrap() < cases.find("<FILE>").unwrap(), "{code}:\n{cases}");
        let via_env = Command::new(BIN).env("LIGHTLAB_LANG", code).args(["grade", "-h"]).output().expect("runs");
        assert_eq!(String::from_utf8_lossy(&via_env.stdout), help, "{code}: LIGHTLAB_LANG gives the same help");
    }
}
