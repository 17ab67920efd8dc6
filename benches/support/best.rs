//! The timing the in-process benchmarks share.

use std::hint::black_box;
use std::time::Instant;

/// The best time (seconds) of five runs after one warm-up run.
pub fn best_of_five(mut run: impl FnMut() -> f64) -> f64 {
    let mut best = f64::INFINITY;
    for _ in 0..6 {
        let start = Instant::now();
        black_box(run());
        best = best.min(start.elapsed().as_secs_f64());
    }
    best
}
