//! Tool radius compensation in the run (G40, G41, G42 with G450, G451,
//! OFFN): the tool centre's path beside the programmed contour, in the
//! working plane of the work's coordinates (Siemens, Programming Manual
//! Fundamentals, "Tool radius compensation"). Where an element ends depends
//! on the next one (the corner between them), so the run holds each element
//! back until the next move in the plane comes, and tells the blocks run
//! meanwhile once it is finished. The geometry is `run::contour`'s.
//!
//! Approach and retraction are NORM's: the block that selects G41/G42 goes
//! in a line to the next element's start moved by the radius (square to
//! it); the element before G40 ends square to its end, and the G40 block
//! goes in a line from there to its programmed end.

use nalgebra::Vector3;

use super::motion::{plane_axes, ArcShape};
use super::{Content, Coordinate, Interpreter, Modes, Motion};
use crate::run::arc::Arc;
use crate::run::contour::{self, Element, Point};
use crate::run::frame::Frame;
use crate::span::Span;

/// Below this, a plane move is none.
const NO_MOVE: f64 = 1e-9;

/// The most moves off the plane held between two elements, the run's own
/// bound (the control's is MD20250, which the data rarely hold).
const MOST_DUMMIES: usize = 64;

#[derive(Default)]
pub(super) struct Compensation {
    /// +1 for G41 (the tool left of the contour in its direction of
    /// travel), -1 for G42; `None` under G40.
    side: Option<f64>,
    /// G451: the moved elements extended to their meeting point at an
    /// outside corner, rather than G450's circle about it.
    meet_outside: bool,
    /// G41/G42 programmed, its approach not yet moved.
    approaching: bool,
    /// OFFN: added to the tool's radius.
    extra: f64,
    held: Option<Held>,
    /// The blocks run since the held element's, to be told with it.
    waiting: Vec<Waiting>,
    /// How many of the blocks that waited for the held element are told.
    released: usize,
    /// Blocks finished, in the order they ran, not yet told.
    pub(super) told: Vec<Told>,
}

/// A block's move as it was programmed, run later: where it is, the
/// modes and the tool it runs with, where it ends.
struct Move {
    row: usize,
    span: Span,
    program: Option<String>,
    modes: Modes,
    exact_here: bool,
    tool: [f64; 3],
    /// The programmed end, every axis.
    end: Vec<Option<f64>>,
    /// The axes the block programs.
    targeted: Vec<bool>,
}

/// An element of the centre's path waiting for the next to know its end.
struct Held {
    block: Move,
    plane: usize,
    /// The approach: a line from `from` to where the next element starts.
    approach: bool,
    /// The programmed element moved by the radius.
    moved: Element,
    /// Where the centre's path of this block starts.
    from: Point,
    /// What the path takes before `moved`: the circle about the corner
    /// before it, or a line to its start.
    lead: Option<Element>,
    /// The applicate's programmed value at the block's start.
    applicate_from: f64,
    /// The moves off the plane programmed after it, before the next
    /// element: run where it ends.
    dummies: Vec<Dummy>,
}

/// A move without a move in the plane while an element is held.
struct Dummy {
    block: Move,
    /// Its place among the blocks waiting since the element was held.
    waiting: usize,
}

struct Waiting {
    program: Option<String>,
    line: usize,
    arc: Option<Arc>,
}

/// A block's end, told later than it ran.
pub(super) struct Told {
    pub program: Option<String>,
    pub line: usize,
    pub mcs: Vec<Option<f64>>,
    pub t_s: f64,
    pub arc: Option<Arc>,
}

impl Compensation {
    /// Whether an element is held back: the blocks run now are told later.
    pub(super) fn holds(&self) -> bool {
        self.held.is_some()
    }

    /// The side, the corners, the approach to come and OFFN, where no
    /// element is held back and no block waits to be told: then they are
    /// all the compensation holds.
    pub(super) fn settled(&self) -> Option<(Option<f64>, bool, bool, f64)> {
        let settled = self.held.is_none() && self.waiting.is_empty() && self.told.is_empty();
        settled.then_some((self.side, self.meet_outside, self.approaching, self.extra))
    }

    pub(super) fn wait(&mut self, program: Option<String>, line: usize, arc: Option<Arc>) {
        self.waiting.push(Waiting { program, line, arc });
    }

    pub(super) fn corners(&mut self, g: u32) {
        self.meet_outside = g == 451;
    }

    pub(super) fn set_extra(&mut self, offset: f64) {
        self.extra = offset;
    }

    /// The side, the corners and OFFN: what SAVE gives back.
    pub(super) fn modes(&self) -> (Option<f64>, bool, f64) {
        (self.side, self.meet_outside, self.extra)
    }

    /// Back to `modes` (with no element held).
    pub(super) fn set_modes(&mut self, (side, meet_outside, extra): (Option<f64>, bool, f64)) {
        if side != self.side {
            self.approaching = side.is_some();
        }
        (self.side, self.meet_outside, self.extra) = (side, meet_outside, extra);
    }
}

impl Interpreter<'_, '_> {
    /// G40, G41, G42.
    pub(super) fn select_compensation(&mut self, row: usize, span: Span, g: u32) {
        let side = match g {
            41 => Some(1.0),
            42 => Some(-1.0),
            _ => None,
        };
        let before = self.compensation.side;
        if side == before {
            return;
        }
        if before.is_some() && side.is_some() {
            self.end_held(Some("G41 and G42 change sides here without G40: the run ends the element square and approaches again"));
        } else {
            self.end_held(None);
        }
        self.compensation.side = side;
        self.compensation.approaching = side.is_some();
        if side.is_some() && self.transformed.is_some() {
            self.unknown(row, span, "G41/G42 under TRAORI (3-D tool radius compensation) is not modelled: positions are the programmed contour's".into());
        }
    }

    /// Under G41/G42, holds a block's move in the plane back as the next
    /// element of the centre's path, finishing the one before; `false`
    /// where the move is run as programmed (no compensation active, none
    /// possible, or no move in the plane).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn compensate(
        &mut self,
        row: usize,
        span: Span,
        start: &[Option<f64>],
        end: &[Option<f64>],
        targets: &[Option<(Result<f64, String>, Coordinate)>],
        centre: &[Option<(Result<f64, String>, Coordinate)>; 3],
        shape: &ArcShape,
        suppress: bool,
        exact_here: bool,
        tool: [f64; 3],
    ) -> bool {
        if self.compensation.side.is_none() {
            return false;
        }
        if suppress || self.transformed.is_some() {
            if suppress {
                self.unknown(row, span, "G41/G42: a move under G53, G153 or SUPA is taken as programmed, not compensated".into());
            }
            return false;
        }
        let (h, v) = plane_axes(self.plane);
        let circular = matches!(
            self.modes.motion,
            Motion::Clockwise | Motion::Counterclockwise
        );
        let point = |p: &[Option<f64>]| Some(Vector3::new(p[0]?, p[1]?, p[2]?));
        let (Some(s), Some(e)) = (point(start), point(end)) else {
            self.end_held(Some("a move from or to a position unknown offline follows"));
            self.unknown(row, span, "G41/G42: a move from or to a position unknown offline is taken as programmed, not compensated".into());
            return false;
        };
        let (s2, e2) = (Point::new(s[h], s[v]), Point::new(e[h], e[v]));
        if !circular && (e2 - s2).norm() <= NO_MOVE {
            // A move off the plane (an infeed): run once the element before
            // it ends, from there (MD20250 $MC_CUTCOM_MAXNUM_DUMMY_BLOCKS
            // bounds how many the control takes; past them it stops).
            let dummy = Dummy {
                block: self.move_of(row, span, exact_here, tool, end, targets),
                waiting: self.compensation.waiting.len(),
            };
            return match &mut self.compensation.held {
                Some(held) if held.dummies.len() < MOST_DUMMIES => {
                    held.dummies.push(dummy);
                    self.programmed = end.to_vec();
                    true
                }
                Some(_) => {
                    self.end_held(Some("more moves off the plane follow than the control takes between two elements (MD20250)"));
                    false
                }
                None => false,
            };
        }
        let offset = self.cutter_offset(row, span);
        if offset == 0.0 {
            self.end_held(None);
            return false;
        }
        let element = if circular {
            let Some(arc) = self.programmed_arc(row, span, start, end, centre, shape) else {
                self.end_held(Some("an arc unknown offline follows"));
                return false;
            };
            in_plane(&arc, self.plane)
        } else {
            Element::Line { from: s2, to: e2 }
        };
        let Some(moved) = element.offset(offset) else {
            self.end_held(Some("an arc the tool does not fit inside follows"));
            self.unknown(row, span, format!("G41/G42: the tool's radius {} does not fit inside this arc (the control stops with an alarm): taken as programmed", offset.abs()));
            return false;
        };
        let approach = self.compensation.approaching && self.compensation.held.is_none();
        if approach && circular {
            self.unknown(row, span, "G41/G42 selected in an arc block (the control asks for G0 or G1): the approach is taken as a line".into());
        }
        let (from, lead) = match self.compensation.held.take() {
            Some(held) if held.approach => {
                let to = moved.from();
                self.finish_held(held, to);
                (to, None)
            }
            Some(held) => {
                let (circle, missing) = self.corner_rule();
                let joined =
                    contour::join(&held.moved, &moved, s2, offset, circle).and_then(|join| {
                        let forward = held.approach
                            || contour::runs_forward(&held.moved, held.from, join.end_before);
                        if forward {
                            Ok(join)
                        } else {
                            Err(contour::NoJoin::Bottleneck)
                        }
                    });
                match joined {
                    Ok(join) => {
                        if let (true, Some(missing)) = (join.outside, missing) {
                            self.note(missing.into());
                        }
                        self.finish_held(held, join.end_before);
                        (join.start_after, join.circle)
                    }
                    Err(contour::NoJoin::Bottleneck) => {
                        let (at, before) = (held.moved.to(), held.block.row + 1);
                        self.finish_held(held, at);
                        self.unknown(row, span, format!("G41/G42: the tool does not fit the inside corner with line {before} (the moved elements do not meet: a bottleneck the control refuses or, with CDON, cuts short): the run goes square from one to the other"));
                        (
                            moved.from(),
                            Some(Element::Line {
                                from: at,
                                to: moved.from(),
                            }),
                        )
                    }
                }
            }
            None if approach => (s2, None),
            // After an element ended square: on from where the tool stands.
            None => {
                let here = self.to_program(&self.mcs, false, tool);
                match (here[h], here[v]) {
                    (Some(x), Some(y)) => {
                        let here = Point::new(x, y);
                        (
                            moved.from(),
                            Some(Element::Line {
                                from: here,
                                to: moved.from(),
                            }),
                        )
                    }
                    _ => (moved.from(), None),
                }
            }
        };
        self.compensation.approaching = false;
        let applicate = [2, 1, 0][self.plane];
        self.compensation.held = Some(Held {
            block: self.move_of(row, span, exact_here, tool, end, targets),
            plane: self.plane,
            approach,
            moved: if approach { element } else { moved },
            from,
            lead,
            applicate_from: s[applicate],
            dummies: Vec::new(),
        });
        self.compensation.released = 0;
        self.programmed = end.to_vec();
        true
    }

    /// Whether an outside corner the contour turns by so many degrees gets
    /// a circle: under G450 unless flatter than MD20230, under G451 where
    /// MD20210 says it is too pointed for the meeting point (W1 Function
    /// Manual, "Tool radius compensation", the automatic switchovers); and
    /// what the run says where the datum is missing.
    fn corner_rule(&self) -> (impl Fn(f64) -> bool, Option<&'static str>) {
        let meet_outside = self.compensation.meet_outside;
        let (limit, missing) = if meet_outside {
            (self.setup.corner_limit, "MD20210 $MC_CUTCOM_CORNER_LIMIT is not in the machine's data: under G451 every outside corner gets the meeting point, however pointed")
        } else {
            (self.setup.curve_insert_limit, "MD20230 $MC_CUTCOM_CURVE_INSERT_LIMIT is not in the machine's data: under G450 every outside corner gets its circle, however flat")
        };
        let rule = move |turned| match limit {
            Some(limit) => turned >= limit,
            None => !meet_outside,
        };
        (rule, limit.is_none().then_some(missing))
    }

    /// The block's move as programmed, to run later.
    fn move_of(
        &self,
        row: usize,
        span: Span,
        exact_here: bool,
        tool: [f64; 3],
        end: &[Option<f64>],
        targets: &[Option<(Result<f64, String>, Coordinate)>],
    ) -> Move {
        Move {
            row,
            span,
            program: self.program.clone(),
            modes: self.modes,
            exact_here,
            tool,
            end: end.to_vec(),
            targeted: targets.iter().map(Option::is_some).collect(),
        }
    }

    /// Ends the held element square to its end (the retraction's start
    /// under G40); `why` says, on its block, why where it is not G40.
    pub(super) fn end_held(&mut self, why: Option<&str>) {
        let Some(held) = self.compensation.held.take() else {
            return;
        };
        if let Some(why) = why {
            let (program, row, span) =
                (held.block.program.clone(), held.block.row, held.block.span);
            let now = std::mem::replace(&mut self.program, program);
            self.unknown(
                row,
                span,
                format!(
                    "G41/G42: this element is taken to end square to its end, as before G40: {why}"
                ),
            );
            self.program = now;
        }
        let to = if held.approach {
            let offset = self.cutter_offset(held.block.row, held.block.span);
            held.moved.offset(offset).unwrap_or(held.moved).to()
        } else {
            held.moved.to()
        };
        self.finish_held(held, to);
    }

    /// The held element's move, the centre's path ending at `to`; then the
    /// blocks that waited for it are told.
    fn finish_held(&mut self, held: Held, to: Point) {
        let program = std::mem::replace(&mut self.program, held.block.program);
        let modes = std::mem::replace(&mut self.modes, held.block.modes);
        let plane = std::mem::replace(&mut self.plane, held.plane);
        let (row, span) = (held.block.row, held.block.span);
        let main = if held.approach {
            Element::Line {
                from: held.from,
                to,
            }
        } else {
            held.moved.between(held.from, to)
        };
        let pieces: Vec<Element> = held.lead.into_iter().chain([main]).collect();
        let total: f64 = pieces.iter().map(Element::length).sum();
        let (h, v) = plane_axes(plane);
        let applicate = [2, 1, 0][plane];
        let mut end = held.block.end;
        end[h] = Some(to.x);
        end[v] = Some(to.y);
        let applicate_to = end[applicate].unwrap_or(held.applicate_from);
        let rise = applicate_to - held.applicate_from;
        let start_mcs = self.mcs.clone();
        let end_mcs = self.reached(&end, held.block.tool, &held.block.targeted, [h, v]);
        let lift = |p: Point, z: f64| {
            let mut at = Vector3::zeros();
            at[h] = p.x;
            at[v] = p.y;
            at[applicate] = z;
            at
        };
        let mut points = vec![end_mcs.clone()];
        // A point of the path in the machine: its geometry axes through the
        // frames, the others at the block's end (they move on a line).
        let on_machine = |interpreter: &Self, p: Vector3<f64>| {
            let mut wcs = end.clone();
            wcs[..3].copy_from_slice(&[Some(p.x), Some(p.y), Some(p.z)]);
            let at = interpreter.to_machine(&wcs, false, held.block.tool);
            let mut point = end_mcs.clone();
            point[..3].copy_from_slice(&at[..3]);
            point
        };
        let mut along = 0.0;
        let mut lone_arc = None;
        for piece in &pieces {
            let share = |along: f64| {
                if total > 0.0 {
                    held.applicate_from + rise * along / total
                } else {
                    held.applicate_from
                }
            };
            let (z0, z1) = (share(along), share(along + piece.length()));
            along += piece.length();
            match *piece {
                Element::Line { from, to } => {
                    points.push(on_machine(self, lift(from, z0)));
                    points.push(on_machine(self, lift(to, z1)));
                }
                Element::Arc {
                    centre,
                    radius,
                    start,
                    sweep,
                } => {
                    let mut normal = Vector3::zeros();
                    normal[applicate] = sweep.signum();
                    let u = lift(Point::new(start.cos(), start.sin()) * radius, 0.0);
                    let arc = Arc {
                        centre: lift(centre, z0),
                        u,
                        v: normal.cross(&u),
                        normal,
                        sweep: sweep.abs(),
                        rise: (z1 - z0) * sweep.signum(),
                    };
                    let arc = self.arc_on_machine(row, span, &arc, false, held.block.tool);
                    points.push(on_machine(self, lift(piece.from(), z0)));
                    for k in 0..3 {
                        for p in arc.turning_points(k) {
                            let mut point = end_mcs.clone();
                            point[0] = Some(p.x);
                            point[1] = Some(p.y);
                            point[2] = Some(p.z);
                            points.push(point);
                        }
                    }
                    if pieces.len() == 1 {
                        lone_arc = Some(arc);
                    }
                }
            }
        }
        let path = (pieces.len() > 1).then_some(total.hypot(rise));
        self.traverse(
            row,
            span,
            &start_mcs,
            end_mcs,
            &points,
            lone_arc.as_ref(),
            path,
            held.block.exact_here,
        );
        self.release(
            held.dummies.first().map_or(usize::MAX, |d| d.waiting),
            lone_arc,
        );
        // The moves off the plane between: from where the element ends.
        let mut dummies = held.dummies.into_iter().peekable();
        while let Some(dummy) = dummies.next() {
            self.program = dummy.block.program;
            self.modes = dummy.block.modes;
            let mut end = dummy.block.end;
            end[h] = Some(to.x);
            end[v] = Some(to.y);
            let start_mcs = self.mcs.clone();
            let end_mcs = self.reached(&end, dummy.block.tool, &dummy.block.targeted, [h, v]);
            let points = [end_mcs.clone()];
            self.traverse(
                dummy.block.row,
                dummy.block.span,
                &start_mcs,
                end_mcs,
                &points,
                None,
                None,
                dummy.block.exact_here,
            );
            self.release(dummies.peek().map_or(usize::MAX, |d| d.waiting), None);
        }
        self.program = program;
        self.modes = modes;
        self.plane = plane;
    }

    /// The machine position of the programmed point `end`: the plane's
    /// axes `moved` and those the block programs go there, the other
    /// geometry axis too where the frames couple it (a rotation), the rest
    /// stay where they are (as `motion_block` takes them).
    fn reached(
        &self,
        end: &[Option<f64>],
        tool: [f64; 3],
        targeted: &[bool],
        moved: [usize; 2],
    ) -> Vec<Option<f64>> {
        let reached = self.to_machine(end, false, tool);
        let coupled = Frame {
            translation: Vec::new(),
            linear: self.frames_linear(false),
        }
        .couples();
        (0..reached.len())
            .map(|k| {
                if targeted[k] || moved.contains(&k) || (k < 3 && coupled) {
                    reached[k]
                } else {
                    self.mcs[k]
                }
            })
            .collect()
    }

    /// Tells the blocks that waited, up to the one at `until` among those
    /// that waited since the element was held; the first told moved along
    /// `arc`.
    fn release(&mut self, until: usize, arc: Option<Arc>) {
        let count = until
            .saturating_sub(self.compensation.released)
            .min(self.compensation.waiting.len());
        self.compensation.released += count;
        let blocks: Vec<Waiting> = self.compensation.waiting.drain(..count).collect();
        for (k, block) in blocks.into_iter().enumerate() {
            self.compensation.told.push(Told {
                program: block.program,
                line: block.line,
                mcs: self.mcs.clone(),
                t_s: self.report.time_s,
                arc: if k == 0 { arc.or(block.arc) } else { block.arc },
            });
        }
    }

    /// Whether a block leaves the held element's path as it is: it moves,
    /// sets the feed and the modes of the path, calls a subprogram, and
    /// changes none of frames, tool, plane or transformation.
    pub(super) fn keeps_contour(&self, content: &Content) -> bool {
        let keeps_word = |name: &str, value: &Result<f64, String>| match name {
            "G" => {
                matches!(value, Ok(g) if matches!(*g as u32, 0..=4 | 9 | 40..=42 | 60 | 64 | 90 | 91 | 93..=95 | 450 | 451 | 641..=645))
            }
            "M" => value != &Ok(6.0),
            "F" | "S" | "S1" | "N" | "I" | "J" | "K" | "CR" | "AR" | "TURN" | "OFFN" | "P" => true,
            name => self.setup.axis(name).is_some() || super::calls::is_numbered_call(name),
        };
        content.frame.is_none()
            && content
                .words
                .iter()
                .all(|word| keeps_word(&word.name, &word.value))
            && content
                .commands
                .iter()
                .chain(content.calls.iter().map(|(name, _)| name))
                .all(|name| {
                    matches!(
                        name.as_str(),
                        "MSG"
                            | "STOPRE"
                            | "BRISK"
                            | "SOFT"
                            | "CFC"
                            | "CFTCP"
                            | "CFIN"
                            | "FFWON"
                            | "FFWOF"
                            | "NORM"
                            | "KONT"
                            | "KONTC"
                            | "KONTT"
                    ) || super::DYNAMIC_GROUPS.contains(&name.as_str())
                        || !(name.starts_with("CYCLE")
                            || name.starts_with("TRA")
                            || crate::semantic::calls::is_predefined(name))
                })
    }

    /// The tool's radius with its wear and OFFN, to the left (G41,
    /// positive) or the right (G42); 0 without a cutting edge (D0).
    fn cutter_offset(&mut self, row: usize, span: Span) -> f64 {
        let Some(side) = self.compensation.side else {
            return 0.0;
        };
        let radius = match (self.tool, self.edge) {
            (Some(t), Some(d)) if d > 0 => match self.setup.tool(t, d) {
                Some(tool) if tool.kind.is_none_or(|k| (100.0..300.0).contains(&k)) => {
                    tool.radius.unwrap_or(0.0) + tool.radius_wear.unwrap_or(0.0)
                }
                Some(tool) => {
                    self.unknown(row, span, format!("G41/G42 with T{t} D{d}, tool type {} (not a milling or drilling tool): the cutting edge's position is not modelled, its radius taken as 0", tool.kind.unwrap_or(0.0)));
                    0.0
                }
                None => {
                    self.unknown(row, span, format!("G41/G42 with T{t} D{d}: the machine's data hold no offsets for it (`$TC_DP`): its radius taken as 0"));
                    0.0
                }
            },
            _ => 0.0,
        };
        side * (radius + self.compensation.extra)
    }
}

/// `arc` (programmed) in the plane's two coordinates, its sweep signed
/// counter-clockwise.
fn in_plane(arc: &Arc, plane: usize) -> Element {
    let (h, v) = plane_axes(plane);
    let applicate = [2, 1, 0][plane];
    Element::Arc {
        centre: Point::new(arc.centre[h], arc.centre[v]),
        radius: arc.u.norm(),
        start: arc.u[v].atan2(arc.u[h]),
        sweep: arc.sweep * arc.normal[applicate].signum(),
    }
}
