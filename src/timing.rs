//! One way to time a frame, for every measurement of the crate: the benchmark (`lightlab
//! bench`, its llvmpipe side and `--roofline`), the scaling study, the speed-accuracy study.
//!
//! | symbol | meaning |
//! | --- | --- |
//! | run | `frames` calls of the frame in a row, timed together; its value is ms per frame |
//! | [`Timing`] | the runs' median, fastest and slowest, ms per frame |
//!
//! The median is Python's `statistics.median` (the mean of the two middle runs for an even
//! count), so `../shared/tools/llvmpipe_bench.py` and this crate report the same statistic.

use std::time::Instant;

/// Wall time of one frame over timed runs, milliseconds per frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// The median run.
    pub ms_median: f64,
    /// The fastest run.
    pub ms_min: f64,
    /// The slowest run.
    pub ms_max: f64,
}

impl Timing {
    /// The timing of runs `runs_ms` (ms per frame each): median, fastest and slowest; every
    /// field NaN without runs.
    ///
    /// ```text
    /// ms_median = median(runs_ms);  ms_min = min(runs_ms);  ms_max = max(runs_ms)
    /// ```
    #[must_use]
    pub fn of_runs(runs_ms: &[f64]) -> Timing {
        let min = runs_ms.iter().copied().reduce(f64::min).unwrap_or(f64::NAN);
        let max = runs_ms.iter().copied().reduce(f64::max).unwrap_or(f64::NAN);
        Timing { ms_median: median(runs_ms), ms_min: min, ms_max: max }
    }
}

/// The median of `xs` (the mean of the two middle values for an even count, as Python's
/// `statistics.median`); NaN for none.
#[must_use]
pub fn median(xs: &[f64]) -> f64 {
    let mut sorted = xs.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

/// `runs` runs (at least 1) of `frames` calls (at least 1) of `frame`, each run ended by
/// `end_of_run` inside its timed span (a GPU's `glFinish`; nothing on the CPU): the ms per
/// frame of each run.
pub fn time_runs(runs: usize, frames: usize, mut frame: impl FnMut(), mut end_of_run: impl FnMut()) -> Vec<f64> {
    let frames = frames.max(1);
    (0..runs.max(1))
        .map(|_| {
            let clock = Instant::now();
            for _ in 0..frames {
                frame();
            }
            end_of_run();
            clock.elapsed().as_secs_f64() * 1e3 / frames as f64
        })
        .collect()
}

/// Milliseconds that one call of `frame` takes, as a probe before sizing runs (the call is
/// timed once; a result under 1e-4 ms counts as 1e-4, so a frame count sized from it stays finite).
pub fn time_once(mut frame: impl FnMut()) -> f64 {
    let clock = Instant::now();
    frame();
    (clock.elapsed().as_secs_f64() * 1e3).max(1e-4)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_median_is_pythons_and_the_extremes_are_the_runs() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
        let t = Timing::of_runs(&[2.0, 5.0, 1.0, 4.0]);
        assert_eq!(t, Timing { ms_median: 3.0, ms_min: 1.0, ms_max: 5.0 });
        let none = Timing::of_runs(&[]);
        assert!(none.ms_median.is_nan() && none.ms_min.is_nan() && none.ms_max.is_nan());
    }

    #[test]
    fn every_run_calls_its_frames_then_ends_once() {
        let (mut frames, mut ends) = (0, 0);
        let runs = {
            let frames = &mut frames;
            let ends = &mut ends;
            time_runs(3, 4, || *frames += 1, || *ends += 1)
        };
        assert_eq!((runs.len(), frames, ends), (3, 12, 3));
        assert!(runs.iter().all(|ms| *ms >= 0.0));
        let zero = time_runs(0, 0, || {}, || {});
        assert_eq!(zero.len(), 1, "runs and frames below 1 count as 1");
    }
}
