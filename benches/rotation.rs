//! Conversions per second on one thread: build the matrix of three angles in
//! one sequence and read it back in another (`sinuprep::rotation::convert`).
//!
//! Run with `cargo bench --bench rotation`. A benchmark, not a test: it asserts
//! nothing about time.

use std::hint::black_box;
use std::time::Instant;

use sinuprep::rotation::{convert, Sequence};

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
    let rounds = 2_000_000usize;
    let mut checksum = 0.0;
    // Warm up, then measure the best of five runs.
    let mut best = f64::INFINITY;
    for _ in 0..6 {
        let start = Instant::now();
        for i in 0..rounds {
            let from = sequences[i % 24];
            let to = sequences[(i / 24) % 24];
            let conversion = convert(from, black_box(angles[i % angles.len()]), to);
            checksum += conversion.output.angles[0];
        }
        best = best.min(start.elapsed().as_secs_f64());
    }
    black_box(checksum);
    println!(
        "rotation convert: {:.1} million conversions/s on one thread ({:.1} ns each, {rounds} conversions, best of 5)",
        rounds as f64 / best / 1e6,
        best / rounds as f64 * 1e9
    );
}
