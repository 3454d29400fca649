//! Scene files (TOML): placeholder.

/// Load a scene file.
pub fn load(
    path: &std::path::Path,
    _aspect: f32,
) -> Result<crate::raster::pipeline::World, Box<dyn std::error::Error>> {
    Err(format!("{}: scene files are not supported yet", path.display()).into())
}
