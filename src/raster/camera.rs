//! The camera: view and projection matrices and the viewport, glam conventions.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `view` | world → eye space, the eye at the origin looking down −z |
//! | `projection` | eye → clip space (OpenGL: depth in [−1, 1] after division) |
//! | `viewport` | NDC → window pixels, origin at the lower left, y up |
//!
//! Source: LearnOpenGL, Coordinate systems and Camera (`glm::lookAt`,
//! `glm::perspective`); glam `camera::rh::view::look_at_mat4`, `camera::rh::proj::opengl::perspective`.

use glam::{Mat4, Vec3};

/// A camera's matrices and eye position.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Eye position in world space (the shaders' `viewPos`).
    pub eye: Vec3,
    /// World → eye.
    pub view: Mat4,
    /// Eye → clip.
    pub projection: Mat4,
}

/// A camera parameter that cannot make a camera, naming the field: `eye`, `target`,
/// `up`, `fovy_deg`, `aspect`, `near` or `far`.
pub type CameraError = crate::error::FieldError;

/// The OpenGL perspective projection, as `glm::perspective`.
///
/// ```text
/// t = 1 / tan(fovy / 2)
/// | t/aspect 0  0                 0               |
/// | 0        t  0                 0               |
/// | 0        0  (f+n)/(n-f)       2 f n / (n-f)   |
/// | 0        0  -1                0               |
/// ```
///
/// Errors name the field: `fovy_deg` outside (0, 180), `aspect` ≤ 0,
/// `near` ≤ 0, `far` ≤ `near`, or any non-finite value.
pub fn perspective(fovy_deg: f32, aspect: f32, near: f32, far: f32) -> Result<Mat4, CameraError> {
    if !(fovy_deg > 0.0 && fovy_deg < 180.0) {
        return Err(CameraError::new("fovy_deg", format!("must be in (0, 180), got {fovy_deg}")));
    }
    if !(aspect > 0.0 && aspect.is_finite()) {
        return Err(CameraError::new("aspect", format!("must be > 0, got {aspect}")));
    }
    if !(near > 0.0 && near.is_finite()) {
        return Err(CameraError::new("near", format!("must be > 0, got {near}")));
    }
    if !(far > near && far.is_finite()) {
        return Err(CameraError::new("far", format!("must be finite and > near ({near}), got {far}")));
    }
    Ok(glam::camera::rh::proj::opengl::perspective(fovy_deg.to_radians(), aspect, near, far))
}

/// The view matrix of an eye at `eye` looking at `target` with `up` roughly up, as `glm::lookAt`.
///
/// Errors name the field: `target` equal to `eye`, `up` parallel to the
/// viewing direction or zero, any non-finite input.
pub fn look_at(eye: Vec3, target: Vec3, up: Vec3) -> Result<Mat4, CameraError> {
    if !(eye.is_finite() && target.is_finite() && up.is_finite()) {
        return Err(CameraError::new("eye", "eye, target and up must be finite"));
    }
    let front = (target - eye).try_normalize().ok_or_else(|| CameraError::new("target", "must differ from eye"))?;
    if front.cross(up).length_squared() <= 1e-12 * up.length_squared().max(f32::MIN_POSITIVE) {
        return Err(CameraError::new("up", "must be non-zero and not parallel to target - eye"));
    }
    Ok(glam::camera::rh::view::look_at_mat4(eye, target, up.normalize()))
}

impl Camera {
    /// A camera at `eye` looking at `target`, with the perspective projection.
    ///
    /// Errors as [`look_at`] and [`perspective`].
    pub fn new(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fovy_deg: f32,
        aspect: f32,
        near: f32,
        far: f32,
    ) -> Result<Camera, CameraError> {
        Ok(Camera { eye, view: look_at(eye, target, up)?, projection: perspective(fovy_deg, aspect, near, far)? })
    }

    /// The tutorials' default camera: at (0, 0, 3) looking down −z
    /// (`view = translate(0, 0, −3)`), `perspective(45°, aspect, 0.1, 100)`.
    ///
    /// A non-positive or non-finite `aspect` falls back to 4/3.
    ///
    /// Source: LearnOpenGL, Camera (initial position); `../shared/DESIGN.md`.
    pub fn learnopengl(aspect: f32) -> Camera {
        let aspect = if aspect > 0.0 && aspect.is_finite() { aspect } else { 4.0 / 3.0 };
        Camera {
            eye: Vec3::new(0.0, 0.0, 3.0),
            view: Mat4::from_translation(Vec3::new(0.0, 0.0, -3.0)),
            projection: glam::camera::rh::proj::opengl::perspective(45f32.to_radians(), aspect, 0.1, 100.0),
        }
    }

    /// `projection · view`.
    pub fn view_projection(&self) -> Mat4 {
        self.projection * self.view
    }
}

/// The viewport transform from normalized device coordinates to window pixels.
///
/// ```text
/// x_w = x_ndc · w/2 + w/2,  y_w = y_ndc · h/2 + h/2,  z_w = z_ndc · ½ + ½
/// ```
///
/// Window coordinates have their origin at the lower-left corner, y up, as
/// OpenGL's `glViewport`; pixel `(i, j)` has its centre at `(i + ½, j + ½)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
}

impl Viewport {
    /// The window position of an NDC point.
    pub fn to_window(&self, ndc: Vec3) -> Vec3 {
        let (hw, hh) = (self.width as f32 * 0.5, self.height as f32 * 0.5);
        Vec3::new(ndc.x * hw + hw, ndc.y * hh + hh, ndc.z * 0.5 + 0.5)
    }
}
