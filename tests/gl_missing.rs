//! A machine without parts of OpenGL gets a typed error from `GlContext`, never a panic.
//!
//! The missing Mesa vendor and DRI driver are simulated in a child process (the loader reads
//! these variables once, when libEGL is first opened):
//! - `__EGL_VENDOR_LIBRARY_FILENAMES` pointing at no file: libglvnd finds no vendor;
//! - `LIBGL_DRIVERS_PATH` pointing at an empty directory: Mesa finds no DRI driver.
#![cfg(feature = "gl")]

use std::process::Command;

use lightlab::gl::{GlContext, GlError};

#[test]
fn missing_library_is_an_error() {
    let err = GlContext::with_library("libEGL-does-not-exist.so.1").unwrap_err();
    println!("{err}");
    assert!(matches!(err, GlError::LibraryMissing { .. }), "{err:?}");
    assert!(err.to_string().contains("libegl1"), "the message names the package");
}

/// In the child: print the error kind of `GlContext::new()`.
#[test]
fn child_report() {
    if std::env::var("LIGHTLAB_GL_CHILD").is_err() {
        return;
    }
    match GlContext::new() {
        Ok(ctx) => println!("CHILD: ok {}", ctx.info().renderer),
        Err(e) => println!("CHILD: {} | {e}", e.kind()),
    }
}

fn run_child(var: &str, value: &str) -> String {
    let exe = std::env::current_exe().unwrap();
    // the test's name in this binary: `child_report`, or `gl_missing::child_report` when this
    // file is a module of tests/suite.rs
    let name =
        module_path!().split_once("::").map_or("child_report".to_string(), |(_, m)| format!("{m}::child_report"));
    let out = Command::new(exe)
        .args(["--exact", &name, "--nocapture", "--test-threads=1"])
        .env("LIGHTLAB_GL_CHILD", "1")
        .env(var, value)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(out.status.success(), "child failed (a panic?):\n{stdout}\n{}", String::from_utf8_lossy(&out.stderr));
    match stdout.find("CHILD:") {
        Some(i) => stdout[i..].lines().next().unwrap_or_default().to_string(),
        None => "CHILD: no report".to_string(),
    }
}

#[test]
fn missing_vendor_or_driver_is_an_error_not_a_panic() {
    if GlContext::new().is_err() {
        println!("skipped: no OpenGL here, nothing to take away");
        return;
    }
    let dir = crate::common::temp_dir("empty-dri", "drivers");
    let no_vendor = run_child("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/vendor.json");
    println!("no Mesa vendor: {no_vendor}");
    assert!(no_vendor.starts_with("CHILD: missing_extension"), "{no_vendor}");
    let no_driver = run_child("LIBGL_DRIVERS_PATH", dir.to_str().unwrap());
    println!("no DRI driver: {no_driver}");
    assert!(no_driver.starts_with("CHILD: egl"), "{no_driver}");
    assert!(no_driver.contains("libgl1-mesa-dri"), "{no_driver}");
}

/// Without a Mesa vendor, `exercise check` and `grade` of a shader exercise stop with the
/// message and exit 3 (OpenGL missing is an internal failure, `lightlab --help`), before
/// reading any answer; numeric exercises still work without OpenGL.
#[test]
fn exercise_commands_without_opengl_exit_3() {
    let bin = env!("CARGO_BIN_EXE_lightlab");
    let dir = crate::common::temp_dir("gl-missing", "answers");
    let shader = dir.join("mine.frag");
    std::fs::write(&shader, "#version 330 core\nout vec4 FragColor;\nvoid main() { FragColor = vec4(1.0); }\n")
        .unwrap();
    let run = |args: &[&str]| {
        Command::new(bin)
            .args(args)
            .env("LIGHTLAB_LANG", "en")
            .env("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/vendor.json")
            .output()
            .unwrap()
    };
    for args in [
        vec!["exercise", "check", "basic-move-light", shader.to_str().unwrap()],
        vec!["grade", dir.to_str().unwrap(), "--exercise", "basic-move-light"],
    ] {
        let out = run(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(3), "{args:?}: {stderr}");
        assert!(stderr.contains("no OpenGL context"), "{args:?}: {stderr}");
    }
    let answer = dir.join("answer.txt");
    std::fs::write(&answer, "32\n").unwrap();
    let out = run(&["exercise", "check", "materials-cyan-plastic", answer.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stdout));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `bench --llvmpipe` without a Mesa vendor stops with the message and exit 3 before any
/// line is printed (plain `bench` does not need OpenGL).
#[test]
fn bench_llvmpipe_without_opengl_exits_3() {
    let out = Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .env("LIGHTLAB_LANG", "en")
        .args(["bench", "quad-single", "--llvmpipe", "--runs", "1", "--frames", "1"])
        .env("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent/vendor.json")
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(3), "{stderr}");
    assert!(stderr.contains("--llvmpipe needs an OpenGL context"), "{stderr}");
    assert!(out.stdout.is_empty(), "nothing measured before the context failed");
}
