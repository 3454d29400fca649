//! How far a result is from the reference: the distance in `f32` ulps ([`ulps`]) and the
//! running summary of a set of cases ([`ErrorSummary`], accumulated by `ErrorAcc`). The
//! checker reports its comparisons with the same summary.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | `got` | a result of llvmpipe or of the `f32` core |
//! | `want` | the `f64` reference's result for the same (exactly widened) inputs |
//! | ulps | `|got - want| / ulp(max(|want|, 2^-10))`, with `ulp(x)` the `f32` spacing at `x` |

/// Floor of the ulp scale: it keeps dark channels (below 1/1024, invisible after 8-bit
/// output) from reporting huge ulp counts for tiny absolute errors.
pub const ULP_FLOOR: f64 = 1.0 / 1024.0;

/// The `f32` spacing at `|x|` (for normal numbers): `2^(floor(log2 |x|) - 23)`.
pub fn ulp_f32(x: f64) -> f64 {
    let x = x.abs().max(f32::MIN_POSITIVE as f64);
    (x.log2().floor() - 23.0).exp2()
}

/// `|got - want|` in `f32` ulps at `max(|want|, ULP_FLOOR)`; NaN or infinite `got` gives infinity.
pub fn ulps(got: f64, want: f64) -> f64 {
    let d = (got - want).abs();
    if d.is_finite() {
        d / ulp_f32(want.abs().max(ULP_FLOOR))
    } else {
        f64::INFINITY
    }
}

/// Max and mean error over a set of cases.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct ErrorSummary {
    /// Number of cases.
    pub count: usize,
    /// Largest absolute error (infinite if a result was NaN or infinite).
    pub max_abs: f64,
    /// Mean absolute error.
    pub mean_abs: f64,
    /// Largest error in ulps.
    pub max_ulps: f64,
    /// Mean error in ulps.
    pub mean_ulps: f64,
    /// Position (in the model's case order) of the case with the largest absolute error.
    pub worst: Option<usize>,
}

/// Accumulates an [`ErrorSummary`] case by case.
#[derive(Default)]
pub(crate) struct ErrorAcc {
    stats: ErrorSummary,
    sum_abs: f64,
    sum_ulps: f64,
}

impl ErrorAcc {
    /// Adds one case; returns its error (the largest channel's, infinite for a NaN).
    pub(crate) fn add(&mut self, index: usize, got: &[f64], want: &[f64]) -> f64 {
        let mut abs = 0.0f64;
        let mut ulp = 0.0f64;
        for (&g, &w) in got.iter().zip(want) {
            let d = (g - w).abs();
            abs = if d.is_nan() { f64::INFINITY } else { abs.max(d) };
            ulp = ulp.max(ulps(g, w));
        }
        let s = &mut self.stats;
        if s.worst.is_none() || abs > s.max_abs {
            s.max_abs = abs;
            s.worst = Some(index);
        }
        s.max_ulps = s.max_ulps.max(ulp);
        s.count += 1;
        self.sum_abs += abs;
        self.sum_ulps += ulp;
        abs
    }

    pub(crate) fn finish(mut self) -> ErrorSummary {
        if self.stats.count > 0 {
            self.stats.mean_abs = self.sum_abs / self.stats.count as f64;
            self.stats.mean_ulps = self.sum_ulps / self.stats.count as f64;
        }
        self.stats
    }
}
