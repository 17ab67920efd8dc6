//! Conversions per second on one thread: build the matrix of three angles in
//! one sequence and read it back in another, one call per conversion
//! (`sinuprep::rotation::convert`) and many per call (`convert_all`).
//!
//! Run with `cargo bench --bench rotation`. A benchmark, not a test: it asserts
//! nothing about time. `SINUPREP_BENCH_ROUNDS=20000` makes a run short enough
//! for callgrind.

use std::hint::black_box;

#[path = "support/best.rs"]
mod best;
use best::best_of_five;

use sinuprep::rotation::{convert, convert_all, Sequence};

fn main() {
    let sequences: Vec<Sequence> = Sequence::all().collect();
    // Deterministic angles spread over every range, gimbal lock included.
    let angles: Vec<[f64; 3]> = (0..4096)
        .map(|i| {
            let x = i as f64;
            [
                (x * 37.3) % 360.0 - 180.0,
                (x * 11.7) % 180.0 - 90.0,
                (x * 53.9) % 720.0 - 360.0,
            ]
        })
        .collect();
    let rounds = std::env::var("SINUPREP_BENCH_ROUNDS")
        .ok()
        .and_then(|text| text.parse().ok())
        .unwrap_or(2_000_000usize);

    let one_by_one = best_of_five(|| {
        let mut checksum = 0.0;
        for i in 0..rounds {
            let from = sequences[i % 24];
            let to = sequences[(i / 24) % 24];
            let conversion = convert(from, black_box(angles[i % angles.len()]), to);
            checksum += conversion.output.angles[0];
        }
        checksum
    });
    report("convert", rounds, one_by_one);

    // The same number of conversions, a slice of angles per sequence pair.
    let batch = 1024;
    let batches = rounds.div_ceil(batch);
    let many = best_of_five(|| {
        let mut checksum = 0.0;
        for n in 0..batches {
            let from = sequences[n % 24];
            let to = sequences[(n / 24) % 24];
            let start = (n * batch) % angles.len();
            let slice = black_box(&angles[start..start + batch]);
            checksum += convert_all(from, slice, to)[batch / 2].output.angles[0];
        }
        checksum
    });
    report("convert_all", batches * batch, many);
}

fn report(what: &str, conversions: usize, seconds: f64) {
    println!(
        "rotation {what}: {:.1} million conversions/s on one thread ({:.1} ns each, {conversions} conversions, best of 5)",
        conversions as f64 / seconds / 1e6,
        seconds / conversions as f64 * 1e9
    );
}
