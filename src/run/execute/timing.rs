//! Time: a move's from the feed and the axes' dynamics (rest to rest as
//! the closed forms give it, the cruise as its lower bound), G0 under
//! RTLIOF axis by axis, and the times the user gives.

use super::{FeedMode, Interpreter, Motion, Word};
use crate::run::arc::Arc;
use crate::run::profile::{rest_to_rest, Limits};
use crate::span::Span;

impl Interpreter<'_, '_> {
    /// The time of a move of `moved` (axis, distance in the machine), along
    /// `arc` where it is one.
    pub(super) fn time(
        &mut self,
        row: usize,
        span: Span,
        moved: &[(usize, f64)],
        arc: Option<&Arc>,
        tip: Option<f64>,
        exact_here: bool,
    ) {
        let geometry: f64 = moved
            .iter()
            .filter(|(k, _)| *k < 3)
            .map(|(_, d)| d * d)
            .sum::<f64>()
            .sqrt();
        let others: f64 = moved
            .iter()
            .filter(|(k, _)| *k >= 3)
            .map(|(_, d)| d * d)
            .sum::<f64>()
            .sqrt();
        // The path the feed is programmed for: the tool tip's under TRAORI,
        // where the machine's linear axes go another way (a block that only
        // turns the tool: the rotary axes' turn, as without TRAORI).
        let length = match (arc, tip) {
            (Some(arc), _) => arc.length(),
            (None, Some(tip)) if tip > 0.0 => tip,
            (None, Some(_)) => others,
            (None, None) if geometry > 0.0 => geometry,
            (None, None) => others,
        };
        if length <= 0.0 {
            return;
        }
        if self.modes.motion == Motion::Rapid && !self.modes.rapid_linear {
            return self.single_axis_rapid(moved, exact_here);
        }
        // The programmed path velocity.
        let mut velocity = match self.modes.motion {
            Motion::Rapid => f64::INFINITY,
            _ => match (self.modes.feed_mode, self.modes.feed) {
                (_, None) => {
                    self.report.blocks_without_time += 1;
                    self.unknown(
                        row,
                        span,
                        "a feed motion without a feed (F): its time is not counted".into(),
                    );
                    return;
                }
                (FeedMode::PerMinute, Some(f)) => f * self.modes.feed_scale / 60.0,
                (FeedMode::PerRevolution, Some(f)) => match self.modes.spindle {
                    Some(s) if s > 0.0 => f * self.modes.feed_scale * s / 60.0,
                    _ => {
                        self.report.blocks_without_time += 1;
                        self.unknown(row, span, "a feed per revolution (G95) without a known spindle speed (S): its time is not counted".into());
                        return;
                    }
                },
                (FeedMode::InverseTime, Some(f)) if f > 0.0 => length / (60.0 / f),
                (FeedMode::InverseTime, Some(_)) => f64::INFINITY,
            },
        };
        let group = self.modes.dynamic_group;
        let mut acceleration = f64::INFINITY;
        let mut jerk = f64::INFINITY;
        let mut complete = true;
        // Each axis's largest share of the path velocity: on a line its part
        // of the way; on an arc (a full circle too, whose ends meet) the
        // largest a geometry axis reaches on the whole circle, its turning
        // and its part of the rise together.
        let mut shares: Vec<(usize, f64)> = match arc {
            Some(arc) => (0..3)
                .map(|k| {
                    let turning = arc.u[k].hypot(arc.v[k]) * arc.sweep;
                    (
                        k,
                        ((turning + (arc.rise * arc.normal[k]).abs()) / length).min(1.0),
                    )
                })
                .collect(),
            None => Vec::new(),
        };
        shares.extend(
            moved
                .iter()
                .filter(|(k, _)| arc.is_none() || *k >= 3)
                .map(|&(k, d)| (k, d.abs() / length)),
        );
        for (k, share) in shares {
            let axis = &self.setup.axes[k];
            if share <= 0.0 {
                continue;
            }
            let name = axis.machine_name();
            match axis.max_velocity() {
                Some(v) => velocity = velocity.min(v / share),
                None => {
                    self.note(format!("MD32000 $MA_MAX_AX_VELO of {name} is not in the machine's data: the blocks that move it are not capped by it (G0: not timed)"));
                    complete = false;
                }
            }
            match axis.max_acceleration(group) {
                Some(a) => acceleration = acceleration.min(a / share),
                None => {
                    self.note(format!("MD32300 $MA_MAX_AX_ACCEL of {name} is not in the machine's data: the upper bound leaves out the blocks that move it"));
                    complete = false;
                }
            }
            if self.modes.soft {
                match axis.max_jerk(group) {
                    Some(j) => jerk = jerk.min(j / share),
                    None => self.note(format!("MD32431 $MA_MAX_AX_JERK of {name} is not in the machine's data: its SOFT blocks are timed as BRISK")),
                }
            }
        }
        if let (Some(arc), true) = (arc, acceleration.is_finite()) {
            // The centripetal acceleration v²/r stays within the axes'.
            velocity = velocity.min((acceleration * arc.radius()).sqrt());
        }
        if !velocity.is_finite() || velocity <= 0.0 {
            self.report.blocks_without_time += 1;
            return;
        }
        let mut lower = length / velocity;
        let upper = (complete && acceleration.is_finite()).then(|| {
            rest_to_rest(
                length,
                Limits {
                    velocity,
                    acceleration,
                    jerk: (self.modes.soft && jerk.is_finite()).then_some(jerk),
                },
            )
        });
        if exact_here || self.modes.exact_stop {
            if let Some(upper) = upper {
                lower = upper;
            }
        }
        if let Some(cycle) = self.setup.ipo_cycle_s {
            lower = lower.max(cycle);
        }
        self.add_time(lower, upper.map(|u| u.max(lower)));
    }

    /// The times the user gives for what the block's words and calls do
    /// (`[run] times`: `M6 = 7.5`), each added where it runs.
    pub(super) fn given_times(&mut self, words: &[Word], called: &[(String, super::Arguments)]) {
        if self.options.times.is_empty() {
            return;
        }
        let words = words.iter().filter_map(|word| match word.value {
            Ok(v) if v >= 0.0 && v.fract() == 0.0 && word.name.len() == 1 => {
                Some(format!("{}{}", word.name, v as u64))
            }
            _ => None,
        });
        let names: Vec<String> = words
            .chain(called.iter().map(|(name, _)| name.clone()))
            .collect();
        for name in names {
            if let Some(&seconds) = self.options.times.get(&name) {
                let said = format!(
                    "{name} takes {seconds} s each time it runs ([run] times in sinuprep.toml)"
                );
                if !self.report.assumptions.contains(&said) {
                    self.report.assumptions.push(said);
                }
                self.add_time(seconds, Some(seconds));
            }
        }
    }

    /// G0 under RTLIOF: each axis at its own velocity, acceleration and
    /// jerk, the block as long as its slowest axis.
    pub(super) fn single_axis_rapid(&mut self, moved: &[(usize, f64)], exact_here: bool) {
        let group = self.modes.dynamic_group;
        let (mut lower, mut upper) = (0.0f64, Some(0.0f64));
        for &(k, d) in moved {
            let axis = &self.setup.axes[k];
            let name = axis.machine_name();
            let Some(velocity) = axis.max_velocity() else {
                self.note(format!("MD32000 $MA_MAX_AX_VELO of {name} is not in the machine's data: the blocks that move it are not capped by it (G0: not timed)"));
                self.report.blocks_without_time += 1;
                return;
            };
            lower = lower.max(d.abs() / velocity);
            let jerk = if self.modes.soft {
                axis.max_jerk(group)
            } else {
                None
            };
            upper = match (upper, axis.max_acceleration(group)) {
                (Some(upper), Some(acceleration)) => Some(upper.max(rest_to_rest(
                    d.abs(),
                    Limits {
                        velocity,
                        acceleration,
                        jerk,
                    },
                ))),
                _ => None,
            };
        }
        if exact_here || self.modes.exact_stop {
            lower = upper.unwrap_or(lower);
        }
        if let Some(cycle) = self.setup.ipo_cycle_s {
            lower = lower.max(cycle);
        }
        self.add_time(lower, upper.map(|u| u.max(lower)));
    }

    pub(super) fn add_time(&mut self, lower: f64, upper: Option<f64>) {
        self.report.time_s += lower;
        self.report.time_bounds_s[0] += lower;
        match upper {
            Some(upper) => self.report.time_bounds_s[1] += upper,
            None => self.upper_complete = false,
        }
        let tool = self
            .tool
            .map_or_else(|| "none".to_string(), |t| t.to_string());
        *self.tool_times.entry(tool).or_default() += lower;
    }
}
