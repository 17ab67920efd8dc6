//! From measurements to rotations: a face probed on the machine to the
//! rotation that turns the tool normal to it (face.rs), a point measured
//! before and after a rotary axis turned to the axis it turned about (the
//! Rodrigues inverse problem, turn.rs), measured positions of one point to
//! the axis and a point on it (circle.rs).
//!
//! Pure math beside `rotation` and `kinematics`, on nalgebra: no syntax, no
//! printing, no units (lengths are in whatever unit the points are given,
//! angles in degrees). It does not fit noisy data in the least-squares sense:
//! each form takes the points it is given as exact and says, with a
//! tolerance, when they do not fit one face or one turn.

pub mod circle;
pub mod face;
pub mod turn;

use nalgebra::{Point3, Vector3};

/// The distance of the first two of three points that lie within
/// `tolerance` of each other (a point measured twice), if any.
fn coincident(points: [Point3<f64>; 3], tolerance: f64) -> Option<f64> {
    let [p1, p2, p3] = points;
    [(p1, p2), (p1, p3), (p2, p3)]
        .into_iter()
        .map(|(a, b)| (b - a).norm())
        .find(|&distance| distance <= tolerance)
}

/// Three points as a triangle: `(p2 − p1) × (p3 − p1)` (its normal, not
/// made unit) and its least height, twice its area over its longest side
/// (how far the points are from lying on one line).
fn triangle(points: [Point3<f64>; 3]) -> (Vector3<f64>, f64) {
    let [p1, p2, p3] = points;
    let (a, b) = (p2 - p1, p3 - p1);
    let cross = a.cross(&b);
    let longest = a.norm().max(b.norm()).max((p3 - p2).norm());
    (cross, cross.norm() / longest)
}

/// A little random generator for the tests, so that they need no
/// dependency.
#[cfg(test)]
pub(crate) struct Noise(pub u64);

#[cfg(test)]
impl Noise {
    /// Uniform in [-1, 1].
    pub fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    pub fn vector(&mut self, size: f64) -> nalgebra::Vector3<f64> {
        nalgebra::Vector3::new(self.next(), self.next(), self.next()) * size
    }
}
