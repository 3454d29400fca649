//! The triangle-size sweep (`lightlab bench --sweep`): `sphere4096-multi` with its sphere
//! tessellated from 256 to 262,144 triangles ([`SWEEP_STACKS`]) at 800 × 600, the same
//! fragments shaded in every frame but split into ever smaller triangles, so the cost of
//! setting up and walking small, partly covered triangles shows against the shading.
//! With `--llvmpipe`, each tessellation is also drawn through OpenGL in the same run.

use serde::{Deserialize, Serialize};

pub use crate::raster::presets::SWEEP_STACKS;

/// Triangles of the sweep's sphere at `stacks` stacks (`2 · stacks` slices): `4 · stacks²`.
pub fn triangles(stacks: u32) -> usize {
    4 * stacks as usize * stacks as usize
}

/// One tessellation: a line of `lightlab bench --sweep` and of its CSV.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepRow {
    /// Stacks of the UV sphere.
    pub stacks: u32,
    /// Triangles of the mesh (the zero-area ones at the poles included).
    pub triangles: usize,
    /// Covered pixels of a frame.
    pub fragments: usize,
    /// lightlab's median ms per frame.
    pub lightlab_ms: f64,
    /// llvmpipe's median ms per frame in the same run (`None` without `--llvmpipe`).
    pub llvmpipe_ms: Option<f64>,
}

impl SweepRow {
    /// Covered pixels per triangle (half the triangles face away and are culled, so a
    /// drawn triangle covers about twice this).
    pub fn pixels_per_triangle(&self) -> f64 {
        self.fragments as f64 / self.triangles.max(1) as f64
    }

    /// llvmpipe's time over lightlab's, when both were measured.
    pub fn ratio(&self) -> Option<f64> {
        self.llvmpipe_ms.map(|gl| gl / self.lightlab_ms)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sweep_spans_256_to_262144_triangles_and_its_meshes_have_them() {
        assert_eq!(triangles(SWEEP_STACKS[0]), 256);
        assert_eq!(triangles(*SWEEP_STACKS.last().unwrap()), 262_144);
        let world = crate::raster::presets::sphere_multi(32).unwrap();
        match &world.objects[0].geometry {
            crate::raster::pipeline::Geometry::Mesh(m) => assert_eq!(m.triangles.len(), triangles(32)),
            other => panic!("{other:?}"),
        }
        assert_eq!(world, crate::raster::presets::bench_scene("sphere4096-multi").unwrap());
    }
}
