//! Shared strategies, configuration and comparison helpers for the property tests.
#![allow(dead_code)]

use glam::{DMat4, DQuat, DVec3, Mat3, Mat4, Quat, Vec3};
use proptest::prelude::*;
use proptest::test_runner::{RngSeed, TestCaseError};

/// Unit roundoff of `f32` (half an ulp of 1): every correctly rounded `f32`
/// operation has relative error at most `U`.
pub const U: f64 = f32::EPSILON as f64 / 2.0;

/// 256 cases from a fixed seed, so every run sees the same inputs (no
/// unseeded randomness), and no regression files written next to the tests.
pub fn config() -> ProptestConfig {
    ProptestConfig {
        cases: 256,
        rng_seed: RngSeed::Fixed(0x1167_2024),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// A unit vector uniform on the sphere (Archimedes: uniform z and azimuth),
/// normalized in `f32` so it is unit to within a few ulps.
pub fn unit_vec3() -> impl Strategy<Value = Vec3> {
    (-1.0f32..=1.0, 0.0f32..std::f32::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(r * phi.cos(), r * phi.sin(), z).normalize()
    })
}

/// A vector with every component in `[-r, r]`.
pub fn vec3_in(r: f32) -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(-r..=r).prop_map(Vec3::from_array)
}

/// A colour with every channel in `[0, 1]`.
pub fn color() -> impl Strategy<Value = Vec3> {
    prop::array::uniform3(0.0f32..=1.0).prop_map(Vec3::from_array)
}

/// A rotation from a unit axis and an angle in `[-π, π]`.
pub fn rotation() -> impl Strategy<Value = Quat> {
    (unit_vec3(), -std::f32::consts::PI..std::f32::consts::PI)
        .prop_map(|(axis, angle)| Quat::from_axis_angle(axis, angle))
}

/// A rigid motion: unit axis, angle in `[-π, π]`, translation in `[-10, 10]³`.
#[derive(Clone, Copy, Debug)]
pub struct Rigid {
    /// Rotation axis (unit).
    pub axis: Vec3,
    /// Rotation angle in radians.
    pub angle: f32,
    /// Translation.
    pub translation: Vec3,
}

impl Rigid {
    /// The `f32` matrix (orthonormal to a few `f32` ulps).
    pub fn mat4(&self) -> Mat4 {
        Mat4::from_rotation_translation(Quat::from_axis_angle(self.axis, self.angle), self.translation)
    }

    /// The same motion built in `f64` (orthonormal to a few `f64` ulps).
    pub fn dmat4(&self) -> DMat4 {
        let q = DQuat::from_axis_angle(self.axis.as_dvec3().normalize(), self.angle as f64);
        DMat4::from_rotation_translation(q, self.translation.as_dvec3())
    }
}

/// A rigid view: see [`Rigid`].
pub fn rigid_view() -> impl Strategy<Value = Rigid> {
    (unit_vec3(), -std::f32::consts::PI..std::f32::consts::PI, vec3_in(10.0))
        .prop_map(|(axis, angle, translation)| Rigid { axis, angle, translation })
}

/// An invertible 3×3 matrix with entries in `[-2, 2]`: general linear maps,
/// non-uniform scale and shear included. `|det| >= 0.05` and a Frobenius
/// condition number below 200 keep `f32` inverses meaningful.
pub fn invertible_mat3() -> impl Strategy<Value = Mat3> {
    prop::array::uniform9(-2.0f32..=2.0)
        .prop_map(|a| Mat3::from_cols_array(&a))
        .prop_filter("well-conditioned invertible matrix", |m| {
            m.determinant().abs() >= 0.05 && lightlab::normals::condition_number(*m) < 200.0
        })
}

/// A tangent/normal pair: `n` unit, `t` unit and perpendicular to `n`.
pub fn normal_and_tangent() -> impl Strategy<Value = (Vec3, Vec3)> {
    (unit_vec3(), unit_vec3()).prop_filter_map("tangent not parallel to normal", |(n, v)| {
        let t = v - n * n.dot(v);
        t.try_normalize().filter(|_| t.length() > 0.1).map(|t| (n, t))
    })
}

/// Fail with expected, actual and difference unless `|actual − expected| <= tol`.
pub fn close(what: &str, expected: f64, actual: f64, tol: f64) -> Result<(), TestCaseError> {
    let diff = (actual - expected).abs();
    if diff <= tol {
        Ok(())
    } else {
        Err(TestCaseError::fail(format!(
            "{what}: expected {expected:e}, actual {actual:e}, difference {diff:e} > tolerance {tol:e}"
        )))
    }
}

/// [`close`] channel by channel.
pub fn close3(what: &str, expected: DVec3, actual: DVec3, tol: f64) -> Result<(), TestCaseError> {
    for k in 0..3 {
        close(&format!("{what}[{k}] (expected {expected}, actual {actual})"), expected[k], actual[k], tol)?;
    }
    Ok(())
}

/// Largest absolute channel difference.
pub fn max_diff3(a: DVec3, b: DVec3) -> f64 {
    (a - b).abs().max_element()
}

/// Runs the built `lightlab` with `args`, in English (`LIGHTLAB_LANG=en`: tests that
/// compare English text do not depend on the machine's locale; `--lang` still wins):
/// (exit status, stdout, stderr).
#[cfg(feature = "book")]
pub fn lightlab(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .args(args)
        .env("LIGHTLAB_LANG", "en")
        .output()
        .expect("run lightlab");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code().unwrap_or(-1), stdout, stderr)
}

/// Runs the built `lightlab` with `args` and `input` on its standard input, in English as
/// [`lightlab`] does: (exit status, stdout, stderr).
#[cfg(feature = "book")]
pub fn lightlab_with_input(args: &[&str], input: &str) -> (i32, String, String) {
    use std::io::Write as _;
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_lightlab"))
        .args(args)
        .env("LIGHTLAB_LANG", "en")
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("run lightlab");
    child.stdin.take().expect("stdin").write_all(input.as_bytes()).expect("write stdin");
    let out = child.wait_with_output().expect("wait for lightlab");
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    (out.status.code().unwrap_or(-1), stdout, stderr)
}

/// The Basic lighting exercise's declarations ([`BASIC_LIGHTING_HEAD`]) with a live local array of `n` floats:
/// every fragment of the batch needs it, so llvmpipe reserves far more than 512 MiB.
pub fn huge_array(n: u32) -> String {
    format!(
        "{}void main()
{{
    float a[{n}];
    for (int i = 0; i < {n}; i++) a[i] = FragPos.x * float(i);
    int k = int(abs(FragPos.y) * {last}.0);
    FragColor = vec4(a[k] * lightColor * objectColor, 1.0);
}}
",
        BASIC_LIGHTING_HEAD,
        last = n - 1
    )
}

/// A test's scratch folder, removed with everything in it when dropped: at the end of the
/// test that holds it, passed or panicked, so no run leaves folders in the temporary
/// directory. It dereferences to its [`std::path::Path`]. Bind it to a name: a guard used
/// only in an expression (`temp_dir(..).join(..)`) removes the folder at the end of the
/// statement.
#[must_use = "the folder is removed when the guard is dropped"]
pub struct TempDir(std::path::PathBuf);

impl TempDir {
    /// A fresh empty folder `lightlab-<prefix>-<pid>-<n>-<name>` in the temporary directory,
    /// `n` counting the guards of this process: tests run in parallel threads, and two of them
    /// asking for the same name must not share (and delete) one folder. A leftover of the same
    /// name, from a killed run of this process id, is emptied first.
    pub fn new(prefix: &str, name: &str) -> TempDir {
        let n = next_scratch_number();
        let dir = std::env::temp_dir().join(format!("lightlab-{prefix}-{}-{n}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
        TempDir(dir)
    }

    /// The folder.
    pub fn path(&self) -> &std::path::Path {
        &self.0
    }
}

impl std::ops::Deref for TempDir {
    type Target = std::path::Path;

    fn deref(&self) -> &std::path::Path {
        &self.0
    }
}

impl AsRef<std::path::Path> for TempDir {
    fn as_ref(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        // best effort: a failure to clean up must not hide the test's own outcome
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The next number of this process's scratch folders and files (see [`TempDir::new`]).
fn next_scratch_number() -> usize {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed)
}

/// A test's scratch file `lightlab-<pid>-<n>-<name>` in the temporary directory holding
/// `text`, removed when dropped, as [`TempDir`] is. It dereferences to its path.
pub struct TempFile(std::path::PathBuf);

impl TempFile {
    /// Writes `text` to the file (replacing a leftover of the same name).
    pub fn new(name: &str, text: &str) -> TempFile {
        let n = next_scratch_number();
        let path = std::env::temp_dir().join(format!("lightlab-{}-{n}-{name}", std::process::id()));
        std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        TempFile(path)
    }
}

impl std::ops::Deref for TempFile {
    type Target = std::path::Path;

    fn deref(&self) -> &std::path::Path {
        &self.0
    }
}

impl AsRef<std::path::Path> for TempFile {
    fn as_ref(&self) -> &std::path::Path {
        &self.0
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

/// A fresh empty folder `lightlab-<prefix>-<pid>-<name>` in the temporary directory,
/// removed when the returned guard is dropped ([`TempDir`]).
pub fn temp_dir(prefix: &str, name: &str) -> TempDir {
    TempDir::new(prefix, name)
}

/// The text of `src/gl/shaders/examples/<name>` (the example class's shaders).
/// The Basic lighting exercise's declarations, the head of the test shaders that grade it.
pub const BASIC_LIGHTING_HEAD: &str = "#version 330 core
in vec3 FragPos;
in vec3 Normal;
out vec4 FragColor;
uniform vec3 lightPos;
uniform vec3 viewPos;
uniform vec3 lightColor;
uniform vec3 objectColor;
";

pub fn example_shader(name: &str) -> String {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("src/gl/shaders/examples").join(name);
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// A copy of the book's sources from `from` to `to`: every file and folder but `build`,
/// `generated` and hidden ones (a test builds its own).
pub fn copy_book_tree(from: &std::path::Path, to: &std::path::Path) {
    std::fs::create_dir_all(to).unwrap();
    for entry in std::fs::read_dir(from).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name().to_string_lossy().into_owned();
        if name == "build" || name == "generated" || name.starts_with('.') {
            continue;
        }
        let (src, dst) = (entry.path(), to.join(&name));
        if src.is_dir() {
            copy_book_tree(&src, &dst);
        } else {
            std::fs::copy(&src, &dst).unwrap();
        }
    }
}
