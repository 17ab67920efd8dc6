//! The axis of a known turn (the inverse problem of the Rodrigues formula,
//! `seeds/002`): a point measured before and after a rotary axis turned by a
//! known angle χ, both relative to a point on the axis, gives the axis's
//! direction, in general two of them.
//!
//! The seed writes the turn as ρ' = ρ + θ × (ρ + ½ θ × ρ) / (1 + ¼|θ|²) with
//! the Gibbs vector θ = 2 tan(χ/2) e, and solves for θ: with r = ρ' − ρ,
//! (3) r · θ = 0, and (5, 7) ρ · θ = c with c² = |θ|²|ρ|² + 2α (r · ρ),
//! α = 1 + ¼|θ|²; θ lies on the line where these two planes meet, at
//! |θ| = 2 tan(χ/2) from the origin (its (6) is that sphere, given (7)), and
//! c = ±√… are its two roots (the angle between axis and point acute or
//! obtuse). Divided by |θ| this reads in the unit vector e itself, which
//! keeps the half turn (tan(χ/2) infinite) and the line's direction
//! (the seed's (9) divides by r₂ρ₁ − r₁ρ₂, zero whenever ρ and r are
//! parallel seen along Z) well defined:
//!
//!   r · e = 0,   ρ · e = p,   p² = |ρ|² + (r · ρ) / (2 sin²(χ/2)),
//!
//! so e = p w / |w|² + t d, with w the part of ρ normal to r,
//! d = ρ × r / |ρ × r| and t² = 1 − p²/|w|². The sign of t is that of
//! sin χ: the seed's equation projected on θ × ρ, the one (3) and (4) leave
//! out, says r · (e × ρ) = t |ρ × r| has the sign of tan(χ/2).
//!
//! There is none when p² < 0: the point moved farther than a turn by χ can
//! move it (|r| > 2|ρ| |sin(χ/2)|); nor when the distance from the axis
//! point changed (a turn keeps it); nor for a turn of 0° that moved the
//! point. Every axis fits when nothing moved and the turn is 0°, or the
//! point is the axis point, or (a half turn) the point went to its opposite.

use nalgebra::Vector3;

use crate::rotation::euler::wrap;
use crate::rotation::frame::from_axis_angle;
use crate::rotation::trig::sin_cos_degrees;

/// Why no axis turns the point `before` into `after` by the angle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NoAxis {
    /// The point moved `chord`, farther than a turn by the angle moves a
    /// point at its distance from the axis point: at most `reach`
    /// (2 |ρ| |sin(χ/2)|).
    TooFar { chord: f64, reach: f64 },
    /// A turn keeps the distance from a point on its axis; this one changed
    /// from `before` to `after`.
    Distance { before: f64, after: f64 },
    /// A turn of 0° (or whole turns) leaves every point where it is; this
    /// one moved `chord`.
    NoTurn { chord: f64 },
    /// Every axis fits: `why` says which case.
    Every { why: Every },
}

/// Why every axis fits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Every {
    /// No turn, and the point did not move.
    NoTurn,
    /// The point is the axis point itself.
    AtOrigin,
    /// A half turn that took the point to its opposite: every axis normal to it.
    HalfTurnThrough,
}

/// One axis direction and how well it reproduces the measurement.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Axis {
    /// Unit; the turn by the angle is right-handed about it.
    pub direction: Vector3<f64>,
    /// |R(e, χ) ρ − ρ'|: zero for exact measurements.
    pub residual: f64,
}

/// The axes about which a turn by `degrees` takes `before` to `after`, both
/// relative to a point on the axis: two in general (the same one when the
/// point lies in the plane normal to the axis through the axis point; at a
/// half turn e and −e, one axis). `tolerance` is a length: how far the
/// measurements may be from fitting.
pub fn axes(
    before: Vector3<f64>,
    after: Vector3<f64>,
    degrees: f64,
    tolerance: f64,
) -> Result<Vec<Axis>, NoAxis> {
    let chi = wrap(degrees);
    let (half_sin, _) = sin_cos_degrees(chi / 2.0);
    let (sin_chi, _) = sin_cos_degrees(chi);
    let r = after - before;
    let chord = r.norm();
    let radius = before.norm();
    if (after.norm() - radius).abs() > tolerance {
        return Err(NoAxis::Distance {
            before: radius,
            after: after.norm(),
        });
    }
    if half_sin == 0.0 {
        return Err(if chord <= tolerance {
            NoAxis::Every { why: Every::NoTurn }
        } else {
            NoAxis::NoTurn { chord }
        });
    }
    if radius <= tolerance {
        return Err(NoAxis::Every {
            why: Every::AtOrigin,
        });
    }
    let reach = 2.0 * radius * half_sin.abs();
    if chord <= tolerance {
        // The point did not move: it lies on the axis, in either direction.
        let e = before / radius;
        return Ok(vec![
            axis(e, before, after, chi),
            axis(-e, before, after, chi),
        ]);
    }
    let mut p2 = radius * radius + r.dot(&before) / (2.0 * half_sin * half_sin);
    if p2 < 0.0 && chord - reach > tolerance {
        return Err(NoAxis::TooFar { chord, reach });
    }
    // Below 0 within the tolerance, or above it by what rounding leaves of
    // a point exactly there: the point lies in the plane normal to the axis,
    // and the roots are one. Farther above they are two, however close:
    // their midpoint fits neither (see [`near_normal_plane`]).
    if p2 <= ROUNDING * radius * radius {
        p2 = 0.0;
    }
    // w: the part of ρ normal to r; the axis's component along it is p / |w|.
    let w = before - r * (r.dot(&before) / (chord * chord));
    if w.norm() <= tolerance {
        return Err(NoAxis::Every {
            why: Every::HalfTurnThrough,
        });
    }
    let p = p2.sqrt();
    let along = w / w.norm_squared();
    let d = before.cross(&r).normalize();
    let t2 = 1.0 - p2 / w.norm_squared();
    // Within the tolerance, |p| ≤ |w| holds (equality at a half turn).
    if t2 < 0.0 && p - w.norm() > tolerance {
        return Err(NoAxis::TooFar { chord, reach });
    }
    let t = t2.max(0.0).sqrt() * if sin_chi < 0.0 { -1.0 } else { 1.0 };
    let first = (along * p + d * t).normalize();
    let second = (-along * p + d * t).normalize();
    if p2 == 0.0 {
        return Ok(vec![axis(first, before, after, chi)]);
    }
    Ok(vec![
        axis(first, before, after, chi),
        axis(second, before, after, chi),
    ])
}

/// What rounding leaves in p² of a point exactly in the plane normal to the
/// axis, as a share of |ρ|²: a few units in the last place.
const ROUNDING: f64 = 64.0 * f64::EPSILON;

/// Whether `before` lies so near the plane normal to `direction` through the
/// axis point that measurements within `tolerance` cannot tell the two roots
/// apart: a length off by δ moves p² = (ρ · e)² by about 2|ρ|δ, so within
/// |ρ| × tolerance of 0 the other root fits the data as well as this one.
pub fn near_normal_plane(before: Vector3<f64>, direction: Vector3<f64>, tolerance: f64) -> bool {
    let p = before.dot(&direction);
    p * p <= before.norm() * tolerance
}

fn axis(direction: Vector3<f64>, before: Vector3<f64>, after: Vector3<f64>, chi: f64) -> Axis {
    Axis {
        direction,
        residual: (from_axis_angle(direction, chi) * before - after).norm(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::measure::Noise;

    /// The numerical solve the analytical one is checked against:
    /// Levenberg-Marquardt on the residual R(v/|v|, χ) ρ − ρ' over v, from
    /// starts spread over the sphere, the converged ends kept once each.
    fn solve_numerically(before: Vector3<f64>, after: Vector3<f64>, chi: f64) -> Vec<Vector3<f64>> {
        let residual = |v: Vector3<f64>| from_axis_angle(v, chi) * before - after;
        let mut found: Vec<Vector3<f64>> = Vec::new();
        for i in 0..6 {
            for j in 0..12 {
                let (lat, lon) = (
                    (-75.0 + 30.0 * f64::from(i)).to_radians(),
                    (30.0 * f64::from(j)).to_radians(),
                );
                let mut v = Vector3::new(lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin());
                let mut mu = 1e-3;
                for _ in 0..100 {
                    let f = residual(v);
                    if f.norm() < 1e-12 {
                        break;
                    }
                    let mut jacobian = nalgebra::Matrix3::zeros();
                    for k in 0..3 {
                        let mut step = Vector3::zeros();
                        step[k] = 1e-7;
                        let column = (residual(v + step) - residual(v - step)) / 2e-7;
                        jacobian.set_column(k, &column);
                    }
                    let normal =
                        jacobian.transpose() * jacobian + nalgebra::Matrix3::identity() * mu;
                    let Some(delta) = normal.lu().solve(&(-jacobian.transpose() * f)) else {
                        break;
                    };
                    let next = (v + delta).normalize();
                    if residual(next).norm() < f.norm() {
                        v = next;
                        mu *= 0.3;
                    } else {
                        mu *= 10.0;
                    }
                }
                let e = v.normalize();
                if residual(e).norm() < 1e-9 && found.iter().all(|f| (f - e).norm() > 1e-6) {
                    found.push(e);
                }
            }
        }
        found
    }

    fn same_set(analytical: &[Axis], numerical: &[Vector3<f64>]) -> bool {
        analytical.len() == numerical.len()
            && analytical
                .iter()
                .all(|a| numerical.iter().any(|n| (a.direction - n).norm() < 1e-6))
    }

    #[test]
    fn known_axes_come_back_and_agree_with_the_numerical_solve() {
        let mut noise = Noise(5);
        for case in 0..300 {
            let e = noise.vector(1.0).normalize();
            let rho = noise.vector(200.0);
            let chi = noise.next() * 179.0;
            if chi.abs() < 1.0 {
                continue;
            }
            let after = from_axis_angle(e, chi) * rho;
            let found = axes(rho, after, chi, 1e-9).expect("a turn");
            assert!(
                found.iter().any(|a| (a.direction - e).norm() < 1e-9),
                "{case}: {e} not in {found:?}"
            );
            for a in &found {
                assert!(a.residual < 1e-9, "{case}: {a:?}");
                assert!((a.direction.norm() - 1.0).abs() < 1e-12);
            }
            assert_eq!(found.len(), 2, "{case}");
            if case % 30 == 0 {
                let numerical = solve_numerically(rho, after, chi);
                assert!(
                    same_set(&found, &numerical),
                    "{case}: {found:?} {numerical:?}"
                );
            }
        }
    }

    #[test]
    fn the_axis_sign_follows_the_turn() {
        let e = Vector3::new(0.1, -0.2, 1.0).normalize();
        let rho = Vector3::new(50.0, 10.0, 20.0);
        for chi in [30.0, -30.0, 150.0, -150.0, 330.0] {
            let after = from_axis_angle(e, chi) * rho;
            let found = axes(rho, after, chi, 1e-9).expect("a turn");
            assert!(
                found.iter().any(|a| (a.direction - e).norm() < 1e-9),
                "{chi}"
            );
        }
    }

    #[test]
    fn a_point_in_the_axis_normal_plane_gives_one_axis() {
        // ρ normal to the axis: p = 0, both roots the same.
        let rho = Vector3::new(100.0, 0.0, 0.0);
        let after = from_axis_angle(Vector3::z(), 40.0) * rho;
        let found = axes(rho, after, 40.0, 1e-9).expect("a turn");
        assert_eq!(found.len(), 1);
        assert!((found[0].direction - Vector3::z()).norm() < 1e-9);
    }

    /// Near the plane normal to the axis the two roots are both given, exact,
    /// not merged into a midpoint that fits neither.
    #[test]
    fn roots_near_the_normal_plane_stay_two() {
        let before = Vector3::new(799.999_374_999_755_9, 0.0, 1.0);
        let after = Vector3::new(0.0, 799.999_374_999_756, 1.0);
        let found = axes(before, after, 90.0, 0.01).expect("a turn");
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(found
            .iter()
            .any(|a| (a.direction - Vector3::z()).norm() < 1e-12));
        assert!(found.iter().all(|a| a.residual < 1e-9), "{found:?}");
        assert!(found
            .iter()
            .all(|a| near_normal_plane(before, a.direction, 0.01)));
        assert!(!near_normal_plane(before, Vector3::z(), 1e-4));
        let numerical = solve_numerically(before, after, 90.0);
        assert!(same_set(&found, &numerical), "{found:?} {numerical:?}");
    }

    #[test]
    fn a_half_turn_gives_the_axis_both_ways() {
        let e = Vector3::new(0.3, 0.4, 0.866).normalize();
        let rho = Vector3::new(10.0, -20.0, 30.0);
        let after = from_axis_angle(e, 180.0) * rho;
        let found = axes(rho, after, 180.0, 1e-9).expect("a turn");
        assert_eq!(found.len(), 2, "{found:?}");
        assert!(found.iter().any(|a| (a.direction - e).norm() < 1e-9));
        assert!(found.iter().any(|a| (a.direction + e).norm() < 1e-9));
        let numerical = solve_numerically(rho, after, 180.0);
        assert!(same_set(&found, &numerical), "{found:?} {numerical:?}");
    }

    #[test]
    fn a_point_on_the_axis_gives_it_both_ways() {
        let rho = Vector3::new(0.0, 0.0, 50.0);
        let found = axes(rho, rho, 25.0, 1e-9).expect("a turn");
        assert_eq!(found.len(), 2);
        assert!((found[0].direction - Vector3::z()).norm() < 1e-15);
        assert!((found[1].direction + Vector3::z()).norm() < 1e-15);
    }

    #[test]
    fn measurements_no_turn_fits_are_refused_with_the_reason() {
        let rho = Vector3::new(100.0, 0.0, 0.0);
        // Moved 100 by a 10° turn at radius 100: at most 2·100·sin 5° = 17.4.
        let after = Vector3::new(0.0, 100.0, 0.0);
        match axes(rho, after, 10.0, 1e-6) {
            Err(NoAxis::TooFar { chord, reach }) => {
                assert!((chord - 100.0 * 2f64.sqrt()).abs() < 1e-9);
                assert!((reach - 200.0 * 5f64.to_radians().sin()).abs() < 1e-9);
            }
            other => panic!("{other:?}"),
        }
        // The numerical solve finds nothing either.
        assert!(solve_numerically(rho, after, 10.0).is_empty());
        assert!(matches!(
            axes(rho, Vector3::new(0.0, 101.0, 0.0), 90.0, 0.01),
            Err(NoAxis::Distance { .. })
        ));
        assert!(matches!(
            axes(rho, Vector3::new(0.0, 100.0, 0.0), 360.0, 0.01),
            Err(NoAxis::NoTurn { .. })
        ));
        assert_eq!(
            axes(rho, rho, 0.0, 0.01),
            Err(NoAxis::Every { why: Every::NoTurn })
        );
        assert_eq!(
            axes(Vector3::zeros(), Vector3::zeros(), 30.0, 0.01),
            Err(NoAxis::Every {
                why: Every::AtOrigin
            })
        );
        assert_eq!(
            axes(rho, -rho, 180.0, 0.01),
            Err(NoAxis::Every {
                why: Every::HalfTurnThrough
            })
        );
        // The opposite point by less than a half turn is too far.
        assert!(matches!(
            axes(rho, -rho, 170.0, 0.01),
            Err(NoAxis::TooFar { .. })
        ));
    }

    #[test]
    fn any_measurements_give_finite_axes_or_a_reason() {
        let mut noise = Noise(17);
        for case in 0..20_000 {
            let scale = 10f64.powi((case % 19) - 9);
            let before = noise.vector(scale.min(1e9));
            let after = if case % 3 == 0 {
                // Same distance, so that the turn is often possible.
                noise.vector(1.0).normalize() * before.norm()
            } else {
                noise.vector(scale.min(1e9))
            };
            let angle = noise.next() * 400.0;
            let tolerance = 10f64.powi((case % 13) - 12);
            if let Ok(found) = axes(before, after, angle, tolerance) {
                for axis in found {
                    assert!(axis.direction.iter().all(|v| v.is_finite()), "{case}");
                    assert!((axis.direction.norm() - 1.0).abs() < 1e-9, "{case}");
                    assert!(axis.residual.is_finite());
                }
            }
        }
    }

    #[test]
    fn noisy_measurements_stay_near_the_true_axis() {
        let mut noise = Noise(9);
        for _ in 0..300 {
            let e = noise.vector(1.0).normalize();
            let rho = noise.vector(200.0);
            // A sphere 150-250 from the axis, turned 60-120°: well conditioned.
            let rho = rho - e * e.dot(&rho);
            // Away from the plane normal to the axis through the axis point,
            // where the two solutions meet and the noise moves them most.
            let axial = (75.0 + noise.next() * 25.0) * noise.next().signum();
            let rho = rho.normalize() * (200.0 + noise.next() * 50.0) + e * axial;
            let chi = 90.0 + noise.next() * 30.0;
            let after = from_axis_angle(e, chi) * rho + noise.vector(0.001);
            let found = axes(rho, after, chi, 0.01).expect("within the tolerance");
            let nearest = found
                .iter()
                .map(|a| (a.direction - e).norm())
                .fold(f64::INFINITY, f64::min);
            // 1 µm over 150 mm and more: well under 1e-4 rad.
            assert!(nearest < 1e-4, "{nearest}");
        }
    }
}
