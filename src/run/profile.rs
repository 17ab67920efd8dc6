//! The time of one move from rest to rest along a path of length `d`,
//! limited by a velocity `v`, an acceleration `a` and (SOFT) a jerk `j`:
//! the closed forms of the trapezoidal (BRISK) and the jerk-limited (SOFT)
//! velocity profile. Pure math: no program, no machine.
//!
//! BRISK (acceleration jumps): `t = d/v + v/a` where the move reaches `v`
//! (`d >= v²/a`), else `t = 2·sqrt(d/a)`.
//!
//! SOFT (acceleration ramps at `j`): reaching a velocity `w` from rest takes
//! `w/a + a/j` where the acceleration reaches `a` (`w >= a²/j`), else
//! `2·sqrt(w/j)`, and covers half of `w` times that; a move that reaches
//! `v` cruises for the rest, one that does not peaks at the `w` whose
//! speeding up and slowing down cover `d` together.

/// The limits of one move along its path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// Path velocity, length per second.
    pub velocity: f64,
    /// Path acceleration, length per second².
    pub acceleration: f64,
    /// Path jerk, length per second³; `None` for BRISK.
    pub jerk: Option<f64>,
}

/// Seconds to move `d` (>= 0) from rest to rest within `limits` (each > 0).
pub fn rest_to_rest(d: f64, limits: Limits) -> f64 {
    if d <= 0.0 {
        return 0.0;
    }
    let Limits {
        velocity: v,
        acceleration: a,
        jerk,
    } = limits;
    match jerk {
        None => {
            if d >= v * v / a {
                d / v + v / a
            } else {
                2.0 * (d / a).sqrt()
            }
        }
        Some(j) => {
            // Time to reach `w` from rest, and the distance that takes.
            let speeding = |w: f64| {
                if w >= a * a / j {
                    w / a + a / j
                } else {
                    2.0 * (w / j).sqrt()
                }
            };
            let to_v = speeding(v);
            if d >= v * to_v {
                return d / v + to_v;
            }
            // The peak `w` with `w · speeding(w) = d`: where the acceleration
            // reaches `a`, `w²/a + w·a/j = d`; else `2·w^1.5/sqrt(j) = d`.
            let reaching = a / 2.0 * (-a / j + (a * a / (j * j) + 4.0 * d / a).sqrt());
            let w = if reaching >= a * a / j {
                reaching
            } else {
                (d * j.sqrt() / 2.0).powf(2.0 / 3.0)
            };
            2.0 * speeding(w)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brisk(velocity: f64, acceleration: f64) -> Limits {
        Limits {
            velocity,
            acceleration,
            jerk: None,
        }
    }

    #[test]
    fn brisk_is_the_trapezoid_and_the_triangle() {
        // 300 mm at 20 m/min (333.3 mm/s), 1.2 m/s²: 0.9 + 0.2778 s.
        let t = rest_to_rest(300.0, brisk(1000.0 / 3.0, 1200.0));
        assert!((t - (0.9 + 1000.0 / 3.0 / 1200.0)).abs() < 1e-12, "{t}");
        // 2 mm at 1 m/s², never at 1 m/s: 2·sqrt(0.002) s.
        let t = rest_to_rest(2.0, brisk(1000.0, 1000.0));
        assert!((t - 2.0 * 0.002f64.sqrt()).abs() < 1e-12, "{t}");
        assert_eq!(rest_to_rest(0.0, brisk(1.0, 1.0)), 0.0);
    }

    /// The minimum times of ruckig 0.19.4 (PyPI; `Ruckig(1)` from rest to
    /// rest, `Trajectory.duration`) for the jerk-limited profile's four
    /// shapes: acceleration and velocity reached (A), acceleration only (B),
    /// velocity only (C), neither (D).
    #[test]
    fn soft_agrees_with_ruckig() {
        for (d, v, a, j, ruckig) in [
            (100.0, 500.0, 2500.0, 40000.0, 0.46735336851754117),
            (1.0, 500.0, 2500.0, 40000.0, 0.09283177667225558),
            (10.0, 500.0, 2500.0, 40000.0, 0.2),
            (800.0, 500.0, 2500.0, 40000.0, 1.8624999999999998),
            (0.01, 500.0, 2500.0, 40000.0, 0.02),
            (50.0, 400.0, 5000.0, 20000.0, 0.43088693800637673),
            (5.0, 400.0, 5000.0, 20000.0, 0.2),
            (200.0, 400.0, 5000.0, 20000.0, 0.7828427124746189),
        ] {
            let limits = Limits {
                velocity: v,
                acceleration: a,
                jerk: Some(j),
            };
            let t = rest_to_rest(d, limits);
            assert!(
                (t - ruckig).abs() <= 1e-12 * ruckig,
                "{d} {v} {a} {j}: {t} s, ruckig {ruckig} s"
            );
        }
    }

    /// As the jerk grows, SOFT becomes BRISK.
    #[test]
    fn soft_tends_to_brisk() {
        for (d, v, a) in [(300.0, 333.333333333, 1200.0), (2.0, 1000.0, 1000.0)] {
            let soft = rest_to_rest(
                d,
                Limits {
                    velocity: v,
                    acceleration: a,
                    jerk: Some(1e12),
                },
            );
            let brisk = rest_to_rest(d, brisk(v, a));
            assert!((soft - brisk - a / 1e12).abs() < 1e-12, "{soft} {brisk}");
        }
    }
}
