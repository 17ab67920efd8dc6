//! The swivels of a program on its machine: each CYCLE800 whose arguments
//! are constants, and each CYCLE600 evaluated offline (the CYCLE800 its
//! rewrite writes), solved on the swivel data record it names. What the
//! control would find out at run time (an orientation out of reach, the
//! `_DIR` solution beyond the limits, a Hirth grid far from the angle, a
//! record it does not hold) is found here, before the program runs.

use crate::diagnostic::Diagnostic;
use crate::kinematics::{
    solve, split, Direction, Kinematics, Preference, Record, RecordError, Request, Solution, Split,
    SplitError, Swivel, TableAsk,
};
use crate::registry::{
    hirth_rounding, swivel_direction_outside_limits, swivel_unreachable, undefined_swivel_record,
};
use crate::rotation::{matrix, Kind, Sequence};
use crate::semantic::cycle800::Arguments;
use crate::semantic::machine::Machine;
use crate::semantic::value::Value;
use crate::semantic::walk::CallSite;
use crate::span::Span;
use crate::syntax::tree::{Call, LineKind, StatementKind};
use nalgebra::Rotation3;

/// The machine `check` solves the swivels on.
#[derive(Debug)]
pub struct OnMachine {
    /// The file it was read from, for messages.
    pub name: String,
    /// What was read (the file, or an archive's data members joined): the
    /// machine's findings point into it.
    pub source: Vec<u8>,
    /// The files or archive members `source` joins, where a finding is
    /// told ([`crate::archive::Part::split`]).
    pub parts: Vec<crate::archive::Part>,
    pub machine: Machine,
    /// The machine data, tool offsets and frame components the file holds,
    /// by the key a program reads each with ([`crate::machine::keyed`]).
    pub values: Vec<(String, crate::semantic::value::Value)>,
    /// The orientation error (degrees) Hirth rounding may make unreported.
    pub hirth_tolerance_deg: f64,
    /// The record of a rotary table under the machine's heads (`--table`,
    /// `table` in sinuprep.toml): a swivel on a head record (`T`, two
    /// axes) is split over the table and the head, three rotary axes.
    /// Checked when the machine is read: a `P` record of one axis.
    pub table: Option<String>,
}

impl OnMachine {
    /// `diagnostics` (spans into [`Self::source`]) by the file or member
    /// they were found in: its name, its text, and them pointing into it.
    pub fn by_file<'a>(
        &'a self,
        diagnostics: &[Diagnostic],
    ) -> Vec<(&'a str, &'a [u8], Vec<Diagnostic>)> {
        crate::archive::Part::split(&self.parts, diagnostics)
            .into_iter()
            .map(|(i, found)| {
                let part = &self.parts[i];
                (part.name.as_str(), &self.source[part.range.clone()], found)
            })
            .collect()
    }

    /// The table under `head`, when one is named and `head` is a head
    /// (kinematics `T`, two rotary axes) other than the table's record.
    pub fn table_under(&self, head: &Record) -> Option<&Record> {
        let table = self.machine.record(self.table.as_deref()?)?;
        let is_head = head.kinematics == Kinematics::Head && head.axis_count() == 2;
        (is_head && table.number != head.number).then_some(table)
    }
}

/// The default of `hirth-tolerance`: a hundredth of a degree tilts the
/// tool by 0.17 mm a metre out, about what a probe resolves.
pub const HIRTH_TOLERANCE_DEG: f64 = 0.01;

/// One swivel asked for: the record by the name the call gives, where the
/// frame is to turn, which solution.
#[derive(Clone, Debug)]
pub struct Asked {
    /// The call, where findings point.
    pub span: Span,
    pub record: String,
    pub rotation: Rotation3<f64>,
    pub direction: Direction,
    /// The axis order the call's CYCLE800 gives its angles in (its
    /// `_MODE`; a CYCLE600's output as an intrinsic order).
    pub sequence: Sequence,
}

/// The swivel of a CYCLE600 call evaluated offline: its target rotation as
/// a new plane (an additive call turns from a frame only the control
/// knows, and a results-only call does not turn).
pub fn of_cycle600(site: &CallSite) -> Option<Asked> {
    let evaluation = site.evaluation.as_ref()?;
    let p = &evaluation.parameters;
    if p.recalculate_only || evaluation.additive_on_control {
        return None;
    }
    let sequence = match p.output.kind {
        Kind::Intrinsic => p.output,
        Kind::Extrinsic => p.output.reversed(),
    };
    Some(Asked {
        span: site.statement,
        record: p.head.clone(),
        rotation: evaluation.target,
        direction: if p.inverse {
            Direction::Plus
        } else {
            Direction::Minus
        },
        sequence,
    })
}

/// The swivel of a CYCLE800 call whose arguments are constants: a new
/// plane (`_ST` ending in 0) axis by axis (`_MODE` below 64) to one side
/// (`_DIR` -1 or 1). Other calls are the control's to work out.
pub fn of_cycle800(source: &[u8], call: &Call) -> Option<Asked> {
    let arguments = Arguments::of(source, call);
    let number = |index: usize| arguments.number(index);
    let record = match arguments.value(1)? {
        Value::Text(name) if !name.trim().is_empty() => name,
        _ => return None,
    };
    let new_plane = number(2)?.rem_euclid(10.0) == 0.0;
    let mode = number(3)?;
    if !new_plane || mode.fract() != 0.0 || !(0.0..64.0).contains(&mode) {
        return None;
    }
    let sequence = Sequence::from_code(mode as i64, Kind::Intrinsic).ok()?;
    let direction = match number(13)? {
        -1.0 => Direction::Minus,
        1.0 => Direction::Plus,
        _ => return None,
    };
    let angles = [number(7)?, number(8)?, number(9)?];
    Some(Asked {
        span: call.name.span.to(call.arguments.span),
        record,
        rotation: matrix(sequence, angles),
        direction,
        sequence,
    })
}

/// `value` with at most `places` decimals, no trailing zeros.
fn decimals(value: f64, places: usize) -> String {
    let text = format!("{value:.places$}");
    let text = if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        &text
    };
    match text {
        "-0" => "0".to_string(),
        text => text.to_string(),
    }
}

/// The CYCLE800 calls of a program with constant arguments, in order.
pub fn cycle800_calls(model: &crate::semantic::Model) -> Vec<Asked> {
    let source = model.source;
    let mut out = Vec::new();
    // The lines are parsed again where the pass kept no trees: only for a
    // program that calls CYCLE800 at all.
    if !crate::semantic::mentions_cycle(source, b"800") {
        return out;
    }
    for (_, line) in model.lines.other_lines() {
        let LineKind::Block(block) = &line.kind else {
            continue;
        };
        for statement in &block.statements {
            if let StatementKind::Call(call) = &statement.kind {
                if call.name.is(source, "CYCLE800") {
                    out.extend(of_cycle800(source, call));
                }
            }
        }
    }
    out
}

/// Why a swivel asked of the machine has no answer.
pub enum Unsolved<'m> {
    /// The machine has no record of that name.
    NoRecord,
    /// The record's data cannot describe a machine (K001's, where the
    /// machine file is checked).
    Unusable(&'m Record, RecordError),
}

/// `asked` solved on the record of `machine` it names, its axes standing
/// at their specified angles (`$TC_CARR13/14`) before the swivel.
pub fn solve_on<'m>(
    asked: &Asked,
    machine: &'m Machine,
) -> Result<(&'m Record, Swivel), Unsolved<'m>> {
    let record = machine.record(&asked.record).ok_or(Unsolved::NoRecord)?;
    let request = Request {
        rotation: asked.rotation,
        direction: asked.direction,
        current: record.specified(),
    };
    solve(record, &request)
        .map(|swivel| (record, swivel))
        .map_err(|error| Unsolved::Unusable(record, error))
}

/// A swivel split over the table under its head record and the head.
pub struct OverTable<'m> {
    pub table: &'m Record,
    pub head: &'m Record,
    /// The split, or why the records cannot make one.
    pub split: Result<Split, SplitError>,
}

/// `asked` split over the table under the head record it names, as `axes
/// --table` splits it by default: the table's angle chosen with the head
/// nearest the middles of its limits, the axes standing at their specified
/// angles (`$TC_CARR13/14`) before; `None` where no table lies under it.
pub fn split_on<'m>(asked: &Asked, on: &'m OnMachine) -> Option<OverTable<'m>> {
    let head = on.machine.record(&asked.record)?;
    let table = on.table_under(head)?;
    let request = Request {
        rotation: asked.rotation,
        direction: asked.direction,
        current: head.specified(),
    };
    let ask = TableAsk {
        current: table.axes[0].angle,
        fixed: None,
        prefer: Preference::Middle,
    };
    Some(OverTable {
        table,
        head,
        split: split(table, head, &request, &ask),
    })
}

/// What the control would report of `asked` on `on`, as findings.
pub fn findings(asked: &Asked, on: &OnMachine) -> Vec<Diagnostic> {
    match solve_on(asked, &on.machine) {
        Ok((record, swivel)) => judge(asked, record, &swivel, on.hirth_tolerance_deg),
        Err(Unsolved::Unusable(..)) => Vec::new(),
        Err(Unsolved::NoRecord) => {
            let known: Vec<&str> = on.machine.usable().map(|r| r.name.as_str()).collect();
            vec![undefined_swivel_record::RULE
                .at(asked.span)
                .message(format!(
                    "{} defines no swivel data record `{}`: the control stops with an alarm",
                    on.name, asked.record
                ))
                .label("no such record")
                .help(if known.is_empty() {
                    "the machine file holds no usable record".to_string()
                } else {
                    format!("its records are {}", known.join(", "))
                })]
        }
    }
}

/// A solution's positions for people: `C=-180 A=-20`.
fn positions(record: &Record, solution: &Solution) -> String {
    (0..record.axis_count())
        .map(|i| {
            let value = decimals(solution.positions[i], 3);
            format!("{}={value}", record.axes[i].label(i))
        })
        .collect::<Vec<_>>()
        .join(" ")
}

/// Where `asked` takes the machine's axes, in a few words for a comment
/// beside the code: the positions, or why there are none.
pub fn taken(asked: &Asked, on: &OnMachine) -> String {
    let name = |record: &Record| {
        if record.name.is_empty() {
            format!("record {}", record.number)
        } else {
            record.name.clone()
        }
    };
    if let Some(OverTable {
        table,
        head,
        split: Ok(split),
    }) = split_on(asked, on)
    {
        let at = format!("{}={}", table.axes[0].label(0), decimals(split.table, 3));
        return match split.head.chosen {
            Some(index) => format!(
                "with the table {} under {} the axes go to {at} {}",
                name(table),
                name(head),
                positions(head, &split.head.solutions[index])
            ),
            None if split.head.solutions.is_empty() => format!(
                "{} cannot reach this orientation at any position of the table {}",
                name(head),
                name(table)
            ),
            None => format!(
                "with the table {} at {at}, {} reaches this orientation only outside its axis limits",
                name(table),
                name(head)
            ),
        };
    }
    match solve_on(asked, &on.machine) {
        Err(Unsolved::NoRecord) => format!("{} defines no record `{}`", on.name, asked.record),
        Err(Unsolved::Unusable(record, error)) => {
            format!("`{}` cannot be used: {error}", name(record))
        }
        Ok((record, swivel)) => match swivel.chosen {
            Some(index) => format!(
                "on {} the axes go to {}",
                name(record),
                positions(record, &swivel.solutions[index])
            ),
            None if swivel.solutions.is_empty() => {
                format!("{} cannot reach this orientation", name(record))
            }
            None => format!(
                "{} reaches this orientation only outside its axis limits",
                name(record)
            ),
        },
    }
}

fn judge(asked: &Asked, record: &Record, swivel: &Swivel, tolerance: f64) -> Vec<Diagnostic> {
    let name = &record.name;
    let positions = |index: usize| positions(record, &swivel.solutions[index]);
    let Some(chosen) = swivel.chosen else {
        let (message, label) = if swivel.solutions.is_empty() {
            (
                format!("record `{name}` cannot reach this orientation: no position of its rotary axes turns the tool there"),
                "out of reach",
            )
        } else {
            let all: Vec<String> = (0..swivel.solutions.len()).map(positions).collect();
            (
                format!(
                    "record `{name}` reaches this orientation only outside its axis limits ({}): the control stops with an alarm",
                    all.join("; ")
                ),
                "outside the axis limits",
            )
        };
        return vec![swivel_unreachable::RULE
            .at(asked.span)
            .message(message)
            .label(label)
            .help("swivel to an orientation the head or table can take, or use another record")];
    };
    let mut out = Vec::new();
    if let Some(preferred) = swivel.preferred.filter(|&p| p != chosen) {
        out.push(
            swivel_direction_outside_limits::RULE
                .at(asked.span)
                .message(format!(
                    "the solution `_DIR` asks for ({}) lies outside the axis limits of `{name}`: the control takes the other one ({})",
                    positions(preferred),
                    positions(chosen)
                ))
                .label("the other solution is taken")
                .help("give `_DIR` the other sign if that solution is the one meant, so that the program says what the machine does"),
        );
    }
    let error = swivel.solutions[chosen].hirth_error_deg;
    if error > tolerance {
        out.push(
            hirth_rounding::RULE
                .at(asked.span)
                .message(format!(
                    "the Hirth grid of `{name}` turns this swivel to {}: the tool direction is off by {}°",
                    positions(chosen),
                    decimals(error, 4)
                ))
                .label(format!("{}° from the orientation asked", decimals(error, 4)))
                .help("swivel to an orientation on the grid, or raise `hirth-tolerance` in sinuprep.toml if the error is acceptable"),
        );
    }
    out
}
