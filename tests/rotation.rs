//! Property tests of the rotation engine over all 24 x 24 conversions.

use nalgebra::Rotation3;
use proptest::prelude::*;
use sinuprep::rotation::{convert, decompose, matrix, Sequence};

fn sequences() -> Vec<Sequence> {
    Sequence::all().collect()
}

fn max_difference(a: &Rotation3<f64>, b: &Rotation3<f64>) -> f64 {
    (a.matrix() - b.matrix()).abs().max()
}

fn in_principal_range(sequence: Sequence, [a, b, c]: [f64; 3]) -> bool {
    let outer = |x: f64| x > -180.0 && x <= 180.0;
    let middle = if sequence.is_proper_euler() {
        (0.0..=180.0).contains(&b)
    } else {
        (-90.0..=90.0).contains(&b)
    };
    outer(a) && outer(c) && middle
}

/// Angles of every size, and middle angles at and next to gimbal lock.
fn angle() -> impl Strategy<Value = f64> {
    prop_oneof![
        -720.0..720.0f64,
        -180.0..180.0f64,
        Just(90.0),
        Just(-90.0),
        Just(0.0),
        Just(180.0),
        (-1e-6..1e-6f64).prop_map(|d| 90.0 + d),
        (-1e-6..1e-6f64).prop_map(|d| -90.0 + d),
        (-1e-6..1e-6f64).prop_map(|d| 180.0 + d),
        (-1e-6..1e-6f64),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    #[test]
    fn every_conversion_reproduces_its_matrix(
        from in 0usize..24, to in 0usize..24, a1 in angle(), a2 in angle(), a3 in angle()
    ) {
        let all = sequences();
        let (from, to) = (all[from], all[to]);
        let conversion = convert(from, [a1, a2, a3], to);
        let output = conversion.output;
        // 1e-12 away from gimbal lock; within 1e-6 degrees of it the issue asks 1e-9.
        let tolerance = if output.gimbal_lock { 1e-9 } else { 1e-12 };
        let principal = matrix(to, output.angles);
        prop_assert!(max_difference(&principal, &conversion.matrix) < tolerance,
            "{from} {:?} -> {to} {:?}: {}", [a1, a2, a3], output.angles, max_difference(&principal, &conversion.matrix));
        let alternative = matrix(to, output.alternative);
        prop_assert!(max_difference(&alternative, &conversion.matrix) < tolerance, "alternative {:?}", output.alternative);
        prop_assert!(in_principal_range(to, output.angles), "{to} out of range: {:?}", output.angles);
        if output.gimbal_lock {
            prop_assert_eq!(output.angles[2], 0.0);
        }
    }

    #[test]
    fn decomposing_again_gives_the_same_angles(seq in 0usize..24, a1 in -180.0..180.0f64, a2 in -180.0..180.0f64, a3 in -180.0..180.0f64) {
        let sequence = sequences()[seq];
        let first = decompose(sequence, &matrix(sequence, [a1, a2, a3]));
        prop_assume!(!first.gimbal_lock);
        let second = decompose(sequence, &matrix(sequence, first.angles));
        for (x, y) in first.angles.iter().zip(second.angles) {
            // Angles near ±180 may come back on the other side of the cut.
            let d = (x - y).rem_euclid(360.0);
            prop_assert!(d.min(360.0 - d) < 1e-9, "{:?} vs {:?}", first.angles, second.angles);
        }
    }
}

#[test]
fn extrinsic_equals_intrinsic_reversed() {
    for sequence in sequences() {
        let angles = [12.5, -33.0, 71.25];
        let reversed = matrix(sequence.reversed(), [angles[2], angles[1], angles[0]]);
        assert!(
            max_difference(&matrix(sequence, angles), &reversed) < 1e-15,
            "{sequence}"
        );
    }
}

// ---- every form, in and out -----------------------------------------------

use sinuprep::cli::notation::{read, write, Notation};
use sinuprep::rotation::forms::{pose, rotate_by_gibbs, Pose};

/// Every form `convert` and `frame` write: the 24 sequences and the others.
fn notations() -> Vec<Notation> {
    let mut all: Vec<Notation> = sequences().into_iter().map(Notation::Angles).collect();
    all.extend([
        Notation::Matrix,
        Notation::Quaternion,
        Notation::AxisAngle,
        Notation::Gibbs,
        Notation::Sinumerik,
        Notation::Gpp,
        Notation::Chain,
    ]);
    all
}

/// The frame written in `notation` (all 15 decimals) and read back from
/// that text.
fn through(notation: Notation, frame: &Pose, whole: bool) -> Result<Pose, String> {
    let written = write(notation, frame, whole, 15)?;
    read(notation, &[written.text], whole)
}

/// The rotation's angle, degrees.
fn turn(frame: &Pose) -> f64 {
    frame.rotation.angle().to_degrees()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    /// Angles -> form (as text) -> the same rotation, to 1e-12 (1e-9 at gimbal
    /// lock, as for the sequences), and the translation of a frame to 1e-12
    /// of its size; the Gibbs vector of a half turn alone is refused.
    #[test]
    fn every_form_reads_back_what_it_writes(
        from in 0usize..24, form in 0usize..31, a1 in angle(), a2 in angle(), a3 in angle(),
        t in proptest::array::uniform3(-1e4..1e4f64), whole in proptest::bool::ANY,
    ) {
        let sequence = sequences()[from];
        let notation = notations()[form];
        let translation = if whole { nalgebra::Vector3::from(t) } else { nalgebra::Vector3::zeros() };
        let frame = pose(translation, matrix(sequence, [a1, a2, a3]));
        match through(notation, &frame, whole) {
            Ok(back) => {
                let gimbal = match notation {
                    Notation::Angles(s) => decompose(s, &frame.rotation).gimbal_lock,
                    Notation::Chain => decompose("i:ZXY".parse().expect("seq"), &frame.rotation).gimbal_lock,
                    Notation::Sinumerik => decompose("i:ZYX".parse().expect("seq"), &frame.rotation).gimbal_lock,
                    _ => false,
                };
                let tolerance = if gimbal { 1e-9 } else { 1e-12 };
                let difference = max_difference(&back.rotation, &frame.rotation);
                prop_assert!(difference < tolerance, "{notation} {sequence} {:?}: {difference:e}", [a1, a2, a3]);
                let moved = (back.translation.vector - frame.translation.vector).abs().max();
                prop_assert!(moved <= 1e-12 * (1.0 + translation.abs().max()), "{notation}: translation off by {moved:e}");
            }
            Err(why) => {
                prop_assert!(notation == Notation::Gibbs && (turn(&frame) - 180.0).abs() < 1e-6,
                    "{notation} {sequence} {:?}: {why}", [a1, a2, a3]);
            }
        }
    }

    /// The Rodrigues formula (seed 002) moves a point as the rotation's
    /// matrix does.
    #[test]
    fn rodrigues_formula_moves_points_as_the_matrix(
        seq in 0usize..24, a1 in -180.0..180.0f64, a2 in -180.0..180.0f64, a3 in -180.0..180.0f64,
        p in proptest::array::uniform3(-100.0..100.0f64),
    ) {
        let rotation = matrix(sequences()[seq], [a1, a2, a3]);
        let frame = pose(nalgebra::Vector3::zeros(), rotation);
        prop_assume!(turn(&frame) < 179.0);
        let g = sinuprep::rotation::forms::gibbs(&rotation).expect("not a half turn");
        let rho = nalgebra::Vector3::from(p);
        let moved = rotate_by_gibbs(&g, &rho);
        prop_assert!((moved - rotation * rho).abs().max() < 1e-11);
    }
}
