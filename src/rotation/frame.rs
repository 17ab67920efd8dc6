//! The rotations frames are built of: an additive rotation on top of the
//! active one (spec section 3), and the turn about an axis by an angle.

use nalgebra::{Rotation3, Vector3};

use crate::rotation::sequence::Kind;

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
        let (axis, angle) = crate::rotation::forms::axis_angle(&rotation);
        let rebuilt = from_axis_angle(axis * 3.0, angle);
        assert!((rebuilt.matrix() - rotation.matrix()).abs().max() < 1e-12);
    }
}
