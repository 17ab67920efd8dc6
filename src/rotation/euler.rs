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

use crate::rotation::lanes::{Lanes, Mask};
use crate::rotation::sequence::{Axis, Kind, Sequence};
use crate::rotation::trig::{atan2_lanes, sin_cos_lanes};

/// `cos(middle)` (Tait-Bryan) or `sin(middle)` (proper Euler) below this is
/// gimbal lock: within about 6e-11 degrees of it. Closer than that, splitting
/// the angle between first and third rotation is meaningless; farther away
/// the two-step decomposition is exact. The rotation the angles give back is
/// off by about the middle angle's distance from the lock, so the bound
/// keeps it within 1e-9 degrees (held by a test on every sequence).
pub const GIMBAL_TOLERANCE: f64 = 1e-12;

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

/// The rotation of three angles (degrees) in `sequence`.
pub fn matrix(sequence: Sequence, angles: Angles) -> Rotation3<f64> {
    let mut rows = [[Lanes([0.0]); 3]; 3];
    matrix_lanes(sequence, angles.map(|a| Lanes([a])), &mut rows);
    rotation_of_lane(&rows, 0)
}

/// Reads `rotation` back as three angles of `sequence`.
pub fn decompose(sequence: Sequence, rotation: &Rotation3<f64>) -> Decomposition {
    let m = rotation.matrix();
    let rows = [0, 1, 2].map(|r| [0, 1, 2].map(|c| Lanes([m[(r, c)]])));
    decompose_lanes(sequence, &rows)[0]
}

/// A rotation matrix in every lane, row by row.
pub(crate) type MatrixLanes<const N: usize> = [[Lanes<N>; 3]; 3];

/// The rotation matrix of lane `lane`.
pub(crate) fn rotation_of_lane<const N: usize>(
    rows: &MatrixLanes<N>,
    lane: usize,
) -> Rotation3<f64> {
    Rotation3::from_matrix_unchecked(Matrix3::from_fn(|r, c| rows[r][c].0[lane]))
}

/// [`matrix`] of every lane, written over every entry of `rows`: a matrix
/// reused from chunk to chunk needs no clearing (a fresh one per chunk would
/// cost a 576-byte fill and a copy).
#[inline(always)]
pub(crate) fn matrix_lanes<const N: usize>(
    sequence: Sequence,
    angles: [Lanes<N>; 3],
    rows: &mut MatrixLanes<N>,
) {
    // Intrinsic R = R_a·R_b·R_c, extrinsic R = R_c·R_b·R_a: start from the
    // rightmost elemental rotation and turn it by the other two from the left.
    let [first, second, third] = match sequence.kind {
        Kind::Intrinsic => [2, 1, 0],
        Kind::Extrinsic => [0, 1, 2],
    };
    let trig = |step: usize| sin_cos_lanes(angles[step]);
    elemental(rows, sequence.axes[first], trig(first));
    turn_rows(rows, sequence.axes[second], trig(second));
    turn_rows(rows, sequence.axes[third], trig(third));
}

/// The indices of `axis` and of the two axes that follow it cyclically.
fn cyclic(axis: Axis) -> (usize, usize, usize) {
    // A table, not `% 3`: an integer division costs more than the lookup.
    const CYCLIC: [(usize, usize, usize); 3] = [(0, 1, 2), (1, 2, 0), (2, 0, 1)];
    CYCLIC[axis.index()]
}

/// `rows` := the elemental right-handed rotation about `axis`, every entry written.
#[inline(always)]
fn elemental<const N: usize>(rows: &mut MatrixLanes<N>, axis: Axis, (s, c): (Lanes<N>, Lanes<N>)) {
    let (i, j, k) = cyclic(axis);
    let zero = Lanes::splat(0.0);
    rows[i] = [zero; 3];
    rows[i][i] = Lanes::splat(1.0);
    rows[j][i] = zero;
    rows[k][i] = zero;
    rows[j][j] = c;
    rows[j][k] = -s;
    rows[k][j] = s;
    rows[k][k] = c;
}

/// `rows` := R_axis · `rows`. An elemental rotation mixes only the two rows
/// of the other axes: 12 multiplications instead of a full product's 27.
#[inline(always)]
fn turn_rows<const N: usize>(rows: &mut MatrixLanes<N>, axis: Axis, (s, c): (Lanes<N>, Lanes<N>)) {
    let (_, j, k) = cyclic(axis);
    let (row_j, row_k) = (rows[j], rows[k]);
    for col in 0..3 {
        rows[j][col] = c * row_j[col] - s * row_k[col];
        rows[k][col] = s * row_j[col] + c * row_k[col];
    }
}

/// [`decompose`] of every lane.
#[inline(always)]
pub(crate) fn decompose_lanes<const N: usize>(
    sequence: Sequence,
    m: &MatrixLanes<N>,
) -> [Decomposition; N] {
    let ([a, b, c], gimbal_lock) = match sequence.kind {
        Kind::Intrinsic => decompose_intrinsic(sequence, m, GimbalZero::Third),
        // Extrinsic a, b, c = intrinsic c, b, a with the angles reversed; at
        // gimbal lock the extrinsic third angle (the intrinsic first) is zeroed.
        Kind::Extrinsic => {
            let ([c, b, a], lock) = decompose_intrinsic(sequence.reversed(), m, GimbalZero::First);
            ([a, b, c], lock)
        }
    };
    let angles = [a + 0.0, b + 0.0, c + 0.0];
    let alternative = alternative(sequence, angles);
    std::array::from_fn(|lane| Decomposition {
        angles: angles.map(|angle| angle.0[lane]),
        alternative: alternative.map(|angle| angle.0[lane]),
        gimbal_lock: gimbal_lock.lane(lane),
    })
}

#[derive(Clone, Copy, PartialEq)]
enum GimbalZero {
    First,
    Third,
}

/// R = R_i(a) · R_j(b) · R_k(c) (or R_i · R_j · R_i for proper Euler), in
/// degrees, each in the principal range, with the lanes in gimbal lock.
#[inline(always)]
fn decompose_intrinsic<const N: usize>(
    sequence: Sequence,
    m: &MatrixLanes<N>,
    zero: GimbalZero,
) -> ([Lanes<N>; 3], Mask<N>) {
    let [first, second, _] = sequence.axes;
    let (i, next, _) = cyclic(first);
    let j = second.index();
    let k = 3 - i - j;
    // +1 when (i, j, k) is a cyclic order of (X, Y, Z), -1 otherwise.
    let s = if next == j { 1.0 } else { -1.0 };
    let proper = sequence.is_proper_euler();

    // Middle angle, and the first angle's (sin, cos) pair scaled by
    // `conditioning`: |sin b| (proper Euler) or |cos b| (Tait-Bryan), read
    // from the matrix as the generated run-time code reads it.
    let (b, conditioning, first_pair) = if proper {
        let sin_b = norm(m[i][j], m[i][k]);
        (atan2_lanes(sin_b, m[i][i]), sin_b, (m[j][i], -s * m[k][i]))
    } else {
        let cos_b = norm(m[i][i], m[i][j]);
        (
            atan2_lanes(s * m[i][k], cos_b),
            cos_b,
            (-s * m[j][k], m[k][k]),
        )
    };
    let gimbal_lock = conditioning.test(|x| x < GIMBAL_TOLERANCE);

    // Gimbal-locked lanes, where `conditioning` may be 0 and the pairs with
    // it, take other pairs: chosen before the atan2, so every lane runs the
    // same instructions.
    let axes = (i, j, k);
    let zero_pair = (Lanes::splat(0.0), Lanes::splat(1.0));
    let (a_pair, c_pair) = match zero {
        // R = R_i(a) · R_j(b): column j of R is R_i(a) · e_j; the third is 0.
        GimbalZero::Third => (
            select_pair(gimbal_lock, (s * m[k][j], m[j][j]), first_pair),
            select_pair(
                gimbal_lock,
                zero_pair,
                third_pair(m, axes, s, proper, first_pair),
            ),
        ),
        // R = R_j(b) · R_k(c): the first is 0, and row j of R is row j of R_k(c).
        GimbalZero::First => {
            let a_pair = select_pair(gimbal_lock, zero_pair, first_pair);
            (a_pair, third_pair(m, axes, s, proper, a_pair))
        }
    };
    let a = atan2_lanes(a_pair.0, a_pair.1);
    let c = atan2_lanes(c_pair.0, c_pair.1);
    ([a, b, c].map(principal), gimbal_lock)
}

/// The (sin, cos) pair of the third angle of R = R_i(a) · R_j(b) · R_k(c),
/// from the first angle's pair. Row j of R_i(a)ᵀ · R equals row j of the
/// third elemental rotation, which gives the third angle exactly for whatever
/// first angle was chosen. The first angle's pair may be scaled by a positive
/// factor, and so is the result: atan2 ignores the scale.
#[inline(always)]
fn third_pair<const N: usize>(
    m: &MatrixLanes<N>,
    (i, j, k): (usize, usize, usize),
    s: f64,
    proper: bool,
    (sin_a, cos_a): (Lanes<N>, Lanes<N>),
) -> (Lanes<N>, Lanes<N>) {
    let (col, sign) = if proper { (k, -s) } else { (i, s) };
    let y = cos_a * m[j][col] + s * sin_a * m[k][col];
    let x = cos_a * m[j][j] + s * sin_a * m[k][j];
    (sign * y, x)
}

/// `locked` where `mask` holds, `pair` elsewhere.
#[inline(always)]
fn select_pair<const N: usize>(
    mask: Mask<N>,
    locked: (Lanes<N>, Lanes<N>),
    pair: (Lanes<N>, Lanes<N>),
) -> (Lanes<N>, Lanes<N>) {
    (
        Lanes::select(mask, locked.0, pair.0),
        Lanes::select(mask, locked.1, pair.1),
    )
}

/// √(x² + y²) of matrix elements, which lie in [-1, 1]: no overflow to guard
/// against, so the plain formula is as exact as `hypot` and much faster.
#[inline(always)]
fn norm<const N: usize>(x: Lanes<N>, y: Lanes<N>) -> Lanes<N> {
    (x * x + y * y).sqrt()
}

/// atan2 gives [-180, 180]; the principal range is (-180, 180].
#[inline(always)]
fn principal<const N: usize>(degrees: Lanes<N>) -> Lanes<N> {
    Lanes::select(degrees.test(|d| d <= -180.0), degrees + 360.0, degrees)
}

/// An angle of the principal range turned half a revolution, back in (-180, 180].
#[inline(always)]
fn half_turn<const N: usize>(degrees: Lanes<N>) -> Lanes<N> {
    Lanes::select(degrees.test(|d| d > 0.0), degrees - 180.0, degrees + 180.0)
}

/// The second solution of the same rotation (`-0` cleaned to `0`).
#[inline(always)]
fn alternative<const N: usize>(sequence: Sequence, [a, b, c]: [Lanes<N>; 3]) -> [Lanes<N>; 3] {
    let middle = if sequence.is_proper_euler() {
        -b
    } else {
        Lanes::select(b.test(|b| b >= 0.0), 180.0 - b, -180.0 - b)
    };
    [half_turn(a), middle, half_turn(c)].map(|angle| angle + 0.0)
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

    /// Near gimbal lock, on either side of the threshold, the angles give
    /// back the rotation to within 1e-9 degrees (as the angle between the
    /// two rotations).
    #[test]
    fn near_gimbal_lock_the_angles_reproduce_the_rotation_within_1e_9_degrees() {
        for seq in Sequence::all() {
            let lock = if seq.is_proper_euler() { 0.0 } else { 90.0 };
            let mut worst: f64 = 0.0;
            for k in 0..=60 {
                let off = 1e-3 * 10f64.powf(-(k as f64) / 5.0);
                for middle in [lock - off, lock + off] {
                    let m = matrix(seq, [25.0, middle, 35.0]);
                    let back = matrix(seq, decompose(seq, &m).angles);
                    // |R1 - R2| (Frobenius) is 2√2 sin(θ/2): exact for small
                    // θ, where acos of the trace loses half the digits.
                    let norm = (back.matrix() - m.matrix()).norm();
                    let turn = (2.0 * (norm / 8f64.sqrt()).asin()).to_degrees();
                    worst = worst.max(turn);
                }
            }
            assert!(worst < 1e-9, "{seq}: {worst:e} degrees");
        }
    }

    #[test]
    fn wrap_keeps_the_principal_range() {
        assert_eq!(wrap(180.0), 180.0);
        assert_eq!(wrap(-180.0), 180.0);
        assert_eq!(wrap(540.0), 180.0);
        assert_eq!(wrap(-190.0), 170.0);
    }
}
