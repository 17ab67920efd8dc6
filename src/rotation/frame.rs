//! Frames: translation before, rotation, translation after, as CYCLE800's
//! X0/Y0/Z0, rotation, X1/Y1/Z1 (spec section 3), on nalgebra isometries.

use nalgebra::{Isometry3, Point3, Rotation3, Translation3, UnitQuaternion, Vector3};

use crate::rotation::sequence::Kind;

/// T = Trans(before) · Rot(rotation) · Trans(after).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub before: Vector3<f64>,
    pub rotation: Rotation3<f64>,
    /// In the rotated system.
    pub after: Vector3<f64>,
}

impl Frame {
    pub fn new(before: Vector3<f64>, rotation: Rotation3<f64>, after: Vector3<f64>) -> Self {
        Self {
            before,
            rotation,
            after,
        }
    }

    /// The whole transformation as one rigid motion.
    pub fn isometry(&self) -> Isometry3<f64> {
        let rotation = UnitQuaternion::from_rotation_matrix(&self.rotation);
        Translation3::from(self.before) * rotation * Translation3::from(self.after)
    }

    /// Where a point given in the new (rotated, shifted) system lies in the old one.
    pub fn apply(&self, point: Point3<f64>) -> Point3<f64> {
        Point3::from(self.before + self.rotation * (point.coords + self.after))
    }
}

/// An additive rotation on top of the active one: about the current workpiece
/// axes (intrinsic, R0 · R_add) or about the machine axes (extrinsic, R_add · R0),
/// as the paper states.
pub fn compose_additive(
    active: &Rotation3<f64>,
    added: &Rotation3<f64>,
    kind: Kind,
) -> Rotation3<f64> {
    match kind {
        Kind::Intrinsic => active * added,
        Kind::Extrinsic => added * active,
    }
}

/// The axis and angle (degrees, in [0, 180]) of a rotation; the axis is `None`
/// for the identity.
pub fn axis_angle(rotation: &Rotation3<f64>) -> (Option<Vector3<f64>>, f64) {
    match rotation.axis_angle() {
        Some((axis, angle)) => (Some(axis.into_inner()), angle.to_degrees()),
        None => (None, 0.0),
    }
}

/// The Rodrigues rotation vector: the unit axis times the angle in degrees.
pub fn rotation_vector(rotation: &Rotation3<f64>) -> Vector3<f64> {
    rotation.scaled_axis().map(f64::to_degrees)
}

/// The rotation about `axis` (need not be unit) by `degrees`, by the
/// Rodrigues formula R = I + sin θ K + (1 - cos θ) K².
pub fn from_axis_angle(axis: Vector3<f64>, degrees: f64) -> Rotation3<f64> {
    let unit = axis.normalize();
    let k = unit.cross_matrix();
    let (s, c) = crate::rotation::trig::sin_cos_degrees(degrees);
    Rotation3::from_matrix_unchecked(nalgebra::Matrix3::identity() + k * s + k * k * (1.0 - c))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::euler::matrix;

    fn close(a: &Vector3<f64>, b: &Vector3<f64>) -> bool {
        (a - b).abs().max() < 1e-12
    }

    #[test]
    fn frame_shifts_rotates_then_shifts_in_the_rotated_system() {
        let rotation = matrix("i:ZYX".parse().expect("valid"), [90.0, 0.0, 0.0]);
        let frame = Frame::new(
            Vector3::new(10.0, 0.0, 0.0),
            rotation,
            Vector3::new(1.0, 0.0, 0.0),
        );
        let moved = frame.apply(Point3::origin());
        assert!(
            close(&moved.coords, &Vector3::new(10.0, 1.0, 0.0)),
            "{moved}"
        );
        let by_isometry = frame.isometry() * Point3::new(1.0, 2.0, 3.0);
        assert!(close(
            &by_isometry.coords,
            &frame.apply(Point3::new(1.0, 2.0, 3.0)).coords
        ));
    }

    #[test]
    fn additive_rotation_orders() {
        let z = matrix("i:ZYX".parse().expect("valid"), [90.0, 0.0, 0.0]);
        let x = matrix("i:XYZ".parse().expect("valid"), [90.0, 0.0, 0.0]);
        assert_eq!(compose_additive(&z, &x, Kind::Intrinsic), z * x);
        assert_eq!(compose_additive(&z, &x, Kind::Extrinsic), x * z);
    }

    #[test]
    fn axis_angle_round_trips_through_rodrigues() {
        let rotation = matrix("e:XYZ".parse().expect("valid"), [30.0, 45.0, 60.0]);
        let (axis, angle) = axis_angle(&rotation);
        let rebuilt = from_axis_angle(axis.expect("not identity"), angle);
        assert!((rebuilt.matrix() - rotation.matrix()).abs().max() < 1e-12);
        let vector = rotation_vector(&rotation);
        assert!((vector.norm() - angle).abs() < 1e-9);
        assert_eq!(axis_angle(&Rotation3::identity()), (None, 0.0));
    }
}
