//! The core's one error shape: a named input field and what is wrong with it; and the
//! text of a caught panic.
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

/// The message of a caught panic: the payload of `panic!("…")` (a `&str` or a
/// `String`), or `(no message)` for any other payload.
pub fn panic_text(payload: &(dyn std::any::Any + Send)) -> String {
    if let Some(s) = payload.downcast_ref::<&str>() {
        (*s).to_owned()
    } else if let Some(s) = payload.downcast_ref::<String>() {
        s.clone()
    } else {
        "(no message)".to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::{panic_text, FieldError};

    #[test]
    fn panic_text_reads_str_and_string_payloads() {
        let from_str = std::panic::catch_unwind(|| panic!("plain")).unwrap_err();
        assert_eq!(panic_text(&*from_str), "plain");
        let n = 3;
        let from_string = std::panic::catch_unwind(move || panic!("formatted {n}")).unwrap_err();
        assert_eq!(panic_text(&*from_string), "formatted 3");
        let other = std::panic::catch_unwind(|| std::panic::panic_any(7_u8)).unwrap_err();
        assert_eq!(panic_text(&*other), "(no message)");
    }

    #[test]
    fn displays_field_then_reason() {
        let e = FieldError::new("near", "must be > 0, got -1");
        assert_eq!(e.to_string(), "near: must be > 0, got -1");
    }
}
