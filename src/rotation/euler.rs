//! Angles to matrix and back, for all 24 sequences.
//!
//! The decomposition is written out here rather than taken from nalgebra's
//! `euler_angles*`, whose gimbal threshold is coarse (1e-6 rad) and which only
//! knows one order. It works in two steps (as in Shoemake, "Euler angle
//! conversion", Graphics Gems IV): the first angle comes from atan2 on a
//! well-conditioned element pair, and the third is then read from the matrix
//! with the first rotation taken out, so the three angles reproduce the matrix
//! to rounding error even next to gimbal lock. The paper's atan formulas
//! (eq. 14) are only right while every angle stays within ±90°.

use nalgebra::{Matrix3, Rotation3};

use crate::rotation::sequence::{Axis, Kind, Sequence};

/// `cos(middle)` (Tait-Bryan) or `sin(middle)` (proper Euler) below this is
/// gimbal lock: within about 6e-9 degrees of it. Closer than that, splitting the
/// angle between first and third rotation is meaningless; farther away the
/// two-step decomposition is exact.
pub const GIMBAL_TOLERANCE: f64 = 1e-10;

/// Three angles in degrees, in the order the rotations are performed.
pub type Angles = [f64; 3];

/// A rotation read back in one sequence.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Decomposition {
    /// First and third in (-180, 180]; middle in [-90, 90] (Tait-Bryan) or
    /// [0, 180] (proper Euler).
    pub angles: Angles,
    /// The other solution: first ± 180, middle mirrored, third ± 180 (what a
    /// two-axis head reaches with `_ROT_INV`).
    pub alternative: Angles,
    /// At gimbal lock only the sum or difference of first and third rotation
    /// is defined: the third is 0 and the first carries the whole rotation.
    pub gimbal_lock: bool,
}

/// Sine and cosine of an angle in degrees, exact at multiples of 90°, so that
/// a programmed 90° gives exactly 0 and not 6e-17.
pub fn sin_cos_degrees(degrees: f64) -> (f64, f64) {
    // `%` is exact, unlike `rem_euclid`, which rounds -1e-14 up to 360.
    let reduced = if degrees.abs() < 360.0 {
        degrees
    } else {
        degrees % 360.0
    };
    // In (-360, 360) the multiples of 90 are seven exact values: compare them
    // rather than pay for `fmod` on every angle.
    if reduced == 0.0 {
        (0.0, 1.0)
    } else if reduced == 90.0 || reduced == -270.0 {
        (1.0, 0.0)
    } else if reduced == 180.0 || reduced == -180.0 {
        (0.0, -1.0)
    } else if reduced == 270.0 || reduced == -90.0 {
        (-1.0, 0.0)
    } else {
        reduced.to_radians().sin_cos()
    }
}

/// The elemental right-handed rotation about `axis` (`sin`, `cos` given).
fn elemental(axis: Axis, (s, c): (f64, f64)) -> Matrix3<f64> {
    match axis {
        Axis::X => Matrix3::new(1.0, 0.0, 0.0, 0.0, c, -s, 0.0, s, c),
        Axis::Y => Matrix3::new(c, 0.0, s, 0.0, 1.0, 0.0, -s, 0.0, c),
        Axis::Z => Matrix3::new(c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0),
    }
}

/// The rotation of three angles (degrees) in `sequence`.
pub fn matrix(sequence: Sequence, angles: Angles) -> Rotation3<f64> {
    let [a, b, c] = sequence.axes;
    let [ra, rb, rc] = [
        elemental(a, sin_cos_degrees(angles[0])),
        elemental(b, sin_cos_degrees(angles[1])),
        elemental(c, sin_cos_degrees(angles[2])),
    ];
    let product = match sequence.kind {
        Kind::Intrinsic => ra * rb * rc,
        Kind::Extrinsic => rc * rb * ra,
    };
    Rotation3::from_matrix_unchecked(product)
}

/// Reads `rotation` back as three angles of `sequence`.
pub fn decompose(sequence: Sequence, rotation: &Rotation3<f64>) -> Decomposition {
    let m = rotation.matrix();
    let (angles, gimbal_lock) = match sequence.kind {
        Kind::Intrinsic => decompose_intrinsic(sequence, m, GimbalZero::Third),
        // Extrinsic a, b, c = intrinsic c, b, a with the angles reversed; at
        // gimbal lock the extrinsic third angle (the intrinsic first) is zeroed.
        Kind::Extrinsic => {
            let (reversed, lock) = decompose_intrinsic(sequence.reversed(), m, GimbalZero::First);
            ([reversed[2], reversed[1], reversed[0]], lock)
        }
    };
    let angles = angles.map(clean);
    Decomposition {
        angles,
        alternative: alternative(sequence, angles),
        gimbal_lock,
    }
}

#[derive(Clone, Copy, PartialEq)]
enum GimbalZero {
    First,
    Third,
}

/// +1 when (i, j, k) is a cyclic order of (X, Y, Z), -1 otherwise.
fn parity(i: usize, j: usize) -> f64 {
    if (i + 1) % 3 == j {
        1.0
    } else {
        -1.0
    }
}

/// R = R_i(a) · R_j(b) · R_k(c) (or R_i · R_j · R_i for proper Euler), in degrees.
fn decompose_intrinsic(sequence: Sequence, m: &Matrix3<f64>, zero: GimbalZero) -> (Angles, bool) {
    let [first, second, _] = sequence.axes;
    let (i, j) = (first.index(), second.index());
    let k = 3 - i - j;
    let s = parity(i, j);
    let proper = sequence.is_proper_euler();

    // Middle angle, and the first angle's (sin, cos) pair scaled by |cos b|
    // (Tait-Bryan) or |sin b| (proper Euler).
    // `conditioning` is |sin b| (proper Euler) or |cos b| (Tait-Bryan), read
    // from the matrix as the generated run-time code reads it.
    let (b, conditioning, first_pair) = if proper {
        let sin_b = norm(m[(i, j)], m[(i, k)]);
        (sin_b.atan2(m[(i, i)]), sin_b, (m[(j, i)], -s * m[(k, i)]))
    } else {
        let cos_b = norm(m[(i, i)], m[(i, j)]);
        (
            (s * m[(i, k)]).atan2(cos_b),
            cos_b,
            (-s * m[(j, k)], m[(k, k)]),
        )
    };
    let gimbal_lock = conditioning < GIMBAL_TOLERANCE;

    // Row j of R_i(a)ᵀ · R equals row j of the third elemental rotation, which
    // gives the third angle exactly for whatever first angle was chosen.
    let third_from = |sin_a: f64, cos_a: f64| {
        let row = |col: usize| cos_a * m[(j, col)] + s * sin_a * m[(k, col)];
        if proper {
            (-s * row(k)).atan2(row(j))
        } else {
            (s * row(i)).atan2(row(j))
        }
    };

    let (a, c) = if gimbal_lock {
        match zero {
            // R = R_i(a) · R_j(b): column j of R is R_i(a) · e_j.
            GimbalZero::Third => ((s * m[(k, j)]).atan2(m[(j, j)]), 0.0),
            // R = R_j(b) · R_k(c): row j of R is row j of R_k(c).
            GimbalZero::First => (0.0, third_from(0.0, 1.0)),
        }
    } else {
        let a = first_pair.0.atan2(first_pair.1);
        let length = norm(first_pair.0, first_pair.1);
        (a, third_from(first_pair.0 / length, first_pair.1 / length))
    };
    (
        [a.to_degrees(), b.to_degrees(), c.to_degrees()].map(principal),
        gimbal_lock,
    )
}

/// √(x² + y²) of matrix elements, which lie in [-1, 1]: no overflow to guard
/// against, so the plain formula is as exact as `hypot` and much faster.
fn norm(x: f64, y: f64) -> f64 {
    (x * x + y * y).sqrt()
}

/// atan2 gives [-180, 180]; the principal range is (-180, 180].
fn principal(degrees: f64) -> f64 {
    if degrees <= -180.0 {
        degrees + 360.0
    } else {
        degrees
    }
}

/// An angle of the principal range turned half a revolution, back in (-180, 180].
fn half_turn(degrees: f64) -> f64 {
    if degrees > 0.0 {
        degrees - 180.0
    } else {
        degrees + 180.0
    }
}

/// The second solution of the same rotation.
fn alternative(sequence: Sequence, [a, b, c]: Angles) -> Angles {
    let middle = if sequence.is_proper_euler() {
        -b
    } else if b >= 0.0 {
        180.0 - b
    } else {
        -180.0 - b
    };
    [half_turn(a), middle, half_turn(c)].map(clean)
}

/// An angle in (-180, 180].
pub fn wrap(degrees: f64) -> f64 {
    let wrapped = (degrees + 180.0).rem_euclid(360.0) - 180.0;
    if wrapped <= -180.0 {
        wrapped + 360.0
    } else {
        wrapped
    }
}

/// `-0` becomes `0`, so that no angle prints as `-0`.
fn clean(degrees: f64) -> f64 {
    degrees + 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sequence(text: &str) -> Sequence {
        text.parse().expect("valid sequence")
    }

    fn assert_angles(actual: Angles, expected: Angles, tolerance: f64) {
        for (a, e) in actual.iter().zip(expected) {
            assert!((a - e).abs() < tolerance, "{actual:?} != {expected:?}");
        }
    }

    fn max_difference(a: &Rotation3<f64>, b: &Rotation3<f64>) -> f64 {
        (a.matrix() - b.matrix()).abs().max()
    }

    #[test]
    #[allow(clippy::approx_constant)] // the paper's matrix, printed to 4 decimals
    fn paper_matrix_of_extrinsic_xyz_30_45_60() {
        let m = matrix(sequence("e:XYZ"), [30.0, 45.0, 60.0]);
        let expected = Matrix3::new(
            0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124,
        );
        assert!((m.matrix() - expected).abs().max() < 5e-5, "{m}");
    }

    #[test]
    fn paper_conversions_of_extrinsic_xyz_30_45_60() {
        let m = matrix(sequence("e:XYZ"), [30.0, 45.0, 60.0]);
        assert_angles(
            decompose(sequence("i:ZXY"), &m).angles,
            [37.7923, 20.7048, 49.1066],
            5e-5,
        );
        // The paper prints 39.6392: it truncates rather than rounds.
        assert_angles(
            decompose(sequence("e:ZXY"), &m).angles,
            [39.6393, -16.2799, 50.3607],
            5e-5,
        );
        // The paper's -24.5939 / 47.6633 / 58.3301 were computed from the matrix
        // rounded to 4 decimals; from the exact matrix these come out.
        assert_angles(
            decompose(sequence("i:XYZ"), &m).angles,
            [-24.5972, 47.6632, 58.3345],
            5e-5,
        );
    }

    #[test]
    #[allow(clippy::approx_constant)] // the paper's matrix, printed to 4 decimals
    fn paper_intrinsic_xyz_from_the_rounded_matrix_gives_the_papers_figures() {
        let rounded = Matrix3::new(
            0.3536, -0.5732, 0.7392, 0.6124, 0.7392, 0.2803, -0.7071, 0.3536, 0.6124,
        );
        let angles = decompose(
            sequence("i:XYZ"),
            &Rotation3::from_matrix_unchecked(rounded),
        )
        .angles;
        assert_angles(angles, [-24.5939, 47.6633, 58.3301], 5e-3);
    }

    #[test]
    fn siemens_rpy_read_backs() {
        // RPY frames are intrinsic Z, Y', X''; CROT(X,a,Y,b,Z,c) is R_Z(c)·R_Y(b)·R_X(a).
        let rpy = sequence("i:ZYX");
        let read = |x: f64, y: f64, z: f64| {
            let d = decompose(rpy, &matrix(rpy, [z, y, x]));
            (d.angles[2], d.angles[1], d.angles[0], d.gimbal_lock)
        };
        let (x, y, z, lock) = read(10.0, 90.0, 40.0);
        assert!(lock);
        assert_angles([x, y, z], [0.0, 90.0, 30.0], 1e-12);
        let (x, y, z, lock) = read(190.0, 0.0, -200.0);
        assert!(!lock);
        assert_angles([x, y, z], [-170.0, 0.0, 160.0], 1e-12);
    }

    #[test]
    fn every_sequence_reproduces_its_matrix_with_both_solutions() {
        for seq in Sequence::all() {
            for angles in [
                [10.0, 20.0, 30.0],
                [-170.0, 89.0, 120.0],
                [200.0, -100.0, 400.0],
                [0.0, 0.0, 0.0],
            ] {
                let m = matrix(seq, angles);
                let d = decompose(seq, &m);
                assert!(
                    max_difference(&matrix(seq, d.angles), &m) < 1e-12,
                    "{seq} {angles:?}"
                );
                assert!(
                    max_difference(&matrix(seq, d.alternative), &m) < 1e-12,
                    "{seq} alt {angles:?}"
                );
            }
        }
    }

    #[test]
    fn gimbal_lock_zeroes_the_third_angle_and_still_reproduces() {
        for seq in Sequence::all() {
            let middle = if seq.is_proper_euler() { 180.0 } else { -90.0 };
            let m = matrix(seq, [25.0, middle, 35.0]);
            let d = decompose(seq, &m);
            assert!(d.gimbal_lock, "{seq}");
            assert_eq!(d.angles[2], 0.0, "{seq}");
            assert!(max_difference(&matrix(seq, d.angles), &m) < 1e-12, "{seq}");
        }
    }

    #[test]
    fn wrap_keeps_the_principal_range() {
        assert_eq!(wrap(180.0), 180.0);
        assert_eq!(wrap(-180.0), 180.0);
        assert_eq!(wrap(540.0), 180.0);
        assert_eq!(wrap(-190.0), 170.0);
        assert_eq!(sin_cos_degrees(-90.0), (-1.0, 0.0));
        assert_eq!(sin_cos_degrees(-270.0), (1.0, 0.0));
        assert_eq!(sin_cos_degrees(720.0), (0.0, 1.0));
        // Found by the property test: a tiny negative angle is not 270 degrees.
        let (s, c) = sin_cos_degrees(-2.842170943040401e-14);
        assert!(s < 0.0 && s > -1e-15 && c == 1.0);
    }
}
