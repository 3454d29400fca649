//! The independent `f64` reference: every formula written again, in `DVec3`/`DMat3`,
//! with explicit projections, angles and cofactors. It never calls the `f32` code.
