//! The f64 ray-cast ground truth (see below).
