//! TRAORI in the run: the orientation transformation keeps the tool tip on
//! the programmed point while the rotary axes turn. Modelled where the
//! machine's data say the transformation's kinematics are those of a swivel
//! data record (MD24100 `$MC_TRAFO_TYPE_n` = 72, the record MD24582
//! `$MC_TRAFO5_TCARR_NO_n` names; Commissioning Manual IM9, "Swiveling",
//! TOOLCARRIER and 5-axis transformation): the record's chain
//! ([`crate::kinematics::Carrier`]) at the rotary axes' positions takes each
//! programmed point, through the frames, to the linear axes. The rotary
//! axes are programmed by their names (machine axis positions) or the tool
//! by a direction (`A3= B3= C3=`); a block is checked against the limits
//! along its way, where the linear axes follow curves between its ends.

use nalgebra::Vector3;

use super::{Coordinate, Interpreter};
use crate::kinematics::swivel::solutions;
use crate::kinematics::{Carrier, Record, Solution};
use crate::run::arc::Arc;
use crate::semantic::value::Value;
use crate::span::Span;

/// The transformation TRAORI made active.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Transformed {
    record: Record,
    /// The run axes of the record's two rotary axes.
    axes: [usize; 2],
}

/// How the tool turns between a block's ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Way {
    /// Each rotary axis linearly (ORIAXES; ORIMKS where MD21104 is 0).
    Axes,
    /// The tool's direction on the great circle between its ends (ORIVECT,
    /// ORIPLANE; ORIWKS where MD21104 is 0), the axes following it.
    GreatCircle,
}

/// What decides the [`Way`]: ORIWKS/ORIMKS (G group 25), or G group 51
/// where MD21104 `$MC_ORI_IPO_WITH_G_CODE` says so (Function Manual F2,
/// "Orientation": "FALSE: the reference is provided by the G commands
/// ORIWKS and ORIMKS").
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Turning {
    /// ORIWKS, the control's basic setting (until ORIMKS).
    pub workpiece: bool,
    /// The G group 51 function programmed last.
    pub g_code: Option<Way>,
}

impl Default for Turning {
    fn default() -> Self {
        Self {
            workpiece: true,
            g_code: None,
        }
    }
}

/// Said once a run that transforms: what the model rests on.
const ASSUMED: &str = "TRAORI: the kinematics of the swivel data record MD24582 names (MD24100 type 72), the tool tip kept on the programmed point through the frames, the rotary axes at their programmed positions, the tool's length along its turned direction; between a block's ends the tip on the line, or on the arc of G2/G3, and the rotary axes turning linearly where their positions are programmed; where a vector is, the tool turning on the great circle between its directions (ORIWKS, the basic setting, with MD21104 0 or not in the data; ORIVECT, G group 51's default, or ORIPLANE with MD21104 1), the axes at the solution nearest their linear way, or each axis linearly (ORIMKS; ORIAXES with MD21104 1); the limits checked along each block at a point every 4 degrees of the rotary axes' turn (64 evenly at most, as many again where a great circle turns them faster; on an arc whose axes turn, every 4 degrees of its sweep too, whatever its length) and at the extremes between them; a block's time from the tip's way at the feed, each axis's share of it from the block's ends (on an arc whose rotary axes stand still, from the holder's arc, as without TRAORI); of two rotary positions for an orientation vector (A3, B3, C3), one inside the record's limits whose farther axis turns less, then whose axes turn less together (the control's choice is in no Siemens text found)";

/// A transformed block is sampled at a point every this many degrees of
/// its rotary axes' turn or of its arc's sweep, before the extremes
/// between the samples are searched: over so short a turn a linear axis's
/// way has one extreme at most. A block whose axes do not turn is a line
/// (its ends hold its extremes) or an arc (its turning points do).
const DEGREES_PER_SAMPLE: f64 = 4.0;

/// A rotary turn of a block at most this many degrees is none: a frame's
/// rotary offset put on and taken off again leaves a few ulps.
const STANDING: f64 = 1e-9;

/// Even samples of a block's rotary turn at most (a turn of 360 degrees,
/// 5.6 degrees apart; an arc's sweep is sampled evenly whatever its
/// length); as many again at most where a great circle turns the axes
/// faster.
const MOST_SAMPLES: usize = 64;

/// How far inside a block's ends (a share of the block) the run looks
/// whether an axis goes on past its value at the end.
const NEAR_END: f64 = 1e-6;

impl Transformed {
    /// The carrier at the machine positions `at` (every run axis), `None`
    /// where a rotary axis's position is unknown.
    pub(super) fn carrier(&self, at: &[Option<f64>]) -> Option<Carrier> {
        let [a, b] = self.axes;
        Some(Carrier::at(&self.record, [at[a]?, at[b]?]))
    }

    /// Whether both rotary axes' positions are known in `at`.
    pub(super) fn rotary_known(&self, at: &[Option<f64>]) -> bool {
        self.axes.iter().all(|&k| at[k].is_some())
    }

    /// The larger turn of the rotary axes from `p` to `q` (degrees; 0
    /// where a position is unknown).
    fn turn(&self, p: &[Option<f64>], q: &[Option<f64>]) -> f64 {
        self.axes
            .iter()
            .filter_map(|&k| Some((q[k]? - p[k]?).abs()))
            .fold(0.0, f64::max)
    }
}

impl Interpreter<'_, '_> {
    /// `TRAORI` or `TRAORI(n, ...)`, its arguments as evaluated.
    /// A TRAORI the run cannot make leaves no transformation on: the
    /// positions after it are of the axes as programmed, as it says.
    pub(super) fn traori(&mut self, row: usize, span: Span, arguments: &[Option<Value>]) {
        self.trafoof(row, span);
        let number = match arguments.first() {
            None | Some(None) if arguments.len() <= 1 => 1,
            Some(Some(Value::Number(n))) if *n >= 1.0 && n.fract() == 0.0 => *n as usize,
            _ => {
                return self.unknown(row, span, "TRAORI's transformation number is unknown offline or no whole number from 1: the positions after it are of the axes as programmed".into());
            }
        };
        if arguments.len() > 1 {
            return self.unknown(row, span, "TRAORI with a base orientation or rotary axis offsets (its second and later arguments) is not modelled: the positions after it are of the axes as programmed".into());
        }
        if self.swivelled.is_some() {
            return self.unknown(row, span, "TRAORI with a CYCLE800 swivel active is not modelled: the positions after it are of the axes as programmed".into());
        }
        let Some(orientation) = self.setup.orientations.get(number - 1) else {
            return self.unknown(row, span, format!("TRAORI({number}): the machine's data hold no orientation transformation {number} (MD24100 `$MC_TRAFO_TYPE_n` from 16 to 255): the positions after it are of the axes as programmed"));
        };
        let (trafo_type, record) = (orientation.trafo_type, orientation.record);
        let Some(record) = record else {
            return self.unknown(row, span, match trafo_type {
                72 => format!("TRAORI({number}): transformation type 72 without the swivel data record it takes (MD24582 `$MC_TRAFO5_TCARR_NO_{number}`): the positions after it are of the axes as programmed"),
                other => format!("TRAORI({number}): transformation type {other} (its kinematics in the TRAFO5 machine data) is not modelled, type 72 (a swivel data record's) is: the positions after it are of the axes as programmed"),
            });
        };
        let Some(record) = self
            .setup
            .records
            .iter()
            .find(|r| r.number == record)
            .cloned()
        else {
            return self.unknown(row, span, format!("TRAORI({number}) takes the swivel data record {record} (MD24582), which the machine's data do not hold as a usable record ($TC_CARR): the positions after it are of the axes as programmed"));
        };
        let axes = [0, 1].map(|i| self.setup.axis(&record.axes[i].name.to_ascii_uppercase()));
        let [Some(a), Some(b)] = axes else {
            return self.unknown(row, span, format!("TRAORI({number}): the record's rotary axes ($TC_CARR35/36) are not both axes of the machine's channel: the positions after it are of the axes as programmed"));
        };
        if !self.report.assumptions.iter().any(|a| a == ASSUMED) {
            self.report.assumptions.push(ASSUMED.to_string());
        }
        let tool = self.tool_offset(row, span);
        self.transformed = Some(Transformed {
            record,
            axes: [a, b],
        });
        // The work's position of where the axes stand, as the tip now counts.
        self.programmed = self.to_program(&self.mcs.clone(), false, tool);
    }

    /// A tool direction programmed as a vector (`A3= B3= C3=`: from the
    /// tip toward the holder, its length of no account, a component not
    /// written 0; Programming Manual Job Planning, "Programming of
    /// orientation vector"), in the work's coordinates (ORIWKS, the
    /// control's default): the rotary axes' positions that turn the tool
    /// onto it, set among `targets` as programmed positions.
    pub(super) fn orientation_vector(
        &mut self,
        row: usize,
        span: Span,
        vector: &[Option<Result<f64, String>>; 3],
        targets: &mut [Option<(Result<f64, String>, Coordinate)>],
    ) {
        let Some(transformed) = self.transformed.clone() else {
            return self.unknown(row, span, "an orientation vector (A3, B3, C3) without TRAORI: the control stops with an alarm; the block's orientation is left out".into());
        };
        let mut given = Vector3::zeros();
        for (k, component) in vector.iter().enumerate() {
            match component {
                Some(Ok(value)) => given[k] = *value,
                Some(Err(why)) => {
                    return self.unknown(row, span, format!("the orientation vector's {} is {why}: the block's orientation is left out", ["A3", "B3", "C3"][k]));
                }
                None => {}
            }
        }
        let turn = self.settable.linear * self.programmable.linear;
        let direction = turn * given;
        if direction.norm() < 1e-12 {
            return self.unknown(
                row,
                span,
                "an orientation vector of length 0: the block's orientation is left out".into(),
            );
        }
        let [a, b] = transformed.axes;
        let current = [a, b].map(|k| self.mcs[k]);
        let [Some(ca), Some(cb)] = current else {
            return self.unknown(row, span, "an orientation vector while the rotary axes' positions are unknown (the two solutions are told apart by them): the block's orientation is left out".into());
        };
        let found = solutions(&transformed.record, &direction.normalize(), [ca, cb]);
        // The solution the control takes is not in a Siemens text found:
        // one inside the record's limits, the one whose farther axis turns
        // less, then the one that turns both less.
        let travel = |s: &Solution| {
            let [da, db] = [(s.positions[0] - ca).abs(), (s.positions[1] - cb).abs()];
            (!s.within_limits, da.max(db), da + db)
        };
        let chosen = found.iter().min_by(|x, y| {
            travel(x)
                .partial_cmp(&travel(y))
                .unwrap_or(std::cmp::Ordering::Equal)
        });
        let Some(chosen) = chosen else {
            return self.unknown(row, span, "the rotary axes cannot turn the tool onto this orientation vector (the control stops with an alarm): the block's orientation is left out".into());
        };
        // Machine positions, as programmed positions: the frames' offsets
        // on the rotary axes taken off.
        let mut machine = self.mcs.clone();
        machine[a] = Some(chosen.positions[0]);
        machine[b] = Some(chosen.positions[1]);
        let programmed = self.programmable.undo(&self.settable.undo(&machine));
        for k in [a, b] {
            if let Some(value) = programmed[k] {
                targets[k] = Some((Ok(value), Coordinate::Absolute));
            }
        }
    }

    /// How the tool turns in the block about to move: with the rotary
    /// axes' positions programmed (or none), each axis linearly; with an
    /// orientation vector, as [`Turning`] says (Programming Manual,
    /// "Reference of the orientation axes (ORIWKS, ORIMKS)": for
    /// orientation programmed by angles or a vector; G group 51's
    /// default is ORIVECT, Programming Manual, "G commands").
    pub(super) fn way(&self, by_vector: bool) -> Way {
        if !by_vector {
            return Way::Axes;
        }
        match self.setup.orientation_by_g_code {
            Some(true) => self.turning.g_code.unwrap_or(Way::GreatCircle),
            _ if self.turning.workpiece => Way::GreatCircle,
            _ => Way::Axes,
        }
    }

    /// `TRAFOOF`: the axes are programmed as the machine's again.
    pub(super) fn trafoof(&mut self, row: usize, span: Span) {
        if self.transformed.take().is_some() {
            let tool = self.tool_offset(row, span);
            self.programmed = self.to_program(&self.mcs.clone(), false, tool);
        }
    }

    /// How the rotary axes turn along a transformed block from `start` to
    /// `end` (programmed).
    pub(super) fn block_turn(
        &self,
        start: &[Option<f64>],
        end: &[Option<f64>],
        suppress: bool,
        way: Way,
    ) -> BlockTurn {
        let Some(transformed) = &self.transformed else {
            return BlockTurn::default();
        };
        let circle = match way {
            Way::GreatCircle => self.great_circle(transformed, start, end, suppress),
            Way::Axes => None,
        };
        let turn = transformed.turn(start, end);
        let degrees = circle
            .as_ref()
            .map_or(turn, |c| turn.max(c.angle.to_degrees()));
        BlockTurn { degrees, circle }
    }

    /// The machine positions along a transformed block from `start` to
    /// `end` (programmed, every run axis): every axis at the sampled
    /// points, and each geometry axis at its extremes between them, found
    /// by a golden-section search on the bracket a sampled extreme lies in.
    /// The tool tip goes on the line between the ends, or on `arc` (G2, G3)
    /// where the block is one.
    pub(super) fn transformed_way(
        &self,
        start: &[Option<f64>],
        end: &[Option<f64>],
        suppress: bool,
        tool: [f64; 3],
        turn: &BlockTurn,
        arc: Option<&Arc>,
    ) -> Vec<Vec<Option<f64>>> {
        let BlockTurn {
            degrees: turn,
            circle,
        } = turn;
        let turn = *turn;
        // The tip on the arc, from where the machine stands: where a frame
        // or the tool changed since the arc's programmed start, the way
        // there is spread over the block, so that it starts at `start`.
        let on_arc = arc.map(|arc| {
            let shift = match start[..3] {
                [Some(x), Some(y), Some(z)] => Vector3::new(x, y, z) - arc.point(0.0),
                _ => Vector3::zeros(),
            };
            (arc, shift)
        });
        let at = |s: f64| -> Vec<Option<f64>> {
            let mut between: Vec<Option<f64>> = start
                .iter()
                .zip(end)
                .map(|(a, b)| match (a, b) {
                    (Some(a), Some(b)) => Some(a + (b - a) * s),
                    _ => *b,
                })
                .collect();
            if let Some((arc, shift)) = &on_arc {
                let tip = arc.point(s * arc.sweep) + shift * (1.0 - s);
                between[..3].copy_from_slice(&[Some(tip.x), Some(tip.y), Some(tip.z)]);
            }
            if let Some(circle) = &circle {
                let machine = self.frames_only(&between, suppress);
                circle.turn(s, &mut between, &machine);
            }
            self.to_machine(&between, suppress, tool)
        };
        if turn <= STANDING && arc.is_none() {
            return vec![at(0.0), at(1.0)];
        }
        // An arc is sampled every DEGREES_PER_SAMPLE of its sweep, its full
        // turns too (TURN=, up to 999): fewer would let two of a
        // coordinate's extremes fall between two samples.
        let by_sweep = arc.map_or(0, |arc| {
            (arc.sweep.to_degrees() / DEGREES_PER_SAMPLE).ceil() as usize
        });
        let count = ((turn / DEGREES_PER_SAMPLE).ceil() as usize)
            .clamp(1, MOST_SAMPLES)
            .max(by_sweep);
        let mut samples: Vec<(f64, Vec<Option<f64>>)> = (0..=count)
            .map(|i| {
                let s = i as f64 / count as f64;
                (s, at(s))
            })
            .collect();
        // Where the axes turn faster than the samples assumed (near a pole
        // of a great circle), halved until they turn no more than
        // DEGREES_PER_SAMPLE between two samples, or MOST_SAMPLES are added.
        if let Some(transformed) = self.transformed.as_ref().filter(|_| circle.is_some()) {
            let mut added = 0;
            let mut i = 0;
            while i + 1 < samples.len() && added < MOST_SAMPLES {
                let (s0, s1) = (samples[i].0, samples[i + 1].0);
                if transformed.turn(&samples[i].1, &samples[i + 1].1) > DEGREES_PER_SAMPLE
                    && s1 - s0 > 1e-6
                {
                    let middle = (s0 + s1) / 2.0;
                    samples.insert(i + 1, (middle, at(middle)));
                    added += 1;
                } else {
                    i += 1;
                }
            }
        }
        let last = samples.len() - 1;
        // Just inside each end: whether an axis goes on rising (or falling)
        // into the block from an end where it is at its sampled extreme.
        let inside = [at(NEAR_END), at(1.0 - NEAR_END)];
        let mut way: Vec<Vec<Option<f64>>> = samples.iter().map(|(_, p)| p.clone()).collect();
        for k in 0..3 {
            for sign in [1.0, -1.0] {
                let value = |point: &[Option<f64>]| point[k].map(|v| sign * v);
                for i in 0..=last {
                    let neighbour = |j: Option<usize>| samples.get(j?).and_then(|(_, p)| value(p));
                    let Some(here) = value(&samples[i].1) else {
                        continue;
                    };
                    let (before, after) = (neighbour(i.checked_sub(1)), neighbour(Some(i + 1)));
                    let sampled_extreme = before.is_none_or(|b| here >= b)
                        && after.is_none_or(|a| here >= a)
                        && (before.is_some_and(|b| here > b) || after.is_some_and(|a| here > a));
                    // At an end the extreme lies inside only where the axis
                    // goes on past the end's value into the block.
                    let rises_inside = match (i == 0, i == last) {
                        (true, _) => value(&inside[0]).is_some_and(|v| v > here),
                        (_, true) => value(&inside[1]).is_some_and(|v| v > here),
                        _ => true,
                    };
                    if sampled_extreme && rises_inside {
                        let s = golden_maximum(
                            |s| value(&at(s)).unwrap_or(f64::NEG_INFINITY),
                            samples[i.saturating_sub(1)].0,
                            samples[(i + 1).min(last)].0,
                        );
                        way.push(at(s));
                    }
                }
            }
        }
        way
    }

    /// The great circle the tool turns on from `start` to `end`
    /// (programmed), `None` where the axes turn linearly instead: an end
    /// unknown, no turn of the direction, or opposite directions (no one
    /// great circle between them).
    fn great_circle(
        &self,
        transformed: &Transformed,
        start: &[Option<f64>],
        end: &[Option<f64>],
        suppress: bool,
    ) -> Option<GreatCircle> {
        let [a, b] = transformed.axes;
        let (from, to) = (
            self.frames_only(start, suppress),
            self.frames_only(end, suppress),
        );
        let positions = |at: &[Option<f64>]| Some([at[a]?, at[b]?]);
        let (from_positions, to_positions) = (positions(&from)?, positions(&to)?);
        let from_direction = transformed.carrier(&from)?.tool_direction();
        let to_direction = transformed.carrier(&to)?.tool_direction();
        let angle = from_direction.dot(&to_direction).clamp(-1.0, 1.0).acos();
        if angle < 1e-12 || std::f64::consts::PI - angle < 1e-9 {
            return None;
        }
        Some(GreatCircle {
            record: transformed.record.clone(),
            axes: transformed.axes,
            from: (from_direction, from_positions),
            to: (to_direction, to_positions),
            angle,
        })
    }

    /// The length of the tool tip's way from `start` to `end` (programmed),
    /// through the frames: the path the feed is programmed for.
    pub(super) fn tip_way(
        &self,
        start: &[Option<f64>],
        end: &[Option<f64>],
        suppress: bool,
    ) -> f64 {
        let point = |p: &[Option<f64>]| -> Option<Vector3<f64>> {
            let at = self.frames_only(p, suppress);
            Some(Vector3::new(at[0]?, at[1]?, at[2]?))
        };
        match (point(start), point(end)) {
            (Some(a), Some(b)) => (b - a).norm(),
            _ => 0.0,
        }
    }
}

/// How the rotary axes turn along a transformed block.
#[derive(Default)]
pub(super) struct BlockTurn {
    /// The larger turn of the two axes, or of the tool on its great
    /// circle: degrees, 0 where a position is unknown.
    degrees: f64,
    /// The great circle the tool turns on, where it does.
    circle: Option<GreatCircle>,
}

impl BlockTurn {
    /// Whether the axes turn (more than [`STANDING`]).
    pub(super) fn turns(&self) -> bool {
        self.degrees > STANDING
    }
}

/// The tool's way on the great circle between two directions, and the
/// rotary axes' positions at its ends.
struct GreatCircle {
    record: Record,
    axes: [usize; 2],
    from: (Vector3<f64>, [f64; 2]),
    to: (Vector3<f64>, [f64; 2]),
    /// Between the directions, radians.
    angle: f64,
}

impl GreatCircle {
    /// Sets the rotary axes of `between` (programmed, at share `s` of the
    /// block; `machine` the same through the frames) to the positions that
    /// turn the tool onto the circle's direction there: of the solutions,
    /// the one nearest the axes' linear way between their ends.
    fn turn(&self, s: f64, between: &mut [Option<f64>], machine: &[Option<f64>]) {
        let ((d0, p0), (d1, p1)) = (self.from, self.to);
        let direction =
            (d0 * ((1.0 - s) * self.angle).sin() + d1 * (s * self.angle).sin()) / self.angle.sin();
        let linear = [0, 1].map(|i| p0[i] + (p1[i] - p0[i]) * s);
        let off = |x: &Solution| {
            (0..2)
                .map(|i| (x.positions[i] - linear[i]).abs())
                .fold(0.0, f64::max)
        };
        let found = solutions(&self.record, &direction.normalize(), linear);
        let Some(nearest) = found.iter().min_by(|x, y| off(x).total_cmp(&off(y))) else {
            return;
        };
        for (i, k) in self.axes.into_iter().enumerate() {
            // The frames' offset on the axis, as programmed positions take it.
            if let (Some(programmed), Some(turned)) = (between[k], machine[k]) {
                between[k] = Some(nearest.positions[i] - (turned - programmed));
            }
        }
    }
}

/// The argument in `low..high` at which the unimodal `f` is largest, to a
/// millionth of the bracket.
fn golden_maximum(f: impl Fn(f64) -> f64, mut low: f64, mut high: f64) -> f64 {
    let ratio = (5f64.sqrt() - 1.0) / 2.0;
    let mut a = high - ratio * (high - low);
    let mut b = low + ratio * (high - low);
    let (mut fa, mut fb) = (f(a), f(b));
    for _ in 0..30 {
        if fa < fb {
            low = a;
            a = b;
            fa = fb;
            b = low + ratio * (high - low);
            fb = f(b);
        } else {
            high = b;
            b = a;
            fb = fa;
            a = high - ratio * (high - low);
            fa = f(a);
        }
    }
    (low + high) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_golden_section_finds_a_maximum_inside_its_bracket() {
        let s = golden_maximum(|s| -(s - 0.3137).powi(2), 0.2, 0.5);
        assert!((s - 0.3137).abs() < 1e-6, "{s}");
        // At the bracket's edge: the edge.
        let edge = golden_maximum(|s| s, 0.0, 1.0);
        assert!((edge - 1.0).abs() < 1e-6, "{edge}");
    }
}
