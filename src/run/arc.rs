//! Circles and helices as the control moves them (G2/G3): the centre from
//! `I`, `J`, `K` or the radius `CR=`, the angle swept, and the points where
//! a coordinate of the arc is largest or smallest, for the limits; pure
//! math, in the coordinates the caller gives (the machine's, after the
//! frames).

use std::f64::consts::TAU;

use nalgebra::Vector3;

/// `centre + cos t · u + sin t · v + (rise · t / sweep) · normal`, for `t`
/// from 0 to `sweep`: `u` from the centre to the start, `v = normal × u`,
/// `normal` the axis the arc turns about in its direction of travel.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Arc {
    pub centre: Vector3<f64>,
    pub u: Vector3<f64>,
    pub v: Vector3<f64>,
    pub normal: Vector3<f64>,
    /// Radians, > 0.
    pub sweep: f64,
    /// Along `normal`, from start to end.
    pub rise: f64,
}

impl Arc {
    /// The arc from `start` to `end` about `centre`, turning about `normal`
    /// (a unit vector: the plane's applicate, negative for G2); a full turn
    /// where the end is the start. `None` where the start is the centre.
    pub fn through(
        start: Vector3<f64>,
        end: Vector3<f64>,
        centre: Vector3<f64>,
        normal: Vector3<f64>,
    ) -> Option<Arc> {
        let in_plane = |p: Vector3<f64>| p - normal * p.dot(&normal);
        let u = in_plane(start - centre);
        let to_end = in_plane(end - centre);
        if u.norm() < 1e-12 {
            return None;
        }
        let v = normal.cross(&u);
        let mut sweep = (to_end.dot(&v) / v.norm()).atan2(to_end.dot(&u) / u.norm());
        if sweep <= 1e-12 {
            sweep += TAU;
        }
        let centre = centre + normal * (start - centre).dot(&normal);
        Some(Arc {
            centre,
            u,
            v,
            normal,
            sweep,
            rise: (end - start).dot(&normal),
        })
    }

    /// The centre of the arc of radius `radius` (`CR=`: positive for at
    /// most a half turn, negative for more) from `start` to `end` about
    /// `normal`; `None` where the points are further apart than the diameter.
    pub fn centre_of_radius(
        start: Vector3<f64>,
        end: Vector3<f64>,
        radius: f64,
        normal: Vector3<f64>,
    ) -> Option<Vector3<f64>> {
        let chord = {
            let d = end - start;
            d - normal * d.dot(&normal)
        };
        let length = chord.norm();
        if length < 1e-12 || length > 2.0 * radius.abs() + 1e-9 {
            return None;
        }
        let middle = start + chord / 2.0;
        let height = (radius * radius - length * length / 4.0).max(0.0).sqrt();
        let side = normal.cross(&(chord / length));
        Some(middle + side * height.copysign(radius))
    }

    pub fn radius(&self) -> f64 {
        self.u.norm()
    }

    pub fn length(&self) -> f64 {
        (self.radius() * self.sweep).hypot(self.rise)
    }

    pub fn point(&self, t: f64) -> Vector3<f64> {
        self.centre
            + self.u * t.cos()
            + self.v * t.sin()
            + self.normal * (self.rise * t / self.sweep)
    }

    /// The points inside the arc where coordinate `k` turns (the largest
    /// and smallest values of `k` lie there or at the ends).
    pub fn turning_points(&self, k: usize) -> Vec<Vector3<f64>> {
        // d/dt of coordinate k: -sin t·u_k + cos t·v_k + rise/sweep·n_k = 0,
        // that is v_k cos t - u_k sin t = -rise/sweep·n_k.
        let (a, b) = (self.v[k], -self.u[k]);
        let c = -self.rise / self.sweep * self.normal[k];
        let rho = a.hypot(b);
        if rho < 1e-15 || c.abs() > rho {
            return Vec::new();
        }
        let phase = b.atan2(a);
        let spread = (c / rho).acos();
        let mut points = Vec::new();
        for first in [phase + spread, phase - spread] {
            let mut t = first.rem_euclid(TAU);
            while t < self.sweep {
                if t > 0.0 {
                    points.push(self.point(t));
                }
                t += TAU;
            }
        }
        points
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn assert_near(a: Vector3<f64>, b: Vector3<f64>) {
        assert!((a - b).norm() < 1e-9, "{a:?} != {b:?}");
    }

    #[test]
    fn a_quarter_circle_counterclockwise_and_clockwise() {
        let z = Vector3::z();
        let start = Vector3::new(10.0, 0.0, 0.0);
        let end = Vector3::new(0.0, 10.0, 0.0);
        let ccw = Arc::through(start, end, Vector3::zeros(), z).expect("arc");
        assert!((ccw.sweep - TAU / 4.0).abs() < 1e-12);
        assert_near(ccw.point(ccw.sweep), end);
        let cw = Arc::through(start, end, Vector3::zeros(), -z).expect("arc");
        assert!((cw.sweep - 3.0 * TAU / 4.0).abs() < 1e-12);
        // Clockwise from +X to +Y passes -Y and -X: both turn there.
        let turning: Vec<_> = cw
            .turning_points(1)
            .into_iter()
            .map(|p| p.y.round())
            .collect();
        assert_eq!(turning, vec![-10.0]);
        let turning: Vec<_> = cw
            .turning_points(0)
            .into_iter()
            .map(|p| p.x.round())
            .collect();
        assert_eq!(turning, vec![-10.0]);
    }

    #[test]
    fn a_radius_gives_the_short_or_the_long_way() {
        let z = Vector3::z();
        let start = Vector3::new(0.0, 0.0, 0.0);
        let end = Vector3::new(20.0, 0.0, 0.0);
        let short = Arc::centre_of_radius(start, end, 20.0, z).expect("centre");
        let arc = Arc::through(start, end, short, z).expect("arc");
        assert!(arc.sweep < TAU / 2.0, "{}", arc.sweep);
        let long = Arc::centre_of_radius(start, end, -20.0, z).expect("centre");
        let arc = Arc::through(start, end, long, z).expect("arc");
        assert!(arc.sweep > TAU / 2.0, "{}", arc.sweep);
        assert_near(arc.point(arc.sweep), end);
        assert!(Arc::centre_of_radius(start, end, 5.0, z).is_none());
    }

    /// The turning points are the extremes a fine sampling finds, on a
    /// helix in a tilted plane too.
    #[test]
    fn turning_points_bound_the_sampled_arc() {
        let normal = Vector3::new(0.3, -0.4, 0.866).normalize();
        let start = Vector3::new(12.0, 3.0, -2.0);
        let centre = Vector3::new(1.0, 2.0, 0.5);
        let end = Vector3::new(-4.0, 9.0, 25.0);
        let arc = Arc::through(start, end, centre, normal).expect("arc");
        for k in 0..3 {
            let mut candidates = vec![arc.point(0.0)[k], arc.point(arc.sweep)[k]];
            candidates.extend(arc.turning_points(k).iter().map(|p| p[k]));
            let high = candidates.iter().copied().fold(f64::MIN, f64::max);
            let low = candidates.iter().copied().fold(f64::MAX, f64::min);
            let samples = 200_000;
            for i in 0..=samples {
                let p = arc.point(arc.sweep * i as f64 / samples as f64)[k];
                assert!(
                    p <= high + 1e-9 && p >= low - 1e-9,
                    "{k}: {p} outside {low}..{high}"
                );
            }
        }
    }
}
