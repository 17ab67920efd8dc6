//! One swivel: the rotary axis positions that turn the tool onto the Z axis
//! of a requested frame rotation, for a record (`reference/kinematics.md`
//! sections 2 and 4).
//!
//! The model, with `R(v, α)` the right-hand rotation about an axis vector
//! of the initial state, `t0 = +Z` the tool's base direction and `f` the
//! requested frame's Z axis:
//!
//! ```text
//! head  (T):  R(v1, α1) R(v2, α2) t0 = f
//! table (P):  R(v1, α1) R(v2, α2) f  = t0
//! mixed (M):  R(v2, -α2) R(v1, α1) t0 = f     (axis 1 the head's, axis 2 the table's)
//! ```
//!
//! all one problem, `R(a, θ1) R(b, θ2) p = q`, solved by Paden-Kahan
//! subproblem 2 for any axis vectors (nutating heads included): two
//! solutions, one where the cones touch, none where the orientation cannot
//! be reached. Each solution is placed inside the axis limits (±360°),
//! rounded to a Hirth grid (the grid neighbours of both axes searched for
//! the smallest tool-axis error), and `_DIR` picks one as CYCLE800 does:
//! the lower (−1) or higher (+1) position of the direction-reference axis,
//! the other solution when the asked one is outside the limits.

use nalgebra::{Rotation3, Vector3};

use crate::kinematics::record::{Kinematics, Record, RecordError};
use crate::kinematics::subproblem::{angle_about, intermediates, UpToTwo};
use crate::rotation::frame::from_axis_angle;

/// CYCLE800's `_DIR`: which of the two solutions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    /// The lower position of the direction-reference axis.
    Minus,
    /// The higher.
    Plus,
}

/// What is asked of the machine.
#[derive(Clone, Copy, Debug)]
pub struct Request {
    /// The frame rotation (workpiece axes in machine coordinates).
    pub rotation: Rotation3<f64>,
    pub direction: Direction,
    /// Axis positions before the swivel: where a pole leaves an axis free,
    /// it stays here, and a position is placed inside its limits nearest it.
    pub current: [f64; 2],
}

/// One way the axes can make the orientation.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Solution {
    /// Axis positions (degrees), offsets applied, placed inside the limits
    /// where possible, on the Hirth grid where there is one.
    pub positions: [f64; 2],
    /// The positions before Hirth rounding.
    pub exact: [f64; 2],
    /// Every position lies inside its axis limits.
    pub within_limits: bool,
    /// The angle (degrees) between the requested tool direction and the
    /// one the rounded positions give: 0 without a Hirth grid.
    pub hirth_error_deg: f64,
}

/// A swivel computed.
#[derive(Clone, Debug, PartialEq)]
pub struct Swivel {
    /// No, one or two solutions; none: the orientation cannot be reached.
    pub solutions: Vec<Solution>,
    /// The solution the control takes, `None` when none lies inside the limits.
    pub chosen: Option<usize>,
    /// The solution `_DIR` asks for, limits aside: when it is not the one
    /// taken, it lies outside the limits and the control took the other.
    pub preferred: Option<usize>,
    /// For the chosen solution: the rotation left in the frame after the
    /// axes have turned (`R_kin^T · R_req`: about the tool axis alone when
    /// the direction is met exactly).
    pub residual: Option<Rotation3<f64>>,
    /// For the chosen solution: the shift of the zero point the offset
    /// vectors make on a table (`[l2 + R1 (l3 + R2 l4)] − (l2 + l3 + l4)`;
    /// mixed: `[l3 + R2 l4] − (l3 + l4)`; zero for a head).
    pub shift: Option<Vector3<f64>>,
}

/// The axis positions for `request` on `record`.
pub fn solve(record: &Record, request: &Request) -> Result<Swivel, RecordError> {
    record.check()?;
    Ok(solve_toward(
        record,
        request,
        &(request.rotation * Vector3::z()),
    ))
}

/// [`solve`] on a record [`Record::check`] passed, with the tool direction
/// `f` (the requested rotation's Z axis) as the caller computed it: the
/// table's split measures the head with the direction it computes, and
/// takes the same solutions it measured.
pub(crate) fn solve_toward(record: &Record, request: &Request, f: &Vector3<f64>) -> Swivel {
    let solutions = solutions(record, f, request.current).to_vec();
    let chosen = choose(record, &solutions, request.direction, |s| s.within_limits);
    let preferred = choose(record, &solutions, request.direction, |_| true);
    let (residual, shift) = match chosen {
        Some(index) => {
            let angles = model(record, solutions[index].positions);
            (
                Some(orientation(record, angles).inverse() * request.rotation),
                Some(shift(record, angles)),
            )
        }
        None => (None, None),
    };
    Swivel {
        solutions,
        chosen,
        preferred,
        residual,
        shift,
    }
}

/// The solutions for the tool direction `f` with the axes at `current`
/// before (a record [`Record::check`] passed): [`solve`] without the
/// choice, the residual and the shift, and without an allocation, for the
/// table's split, which asks this for a hundred table angles.
pub(crate) fn solutions(record: &Record, f: &Vector3<f64>, current: [f64; 2]) -> UpToTwo<Solution> {
    let model_current = [0, 1].map(|i| current[i] - record.axes[i].offset);
    let mut solutions = UpToTwo::new();
    for angles in model_angles(record, f, model_current).iter() {
        let solution = place(record, f, *angles, current);
        // One touching solution reached twice, or a pole: report it once.
        let same = |other: &Solution| {
            (0..2).all(|i| (other.positions[i] - solution.positions[i]).abs() < 1e-9)
        };
        if !solutions.iter().any(same) {
            solutions.push(solution);
        }
    }
    solutions
}

/// The model angles (α1, α2) that meet the tool direction `f` exactly.
fn model_angles(record: &Record, f: &Vector3<f64>, current: [f64; 2]) -> UpToTwo<[f64; 2]> {
    let t0 = Vector3::z();
    let v1 = record.axes[0].vector.normalize();
    if record.axis_count() == 1 {
        // One axis: the direction is reached only on its cone.
        let (p, q) = match record.kinematics {
            Kinematics::Table => (*f, t0),
            _ => (t0, *f),
        };
        let mut found = UpToTwo::new();
        if (v1.dot(&p) - v1.dot(&q)).abs() <= 1e-9 {
            found.push([angle_about(&v1, &p, &q).unwrap_or(current[0]), current[1]]);
        }
        return found;
    }
    let v2 = record.axes[1].vector.normalize();
    // R(a, θ1) R(b, θ2) p = q, and how (θ1, θ2) are the axes' angles.
    let (a, b, p, q) = match record.kinematics {
        Kinematics::Head => (v1, v2, t0, *f),
        Kinematics::Table => (v1, v2, *f, t0),
        Kinematics::Mixed => (v2, v1, t0, *f),
    };
    let (free_1, free_2) = match record.kinematics {
        Kinematics::Mixed => (-current[1], current[0]),
        _ => (current[0], current[1]),
    };
    let mut found = UpToTwo::new();
    for w in intermediates(&a, &b, &p, &q).iter() {
        let theta_2 = angle_about(&b, &p, w).unwrap_or(free_2);
        let theta_1 = angle_about(&a, w, &q).unwrap_or(free_1);
        found.push(match record.kinematics {
            Kinematics::Mixed => [theta_2, -theta_1],
            _ => [theta_1, theta_2],
        });
    }
    found
}

/// Machine positions of model `angles`: offsets added, each placed inside
/// its limits (nearest the current position), then onto the Hirth grid.
fn place(record: &Record, f: &Vector3<f64>, angles: [f64; 2], current: [f64; 2]) -> Solution {
    let exact = [0, 1].map(|i| {
        let axis = &record.axes[i];
        let position = angles[i] + axis.offset;
        match axis.limits {
            // Within the tolerance of a limit counts as at it, and is put
            // there: a position printed never lies beyond a limit it is
            // said to keep.
            Some((min, max)) => match inside(position, min, max, current[i]) {
                Some(placed) => placed.clamp(min, max),
                None => position,
            },
            None => wrap_near(position, current[i]),
        }
    });
    let within = |positions: [f64; 2]| {
        (0..record.axis_count()).all(|i| match record.axes[i].limits {
            Some((min, max)) => (min - 1e-9..=max + 1e-9).contains(&positions[i]),
            None => true,
        })
    };
    let error = |positions: [f64; 2]| {
        let reached = orientation(record, model(record, positions)) * Vector3::z();
        reached.dot(f).clamp(-1.0, 1.0).acos().to_degrees()
    };
    let mut best = Solution {
        positions: exact,
        exact,
        within_limits: within(exact),
        hirth_error_deg: 0.0,
    };
    if record.axes.iter().all(|a| a.hirth.is_none()) {
        return best;
    }
    // The grid neighbours of both axes: rounding each on its own is not the
    // nearest orientation once the axes are not orthogonal.
    let candidates = |i: usize| match record.axes[i].hirth {
        Some(hirth) if hirth.increment > 0.0 => hirth.neighbours(exact[i]),
        _ => [exact[i]; 2],
    };
    let mut first = true;
    for p1 in candidates(0) {
        for p2 in candidates(1) {
            let positions = [p1, p2];
            let (inside, error) = (within(positions), error(positions));
            let better = first
                || (inside && !best.within_limits)
                || (inside == best.within_limits && error < best.hirth_error_deg - 1e-12);
            if better {
                best = Solution {
                    positions,
                    exact,
                    within_limits: inside,
                    hirth_error_deg: error,
                };
                first = false;
            }
        }
    }
    best
}

/// `position` ± 360° inside `[min, max]`, nearest `current` (of two as
/// near, the lower), in constant time whatever the limits: the turns are
/// counted, not stepped through.
fn inside(position: f64, min: f64, max: f64, current: f64) -> Option<f64> {
    // The candidates are `position + 360 k` for whole k in [lowest, highest],
    // within the tolerance of either limit.
    let lowest = ((min - 1e-9 - position) / 360.0).ceil();
    let highest = ((max + 1e-9 - position) / 360.0).floor();
    if lowest.is_nan() || highest.is_nan() || lowest > highest {
        return None;
    }
    // The turn nearest `current`, a tie to the lower one (the lowest where
    // `current` is no number).
    let nearest = ((current - position) / 360.0 - 0.5).ceil();
    Some(position + 360.0 * nearest.max(lowest).min(highest))
}

/// `position` ± 360° within half a turn of `current` (an axis without limits).
fn wrap_near(position: f64, current: f64) -> f64 {
    current + crate::rotation::euler::wrap(position - current)
}

/// Model angles of machine positions.
pub(crate) fn model(record: &Record, positions: [f64; 2]) -> [f64; 2] {
    [0, 1].map(|i| positions[i] - record.axes[i].offset)
}

/// The rotation the axes make, `R_kin`, with `R_kin · Z = f` when met.
pub fn orientation(record: &Record, angles: [f64; 2]) -> Rotation3<f64> {
    let (r1, r2) = (turn(record, 0, angles), turn(record, 1, angles));
    match record.kinematics {
        Kinematics::Head => r1 * r2,
        Kinematics::Table => (r1 * r2).inverse(),
        Kinematics::Mixed => r2.inverse() * r1,
    }
}

/// The zero-point shift of model `angles` (see [`Swivel::shift`]).
pub(crate) fn shift(record: &Record, angles: [f64; 2]) -> Vector3<f64> {
    shift_of_turns(record, turn(record, 0, angles), turn(record, 1, angles))
}

/// [`shift`] of the axes' turns `r1`, `r2` (see [`turn`]).
pub(crate) fn shift_of_turns(
    record: &Record,
    r1: Rotation3<f64>,
    r2: Rotation3<f64>,
) -> Vector3<f64> {
    let [_, l2, l3, l4] = record.offsets;
    match record.kinematics {
        Kinematics::Head => Vector3::zeros(),
        Kinematics::Table => (l2 + r1 * (l3 + r2 * l4)) - (l2 + l3 + l4),
        Kinematics::Mixed => (l3 + r2 * l4) - (l3 + l4),
    }
}

/// `R(v_i, α_i)` of axis `i` (the identity for an axis the record lacks).
pub(crate) fn turn(record: &Record, i: usize, angles: [f64; 2]) -> Rotation3<f64> {
    if record.axes[i].exists() {
        from_axis_angle(record.axes[i].vector, angles[i])
    } else {
        Rotation3::identity()
    }
}

/// The solution `direction` asks for among the `usable` ones: among those
/// inside the limits, the other when only one is (Siemens: "the
/// alternative is selected automatically").
pub(crate) fn choose(
    record: &Record,
    solutions: &[Solution],
    direction: Direction,
    usable: impl Fn(&Solution) -> bool,
) -> Option<usize> {
    let reference = record.direction_reference();
    let usable = solutions.iter().enumerate().filter(|(_, s)| usable(s));
    let key = |s: &Solution| s.positions[reference];
    match direction {
        Direction::Minus => usable.min_by(|(_, a), (_, b)| key(a).total_cmp(&key(b))),
        Direction::Plus => usable.max_by(|(_, a), (_, b)| key(a).total_cmp(&key(b))),
    }
    .map(|(index, _)| index)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::record::{Hirth, RotaryAxis};
    use crate::rotation::{matrix, Kind, Sequence};

    fn record(kinematics: Kinematics, first: RotaryAxis, second: RotaryAxis) -> Record {
        Record {
            number: 1,
            name: "TEST".into(),
            kinematics,
            offsets: [Vector3::zeros(); 4],
            axes: [first, second],
            options: 0,
            direction_axis: None,
        }
    }

    fn none() -> RotaryAxis {
        RotaryAxis::along("", [0.0; 3])
    }

    fn request(rotation: Rotation3<f64>) -> Request {
        Request {
            rotation,
            direction: Direction::Minus,
            current: [0.0; 2],
        }
    }

    /// The frame that turns the tool onto `direction` by the shortest way.
    fn toward(direction: [f64; 3]) -> Rotation3<f64> {
        Rotation3::rotation_between(&Vector3::z(), &Vector3::from(direction)).expect("not opposite")
    }

    fn positions(swivel: &Swivel) -> Vec<[f64; 2]> {
        let round = |x: f64| (x * 1000.0).round() / 1000.0;
        swivel
            .solutions
            .iter()
            .map(|s| s.positions.map(round))
            .collect()
    }

    #[test]
    fn a_table_about_y_turns_rot_y_minus_45_into_plus_45() {
        // Function Manual W1: table axis +Y, ROT Y-45 with TCOFR gives +45°.
        let table = record(
            Kinematics::Table,
            RotaryAxis::along("B", [0.0, 1.0, 0.0]),
            none(),
        );
        let rotation = Rotation3::from_axis_angle(&Vector3::y_axis(), (-45f64).to_radians());
        let swivel = solve(&table, &request(rotation)).expect("valid");
        assert_eq!(positions(&swivel), [[45.0, 0.0]]);
    }

    #[test]
    fn the_fourth_offset_vector_shifts_the_zero_point_as_the_manual_shows() {
        // W1 example: table "P", l4 = (0, 0, 15), A0 B45: X +10.607, Z -4.393.
        let mut table = record(
            Kinematics::Table,
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
            RotaryAxis::along("B", [0.0, 1.0, 0.0]),
        );
        table.offsets[3] = Vector3::new(0.0, 0.0, 15.0);
        let shift = super::shift(&table, [0.0, 45.0]);
        assert!(
            (shift - Vector3::new(10.606_601_717_798_2, 0.0, -4.393_398_282_201_8)).norm() < 1e-9
        );
    }

    #[test]
    fn a_c_a_head_has_two_solutions_half_a_turn_apart() {
        let head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
        );
        let swivel = solve(&head, &request(toward([0.3, -0.5, 0.8]))).expect("valid");
        let mut found = positions(&swivel);
        found.sort_by(|a, b| a[1].total_cmp(&b[1]));
        assert_eq!(found, [[-149.036, -36.087], [30.964, 36.087]]);
        // _DIR refers to A, the tilting axis: minus takes A -36.087.
        let chosen = &swivel.solutions[swivel.chosen.expect("one inside")];
        assert!((chosen.positions[1] + 36.087).abs() < 1e-3);
    }

    #[test]
    fn a_45_degree_nutating_head_and_its_reach() {
        let head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("B", [0.0, 1.0, 1.0]),
        );
        let tilt = 60f64.to_radians();
        let swivel = solve(&head, &request(toward([tilt.sin(), 0.0, tilt.cos()]))).expect("valid");
        let mut found = positions(&swivel);
        found.sort_by(|a, b| a[1].total_cmp(&b[1]));
        // kinematics_examples.py: (C, B') = (215.264, -90) or (324.736, +90).
        assert_eq!(found, [[-144.736, -90.0], [-35.264, 90.0]]);
        let past = solve(&head, &request(toward([1.0, 0.0, -0.2]))).expect("valid");
        assert!(past.solutions.is_empty() && past.chosen.is_none());
    }

    #[test]
    fn a_b_head_over_a_c_table_tilts_ten_degrees() {
        // kinematics_examples.py: frame ROT X10, v2 = +Z: (B, C) = (-10, -90) or (+10, +90).
        let mixed = record(
            Kinematics::Mixed,
            RotaryAxis::along("B", [0.0, 1.0, 0.0]),
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
        );
        let rotation = matrix(
            Sequence::new(
                [
                    crate::rotation::Axis::X,
                    crate::rotation::Axis::Y,
                    crate::rotation::Axis::Z,
                ],
                Kind::Intrinsic,
            )
            .expect("XYZ"),
            [10.0, 0.0, 0.0],
        );
        let swivel = solve(&mixed, &request(rotation)).expect("valid");
        let mut found = positions(&swivel);
        found.sort_by(|a, b| a[0].total_cmp(&b[0]));
        assert_eq!(found, [[-10.0, -90.0], [10.0, 90.0]]);
    }

    /// A position a rounding beyond a limit counts as at it, and is put
    /// there: never printed beyond a limit it is said to keep.
    #[test]
    fn a_position_at_a_limit_is_never_beyond_it() {
        let mut head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
        );
        let (s, c) = (40f64.to_radians().sin(), 40f64.to_radians().cos());
        // A limit of 40° on either side, a rounding inside, at and beyond it.
        let near = |at: f64| [at - 5e-10, at, at + 5e-10];
        let upper = near(40.0).map(|max| (-30.0, max));
        let lower = near(-40.0).map(|min| (min, 30.0));
        for (min, max) in upper.into_iter().chain(lower) {
            head.axes[1].limits = Some((min, max));
            let swivel = solve(&head, &request(toward([0.0, -s, c]))).expect("valid");
            let inside: Vec<_> = swivel
                .solutions
                .iter()
                .filter(|s| s.within_limits)
                .collect();
            assert!(!inside.is_empty(), "{min}..{max}: {:?}", swivel.solutions);
            for solution in inside {
                let a = solution.positions[1];
                assert!(
                    (min..=max).contains(&a),
                    "{min}..{max}: {:?}",
                    solution.positions
                );
            }
        }
    }

    #[test]
    fn limits_place_a_position_and_dir_falls_back_to_the_other_solution() {
        let mut head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
        );
        head.axes[0].limits = Some((0.0, 360.0));
        head.axes[1].limits = Some((-10.0, 90.0));
        let swivel = solve(&head, &request(toward([0.3, -0.5, 0.8]))).expect("valid");
        let inside: Vec<_> = swivel
            .solutions
            .iter()
            .filter(|s| s.within_limits)
            .collect();
        assert_eq!(inside.len(), 1, "A -36 is outside -10..90");
        let chosen = &swivel.solutions[swivel.chosen.expect("the other one")];
        assert!((chosen.positions[0] - 30.964).abs() < 1e-3 && chosen.positions[1] > 0.0);
        // C -149 is placed at 211 inside 0..360 all the same.
        assert!(swivel
            .solutions
            .iter()
            .any(|s| (s.positions[0] - 210.964).abs() < 1e-3));
    }

    #[test]
    fn a_hirth_grid_rounds_and_tells_the_error() {
        let mut head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
        );
        head.axes[1].hirth = Some(Hirth {
            offset: 0.0,
            increment: 2.5,
        });
        assert_eq!(
            Hirth {
                offset: 0.0,
                increment: 2.5
            }
            .round(37.3),
            37.5
        );
        let swivel = solve(&head, &request(toward([0.3, -0.5, 0.8]))).expect("valid");
        for solution in &swivel.solutions {
            assert!((solution.positions[1] / 2.5).fract().abs() < 1e-12);
            assert!(solution.hirth_error_deg > 0.0 && solution.hirth_error_deg < 1.25);
        }
    }

    /// The stepping search `inside` replaced, as the reference.
    fn inside_by_steps(position: f64, min: f64, max: f64, current: f64) -> Option<f64> {
        let lowest = position - 360.0 * ((position - (min - 1e-9)) / 360.0).floor();
        let mut best: Option<f64> = None;
        let mut candidate = lowest;
        while candidate <= max + 1e-9 {
            if best.is_none_or(|b| (candidate - current).abs() < (b - current).abs()) {
                best = Some(candidate);
            }
            candidate += 360.0;
        }
        best
    }

    #[test]
    fn placement_inside_the_limits_counts_turns_as_stepping_did() {
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut next = |range: f64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64 * 2.0 * range - range
        };
        for _ in 0..20_000 {
            let (a, b) = (next(2000.0).round(), next(2000.0).round());
            let (min, max) = (a.min(b), a.max(b));
            let (position, current) = (next(1000.0), next(3000.0));
            let (found, stepped) = (
                inside(position, min, max, current),
                inside_by_steps(position, min, max, current),
            );
            match (found, stepped) {
                (Some(f), Some(s)) => assert!(
                    (f - s).abs() < 1e-9,
                    "{position} in {min}..{max} near {current}: {f} vs {s}"
                ),
                _ => assert_eq!(found, stepped, "{position} in {min}..{max} near {current}"),
            }
        }
        // Exactly between two turns: the lower, as the search took it.
        assert_eq!(inside(0.0, -720.0, 720.0, 180.0), Some(0.0));
        assert_eq!(inside(10.0, 0.0, 100.0, 200.0), Some(10.0));
        assert_eq!(inside(10.0, 20.0, 100.0, 0.0), None);
        assert_eq!(inside(f64::NAN, 0.0, 100.0, 0.0), None);
        assert_eq!(inside(10.0, 0.0, 800.0, f64::NAN), Some(10.0));
        // Limits of any size take no longer.
        assert_eq!(inside(30.0, -1e300, 1e300, 0.0), Some(30.0));
        let far = inside(30.0, -10.0, 1e300, 1e200).expect("inside");
        assert!((far - 1e200).abs() <= 1e200 * 1e-15, "{far}");
    }

    #[test]
    fn a_pole_keeps_the_free_axis_where_it_is() {
        let head = record(
            Kinematics::Head,
            RotaryAxis::along("C", [0.0, 0.0, 1.0]),
            RotaryAxis::along("A", [1.0, 0.0, 0.0]),
        );
        let swivel = solve(
            &head,
            &Request {
                current: [42.0, 0.0],
                ..request(Rotation3::identity())
            },
        )
        .expect("valid");
        assert_eq!(positions(&swivel), [[42.0, 0.0]]);
    }
}
