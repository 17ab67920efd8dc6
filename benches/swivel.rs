//! Swivels solved per second on one thread: the rotary axis positions of a
//! frame rotation on four records (a C-A head with limits, an A-C table with
//! offset vectors, a 45° nutating mixed machine, a Hirth-toothed head), one
//! `kinematics::solve` call per swivel; and swivels split over a table and
//! a head (three rotary axes), one `kinematics::split` call each.
//!
//! Run with `cargo bench --bench swivel`. A benchmark, not a test: it asserts
//! nothing about time. `SINUPREP_BENCH_ROUNDS=20000` makes a run short enough
//! for callgrind.

use std::hint::black_box;

#[path = "support/best.rs"]
mod best;
use best::best_of_five;

use nalgebra::Vector3;
use sinuprep::kinematics::{
    solve, split, Direction, Hirth, Kinematics, Preference, Record, Request, RotaryAxis, TableAsk,
};
use sinuprep::rotation::{matrix, Kind, Sequence};

fn axis(vector: [f64; 3], limits: Option<(f64, f64)>, hirth: Option<f64>) -> RotaryAxis {
    RotaryAxis {
        name: String::new(),
        vector: Vector3::from(vector),
        offset: 0.0,
        hirth: hirth.map(|increment| Hirth {
            offset: 0.0,
            increment,
        }),
        limits,
        angle: 0.0,
    }
}

fn record(kinematics: Kinematics, axes: [RotaryAxis; 2], l: [[f64; 3]; 4]) -> Record {
    Record {
        number: 1,
        name: String::new(),
        kinematics,
        offsets: l.map(Vector3::from),
        axes,
        options: 0,
        direction_axis: None,
    }
}

fn main() {
    let zero = [[0.0; 3]; 4];
    let records = [
        record(
            Kinematics::Head,
            [
                axis([0.0, 0.0, 1.0], Some((-360.0, 360.0)), None),
                axis([1.0, 0.0, 0.0], Some((-100.0, 100.0)), None),
            ],
            [[0.0, 0.0, -150.0], [0.0; 3], [0.0, 0.0, 150.0], [0.0; 3]],
        ),
        record(
            Kinematics::Table,
            [
                axis([-1.0, 0.0, 0.0], Some((-120.0, 30.0)), None),
                axis([0.0, 0.0, -1.0], None, None),
            ],
            [
                [0.0; 3],
                [300.0, 200.0, 100.0],
                [0.0, 0.0, 50.0],
                [-300.0, -200.0, -150.0],
            ],
        ),
        record(
            Kinematics::Mixed,
            [
                axis([0.0, 1.0, 1.0], Some((-180.0, 180.0)), None),
                axis([0.0, 0.0, -1.0], Some((0.0, 360.0)), None),
            ],
            zero,
        ),
        record(
            Kinematics::Head,
            [
                axis([0.0, 0.0, 1.0], None, Some(1.0)),
                axis([1.0, 0.0, 0.0], Some((-90.0, 90.0)), Some(2.5)),
            ],
            zero,
        ),
    ];
    let xyz = Sequence::from_code(57, Kind::Intrinsic).expect("XYZ");
    // Deterministic frames spread over the tilts these machines reach.
    let requests: Vec<Request> = (0..4096)
        .map(|i| {
            let x = i as f64;
            Request {
                rotation: matrix(
                    xyz,
                    [
                        (x * 37.3) % 170.0 - 85.0,
                        (x * 11.7) % 120.0 - 60.0,
                        (x * 53.9) % 360.0 - 180.0,
                    ],
                ),
                direction: if i % 2 == 0 {
                    Direction::Minus
                } else {
                    Direction::Plus
                },
                current: [0.0; 2],
            }
        })
        .collect();
    let rounds = std::env::var("SINUPREP_BENCH_ROUNDS")
        .ok()
        .and_then(|text| text.parse().ok())
        .unwrap_or(2_000_000usize);
    for (name, record) in ["C-A head", "A-C table", "nutating mixed", "Hirth head"]
        .iter()
        .zip(&records)
    {
        let seconds = best_of_five(|| {
            let mut checksum = 0.0;
            for i in 0..rounds / 4 {
                let swivel =
                    solve(record, black_box(&requests[i % requests.len()])).expect("valid");
                checksum += swivel
                    .chosen
                    .map_or(0.0, |c| swivel.solutions[c].positions[0]);
            }
            checksum
        });
        let swivels = rounds / 4;
        println!(
            "swivel {name}: {:.2} million swivels/s on one thread ({:.0} ns each, {swivels} swivels, best of 5)",
            swivels as f64 / seconds / 1e6,
            seconds / swivels as f64 * 1e9
        );
    }
    // Three rotary axes: a B table under a C-A head, the table's angle
    // found in closed form (about 15 events, 20 to 30 head solutions each).
    let table = record(
        Kinematics::Table,
        [
            axis([0.0, -1.0, 0.0], Some((-360.0, 360.0)), None),
            axis([0.0; 3], None, None),
        ],
        zero,
    );
    let head = record(
        Kinematics::Head,
        [
            axis([0.0, 0.0, 1.0], Some((-180.0, 180.0)), None),
            axis([1.0, 0.0, 0.0], Some((-45.0, 45.0)), None),
        ],
        zero,
    );
    let ask = TableAsk {
        current: 0.0,
        fixed: None,
        prefer: Preference::Middle,
    };
    let splits = (rounds / 4000).max(10);
    let seconds = best_of_five(|| {
        let mut checksum = 0.0;
        for i in 0..splits {
            let request = black_box(&requests[i % requests.len()]);
            checksum += split(&table, &head, request, &ask).expect("valid").table;
        }
        checksum
    });
    println!(
        "split B table + C-A head: {:.0} splits/s on one thread ({:.0} µs each, {splits} splits, best of 5)",
        splits as f64 / seconds,
        seconds / splits as f64 * 1e6
    );
}
