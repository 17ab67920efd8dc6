//! Motion: the units and frames a block's words set, the tool's length,
//! where a programmed point lies on the machine and back, a block's move
//! with its arc, and every position against the software limits.

use std::collections::HashSet;

use nalgebra::{Matrix3, Vector3};

use super::{Coordinate, Interpreter, Motion, Word, UNTOLD};
use crate::kinematics::Carrier;
use crate::run::arc::Arc;
use crate::run::frame::{rpy, scale_mirror, Frame};
use crate::run::{Side, Violation, MOST_VIOLATIONS};
use crate::semantic::frame_statements::solid_angles;
use crate::span::Span;
use crate::syntax::tree::FrameKind;
use std::f64::consts::TAU;

impl Interpreter<'_, '_> {
    pub(super) fn units(&mut self, row: usize, span: Span, g: u32) {
        let inch = matches!(g, 70 | 700);
        let scale = match (self.setup.metric, inch) {
            (Some(true), true) => 25.4,
            (Some(false), false) => 1.0 / 25.4,
            (Some(_), _) => 1.0,
            (None, _) => {
                self.unknown(row, span, "G70/G71: the machine's system of units (MD10240) is not in its data: lengths taken as they are written".into());
                1.0
            }
        };
        self.length_scale = scale;
        self.modes.feed_scale = if matches!(g, 700 | 710) { scale } else { 1.0 };
    }

    /// G54..G57, G505..G599: the settable frame the machine's data hold.
    pub(super) fn select_frame(&mut self, row: usize, span: Span, g: u32) {
        let name = format!("G{g}");
        let Some(components) = self.setup.frames.get(&name) else {
            self.unknown(
                row,
                span,
                format!("{name}: the machine's data hold no such frame (`$P_UIFR`): taken as zero"),
            );
            self.settable = Frame::identity(self.setup.axes.len());
            return;
        };
        let mut frame = Frame::identity(self.setup.axes.len());
        let mut angles = [0.0; 3];
        let mut scale = [1.0; 3];
        let mut mirrored = [false; 3];
        for (axis, c) in components {
            let Some(at) = self.setup.axis(axis) else {
                self.unknown(
                    row,
                    span,
                    format!("{name} moves axis `{axis}`, which is no axis of the channel"),
                );
                continue;
            };
            frame.translation[at] = c.tr.unwrap_or(0.0) + c.fi.unwrap_or(0.0);
            match self.setup.axes[at].geometry {
                Some(g) => {
                    angles[g] = c.rt.unwrap_or(0.0);
                    scale[g] = c.sc.unwrap_or(1.0);
                    mirrored[g] = c.mi.is_some_and(|m| m != 0.0);
                }
                None if c.sc.is_some_and(|s| s != 1.0) || c.mi.is_some_and(|m| m != 0.0) => {
                    self.unknown(
                        row,
                        span,
                        format!("{name}: the scale or mirror of axis `{axis}` is not modelled"),
                    );
                }
                None => {}
            }
        }
        frame.linear = self.rotation(row, span, angles) * scale_mirror(scale, mirrored);
        self.settable = frame;
    }

    /// A rotation by RPY angles; with more than one axis, MD10600 decides
    /// the order, RPY where the data say so.
    pub(super) fn rotation(&mut self, row: usize, span: Span, angles: [f64; 3]) -> Matrix3<f64> {
        if angles.iter().filter(|a| **a != 0.0).count() > 1 {
            match self.setup.angles_rpy {
                Some(true) => {}
                Some(false) => self.unknown(row, span, "a rotation about several axes in Euler angles (MD10600 = 2) is not modelled: taken as RPY (Z, Y', X'')".into()),
                None => self.unknown(row, span, "a rotation about several axes, and MD10600 (RPY or Euler) not in the machine's data: taken as RPY (Z, Y', X'')".into()),
            }
        }
        rpy(angles)
    }

    pub(super) fn frame_statement(
        &mut self,
        row: usize,
        span: Span,
        kind: FrameKind,
        words: &[Word],
    ) {
        let axes = self.setup.axes.len();
        let mut values = vec![0.0; axes];
        let mut angles = [0.0; 3];
        let mut solid: [Option<f64>; 3] = [None; 3];
        // SCALE's factors and MIRROR's axes: those of the geometry axes given.
        let mut scale = [1.0; 3];
        let mut mirrored = [false; 3];
        let mut other_axes = false;
        let mut in_plane = None;
        for word in words {
            let Ok(value) = word.value else {
                self.unknown(
                    row,
                    span,
                    format!("the frame's `{}` is unknown offline: taken as 0", word.name),
                );
                continue;
            };
            if word.name == "RPL" {
                in_plane = Some(value);
                continue;
            }
            match self.setup.axis(&word.name) {
                Some(at) => {
                    values[at] = value;
                    match self.setup.axes[at].geometry {
                        Some(g) => {
                            angles[g] = value;
                            solid[g] = Some(value);
                            scale[g] = value;
                            mirrored[g] = true;
                        }
                        None => other_axes = true,
                    }
                }
                None => self.unknown(
                    row,
                    span,
                    format!("`{}` is no axis of the channel", word.name),
                ),
            }
        }
        if let Some(angle) = in_plane {
            angles = [0.0; 3];
            angles[[2, 1, 0][self.plane]] = angle;
        }
        if other_axes
            && matches!(
                kind,
                FrameKind::Scale | FrameKind::AScale | FrameKind::Mirror | FrameKind::AMirror
            )
        {
            self.unknown(
                row,
                span,
                format!("{kind:?} of an axis other than the geometry axes is not modelled"),
            );
        }
        match kind {
            FrameKind::Trans => {
                self.programmable = Frame::identity(axes);
                self.programmable.translation = values.iter().map(|v| v * self.length_scale).collect();
            }
            FrameKind::ATrans => {
                let geometry = Vector3::new(values[0], values[1], values[2]) * self.length_scale;
                let turned = self.programmable.turn(geometry);
                for (k, v) in values.iter().enumerate() {
                    self.programmable.translation[k] += if k < 3 { turned[k] } else { *v };
                }
            }
            FrameKind::Rot => {
                self.programmable = Frame::identity(axes);
                self.programmable.linear = self.rotation(row, span, angles);
            }
            FrameKind::ARot => {
                let rotation = self.rotation(row, span, angles);
                self.programmable.linear *= rotation;
            }
            FrameKind::Scale | FrameKind::Mirror => {
                self.programmable = Frame::identity(axes);
                self.programmable.linear = self.scaled_or_mirrored(kind, scale, mirrored);
            }
            FrameKind::AScale | FrameKind::AMirror => {
                let linear = self.scaled_or_mirrored(kind, scale, mirrored);
                self.programmable.linear *= linear;
            }
            FrameKind::Rots | FrameKind::ARots => match solid_angles(solid) {
                Ok(rotation) => {
                    if kind == FrameKind::Rots {
                        self.programmable = Frame::identity(axes);
                    }
                    self.programmable.linear *= rotation.into_inner();
                }
                Err(why) => self.unknown(row, span, format!("{kind:?}: {why}: the frame is left as it was")),
            },
            FrameKind::CRots => self.unknown(row, span, "CROTS turns the frame the control holds in its data, which the run does not follow: the frame is left as it was".into()),
        }
    }

    /// SCALE's or MIRROR's matrix (MIRROR's values say nothing: the axis
    /// named is mirrored).
    fn scaled_or_mirrored(
        &self,
        kind: FrameKind,
        scale: [f64; 3],
        mirrored: [bool; 3],
    ) -> Matrix3<f64> {
        match kind {
            FrameKind::Scale | FrameKind::AScale => scale_mirror(scale, [false; 3]),
            _ => scale_mirror([1.0; 3], mirrored),
        }
    }

    /// The tool's length along the infeed axis of the plane, in the machine.
    pub(super) fn tool_offset(&mut self, row: usize, span: Span) -> [f64; 3] {
        let mut offset = [0.0; 3];
        let (Some(t), Some(d)) = (self.tool, self.edge) else {
            return offset;
        };
        if d == 0 {
            return offset;
        }
        // Asked by every block that moves: the tool's offsets are searched
        // once a tool, edge and plane.
        let key = (t, d, self.plane);
        if let Some((cached, offset)) = self.tool_offset {
            if cached == key {
                return offset;
            }
        }
        let Some(tool) = self.setup.tool(t, d) else {
            self.unknown(row, span, format!("T{t} D{d}: the machine's data hold no offsets for it (`$TC_DP`): its length taken as 0"));
            return offset;
        };
        let milling = tool.kind.is_none_or(|k| (100.0..300.0).contains(&k));
        if !milling {
            self.unknown(row, span, format!("T{t} D{d}: tool type {} (not a milling or drilling tool) is not modelled: its length taken as 0", tool.kind.unwrap_or(0.0)));
            return offset;
        }
        let length = tool.length[0].unwrap_or(0.0) + tool.length_wear[0].unwrap_or(0.0);
        offset[[2, 1, 0][self.plane]] = length;
        self.tool_offset = Some((key, offset));
        offset
    }

    /// The machine position of the programmed point `wcs`: through the
    /// frames (programmable, the swivel's, settable) unless suppressed,
    /// then the tool carrier's turn and offsets with the tool.
    pub(super) fn to_machine(
        &self,
        wcs: &[Option<f64>],
        suppress: bool,
        tool: [f64; 3],
    ) -> Vec<Option<f64>> {
        let mut at = self.frames_only(wcs, suppress);
        let length = Vector3::from(tool);
        // TRAORI: the chain at the rotary axes' positions, frames suppressed
        // or not (G53 and SUPA leave the transformation on).
        if let Some(transformed) = &self.transformed {
            match transformed.carrier(&at) {
                Some(carrier) => on_geometry(&mut at, |p| carrier.machine(p, length)),
                None => at[..3].fill(None),
            }
            return at;
        }
        match (self.carrier(), suppress) {
            (Some(carrier), false) => on_geometry(&mut at, |p| carrier.machine(p, length)),
            // G53, SUPA: the machine's axes, the tool as the carrier holds it.
            (Some(carrier), true) => {
                on_geometry(&mut at, |p| p + carrier.tool * length + carrier.head)
            }
            (None, _) => {
                for (k, length) in tool.iter().enumerate() {
                    at[k] = at[k].map(|v| v + length);
                }
            }
        }
        at
    }

    /// The programmed point of the machine position `mcs`.
    pub(super) fn to_program(
        &self,
        mcs: &[Option<f64>],
        suppress: bool,
        tool: [f64; 3],
    ) -> Vec<Option<f64>> {
        let mut at = mcs.to_vec();
        let length = Vector3::from(tool);
        let transformed = self.transformed.as_ref().map(|t| t.carrier(mcs));
        match (self.carrier(), suppress) {
            _ if transformed.is_some() => match transformed.flatten() {
                Some(carrier) => on_geometry(&mut at, |p| carrier.part_point(p, length)),
                None => at[..3].fill(None),
            },
            (Some(carrier), false) => on_geometry(&mut at, |p| carrier.part_point(p, length)),
            (Some(carrier), true) => {
                on_geometry(&mut at, |p| p - carrier.tool * length - carrier.head)
            }
            (None, _) => {
                for (k, length) in tool.iter().enumerate() {
                    at[k] = at[k].map(|v| v - length);
                }
            }
        }
        if suppress {
            return at;
        }
        let at = self.settable.undo(&at);
        let at = match &self.swivelled {
            Some(swivelled) => swivelled.frame.undo(&at),
            None => at,
        };
        self.programmable.undo(&at)
    }

    /// The programmed point `wcs` through the frames (programmable, the
    /// swivel's, settable), unless suppressed.
    pub(super) fn frames_only(&self, wcs: &[Option<f64>], suppress: bool) -> Vec<Option<f64>> {
        match (suppress, &self.swivelled) {
            (true, _) => wcs.to_vec(),
            (false, None) => self.settable.apply(&self.programmable.apply(wcs)),
            (false, Some(swivelled)) => self
                .settable
                .apply(&swivelled.frame.apply(&self.programmable.apply(wcs))),
        }
    }

    /// The tool carrier a swivel left active.
    fn carrier(&self) -> Option<&Carrier> {
        self.swivelled.as_ref()?.carrier.as_ref()
    }

    /// The frames' linear part from the program to the machine: what turns,
    /// scales or mirrors a programmed move.
    pub(super) fn frames_linear(&self, suppress: bool) -> Matrix3<f64> {
        if suppress {
            return Matrix3::identity();
        }
        let swivel = self
            .swivelled
            .as_ref()
            .map_or(Matrix3::identity(), |s| s.frame.linear);
        let part = self
            .carrier()
            .map_or(Matrix3::identity(), |c| c.part.into_inner());
        part * self.settable.linear * swivel * self.programmable.linear
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn motion_block(
        &mut self,
        row: usize,
        span: Span,
        targets: &[Option<(Result<f64, String>, Coordinate)>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        shape: &ArcShape,
        suppress: bool,
        exact_here: bool,
    ) {
        let tool = self.tool_offset(row, span);
        // A move that leaves the frames or the plane of the compensation
        // ends the element held back first: it starts where that one ends.
        if self.compensation.holds() && (suppress || self.transformed.is_some()) {
            self.end_held(Some("a move under G53, G153, SUPA or TRAORI follows"));
        }
        let mut start_mcs = self.mcs.clone();
        // Where the program left each axis; in machine coordinates less the
        // tool for a block that suppresses the frames (G53, G153, SUPA).
        let start = if suppress {
            self.to_program(&start_mcs, true, tool)
        } else {
            self.programmed.clone()
        };
        let mut end = start.clone();
        for (k, target) in targets.iter().enumerate() {
            let Some((value, coordinate)) = target else {
                continue;
            };
            let scale = if self.setup.axes[k].rotary() {
                1.0
            } else {
                self.length_scale
            };
            end[k] = match value {
                Ok(v) => {
                    let incremental = match coordinate {
                        Coordinate::Modal => self.incremental,
                        Coordinate::Absolute => false,
                        Coordinate::Incremental => true,
                    };
                    if incremental {
                        if start[k].is_none() {
                            let name = &self.setup.axes[k].name;
                            self.unknown(row, span, format!("axis `{name}` moves incrementally from a position unknown offline (no absolute position before): where it goes is unknown"));
                        }
                        start[k].map(|s| s + v * scale)
                    } else {
                        Some(v * scale)
                    }
                }
                Err(why) => {
                    self.unknown(
                        row,
                        span,
                        format!("axis `{}`: its position is {why}", self.setup.axes[k].name),
                    );
                    None
                }
            };
        }
        // A changed frame or tool is traversed with the next move of the
        // axes it concerns (MD42440, MD42442 at their defaults): an axis not
        // programmed stays where it is; under a rotation, or where it
        // changed, the geometry axes go together.
        let held = self.compensation.holds();
        if self.compensate(
            row, span, &start, &end, targets, centre, shape, suppress, exact_here, tool,
        ) {
            return;
        }
        // Not compensated, the element held before ended: from its end.
        if held {
            start_mcs = self.mcs.clone();
        }
        let reached = self.to_machine(&end, suppress, tool);
        let linear = self.frames_linear(suppress);
        // A rotation couples the geometry axes: one programmed moves them all.
        let frames = Frame {
            translation: Vec::new(),
            linear,
        };
        // Under TRAORI the tip stays where it is programmed: every geometry
        // axis follows the rotary axes.
        let coupled = self.transformed.is_some()
            || ((linear != self.last_linear || frames.couples())
                && targets.iter().take(3).any(Option::is_some));
        self.last_linear = linear;
        let end_mcs: Vec<Option<f64>> = (0..reached.len())
            .map(|k| {
                if targets[k].is_some() || (k < 3 && coupled) {
                    reached[k]
                } else {
                    start_mcs[k]
                }
            })
            .collect();
        self.programmed = if suppress {
            self.to_program(&end_mcs, false, tool)
        } else {
            end.clone()
        };
        // Under TRAORI the way starts where the machine stands, under the
        // frames and tool now.
        let way_start = self
            .transformed
            .is_some()
            .then(|| self.to_program(&start_mcs, suppress, tool));
        let way = self.way(self.by_vector);
        // The arc as programmed (under TRAORI the tool tip's), and in the
        // machine's coordinates: under TRAORI only while the rotary axes
        // stand still (an affine map of the tip's arc); where they turn,
        // the way is sampled along the tip's arc instead.
        let programmed_arc = match self.modes.motion {
            Motion::Clockwise | Motion::Counterclockwise => {
                self.programmed_arc(row, span, &start, &end, centre, shape)
            }
            _ => None,
        };
        let turn = way_start
            .as_deref()
            .map(|from| self.block_turn(from, &end, suppress, way))
            .unwrap_or_default();
        let turning = turn.turns();
        let from_unknown_angles = match (&self.transformed, &way_start) {
            (Some(transformed), Some(from)) => !transformed.rotary_known(from),
            _ => false,
        };
        if programmed_arc.is_some() && from_unknown_angles {
            self.unknown(row, span, "an arc under TRAORI from rotary axes whose positions are unknown offline: its way is taken with the axes at the block's end".into());
        }
        let arc = match &programmed_arc {
            Some(arc) if self.transformed.is_none() => {
                Some(self.arc_on_machine(row, span, arc, suppress, tool))
            }
            Some(arc) if !turning => self.arc_on_machine_at(row, span, arc, &end, suppress, tool),
            _ => None,
        };
        self.last_arc = arc;
        // Limits and travel: the ends, and the arc's turning points. Where
        // the block traverses a changed offset, the arc's start under the new
        // one too: the path lies between the arc under the old offset and
        // under the new, which holds its extremes.
        let mut points = vec![end_mcs.clone()];
        if let Some(from) = &way_start {
            if self.modes.motion == Motion::Rapid && !self.modes.rapid_linear {
                self.unknown(row, span, "G0 under TRAORI after RTLIOF: the run takes the tip on the line between the block's ends, where the control may move the machine axes each on its own".into());
            }
            let tip_arc = programmed_arc.as_ref().filter(|_| turning);
            points.extend(self.transformed_way(from, &end, suppress, tool, &turn, tip_arc));
        }
        if let Some(arc) = &arc {
            for k in 0..3 {
                let start = std::iter::once(arc.point(0.0));
                for point in arc.turning_points(k).into_iter().chain(start) {
                    let mut at = end_mcs.clone();
                    at[0] = Some(point.x);
                    at[1] = Some(point.y);
                    at[2] = Some(point.z);
                    points.push(at);
                }
            }
        }
        // The tool tip's way under TRAORI: its arc (where a frame or tool
        // changed since its programmed start, without the shift the sampled
        // way spreads over it), or the line between the block's ends.
        let tip = way_start.as_deref().map(|from| match &programmed_arc {
            Some(arc) => self.tip_arc_length(arc, suppress),
            None => self.tip_way(from, &end, suppress),
        });
        self.traverse(
            row,
            span,
            &start_mcs,
            end_mcs,
            &points,
            arc.as_ref(),
            tip,
            exact_here,
        );
    }

    /// A move from `start_mcs` to `end_mcs` through `points` (its extremes
    /// besides its end): each against the limits, the travel, the time (along
    /// `arc` where it is one, or a path of length `path` where that is
    /// neither the chord nor the arc).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn traverse(
        &mut self,
        row: usize,
        span: Span,
        start_mcs: &[Option<f64>],
        end_mcs: Vec<Option<f64>>,
        points: &[Vec<Option<f64>>],
        arc: Option<&Arc>,
        path: Option<f64>,
        exact_here: bool,
    ) {
        let mut out = HashSet::new();
        for point in points {
            self.check(row, span, point, &mut out);
        }

        // An axis back within its limits ends its excursion.
        self.beyond.retain(|key, _| out.contains(key));
        // Time.
        let moved: Vec<(usize, f64)> = start_mcs
            .iter()
            .zip(&end_mcs)
            .enumerate()
            .filter_map(|(k, (a, b))| match (a, b) {
                (Some(a), Some(b)) if (b - a).abs() > 1e-12 => Some((k, b - a)),
                _ => None,
            })
            .collect();
        // An axis whose start or end is unknown: how far it goes is unknown.
        let timed = start_mcs
            .iter()
            .zip(&end_mcs)
            .all(|(a, b)| a.is_some() == b.is_some());
        self.mcs = end_mcs;
        if !timed {
            self.report.blocks_without_time += 1;
            self.unknown(row, span, "where the axes were before this block is unknown (the program's start, or a value unknown offline): its time is not counted".into());
            return;
        }
        if moved.is_empty() && arc.is_none() && path.is_none() {
            return;
        }
        self.time(row, span, &moved, arc, path, exact_here);
    }

    /// An arc by its centre and opening angle (`G2/G3 I.. J.. AR=..`): its
    /// end in the plane, set among `targets` as the end a block writes; the
    /// opening is then spent. `false`, named, where the start, the centre
    /// or the angle is unknown.
    pub(super) fn end_of_opening(
        &mut self,
        row: usize,
        span: Span,
        targets: &mut [Option<(Result<f64, String>, Coordinate)>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        shape: &mut ArcShape,
    ) -> bool {
        let Some(opening) = shape.opening.take() else {
            return true;
        };
        let (h, v) = plane_axes(self.plane);
        let scale = self.length_scale;
        let start = [h, v].map(|k| self.programmed.get(k).copied().flatten());
        let centre_of = |k: usize, start: Option<f64>| match &centre[k] {
            Some((Ok(c), Coordinate::Absolute)) => Some(c * scale),
            Some((Ok(c), _)) => start.map(|s| s + c * scale),
            Some((Err(_), _)) => None,
            None => start,
        };
        let (Ok(opening), [Some(sh), Some(sv)]) = (opening, start) else {
            self.unknown(row, span, "an arc by its centre and opening angle (AR=) from a start or with an angle unknown offline: its move is left out".into());
            return false;
        };
        let (Some(ch), Some(cv)) = (centre_of(h, Some(sh)), centre_of(v, Some(sv))) else {
            self.unknown(
                row,
                span,
                "the arc's centre is unknown offline: its move is left out".into(),
            );
            return false;
        };
        if !(opening > 0.0 && opening <= 360.0) {
            self.unknown(
                row,
                span,
                format!(
                    "an opening angle AR={opening} outside 0..360 degrees: its move is left out"
                ),
            );
            return false;
        }
        let turn = match self.modes.motion {
            Motion::Clockwise => -opening,
            _ => opening,
        };
        let (sin, cos) = turn.to_radians().sin_cos();
        let (dh, dv) = (sh - ch, sv - cv);
        targets[h] = Some((Ok((ch + dh * cos - dv * sin) / scale), Coordinate::Absolute));
        targets[v] = Some((Ok((cv + dh * sin + dv * cos) / scale), Coordinate::Absolute));
        true
    }

    /// The arc a circular block programs, in the work's coordinates;
    /// `None`, named, where it cannot be known.
    pub(super) fn programmed_arc(
        &mut self,
        row: usize,
        span: Span,
        start: &[Option<f64>],
        end: &[Option<f64>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        shape: &ArcShape,
    ) -> Option<Arc> {
        let point = |p: &[Option<f64>]| Some(Vector3::new(p[0]?, p[1]?, p[2]?));
        let (Some(s), Some(e)) = (point(start), point(end)) else {
            self.unknown(
                row,
                span,
                "an arc from or to a point unknown offline: its travel is not checked".into(),
            );
            return None;
        };
        let applicate = [2, 1, 0][self.plane];
        let mut normal = Vector3::zeros();
        normal[applicate] = if self.modes.motion == Motion::Clockwise {
            -1.0
        } else {
            1.0
        };
        let given_centre = centre.iter().any(Option::is_some);
        let radius = match (&shape.radius, &shape.opening) {
            (Some(radius), _) => Some(radius.clone()),
            (None, Some(Ok(opening))) => match radius_of_opening(s, e, *opening, normal) {
                Some(radius) => Some(Ok(radius / self.length_scale)),
                None => {
                    self.unknown(row, span, format!("an opening angle AR={opening} outside 0..360 degrees, or an arc whose end is its start: not modelled"));
                    return None;
                }
            },
            (None, Some(Err(why))) => Some(Err(format!("by its opening angle AR, {why}"))),
            (None, None) => None,
        };
        let c = match (given_centre, radius) {
            (true, _) => {
                let mut c = s;
                for (k, given) in centre.iter().enumerate() {
                    match given {
                        Some((Ok(v), Coordinate::Absolute)) => c[k] = v * self.length_scale,
                        Some((Ok(v), _)) => c[k] = s[k] + v * self.length_scale,
                        Some((Err(why), _)) => {
                            self.unknown(row, span, format!("the arc's centre is {why}"));
                            return None;
                        }
                        None => {}
                    }
                }
                c
            }
            (false, Some(Ok(r))) => {
                match Arc::centre_of_radius(s, e, r * self.length_scale, normal) {
                    Some(c) => c,
                    None => {
                        self.unknown(row, span, "the arc's radius is smaller than half the way from start to end: the control stops with an alarm (14045)".into());
                        return None;
                    }
                }
            }
            (false, Some(Err(why))) => {
                self.unknown(row, span, format!("the arc's radius is {why}"));
                return None;
            }
            (false, None) => {
                self.unknown(
                    row,
                    span,
                    "an arc without its centre (I, J, K) or radius (CR=)".into(),
                );
                return None;
            }
        };
        let mut arc = Arc::through(s, e, c, normal)?;
        // TURN=n: n full turns more, the helix's rise spread over them all.
        match &shape.turns {
            Some(Ok(turns)) if *turns >= 0.0 && turns.fract() == 0.0 && *turns <= 999.0 => {
                arc.sweep += turns * TAU;
            }
            Some(Ok(turns)) => {
                self.unknown(row, span, format!("TURN={turns} is no whole number of turns from 0 to 999: the turns are not added"));
            }
            Some(Err(why)) => {
                self.unknown(row, span, format!("TURN is {why}: the turns are not added"))
            }
            None => {}
        }
        Some(arc)
    }

    /// `arc`, programmed, in the machine: the frames turn and shift it, the
    /// tool shifts it. Without TRAORI every point has a machine position.
    pub(super) fn arc_on_machine(
        &mut self,
        row: usize,
        span: Span,
        arc: &Arc,
        suppress: bool,
        tool: [f64; 3],
    ) -> Arc {
        let origin = vec![Some(0.0); self.setup.axes.len()];
        self.arc_on_machine_at(row, span, arc, &origin, suppress, tool)
            .unwrap_or(*arc)
    }

    /// `arc` (under TRAORI the tool tip's, programmed) in the machine, the
    /// other axes at their positions in `at` (programmed): the frames, and
    /// under TRAORI the chain at the rotary axes' fixed angles, are an
    /// affine map, so the holder too moves on an arc (an ellipse under
    /// unequal scales). `None` where a rotary axis's position is unknown.
    pub(super) fn arc_on_machine_at(
        &mut self,
        row: usize,
        span: Span,
        arc: &Arc,
        at: &[Option<f64>],
        suppress: bool,
        tool: [f64; 3],
    ) -> Option<Arc> {
        let on_machine = arc_through(arc, at, |p| self.to_machine(p, suppress, tool))?;
        self.ellipse_named(row, span, &on_machine);
        Some(on_machine)
    }

    /// The length of `arc` (programmed) through the frames: the tool tip's
    /// way under TRAORI, which the feed is programmed for.
    pub(super) fn tip_arc_length(&self, arc: &Arc, suppress: bool) -> f64 {
        let origin = vec![Some(0.0); self.setup.axes.len()];
        arc_through(arc, &origin, |p| self.frames_only(p, suppress))
            .map_or(arc.length(), |tip| tip.length())
    }

    /// Unequal scales make the circle an ellipse: its extremes are still
    /// exact, its length and radius (the time) taken from its start.
    fn ellipse_named(&mut self, row: usize, span: Span, arc: &Arc) {
        if (arc.u.norm() - arc.v.norm()).abs() > 1e-9 * arc.u.norm() {
            self.unknown(row, span, "an arc under unequal scales of its plane's axes: its length and the radius that limits its speed are taken from its start".into());
        }
    }

    /// Every position of `point` against its axis's software limits, and
    /// the travel's extent.
    pub(super) fn check(
        &mut self,
        row: usize,
        span: Span,
        point: &[Option<f64>],
        out: &mut HashSet<(usize, bool)>,
    ) {
        for (k, value) in point.iter().enumerate() {
            let Some(value) = *value else { continue };
            self.minimum[k] = Some(self.minimum[k].map_or(value, |m| m.min(value)));
            self.maximum[k] = Some(self.maximum[k].map_or(value, |m| m.max(value)));
            let axis = &self.setup.axes[k];
            let limits = axis.limits(self.options.second_limits);
            for (side, limit) in [(Side::Minus, limits[0]), (Side::Plus, limits[1])] {
                let Some(limit) = limit else { continue };
                let past = match side {
                    Side::Minus => value < limit,
                    Side::Plus => value > limit,
                };
                if !past {
                    continue;
                }
                let key = (k, side == Side::Plus);
                out.insert(key);
                let known = self
                    .beyond
                    .get(&key)
                    .or_else(|| {
                        self.began
                            .get(&(self.program.clone(), row, k, side == Side::Plus))
                    })
                    .copied();
                match known {
                    // Counted once an excursion, not listed.
                    Some(UNTOLD) => {
                        self.beyond.insert(key, UNTOLD);
                    }
                    Some(at) => {
                        let violation = &mut self.violations[at];
                        let worse = match side {
                            Side::Minus => value < violation.value,
                            Side::Plus => value > violation.value,
                        };
                        if worse {
                            violation.value = value;
                        }
                        violation.last_line = violation.last_line.max(row + 1);
                        self.beyond.insert(key, at);
                    }
                    None if self.violations.len() >= MOST_VIOLATIONS => {
                        self.report.violations_untold += 1;
                        self.beyond.insert(key, UNTOLD);
                    }
                    None => {
                        self.violations.push(Violation {
                            program: self.program.clone(),
                            line: row + 1,
                            last_line: row + 1,
                            span,
                            axis: axis.machine_name(),
                            value,
                            limit,
                            side,
                        });
                        let at = self.violations.len() - 1;
                        self.beyond.insert(key, at);
                        self.began
                            .insert((self.program.clone(), row, k, side == Side::Plus), at);
                    }
                }
            }
        }
    }
}

/// `point`'s geometry axes through `map`, all three unknown where one is.
fn on_geometry(point: &mut [Option<f64>], map: impl Fn(Vector3<f64>) -> Vector3<f64>) {
    let mapped = match (point[0], point[1], point[2]) {
        (Some(x), Some(y), Some(z)) => {
            let p = map(Vector3::new(x, y, z));
            [Some(p.x), Some(p.y), Some(p.z)]
        }
        _ => [None; 3],
    };
    point[..3].copy_from_slice(&mapped);
}

/// What a circular block gives of its arc beyond its end and centre: its
/// radius (`CR=`), its opening angle (`AR=`, degrees), the full turns it
/// adds (`TURN=`).
#[derive(Default)]
pub(super) struct ArcShape {
    pub radius: Option<Result<f64, String>>,
    pub opening: Option<Result<f64, String>>,
    pub turns: Option<Result<f64, String>>,
}

/// The signed radius (`CR=`'s sign: negative past a half turn) of the arc
/// from `start` to `end` about `normal` that opens by `opening` degrees;
/// `None` outside (0, 360) or where the chord is empty.
fn radius_of_opening(
    start: Vector3<f64>,
    end: Vector3<f64>,
    opening: f64,
    normal: Vector3<f64>,
) -> Option<f64> {
    if !(opening > 0.0 && opening < 360.0) {
        return None;
    }
    let d = end - start;
    let chord = (d - normal * d.dot(&normal)).norm();
    if chord < 1e-12 {
        return None;
    }
    let radius = chord / 2.0 / (opening.to_radians() / 2.0).sin();
    Some(if opening <= 180.0 { radius } else { -radius })
}

/// The horizontal and vertical axis of plane `plane` (0: G17 X Y, 1: G18
/// Z X, 2: G19 Y Z), as geometry axis indices: a turn from the first
/// towards the second is counter-clockwise about the plane's normal.
pub(super) fn plane_axes(plane: usize) -> (usize, usize) {
    [(0, 1), (2, 0), (1, 2)][plane]
}

/// `arc` through the affine map `map` (a point's coordinates, every run
/// axis, from a programmed point: `base` with the arc's point on the
/// geometry axes): the centre mapped, its directions as the map moves them
/// from the origin. `None` where the map leaves a geometry coordinate
/// unknown.
fn arc_through(
    arc: &Arc,
    base: &[Option<f64>],
    map: impl Fn(&[Option<f64>]) -> Vec<Option<f64>>,
) -> Option<Arc> {
    let point = |p: Vector3<f64>| -> Option<Vector3<f64>> {
        let mut programmed = base.to_vec();
        programmed[..3].copy_from_slice(&[Some(p.x), Some(p.y), Some(p.z)]);
        let at = map(&programmed);
        Some(Vector3::new(at[0]?, at[1]?, at[2]?))
    };
    let origin = point(Vector3::zeros())?;
    let turn = |d: Vector3<f64>| Some(point(d)? - origin);
    // The normal kept a unit vector, the rise scaled as it is (SCALE on
    // the infeed axis): the points are the same, the length is right.
    let normal = turn(arc.normal)?;
    let stretch = normal.norm();
    let (normal, rise) = match stretch > 1e-12 {
        true => (normal / stretch, arc.rise * stretch),
        false => (normal, arc.rise),
    };
    Some(Arc {
        centre: point(arc.centre)?,
        u: turn(arc.u)?,
        v: turn(arc.v)?,
        normal,
        sweep: arc.sweep,
        rise,
    })
}
