//! A rotary axis from measured positions of one point it turns (a sphere on
//! the table or in the spindle, probed at each position, as a kinematics
//! measuring cycle does): its direction and a point on it.
//!
//! Three positions fix the circle they lie on: the axis is its normal
//! through its centre. Two positions and the angle turned between them fix
//! only the axis's tilt in one plane: the axis is normal to the chord, so
//! the direction taken is the nominal one given, made normal to the chord
//! (the least change), and the point on it is the centre of the arc of that
//! angle. It does not fit more positions in the least-squares sense.

use nalgebra::{Point3, Vector3};

use crate::rotation::trig::{atan2_degrees, sin_cos_degrees};

/// A rotary axis found from measured positions.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Found {
    /// Unit, oriented so that the turns from each position to the next are
    /// right-handed about it (positive), or as the angle given says.
    pub direction: Vector3<f64>,
    /// The centre of the circle: the point of the axis in the positions' plane.
    pub point: Point3<f64>,
    /// The point's distance from the axis.
    pub radius: f64,
    /// The turn from each position to the next, degrees, about `direction`.
    pub turns: [f64; 2],
    /// For two positions: the angle between the nominal direction given and
    /// the one found, degrees (0 for three positions).
    pub correction: f64,
}

/// Why the positions give no axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CircleError {
    /// Two positions are no farther apart than the tolerance.
    Coincident { distance: f64 },
    /// Three positions on one line: the third is `height` from the line
    /// through the other two.
    Collinear { height: f64 },
    /// The nominal direction is (nearly) along the chord: no axis normal to
    /// the chord is near it.
    AlongChord,
    /// The nominal direction is zero.
    NoDirection,
    /// The angle is 0 (or whole turns): two different positions are no turn.
    NoTurn,
}

/// The axis through three positions: the normal of their plane through the
/// centre of their circle, oriented so that the turn from the first to the
/// second to the third is positive.
pub fn three(positions: [Point3<f64>; 3], tolerance: f64) -> Result<Found, CircleError> {
    let [p1, p2, p3] = positions;
    if let Some(distance) = super::coincident(positions, tolerance) {
        return Err(CircleError::Coincident { distance });
    }
    let (a, b) = (p2 - p1, p3 - p1);
    let (cross, height) = super::triangle(positions);
    if height <= tolerance {
        return Err(CircleError::Collinear { height });
    }
    // The circumcentre, from p1: (|a|² b − |b|² a) × (a × b) / (2 |a × b|²).
    let centre = p1
        + (b * a.norm_squared() - a * b.norm_squared()).cross(&cross)
            / (2.0 * cross.norm_squared());
    // a × b points along the axis the way p1 -> p2 -> p3 goes round,
    // whether p3 lies past p2 or the arc runs the long way.
    let direction = (p2 - p1).cross(&(p3 - p2)).normalize();
    let turn = |from: Point3<f64>, to: Point3<f64>| {
        let (u, v) = (from - centre, to - centre);
        atan2_degrees(u.cross(&v).dot(&direction), u.dot(&v)).rem_euclid(360.0)
    };
    Ok(Found {
        direction,
        point: centre,
        radius: (p1 - centre).norm(),
        turns: [turn(p1, p2), turn(p2, p3)],
        correction: 0.0,
    })
}

/// The axis of a turn by `degrees` from `positions[0]` to `positions[1]`,
/// nearest the direction `nominal`: normal to the chord, and through the
/// centre of the arc.
pub fn two(
    positions: [Point3<f64>; 2],
    degrees: f64,
    nominal: Vector3<f64>,
    tolerance: f64,
) -> Result<Found, CircleError> {
    let [p1, p2] = positions;
    let r = p2 - p1;
    let chord = r.norm();
    if chord <= tolerance {
        return Err(CircleError::Coincident { distance: chord });
    }
    let (half_sin, half_cos) = sin_cos_degrees(degrees / 2.0);
    if half_sin == 0.0 {
        return Err(CircleError::NoTurn);
    }
    let along = r / chord;
    let normal = nominal - along * along.dot(&nominal);
    if nominal.norm() == 0.0 {
        return Err(CircleError::NoDirection);
    }
    if normal.norm() <= 1e-9 * nominal.norm() {
        return Err(CircleError::AlongChord);
    }
    let direction = normal.normalize();
    // From the chord's middle towards the centre: e × r̂ for a positive
    // turn, at (|r|/2) / tan(χ/2); negative angles come out through the sign.
    let height = chord / 2.0 * half_cos / half_sin;
    let point = p1 + r / 2.0 + direction.cross(&along) * height;
    Ok(Found {
        direction,
        point,
        radius: chord / (2.0 * half_sin.abs()),
        turns: [degrees, 0.0],
        correction: atan2_degrees(direction.cross(&nominal).norm(), direction.dot(&nominal)),
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::frame::from_axis_angle;

    fn turned(
        axis: Vector3<f64>,
        through: Point3<f64>,
        point: Point3<f64>,
        degrees: f64,
    ) -> Point3<f64> {
        through + from_axis_angle(axis, degrees) * (point - through)
    }

    #[test]
    fn three_positions_give_the_axis_and_its_centre() {
        let axis = Vector3::new(0.02, -0.01, 1.0).normalize();
        let through = Point3::new(10.0, -20.0, 5.0);
        let sphere = Point3::new(210.0, 30.0, 80.0);
        for steps in [[45.0, 45.0], [-30.0, -60.0], [120.0, 150.0], [10.0, 300.0]] {
            let p1 = sphere;
            let p2 = turned(axis, through, p1, steps[0]);
            let p3 = turned(axis, through, p2, steps[1]);
            let found = three([p1, p2, p3], 1e-6).expect("an axis");
            let positive = steps[0] > 0.0 && steps[0] + steps[1] < 360.0;
            let sign = if positive { 1.0 } else { -1.0 };
            assert!(
                (found.direction - axis * sign).norm() < 1e-9,
                "{steps:?}: {found:?}"
            );
            // The centre lies on the axis.
            let off = (found.point - through) - axis * axis.dot(&(found.point - through));
            assert!(off.norm() < 1e-9, "{steps:?}");
            let expected = steps.map(|s| (s * sign).rem_euclid(360.0));
            assert!(
                (found.turns[0] - expected[0]).abs() < 1e-9
                    && (found.turns[1] - expected[1]).abs() < 1e-9,
                "{steps:?}: {:?}",
                found.turns
            );
        }
    }

    #[test]
    fn two_positions_and_the_nominal_direction_give_the_point() {
        let axis = Vector3::new(0.0, 0.01, 1.0).normalize();
        let through = Point3::new(-5.0, 40.0, 0.0);
        let p1 = Point3::new(120.0, 40.0, 30.0);
        for degrees in [90.0, -45.0, 170.0, 200.0] {
            let p2 = turned(axis, through, p1, degrees);
            // The nominal Z, off by the 0.01 tilt.
            let found = two([p1, p2], degrees, Vector3::z(), 1e-6).expect("an axis");
            // Normal to the chord, near the nominal: turns p1 into p2 about its point.
            let back = found.point + from_axis_angle(found.direction, degrees) * (p1 - found.point);
            assert!((back - p2).norm() < 1e-9, "{degrees}: {back} {p2}");
            assert!(found.correction < 1.0, "{degrees}");
        }
        // With the true direction given, the true point comes out.
        let p2 = turned(axis, through, p1, 90.0);
        let found = two([p1, p2], 90.0, axis, 1e-6).expect("an axis");
        let off = (found.point - through) - axis * axis.dot(&(found.point - through));
        assert!(off.norm() < 1e-9 && found.correction < 1e-9);
    }

    #[test]
    fn any_positions_give_a_finite_axis_or_an_error() {
        let mut state = 23u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        };
        for case in 0..20_000 {
            let scale = 10f64.powi((case % 19) - 9).min(1e9);
            let mut point = || Point3::new(next() * scale, next() * scale, next() * scale);
            let (a, b, c) = (point(), point(), point());
            let tolerance = 10f64.powi((case % 13) - 12);
            let nominal = Vector3::new(next(), next(), next());
            for found in [
                three([a, b, c], tolerance),
                two([a, b], 37.0 * f64::from(case % 11), nominal, tolerance),
            ]
            .into_iter()
            .flatten()
            {
                assert!(found.direction.iter().all(|v| v.is_finite()), "{case}");
                assert!(found.point.iter().all(|v| v.is_finite()), "{case}");
                assert!(found.radius.is_finite() && found.turns.iter().all(|t| t.is_finite()));
            }
        }
    }

    #[test]
    fn bad_positions_are_refused() {
        let o = Point3::origin();
        let x = Point3::new(100.0, 0.0, 0.0);
        assert!(matches!(
            three([o, o, x], 0.01),
            Err(CircleError::Coincident { .. })
        ));
        assert!(matches!(
            three([o, x, Point3::new(200.0, 0.001, 0.0)], 0.01),
            Err(CircleError::Collinear { .. })
        ));
        assert!(matches!(
            two([o, o], 90.0, Vector3::z(), 0.01),
            Err(CircleError::Coincident { .. })
        ));
        assert_eq!(
            two([o, x], 360.0, Vector3::z(), 0.01),
            Err(CircleError::NoTurn)
        );
        assert_eq!(
            two([o, x], 90.0, Vector3::x(), 0.01),
            Err(CircleError::AlongChord)
        );
    }
}
