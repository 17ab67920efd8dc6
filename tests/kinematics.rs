//! The swivel solver checked independently: for random records (heads,
//! tables, mixed; orthogonal and nutating axes; offsets and limits) and
//! random frames, the axis positions it gives turn the tool onto the
//! requested direction, the positions and the residual give back the whole
//! frame, and an orientation made from known positions is always found.

use nalgebra::{Rotation3, Unit, Vector3};
use proptest::prelude::*;
use sinuprep::kinematics::{
    orientation, solve, split, Direction, Kinematics, Preference, Record, Request, RotaryAxis,
    TableAngle, TableAsk,
};

fn axis(vector: Vector3<f64>, offset: f64, limits: Option<(f64, f64)>) -> RotaryAxis {
    RotaryAxis {
        name: String::new(),
        vector,
        offset,
        hirth: None,
        limits,
        angle: 0.0,
    }
}

/// A unit vector from two angles (degrees).
fn direction(azimuth: f64, elevation: f64) -> Vector3<f64> {
    let (a, e) = (azimuth.to_radians(), elevation.to_radians());
    Vector3::new(e.cos() * a.cos(), e.cos() * a.sin(), e.sin())
}

prop_compose! {
    fn records()(
        kinematics in prop_oneof![Just(Kinematics::Head), Just(Kinematics::Table), Just(Kinematics::Mixed)],
        shape in 0..3usize,
        az in -180.0..180.0f64, el in -89.0..89.0f64,
        az2 in -180.0..180.0f64, el2 in -89.0..89.0f64,
        offsets in proptest::array::uniform2(-90.0..90.0f64),
        flip in any::<bool>(),
    ) -> Record {
        // The machines built: orthogonal axes (a C-A head, an A-C table, a B
        // head over a C table), a 45° nutating axis, or any two axes.
        let nutating = Vector3::new(0.0, 1.0, 1.0);
        let (v1, v2) = match (shape, kinematics) {
            (0, Kinematics::Head) => (Vector3::z(), Vector3::x()),
            (0, Kinematics::Table) => (Vector3::x(), Vector3::z()),
            (0, Kinematics::Mixed) => (Vector3::y(), Vector3::z()),
            (1, Kinematics::Head) => (Vector3::z(), nutating),
            (1, _) => (nutating, Vector3::z()),
            _ => (direction(az, el), direction(az2, el2)),
        };
        let v2 = if flip { -v2 } else { v2 };
        Record {
            number: 1,
            name: "RANDOM".into(),
            kinematics,
            offsets: [Vector3::new(1.0, 2.0, 3.0), Vector3::new(0.0, 0.0, 40.0), Vector3::new(10.0, 0.0, -5.0), Vector3::new(-10.0, 0.0, -35.0)],
            axes: [axis(v1, offsets[0], None), axis(v2, offsets[1], None)],
            options: 0,
            direction_axis: None,
        }
    }
}

fn frame(axis: Vector3<f64>, degrees: f64) -> Rotation3<f64> {
    Rotation3::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians())
}

/// The model angles of machine positions.
fn model(record: &Record, positions: [f64; 2]) -> [f64; 2] {
    [0, 1].map(|i| positions[i] - record.axes[i].offset)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn every_solution_turns_the_tool_onto_the_frame_and_the_residual_completes_it(
        record in records(),
        az in -180.0..180.0f64, el in -89.0..89.0f64, angle in -180.0..180.0f64,
        plus in any::<bool>(),
    ) {
        prop_assume!(1.0 - record.axes[0].vector.normalize().dot(&record.axes[1].vector.normalize()).abs() > 1e-3);
        let rotation = frame(direction(az, el), angle);
        let direction = if plus { Direction::Plus } else { Direction::Minus };
        let swivel = solve(&record, &Request { rotation, direction, current: [0.0; 2] }).expect("valid record");
        let f = rotation * Vector3::z();
        for solution in &swivel.solutions {
            let reached = orientation(&record, model(&record, solution.positions)) * Vector3::z();
            prop_assert!((reached - f).norm() < 1e-9, "{:?} reaches {} for {}", solution.positions, reached, f);
        }
        if let (Some(chosen), Some(residual)) = (swivel.chosen, swivel.residual) {
            let kinematic = orientation(&record, model(&record, swivel.solutions[chosen].positions));
            prop_assert!(((kinematic * residual).matrix() - rotation.matrix()).norm() < 1e-9);
            // What stays in the frame turns about the tool axis only.
            prop_assert!((residual * Vector3::z() - Vector3::z()).norm() < 1e-9);
        }
        prop_assert_eq!(swivel.chosen.is_some(), !swivel.solutions.is_empty(), "no limits: a solution is taken");
    }

    #[test]
    fn an_orientation_the_axes_can_make_is_always_found(
        record in records(),
        angles in proptest::array::uniform2(-180.0..180.0f64),
    ) {
        prop_assume!(1.0 - record.axes[0].vector.normalize().dot(&record.axes[1].vector.normalize()).abs() > 1e-3);
        let made = orientation(&record, angles);
        let swivel = solve(&record, &Request { rotation: made, direction: Direction::Minus, current: [0.0; 2] }).expect("valid record");
        prop_assert!(!swivel.solutions.is_empty(), "{:?} not found", angles);
        // One of the solutions makes the same tool direction (both do), and
        // the positions given are where the axes were, or the other solution.
        let f = made * Vector3::z();
        let reaches = |positions: [f64; 2]| {
            (orientation(&record, model(&record, positions)) * Vector3::z() - f).norm() < 1e-9
        };
        prop_assert!(swivel.solutions.iter().all(|s| reaches(s.positions)), "a solution misses");
        // At a pole one axis is free, and any position of it is as good.
        let (v1, v2, z) = (record.axes[0].vector.normalize(), record.axes[1].vector.normalize(), Vector3::z());
        let (a, q, b, p) = match record.kinematics {
            Kinematics::Head => (v1, f, v2, z),
            Kinematics::Table => (v1, z, v2, f),
            Kinematics::Mixed => (v2, f, v1, z),
        };
        prop_assume!(a.dot(&q).abs() < 1.0 - 1e-9 && b.dot(&p).abs() < 1.0 - 1e-9);
        // Positions are only as sharp as the direction fixes them: a
        // direction found to 1e-9 leaves an axis near its pole, or two axes
        // nearly parallel, that error divided by how far they are from
        // degenerate (sines of the angles), in radians.
        let sine = |c: f64| (1.0 - c * c).max(0.0).sqrt();
        let conditioning = sine(v1.dot(&v2)) * sine(a.dot(&q)) * sine(b.dot(&p));
        let tolerance = 2e-6 + (1e-9 / conditioning).to_degrees();
        let same = |a: f64, b: f64| {
            let apart = (a - b).rem_euclid(360.0);
            apart.min(360.0 - apart) < tolerance
        };
        prop_assert!(
            swivel.solutions.iter().any(|s| {
                let found = model(&record, s.positions);
                same(found[0], angles[0]) && same(found[1], angles[1])
            }),
            "{:?} is not among {:?}", angles, swivel.solutions
        );
    }

    #[test]
    fn limits_are_kept_and_dir_takes_the_lower_or_higher_reference_position(
        record in records(),
        az in -180.0..180.0f64, el in -89.0..89.0f64,
        min in -200.0..0.0f64, span in 30.0..400.0f64,
    ) {
        prop_assume!(1.0 - record.axes[0].vector.normalize().dot(&record.axes[1].vector.normalize()).abs() > 1e-3);
        let mut record = record;
        for axis in &mut record.axes {
            axis.limits = Some((min, min + span));
        }
        let rotation = frame(direction(az, el), 30.0);
        let ask = |direction| solve(&record, &Request { rotation, direction, current: [0.0; 2] }).expect("valid");
        let (minus, plus) = (ask(Direction::Minus), ask(Direction::Plus));
        let reference = record.direction_reference();
        for swivel in [&minus, &plus] {
            for solution in swivel.solutions.iter().filter(|s| s.within_limits) {
                prop_assert!(solution.positions.iter().all(|&p| p >= min - 1e-9 && p <= min + span + 1e-9));
            }
            let inside = swivel.solutions.iter().filter(|s| s.within_limits).count();
            prop_assert_eq!(swivel.chosen.is_some(), inside > 0);
        }
        if let (Some(m), Some(p)) = (minus.chosen, plus.chosen) {
            prop_assert!(minus.solutions[m].positions[reference] <= plus.solutions[p].positions[reference] + 1e-9);
        }
    }
}

prop_compose! {
    /// A table of one axis (any direction, with or without limits) under a
    /// two-axis head (a C-A head, a nutating head, or any two axes) whose
    /// second axis is limited.
    fn table_and_head()(
        table_az in -180.0..180.0f64, table_el in -89.0..89.0f64,
        table_limits in prop_oneof![Just(None), (-200.0..0.0f64, 0.0..200.0f64).prop_map(Some)],
        table_offset in -30.0..30.0f64,
        shape in 0..3usize,
        az in -180.0..180.0f64, el in -89.0..89.0f64,
        reach in 20.0..120.0f64,
        c_reach in prop_oneof![Just(180.0), 60.0..170.0f64],
    ) -> (Record, Record) {
        let (v1, v2) = match shape {
            0 => (Vector3::z(), Vector3::x()),
            1 => (Vector3::z(), Vector3::new(0.0, 1.0, 1.0)),
            _ => (Vector3::z(), direction(az, el)),
        };
        let table = Record {
            number: 1,
            name: "TABLE".into(),
            kinematics: Kinematics::Table,
            offsets: [Vector3::zeros(), Vector3::new(0.0, 0.0, 40.0), Vector3::new(10.0, 0.0, -5.0), Vector3::zeros()],
            axes: [axis(direction(table_az, table_el), table_offset, table_limits), axis(Vector3::zeros(), 0.0, None)],
            options: 0,
            direction_axis: None,
        };
        let head = Record {
            number: 2,
            name: "HEAD".into(),
            kinematics: Kinematics::Head,
            offsets: [Vector3::zeros(); 4],
            axes: [axis(v1, 0.0, Some((-c_reach, c_reach))), axis(v2, 0.0, Some((-reach, reach)))],
            options: 0,
            direction_axis: None,
        };
        (table, head)
    }
}

/// The largest distance of the head's taken positions from the middles of
/// their limits, as a share of the half range (what the split minimises),
/// computed here on its own.
fn spread(head: &Record, positions: [f64; 2]) -> f64 {
    head.axes
        .iter()
        .zip(positions)
        .filter_map(|(axis, p)| {
            let (min, max) = axis.limits.expect("limited");
            // A whole turn within the limits: any angle is as good.
            (max - min < 360.0).then(|| (p - (min + max) / 2.0).abs() / ((max - min) / 2.0))
        })
        .fold(0.0, f64::max)
}

/// The largest travel (degrees) of the table and the head's axes from
/// where they stood (what `Preference::Nearest` minimises), computed here on
/// its own.
fn travel(from: [f64; 3], table: f64, positions: [f64; 2]) -> f64 {
    (table - from[0])
        .abs()
        .max((positions[0] - from[1]).abs())
        .max((positions[1] - from[2]).abs())
}

/// How far (degrees) the head's positions lie beyond their limits at most,
/// a position counted on the circle (`p` and `p ± 360` are one).
fn beyond(head: &Record, positions: [f64; 2]) -> f64 {
    head.axes
        .iter()
        .zip(positions)
        .filter_map(|(axis, p)| {
            let (min, max) = axis.limits.expect("limited");
            (max - min < 360.0).then(|| {
                let past = (p - min).rem_euclid(360.0);
                if past <= max - min {
                    0.0
                } else {
                    (past - (max - min)).min(360.0 - past)
                }
            })
        })
        .fold(0.0, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Three rotary axes: the table's and the head's positions together turn
    /// the tool onto the frame, with the residual the whole frame; the
    /// table stays inside its limits, and no other table position (sampled
    /// here) is better under the preference asked for: the head nearer the
    /// middles of its limits, or the axes nearer where they stood (to 1e-9:
    /// the best table angle is found exactly). Where no table position brings
    /// the head inside its limits, none sampled brings it nearer them than
    /// the one given.
    #[test]
    fn a_table_and_a_head_together_make_the_frame(
        (table, head) in table_and_head(),
        az in -180.0..180.0f64, el in -89.0..89.0f64, angle in -180.0..180.0f64,
        samples in proptest::collection::vec(0.0..1.0f64, 24),
        nearest in any::<bool>(), plus in any::<bool>(),
        from in proptest::array::uniform3(-180.0..180.0f64),
    ) {
        let rotation = frame(direction(az, el), angle);
        let prefer = if nearest { Preference::Nearest } else { Preference::Middle };
        let (low, high) = table.axes[0].limits.unwrap_or((-180.0, 180.0));
        // The axes' positions before: the table's inside its limits.
        let from = if nearest { [from[0].clamp(low, high), from[1], from[2]] } else { [0.0; 3] };
        let request = Request {
            rotation,
            direction: if plus { Direction::Plus } else { Direction::Minus },
            current: [from[1], from[2]],
        };
        let ask = |fixed| TableAsk { current: from[0], fixed, prefer };
        let split = split(&table, &head, &request, &ask(None)).expect("valid records");
        prop_assert!(split.table_within_limits);
        let table_turn = |gamma: f64| orientation(&table, [gamma - table.axes[0].offset, 0.0]);
        let at = |gamma: f64| sinuprep::kinematics::split(&table, &head, &request, &ask(Some(gamma))).expect("valid");
        let Some(chosen) = split.head.chosen else {
            // Nowhere inside its limits: then no sampled table position
            // brings the head inside them, nor nearer them.
            let TableAngle::Beyond { solution, beyond_deg } = split.found else {
                prop_assert_eq!(split.found, TableAngle::Unreachable);
                prop_assert!(split.head.solutions.is_empty());
                for s in samples {
                    prop_assert!(at(low + s * (high - low)).head.solutions.is_empty());
                }
                return Ok(());
            };
            let given = beyond(&head, split.head.solutions[solution].exact);
            prop_assert!((given - beyond_deg).abs() < 1e-9, "{} told as {}", given, beyond_deg);
            prop_assert!(given > 0.0);
            for s in samples {
                let gamma = low + s * (high - low);
                let other = at(gamma);
                prop_assert!(other.head.chosen.is_none(), "table {} brings the head inside", gamma);
                for solution in &other.head.solutions {
                    let theirs = beyond(&head, solution.exact);
                    prop_assert!(given <= theirs + 1e-9, "table {} gives {} < {} at {}", gamma, theirs, given, split.table);
                }
            }
            return Ok(());
        };
        prop_assert_eq!(split.found, TableAngle::Chosen(prefer));
        let positions = split.head.solutions[chosen].positions;
        let kinematic = table_turn(split.table) * orientation(&head, positions);
        let f = rotation * Vector3::z();
        prop_assert!((kinematic * Vector3::z() - f).norm() < 1e-9);
        let residual = split.head.residual.expect("residual");
        prop_assert!(((kinematic * residual).matrix() - rotation.matrix()).norm() < 1e-9);
        let cost = |gamma: f64, positions: [f64; 2]| match prefer {
            Preference::Middle => spread(&head, positions),
            Preference::Nearest => travel(from, gamma, positions),
        };
        let best = cost(split.table, positions);
        for s in samples {
            let gamma = low + s * (high - low);
            let other = at(gamma);
            if let Some(index) = other.head.chosen {
                let theirs = cost(gamma, other.head.solutions[index].positions);
                prop_assert!(best <= theirs + 1e-9, "table {} gives {} < {} at {}", gamma, theirs, best, split.table);
            }
        }
    }
}
