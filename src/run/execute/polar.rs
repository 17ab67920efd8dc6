//! Polar coordinates (Siemens, Programming Manual Fundamentals, "Travel
//! commands with polar coordinates"): a pole set by G110 (from the last
//! position), G111 (in the work's coordinates) or G112 (from the last
//! pole), in Cartesian words of the plane or by its own `AP=`/`RP=`; a
//! move to `AP=` (the angle from the plane's horizontal axis, counter-
//! clockwise, `AC`/`IC`) and `RP=` (the radius, always absolute) about it;
//! G2/G3 turn about the pole. Without a pole, the work's zero is the pole.
//! The angle is kept until a new pole or plane; the radius until a new one.

use super::motion::plane_axes;
use super::{Coordinate, Interpreter};
use crate::span::Span;

/// A word's value and how it is dimensioned, as the block gives it.
pub(super) type Given = Option<(Result<f64, String>, Coordinate)>;

/// The pole and the polar words last programmed.
#[derive(Clone, Debug, Default, PartialEq)]
pub(super) struct Polar {
    /// The pole in the work's coordinates, machine length units; `None`:
    /// the work's zero.
    pole: Option<[f64; 3]>,
    /// `AP`, degrees.
    angle: Option<f64>,
    /// `RP`, machine length units.
    radius: Option<f64>,
}

impl Polar {
    /// A new plane: the angle is measured from another axis.
    pub(super) fn plane_changed(&mut self) {
        self.angle = None;
    }
}

impl Interpreter<'_, '_> {
    /// G110, G111 or G112 (`kind`) in a block whose geometry axis words
    /// are `targets` (taken for the pole, not moved to) and whose polar
    /// words are `ap`, `rp`.
    pub(super) fn define_pole(
        &mut self,
        row: usize,
        span: Span,
        kind: u32,
        targets: &mut [Given],
        (ap, rp): (&Given, &Given),
    ) {
        // The block's geometry axis words name the pole: none is moved to.
        let written: Vec<Given> = targets.iter_mut().take(3).map(Option::take).collect();
        let scale = self.length_scale;
        let here = |k: usize| self.programmed.get(k).copied().flatten();
        let base: [Option<f64>; 3] = match kind {
            110 => [here(0), here(1), here(2)],
            112 => self.polar.pole.unwrap_or_default().map(Some),
            _ => [Some(0.0); 3],
        };
        let mut pole = base;
        if ap.is_some() || rp.is_some() {
            let (h, v) = plane_axes(self.plane);
            match (kind, absolute(ap), absolute(rp)) {
                (111 | 112, Some(Ok(angle)), Some(Ok(radius))) => {
                    let (sin, cos) = angle.to_radians().sin_cos();
                    pole[h] = base[h].map(|b| b + radius * scale * cos);
                    pole[v] = base[v].map(|b| b + radius * scale * sin);
                }
                _ => {
                    self.unknown(row, span, format!("a pole by G{kind} with AP= and RP= is modelled only for G111 and G112 with both given as absolute values: the pole is not changed"));
                    return;
                }
            }
        }
        for (k, word) in written.into_iter().enumerate() {
            let Some((value, coordinate)) = word else {
                continue;
            };
            pole[k] = match (value, coordinate) {
                (Ok(v), Coordinate::Incremental) => base[k].map(|b| b + v * scale),
                (Ok(v), _) if kind == 111 => Some(v * scale),
                (Ok(v), _) => base[k].map(|b| b + v * scale),
                (Err(_), _) => None,
            };
        }
        match pole {
            [Some(x), Some(y), Some(z)] => {
                self.polar.pole = Some([x, y, z]);
                self.polar.angle = None;
            }
            _ => self.unknown(
                row,
                span,
                format!("the pole G{kind} sets is unknown offline: the pole is not changed"),
            ),
        }
    }

    /// A move by `AP=` and `RP=`: the plane's two axes as absolute targets
    /// (in program units, as written words are) and, for an arc, its centre
    /// at the pole; named where the move's end is not known.
    pub(super) fn polar_move(
        &mut self,
        row: usize,
        span: Span,
        (ap, rp): (&Given, &Given),
        targets: &mut [Given],
        centre: &mut [Given; 3],
    ) {
        let angle = match ap {
            None => self.polar.angle,
            Some((Ok(a), Coordinate::Absolute)) => Some(*a),
            Some((Ok(a), Coordinate::Modal)) if !self.incremental => Some(*a),
            Some((Ok(a), Coordinate::Incremental)) => self.polar.angle.map(|last| last + a),
            Some((Ok(_), _)) => {
                self.unknown(row, span, "AP= under G91 without AC or IC: whether the control adds it to the last angle is not confirmed here; the move is not modelled".into());
                return;
            }
            Some((Err(why), _)) => {
                self.unknown(row, span, format!("the polar angle AP is {why}"));
                return;
            }
        };
        let radius = match rp {
            None => self.polar.radius,
            Some((Ok(_), Coordinate::Incremental)) => {
                self.unknown(row, span, "RP= as an increment: the polar radius is always absolute (Programming Manual); the move is not modelled".into());
                return;
            }
            Some((Ok(r), _)) => Some(r * self.length_scale),
            Some((Err(why), _)) => {
                self.unknown(row, span, format!("the polar radius RP is {why}"));
                return;
            }
        };
        self.polar.angle = angle;
        self.polar.radius = radius;
        let (Some(angle), Some(radius)) = (angle, radius) else {
            self.unknown(row, span, "a polar move before both its angle (AP) and radius (RP) were programmed: not modelled".into());
            return;
        };
        let (h, v) = plane_axes(self.plane);
        if targets[h].is_some() || targets[v].is_some() {
            self.unknown(row, span, "a block with both polar words and the plane's axes: the control refuses it; not modelled".into());
            return;
        }
        let pole = self.polar.pole.unwrap_or_default();
        let (sin, cos) = angle.to_radians().sin_cos();
        let scale = self.length_scale;
        targets[h] = Some((Ok((pole[h] + radius * cos) / scale), Coordinate::Absolute));
        targets[v] = Some((Ok((pole[v] + radius * sin) / scale), Coordinate::Absolute));
        if centre.iter().all(Option::is_none) {
            centre[h] = Some((Ok(pole[h] / scale), Coordinate::Absolute));
            centre[v] = Some((Ok(pole[v] / scale), Coordinate::Absolute));
        }
    }
}

/// A polar word's value where it is given as an absolute one.
fn absolute(given: &Given) -> Option<Result<f64, String>> {
    match given {
        Some((value, Coordinate::Absolute | Coordinate::Modal)) => Some(value.clone()),
        _ => None,
    }
}
