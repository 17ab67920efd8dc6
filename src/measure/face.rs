//! A face probed on the machine, and the rotation that turns the tool normal
//! to it: the paper's flange (two points along X and two along Y, section 1
//! and Example 3), three points anywhere on it, or its normal.
//!
//! The face's two angles are those of a rotation performed about the fixed
//! machine axes, X first, then Y (extrinsic X, Y, Z with Z = 0, the
//! sequence CYCLE600 takes from a probe, `_BIN_IN` 57): R = R_Y(b) · R_X(a)
//! turns the tool axis Z onto the normal and keeps the new X axis in the
//! machine's ZX plane. They are exact (`reference/kinematics.md` section 6):
//! with the normal n, a = atan2(-n_y, √(n_x² + n_z²)) and b = atan2(n_x, n_z).
//! The projection angles a probe cycle reports (the slope of the face's
//! trace in the YZ and the ZX planes) equal them only while one slope is
//! zero; [`projection_angles`] gives them for comparison, never for a swivel.
//!
//! It does not know units: lengths (the tolerance among them) are in the
//! unit of the points, and the angles do not depend on it.

use nalgebra::{Point3, Rotation3, Vector3};

use crate::rotation::trig::atan2_degrees;
use crate::rotation::{matrix, Kind, Sequence};

/// Which of the measurements an error is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Measured {
    /// The two points along X.
    AlongX,
    /// The two points along Y.
    AlongY,
    /// The three points.
    Points,
    /// The normal.
    Normal,
}

/// Why measured points give no face.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FaceError {
    /// Two points of `which` are no farther apart than the tolerance.
    Coincident { which: Measured, distance: f64 },
    /// The line along X and the line along Y are parallel: they span no face.
    Parallel,
    /// The three points lie on one line: the third is `height` from the line
    /// through the other two.
    Collinear { height: f64 },
    /// The face's normal is horizontal: the face is vertical, and which side
    /// of it the tool is on is not known from the points.
    Vertical { normal: Vector3<f64> },
    /// The points along Y are `distance` from the face through the points
    /// along X, more than the tolerance.
    NotFlat { distance: f64 },
    /// The given normal is zero (or not finite).
    NoNormal,
}

/// A face: its unit normal, on the tool's side.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Face {
    pub normal: Vector3<f64>,
    /// How far the measured points lie from one plane (0 for three points
    /// or a normal).
    pub flatness: f64,
}

/// A normal whose Z component is below this (against 1) is horizontal.
const VERTICAL: f64 = 1e-9;

/// The face through two points along X and two along Y (the paper's probe on
/// the flange, each pair measured on the face in the machine's coordinates):
/// the lines through each pair span it. The normal points up (the tool's
/// side); the two pairs must lie on one plane within `tolerance`.
pub fn along(x: [Point3<f64>; 2], y: [Point3<f64>; 2], tolerance: f64) -> Result<Face, FaceError> {
    let u = x[1] - x[0];
    let v = y[1] - y[0];
    for (which, span) in [(Measured::AlongX, u), (Measured::AlongY, v)] {
        if span.norm() <= tolerance {
            return Err(FaceError::Coincident {
                which,
                distance: span.norm(),
            });
        }
    }
    let cross = u.cross(&v);
    // Over the shorter span the two lines part by less than the tolerance.
    if cross.norm() / u.norm().max(v.norm()) <= tolerance {
        return Err(FaceError::Parallel);
    }
    let normal = upward(cross.normalize())?;
    // The plane through the line along X with this normal holds the line
    // along Y's direction; its points must lie on it too.
    let distance = normal.dot(&(y[0] - x[0])).abs();
    if distance > tolerance {
        return Err(FaceError::NotFlat { distance });
    }
    Ok(Face {
        normal,
        flatness: distance,
    })
}

/// The face through three points, its normal up (the tool's side).
pub fn through(points: [Point3<f64>; 3], tolerance: f64) -> Result<Face, FaceError> {
    if let Some(distance) = super::coincident(points, tolerance) {
        return Err(FaceError::Coincident {
            which: Measured::Points,
            distance,
        });
    }
    let (cross, height) = super::triangle(points);
    if height <= tolerance {
        return Err(FaceError::Collinear { height });
    }
    Ok(Face {
        normal: upward(cross.normalize())?,
        flatness: 0.0,
    })
}

/// The face with this normal (any length), taken as given: its side is the
/// tool's, and a horizontal normal (a vertical face) is a face like any other.
pub fn with_normal(normal: Vector3<f64>) -> Result<Face, FaceError> {
    let length = normal.norm();
    if !(length.is_finite() && length > 0.0) {
        return Err(FaceError::NoNormal);
    }
    Ok(Face {
        normal: normal / length,
        flatness: 0.0,
    })
}

/// A measured face's normal turned to the tool's side (up); a horizontal
/// one is refused, as the points cannot tell the side.
fn upward(normal: Vector3<f64>) -> Result<Vector3<f64>, FaceError> {
    if normal.z.abs() < VERTICAL {
        return Err(FaceError::Vertical { normal });
    }
    Ok(if normal.z < 0.0 { -normal } else { normal })
}

/// The sequence of the face's angles: extrinsic X, Y, Z (the third is 0).
pub fn sequence() -> Sequence {
    Sequence {
        axes: [
            crate::rotation::Axis::X,
            crate::rotation::Axis::Y,
            crate::rotation::Axis::Z,
        ],
        kind: Kind::Extrinsic,
    }
}

/// The face's two angles in degrees, about the machine's X, then its Y: the
/// rotation R_Y(b) · R_X(a) turns Z onto `normal` (unit).
pub fn angles(normal: &Vector3<f64>) -> [f64; 2] {
    [
        atan2_degrees(-normal.y, normal.x.hypot(normal.z)),
        atan2_degrees(normal.x, normal.z),
    ]
}

/// The rotation of the face's angles: the tool axis Z onto the normal, the
/// new X in the machine's ZX plane.
pub fn rotation(angles: [f64; 2]) -> Rotation3<f64> {
    matrix(sequence(), [angles[0], angles[1], 0.0])
}

/// The slopes of the face's traces as angles: about X, the trace in the YZ
/// plane; about Y, the trace in the ZX plane. The one about Y is the face's
/// angle b; the one about X differs from a once both slopes are non-zero.
pub fn projection_angles(normal: &Vector3<f64>) -> [f64; 2] {
    [
        atan2_degrees(-normal.y, normal.z),
        atan2_degrees(normal.x, normal.z),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four probe points of a face through `centre` turned by `angles`:
    /// two along the face's own X, two along its own Y.
    fn probed(angles: [f64; 2], centre: Point3<f64>, span: f64) -> [Point3<f64>; 4] {
        let r = rotation(angles);
        let (ex, ey) = (r * Vector3::x(), r * Vector3::y());
        [
            centre,
            centre + ex * span,
            centre + ey * 0.3 * span,
            centre + ey * 1.1 * span,
        ]
    }

    use crate::measure::Noise;

    #[test]
    fn the_reference_example_comes_out() {
        // reference/kinematics.md section 6: Lx = 100, Δz = +2, Ly = 80, Δz = -1.5.
        let face = along(
            [Point3::new(0.0, 0.0, 0.0), Point3::new(100.0, 0.0, 2.0)],
            [Point3::new(0.0, 0.0, 0.0), Point3::new(0.0, 80.0, -1.5)],
            0.01,
        )
        .expect("a face");
        let [a, b] = angles(&face.normal);
        assert!((b - -1.1458).abs() < 5e-5, "{b}");
        assert!((a - -1.0740).abs() < 5e-5, "{a}");
        // The projection about X is the small-angle one, and differs.
        let [pa, pb] = projection_angles(&face.normal);
        assert!((pa - -1.0742).abs() < 5e-5 && pb == b, "{pa} {pb}");
        let tilt = face.normal.z.acos().to_degrees();
        assert!((tilt - 1.5703).abs() < 5e-5, "{tilt}");
    }

    #[test]
    fn angles_to_points_to_angles_round_trip() {
        let mut noise = Noise(7);
        for _ in 0..2000 {
            let angles = [noise.next() * 89.0, noise.next() * 89.0];
            let centre = Point3::from(noise.vector(500.0));
            let [p1, p2, p3, p4] = probed(angles, centre, 100.0);
            for face in [
                along([p1, p2], [p3, p4], 1e-6).expect("along"),
                through([p1, p2, p4], 1e-6).expect("through"),
                with_normal(rotation(angles) * Vector3::z() * 3.0).expect("normal"),
            ] {
                let back = super::angles(&face.normal);
                assert!(
                    (back[0] - angles[0]).abs() < 1e-12 && (back[1] - angles[1]).abs() < 1e-12,
                    "{angles:?} -> {back:?}"
                );
            }
        }
    }

    #[test]
    fn the_rotation_turns_the_tool_onto_the_normal_with_x_in_the_zx_plane() {
        let mut noise = Noise(11);
        for _ in 0..500 {
            let normal =
                Vector3::new(noise.next(), noise.next(), noise.next().abs() + 0.01).normalize();
            let r = rotation(angles(&normal));
            assert!((r * Vector3::z() - normal).norm() < 1e-14);
            assert!((r * Vector3::x()).y.abs() < 1e-15);
            // The engine reads the same rotation back as the same angles.
            let back = crate::rotation::decompose(sequence(), &r).angles;
            let [a, b] = angles(&normal);
            assert!((back[0] - a).abs() < 1e-12 && (back[1] - b).abs() < 1e-12);
            assert!(back[2].abs() < 1e-12);
        }
    }

    #[test]
    fn noisy_points_give_angles_within_the_noise() {
        // A probe repeating to 1 µm over 100 mm spans: the angle is off by
        // at most about 2 µm / 30 mm, 0.004°.
        let mut noise = Noise(3);
        for _ in 0..1000 {
            let angles = [noise.next() * 30.0, noise.next() * 30.0];
            let centre = Point3::from(noise.vector(300.0));
            let mut points = probed(angles, centre, 100.0);
            for point in &mut points {
                *point += noise.vector(0.001);
            }
            let [p1, p2, p3, p4] = points;
            let face = along([p1, p2], [p3, p4], 0.01).expect("within the tolerance");
            let back = super::angles(&face.normal);
            assert!(
                (back[0] - angles[0]).abs() < 0.004 && (back[1] - angles[1]).abs() < 0.004,
                "{angles:?} -> {back:?}"
            );
            assert!(face.flatness < 0.01);
        }
    }

    #[test]
    fn bad_points_are_refused() {
        let o = Point3::origin();
        let x = Point3::new(100.0, 0.0, 1.0);
        let y = Point3::new(0.0, 80.0, 0.0);
        assert_eq!(
            along([o, o], [o, y], 0.01),
            Err(FaceError::Coincident {
                which: Measured::AlongX,
                distance: 0.0
            })
        );
        assert!(matches!(
            along([o, x], [y, y + Vector3::new(0.0, 0.005, 0.0)], 0.01),
            Err(FaceError::Coincident {
                which: Measured::AlongY,
                ..
            })
        ));
        assert_eq!(
            along([o, x], [y, y + (x - o) * 0.5], 0.01),
            Err(FaceError::Parallel)
        );
        // Points along Y 0.5 above the face through the points along X.
        assert!(matches!(
            along([o, x], [y + Vector3::z() * 0.5, Point3::new(0.0, 160.0, 0.5)], 0.01),
            Err(FaceError::NotFlat { distance }) if (distance - 0.5).abs() < 1e-3
        ));
        // A vertical face: both lines horizontal or vertical in one plane.
        assert!(matches!(
            along(
                [o, Point3::new(100.0, 0.0, 0.0)],
                [o, Point3::new(0.0, 0.0, 80.0)],
                0.01
            ),
            Err(FaceError::Vertical { .. })
        ));
        assert!(matches!(
            through([o, x, Point3::new(200.0, 0.0, 2.0)], 0.01),
            Err(FaceError::Collinear { .. })
        ));
        assert!(matches!(
            through([o, x, x], 0.01),
            Err(FaceError::Coincident {
                which: Measured::Points,
                ..
            })
        ));
        assert_eq!(with_normal(Vector3::zeros()), Err(FaceError::NoNormal));
        assert_eq!(
            with_normal(Vector3::new(f64::NAN, 0.0, 1.0)),
            Err(FaceError::NoNormal)
        );
        // Given as a normal, a vertical face is a face.
        let side = with_normal(Vector3::x()).expect("a face");
        assert_eq!(angles(&side.normal), [0.0, 90.0]);
    }

    #[test]
    fn any_points_give_a_finite_face_or_an_error() {
        // Coordinates up to the command line's ±1e9, spans down to nothing,
        // tolerances from tiny to huge: never a NaN.
        let mut noise = Noise(13);
        for case in 0..20_000 {
            let scale = 10f64.powi((case % 19) - 9);
            let mut point = || Point3::from(noise.vector(scale.min(1e9)));
            let (a, b, c, d) = (point(), point(), point(), point());
            let tolerance = 10f64.powi((case % 13) - 12);
            for face in [
                along([a, b], [c, d], tolerance),
                through([a, b, c], tolerance),
            ]
            .into_iter()
            .flatten()
            {
                assert!(face.normal.iter().all(|v| v.is_finite()), "{case}");
                assert!((face.normal.norm() - 1.0).abs() < 1e-12);
                assert!(angles(&face.normal).iter().all(|v| v.is_finite()));
            }
        }
    }

    #[test]
    fn the_points_normal_points_to_the_tool_whatever_their_order() {
        let [p1, p2, p3, p4] = probed([10.0, -20.0], Point3::origin(), 50.0);
        for face in [
            along([p2, p1], [p3, p4], 1e-6),
            along([p1, p2], [p4, p3], 1e-6),
            through([p3, p2, p1], 1e-6),
        ] {
            assert!(face.expect("a face").normal.z > 0.0);
        }
    }
}
