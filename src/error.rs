//! The core's one error shape: a named input field and what is wrong with it.
//!
//! Every checked constructor of the core (lights, cameras, framebuffers, meshes)
//! fails with a [`FieldError`], so a caller reporting a bad input names the field the
//! user wrote, whatever the constructor. The aliases ([`crate::casters::ParamError`],
//! [`crate::raster::camera::CameraError`], [`crate::raster::framebuffer::SizeError`],
//! [`crate::raster::mesh::MeshError`]) name the same type after the place that
//! returns it.

/// A field that makes a value invalid, and why.
///
/// Displays as `field: reason`.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    /// The field, as the JSON and TOML inputs spell it (e.g. `cut_off_deg`, `width`,
    /// `normals`).
    pub field: &'static str,
    /// What is wrong with it.
    pub reason: String,
}

impl FieldError {
    /// The error for `field`, with `reason`.
    pub fn new(field: &'static str, reason: impl Into<String>) -> FieldError {
        FieldError { field, reason: reason.into() }
    }
}

impl std::fmt::Display for FieldError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.field, self.reason)
    }
}

impl std::error::Error for FieldError {}

#[cfg(test)]
mod tests {
    use super::FieldError;

    #[test]
    fn displays_field_then_reason() {
        let e = FieldError::new("near", "must be > 0, got -1");
        assert_eq!(e.to_string(), "near: must be > 0, got -1");
    }
}
