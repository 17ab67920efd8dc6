//! CYCLE800 in the run: the swivel a call asks for, solved on the swivel
//! data record it names as `check` solves it ([`crate::kinematics::solve`]),
//! its rotary axes turned there, and from then on every programmed point
//! taken through the swivel frame and the tool carrier
//! ([`crate::kinematics::Carrier`]).
//!
//! The swivel frame sits between the settable frame and the programmable
//! one, where the control's chain puts its system frames (`$P_ACTFRAME =
//! ... $P_IFRAME ... $P_TOOLFRAME : $P_WPFRAME ... $P_PFRAME`,
//! `reference/sinumerik.md` §1.4): a TRANS programmed before or after the
//! call shifts inside the swivelled plane. The frame is "to `_X0 _Y0 _Z0`,
//! turn, then `_X1 _Y1 _Z1`"; `_ST` ending in 1 adds it to the active one.
//! `CYCLE800()` takes the swivel back and leaves the rotary axes where
//! they are. What the manuals leave open is said in the run's assumptions.

use nalgebra::{Matrix3, Rotation3, Vector3};

use super::Interpreter;
use crate::kinematics::{orientation, solve, Carrier, Direction, Record, Request};
use crate::rotation::matrix;
use crate::run::frame::Frame;
use crate::semantic::cycle800::{Mode, PARAMETERS};
use crate::semantic::value::Value;
use crate::span::Span;

/// The swivel the control holds after a CYCLE800.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Swivelled {
    /// The swivel frame (the plane's zero and rotation).
    pub frame: Frame,
    /// The record's carrier at the axes' positions; `None` where the
    /// record's axes are not known to the run.
    pub carrier: Option<Carrier>,
}

/// Said once a run that swivels: what the model rests on.
const ASSUMED: &str = "CYCLE800: the swivel frame between the settable and the programmable frame, the rotary axes turned at rapid each at its own MD32000/MD32300 after the retraction, the linear axes not following (no tool tip tracking), the tool carrier's offset vectors and the table's turn applied to every point after it (TCARR with PAROT); CYCLE800() takes the swivel frame and the carrier's offsets back and keeps the rotary axes where they are (what it resets, no Siemens text found says)";

impl Interpreter<'_, '_> {
    /// A CYCLE800 call with its arguments as evaluated (`None`: unknown
    /// offline).
    pub(super) fn cycle800(&mut self, row: usize, span: Span, arguments: &[Option<Value>]) {
        if self.transformed.is_some() {
            return self.unknown(
                row,
                span,
                "CYCLE800 with TRAORI active is not modelled: the swivel is not made".into(),
            );
        }
        if !self.report.assumptions.iter().any(|a| a == ASSUMED) {
            self.report.assumptions.push(ASSUMED.to_string());
        }
        if arguments.is_empty() {
            self.swivelled = None;
            return;
        }
        // Every argument is read: one unknown offline leaves the swivel
        // unknown (left out: 0, as the cycle reads it).
        let mut numbers = [0.0; 16];
        let mut name = String::new();
        for (i, argument) in arguments.iter().enumerate().take(PARAMETERS.len()) {
            match (i, argument) {
                (_, None) => {
                    return self.unknown(row, span, format!("CYCLE800's `{}` is unknown offline: the swivel is not made; give its value with --set", PARAMETERS[i]));
                }
                (1, Some(Value::Text(text))) => name = text.trim().to_ascii_uppercase(),
                (_, Some(Value::Number(n))) => numbers[i] = *n,
                (_, Some(Value::Text(_))) => {
                    return self.unknown(row, span, format!("CYCLE800's `{}` is text where a number is read: the control stops with an alarm", PARAMETERS[i]));
                }
            }
        }
        let [retract, _, plane, mode, x0, y0, z0, a, b, c, x1, y1, z1, direction, retract_by, _] =
            numbers;
        let Some(record) = self.record_named(&name) else {
            return self.unknown(row, span, format!("CYCLE800 names the swivel data record \"{name}\", which the machine's data do not hold ($TC_CARR34): the swivel is not made"));
        };
        let additive = match plane.rem_euclid(10.0) {
            0.0 => false,
            1.0 => true,
            _ => {
                return self.unknown(row, span, format!("CYCLE800's `_ST` {plane}: its last digit is neither 0 (new plane) nor 1 (additive): the swivel is not made"));
            }
        };
        let Some(mode) = Mode::of(mode) else {
            return self.unknown(
                row,
                span,
                format!("CYCLE800's `_MODE` {mode} is no swivel mode: the swivel is not made"),
            );
        };
        let mut current = record.specified();
        let axes = record
            .axes
            .clone()
            .map(|axis| self.setup.axis(&axis.name.to_ascii_uppercase()));
        for (i, axis) in axes.iter().enumerate() {
            if let Some(position) = axis.and_then(|k| self.mcs[k]) {
                current[i] = position;
            }
        }
        // The turn the call asks for in the plane it starts from.
        let (turn, direct) = match mode {
            Mode::AxisByAxis(sequence) => (matrix(sequence, [a, b, c]), None),
            Mode::RotaryAxesDirect => {
                let positions = [a, b];
                let angles = [0, 1].map(|i| positions[i] - record.axes[i].offset);
                (orientation(&record, angles), Some(positions))
            }
            Mode::SolidAngle | Mode::ProjectionAngle => {
                return self.unknown(
                    row,
                    span,
                    format!("CYCLE800 by {mode} is not modelled: the swivel is not made"),
                );
            }
        };
        let mut local = Frame::identity(self.setup.axes.len());
        let turned = turn.into_inner() * Vector3::new(x1, y1, z1);
        for (k, (zero, after)) in [x0, y0, z0].into_iter().zip(turned.iter()).enumerate() {
            local.translation[k] = zero + after;
        }
        local.linear = turn.into_inner();
        let frame = match (&self.swivelled, additive) {
            (Some(active), true) => active.frame.then(&local),
            _ => local,
        };
        // The tool's direction is the plane's in the machine: a rotation in
        // the zero offset counts (the control may refuse it, MD55410).
        let Some(rotation) = pure_rotation(self.settable.linear * frame.linear) else {
            return self.unknown(
                row,
                span,
                "CYCLE800 under a scaled or mirrored frame: the swivel is not made".into(),
            );
        };
        let positions = match (direct, direction) {
            (Some(positions), _) => Some(positions),
            (None, 0.0) => None,
            (None, _) => {
                let direction = if direction < 0.0 {
                    Direction::Minus
                } else {
                    Direction::Plus
                };
                let request = Request {
                    rotation,
                    direction,
                    current,
                };
                match solve(&record, &request) {
                    Ok(swivel) => match swivel.chosen {
                        Some(chosen) => Some(swivel.solutions[chosen].positions),
                        None if swivel.solutions.is_empty() => {
                            return self.unknown(row, span, format!("CYCLE800: the record \"{name}\" cannot turn the tool onto this plane (the control stops with an alarm): the swivel is not made"));
                        }
                        None => {
                            return self.unknown(row, span, format!("CYCLE800: the record \"{name}\" reaches this plane only outside its axes' limits ($TC_CARR30..33; the control stops with an alarm): the swivel is not made"));
                        }
                    },
                    Err(why) => {
                        return self.unknown(row, span, format!("CYCLE800: the record \"{name}\" cannot be solved on ({why}): the swivel is not made"));
                    }
                }
            }
        };
        if positions.is_none() {
            self.unknown(row, span, "CYCLE800 with `_DIR` 0 sets the plane without turning the rotary axes (as CAM posts use it): the carrier is taken at the axes' positions before it".into());
        }
        self.retract(row, span, retract, retract_by);
        let target = positions.unwrap_or(current);
        let mut moved = Vec::new();
        for (i, axis) in axes.iter().enumerate().take(record.axis_count()) {
            match axis {
                Some(k) => {
                    if let Some(from) = self.mcs[*k] {
                        if (target[i] - from).abs() > 1e-12 {
                            moved.push((*k, target[i] - from));
                        }
                    }
                    self.mcs[*k] = Some(target[i]);
                }
                None => self.unknown(row, span, format!("the record's rotary axis {} is no axis of the machine's channel: its turn is not in the run", record.axes[i].label(i))),
            }
        }
        let mut out = std::collections::HashSet::new();
        let at = self.mcs.clone();
        self.check(row, span, &at, &mut out);
        self.beyond.retain(|key, _| out.contains(key));
        if !moved.is_empty() {
            self.single_axis_rapid(&moved, true);
        }
        self.swivelled = Some(Swivelled {
            frame,
            carrier: Some(Carrier::at(&record, target)),
        });
        // The work's position of where the axes stand, in the new plane.
        let tool = self.tool_offset(row, span);
        self.programmed = self.to_program(&self.mcs.clone(), false, tool);
    }

    /// The record `name` (upper case) names: `""` the machine's only one.
    fn record_named(&self, name: &str) -> Option<Record> {
        let records = &self.setup.records;
        match name {
            "" if records.len() == 1 => records.first().cloned(),
            _ => records
                .iter()
                .find(|r| r.name.eq_ignore_ascii_case(name))
                .cloned(),
        }
    }

    /// The retraction before the swivel (`_FR`): along the tool by `_FR_I`
    /// (5) is followed; to the record's retraction position or the
    /// software limit (1, 2, 4) is named.
    fn retract(&mut self, row: usize, span: Span, retract: f64, by: f64) {
        match retract {
            0.0 => {}
            5.0 => {
                let direction = self
                    .swivelled
                    .as_ref()
                    .and_then(|s| s.carrier.as_ref())
                    .map_or(Vector3::z(), |c| c.tool.into_inner() * Vector3::z());
                let mut moved = Vec::new();
                for k in 0..3 {
                    if let Some(at) = self.mcs[k] {
                        let step = direction[k] * by;
                        self.mcs[k] = Some(at + step);
                        if step.abs() > 1e-12 {
                            moved.push((k, step));
                        }
                    }
                }
                let mut out = std::collections::HashSet::new();
                let at = self.mcs.clone();
                self.check(row, span, &at, &mut out);
                if !moved.is_empty() {
                    self.single_axis_rapid(&moved, true);
                }
            }
            other => self.unknown(row, span, format!("CYCLE800's retraction `_FR` {other} (to the record's retraction position $TC_CARR38..40 or the software limit) is not modelled: the linear axes are taken where they were")),
        }
    }
}

/// `linear` as a rotation, `None` where it scales or mirrors.
fn pure_rotation(linear: Matrix3<f64>) -> Option<Rotation3<f64>> {
    let orthonormal = (linear.transpose() * linear - Matrix3::identity()).norm() < 1e-9;
    (orthonormal && linear.determinant() > 0.0).then(|| Rotation3::from_matrix_unchecked(linear))
}
