//! Output paths are written, not replaced: `render -o` through a temporary file and a
//! rename only onto a regular file or nothing, following symbolic links, refusing
//! directories and FIFOs with an error naming the path, leaving no temporary file;
//! `study --out` locks its directory so a second run waits.
//!
//! Runs the binary, as a user would.
#![cfg(feature = "book")]

use std::io::{BufRead, BufReader};
use std::path::Path;
use std::process::{Command, Output, Stdio};

const BIN: &str = env!("CARGO_BIN_EXE_lightlab");

fn scratch(name: &str) -> crate::common::TempDir {
    crate::common::TempDir::new("cli-paths", name)
}

fn entries(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// `lightlab render --preset quad-single --size 8x6 -o PATH` (a tiny frame: fast).
fn render_to(path: &Path) -> Output {
    Command::new(BIN)
        .args(["render", "--preset", "quad-single", "--size", "8x6", "-o"])
        .arg(path)
        .stdin(Stdio::null())
        .output()
        .expect("lightlab runs")
}

const PNG_MAGIC: &[u8] = b"\x89PNG\r\n\x1a\n";

#[test]
fn regular_file_is_written_and_replaced() {
    let dir = scratch("regular");
    let out = dir.join("out.png");
    for _ in 0..2 {
        let o = render_to(&out);
        assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(std::fs::read(&out).expect("png").starts_with(PNG_MAGIC));
    assert_eq!(entries(&dir), ["out.png"]);
}

#[test]
fn directory_is_refused_by_name_and_nothing_is_left() {
    let dir = scratch("directory");
    let target = dir.join("some_directory");
    std::fs::create_dir(&target).expect("mkdir");
    let o = render_to(&target);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(&target.display().to_string()) && stderr.contains("directory"), "{stderr}");
    assert_eq!(entries(&dir), ["some_directory"], "a temporary file was left behind");
    assert!(entries(&target).is_empty());
}

#[cfg(unix)]
#[test]
fn symlink_is_followed_and_kept() {
    let dir = scratch("symlink");
    let real = dir.join("real.png");
    std::fs::write(&real, "old").expect("write");
    let link = dir.join("link.png");
    std::os::unix::fs::symlink("real.png", &link).expect("symlink");
    let o = render_to(&link);
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(std::fs::symlink_metadata(&link).expect("meta").file_type().is_symlink(), "the link was replaced");
    assert!(std::fs::read(&real).expect("png").starts_with(PNG_MAGIC));
}

#[cfg(unix)]
#[test]
fn fifo_is_refused_and_kept() {
    use std::os::unix::fs::FileTypeExt;
    let dir = scratch("fifo");
    let fifo = dir.join("pipe.png");
    let made = Command::new("mkfifo").arg(&fifo).status();
    if !matches!(made, Ok(s) if s.success()) {
        eprintln!("no mkfifo here; skipped");
        return;
    }
    let o = render_to(&fifo);
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(&fifo.display().to_string()) && stderr.contains("FIFO"), "{stderr}");
    assert!(std::fs::symlink_metadata(&fifo).expect("meta").file_type().is_fifo(), "the FIFO was replaced");
    assert_eq!(entries(&dir), ["pipe.png"]);
}

#[cfg(unix)]
#[test]
fn device_is_refused() {
    // /dev/null is a character device on every unix; as root the old code renamed a
    // regular file over it.
    let o = render_to(Path::new("/dev/null"));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("/dev/null: is a device"), "{stderr}");
}

#[test]
fn missing_directory_is_named() {
    let dir = scratch("missing");
    let missing = dir.join("no_such_dir");
    let o = render_to(&missing.join("out.png"));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(&missing.display().to_string()), "{stderr}");
}

#[cfg(unix)]
#[test]
fn read_only_directory_is_named() {
    use std::os::unix::fs::PermissionsExt;
    let dir = scratch("read-only");
    let ro = dir.join("ro");
    std::fs::create_dir(&ro).expect("mkdir");
    std::fs::set_permissions(&ro, std::fs::Permissions::from_mode(0o555)).expect("chmod");
    if std::fs::write(ro.join("probe"), "x").is_ok() {
        eprintln!("running as root: permissions are not enforced; skipped");
        return;
    }
    let o = render_to(&ro.join("out.png"));
    let stderr = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains(&ro.display().to_string()), "{stderr}");
}

#[test]
fn stale_temporary_files_are_removed() {
    let dir = scratch("stale");
    // What a save killed half-way leaves: pid 4294967295 is above any pid_max.
    std::fs::write(dir.join(".out.png.4294967295-0.lightlab-tmp"), "partial").expect("write");
    let o = render_to(&dir.join("out.png"));
    assert_eq!(o.status.code(), Some(0), "{}", String::from_utf8_lossy(&o.stderr));
    assert_eq!(entries(&dir), ["out.png"]);
}

#[test]
fn a_second_study_waits_for_the_lock_and_names_the_holder() {
    let dir = scratch("study-lock");
    let lock = lightlab::outfile::lock_dir(&dir, |_| panic!("the directory is new")).expect("lock");
    let mut child = Command::new(BIN)
        .args(["study", "--quick", "--out"])
        .arg(dir.path())
        .stdin(Stdio::null())
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("lightlab runs");
    let mut stderr = BufReader::new(child.stderr.take().expect("stderr"));
    let mut first = String::new();
    stderr.read_line(&mut first).expect("read stderr");
    // Before any work, the study says it waits, and for whom.
    assert!(
        first.contains("waiting for the lock") && first.contains(&std::process::id().to_string()),
        "first line: {first:?}"
    );
    drop(lock);
    let mut rest = String::new();
    std::io::Read::read_to_string(&mut stderr, &mut rest).expect("read stderr");
    let status = child.wait().expect("wait");
    assert_eq!(status.code(), Some(0), "{rest}");
    let files = entries(&dir);
    assert!(files.iter().any(|f| f.ends_with(".csv")) && files.iter().any(|f| f.ends_with(".png")), "{files:?}");
    assert!(!files.iter().any(|f| f.contains("tmp")), "temporary files left: {files:?}");
}
