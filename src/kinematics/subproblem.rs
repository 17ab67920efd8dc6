//! Paden-Kahan subproblems on directions: the rotation angles that carry one
//! unit vector onto another about given axes. Angles in degrees,
//! right-handed about the (unit) axis.

use nalgebra::Vector3;

use crate::rotation::trig::atan2_degrees;

/// Below this, a vector is taken to lie on an axis (its projection onto the
/// plane normal to the axis has no direction).
const ON_AXIS: f64 = 1e-9;

/// Subproblem 1: the angle θ with `R(k, θ) p = q` as far as the directions
/// allow (`k` unit), or `None` when `p` or `q` lies on the axis, where every
/// angle does (a pole).
pub fn angle_about(k: &Vector3<f64>, p: &Vector3<f64>, q: &Vector3<f64>) -> Option<f64> {
    let p_perp = p - k * k.dot(p);
    let q_perp = q - k * k.dot(q);
    if p_perp.norm_squared() < ON_AXIS * ON_AXIS || q_perp.norm_squared() < ON_AXIS * ON_AXIS {
        return None;
    }
    Some(atan2_degrees(
        k.dot(&p_perp.cross(&q_perp)),
        p_perp.dot(&q_perp),
    ))
}

/// None, one or two of a kind, held without an allocation: what the
/// subproblems give, which the table's split asks for a hundred times a
/// split.
#[derive(Clone, Copy, Debug)]
pub struct UpToTwo<T> {
    items: [T; 2],
    len: usize,
}

impl<T: Copy + Default> UpToTwo<T> {
    pub fn new() -> Self {
        Self {
            items: [T::default(); 2],
            len: 0,
        }
    }

    /// Adds `item`; a third is not kept (none is ever made).
    pub fn push(&mut self, item: T) {
        if let Some(slot) = self.items.get_mut(self.len) {
            *slot = item;
            self.len += 1;
        }
    }
}

impl<T: Copy + Default> Default for UpToTwo<T> {
    fn default() -> Self {
        Self::new()
    }
}

impl<T> std::ops::Deref for UpToTwo<T> {
    type Target = [T];

    fn deref(&self) -> &[T] {
        &self.items[..self.len]
    }
}

impl<T> std::ops::DerefMut for UpToTwo<T> {
    fn deref_mut(&mut self) -> &mut [T] {
        &mut self.items[..self.len]
    }
}

/// The intermediate directions `w = R(b, θ2) p = R(a, −θ1) q` of
/// subproblem 2 (`R(a, θ1) R(b, θ2) p = q`, all unit, `a` and `b` not
/// parallel): two, one where the cones touch, none where `q` cannot be
/// reached.
pub fn intermediates(
    a: &Vector3<f64>,
    b: &Vector3<f64>,
    p: &Vector3<f64>,
    q: &Vector3<f64>,
) -> UpToTwo<Vector3<f64>> {
    // In the frame (a, e2, c/|c|) of the axes' plane: a·w = a·q fixes w's
    // first coordinate, b·w = b·p its second, and what is left of a unit
    // vector its third. 1 − (a·q)² is taken as |a × q|², which keeps its
    // digits near a pole (a·q near ±1); 1 − α² − β² − 2αβd lost them all
    // there for axes 3.6° from parallel (a tool 1e-5° off the pole was
    // reached 5.1e-8 off).
    let d = a.dot(b);
    let c = a.cross(b);
    let sine_squared = c.norm_squared();
    let sine = sine_squared.sqrt();
    let along_a = a.dot(q);
    let along_e2 = (b.dot(p) - d * along_a) / sine;
    let gamma_squared = (a.cross(q).norm_squared() - along_e2 * along_e2) / sine_squared;
    // Rounding puts a tangent case a few ulps either side of zero: below
    // zero it is taken for the touching direction. Above, the two
    // directions are kept as far apart as they are: taking them for the
    // touching one moves the tool by γ (a γ² of 1e-13, near a pole, missed
    // the frame by 3e-7), so only a γ below 1e-9 is that close.
    const BELOW_TANGENT: f64 = 1e-12;
    const ABOVE_TANGENT: f64 = 1e-18;
    let mut found = UpToTwo::new();
    if gamma_squared < -BELOW_TANGENT {
        return found;
    }
    let base = a * along_a + (b - a * d) * (along_e2 / sine);
    if gamma_squared <= ABOVE_TANGENT {
        found.push(base.normalize());
        return found;
    }
    let gamma = gamma_squared.sqrt();
    found.push((base + c * gamma).normalize());
    found.push((base - c * gamma).normalize());
    found
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotation::frame::from_axis_angle;

    #[test]
    fn subproblem_one_turns_p_onto_q() {
        let z = Vector3::z();
        let theta = angle_about(&z, &Vector3::x(), &Vector3::y()).expect("off the axis");
        assert!((theta - 90.0).abs() < 1e-12);
        assert_eq!(angle_about(&z, &z, &Vector3::x()), None, "p on the axis");
        assert_eq!(angle_about(&z, &Vector3::x(), &-z), None, "q on the axis");
    }

    #[test]
    fn subproblem_two_gives_both_directions_or_none() {
        let (a, b) = (Vector3::z(), Vector3::x());
        let p = Vector3::z();
        let q = Vector3::new(0.3, -0.5, 0.8).normalize();
        let ws = intermediates(&a, &b, &p, &q);
        assert_eq!(ws.len(), 2);
        for w in ws.iter() {
            let t2 = angle_about(&b, &p, w).expect("θ2");
            let t1 = angle_about(&a, w, &q).expect("θ1");
            let reached = from_axis_angle(a, t1) * (from_axis_angle(b, t2) * p);
            assert!((reached - q).norm() < 1e-12, "{reached}");
        }
        // A 45° nutating axis cannot tilt the tool past 90°.
        let nutating = Vector3::new(0.0, 1.0, 1.0).normalize();
        let past = Vector3::new(1.0, 0.0, -0.2).normalize();
        assert!(intermediates(&a, &nutating, &p, &past).is_empty());
    }

    #[test]
    fn near_a_pole_between_nearly_parallel_axes_the_digits_are_kept() {
        // A head's C axis and a second axis 3.6° from its opposite, the
        // tool a little off the pole: 1 − α² − β² − 2αβd left 5.1e-8 of
        // error at a tilt of 1e-5°.
        let a = Vector3::z();
        let b = Vector3::new(0.06227202121106225, 0.0, -0.9980592143626995).normalize();
        let p = Vector3::z();
        for degrees in [1e-5, 1e-3, 0.1, 5.0] {
            let q = from_axis_angle(Vector3::new(0.6, 0.8, 0.0), degrees) * p;
            let ws = intermediates(&a, &b, &p, &q);
            assert_eq!(ws.len(), 2, "{degrees}");
            for w in ws.iter() {
                let t2 = angle_about(&b, &p, w).expect("θ2");
                let t1 = angle_about(&a, w, &q).expect("θ1");
                let reached = from_axis_angle(a, t1) * (from_axis_angle(b, t2) * p);
                assert!(
                    (reached - q).norm() < 1e-14,
                    "{degrees}: {:e}",
                    (reached - q).norm()
                );
            }
        }
    }
}
