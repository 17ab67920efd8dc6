//! Whether the run has come back to a state it was in. The interpreter
//! is a function of its state: from the same state it runs the same blocks
//! the same way, so a program that comes back to one runs until it is
//! stopped (a run-in program's `GOTOB START`, a `LOOP` without an exit),
//! and what the run has found so far is all it will ever find: no block is
//! run from a state it was not already run from.
//!
//! The variables that only count (`_PASS=_PASS+1`, see [`counters`]) are
//! left out of the state: nothing reads them but themselves, so a program
//! that counts its passes comes back all the same.
//!
//! The states are compared where the run jumps back (the only way to come
//! back), with Brent's cycle finding: the state is kept at the 1st, 2nd,
//! 4th, 8th ... jump back and each jump back compares with the one kept,
//! so a repetition is found within two of its passes, however long the
//! lead-in, with as many copies of the state as doublings.

use std::collections::{HashMap, HashSet};

use nalgebra::Matrix3;

use super::counters::counters;
use super::polar::Polar;
use super::swivel::Swivelled;
use super::traori::{Transformed, Turning};
use super::{calls, Arguments, Interpreter, ModalCall, Modes, Return};
use crate::run::frame::Frame;
use crate::run::Endless;
use crate::semantic::value::Value;

/// Watches the jumps back of one run.
pub(super) struct Watch {
    /// The variables that only count, found at the first jump back (a
    /// program without one is never read for them).
    counters: Option<HashSet<String>>,
    kept: Option<Kept>,
    /// Jumps back since the state was kept, and how many before the next
    /// is kept.
    since: u64,
    next_keep: u64,
}

impl Default for Watch {
    fn default() -> Self {
        Self {
            counters: None,
            kept: None,
            since: 0,
            next_keep: 1,
        }
    }
}

/// A state kept, and where the run stood when it was.
struct Kept {
    state: State,
    blocks: u64,
    time_s: f64,
    guesses: u64,
    /// The counters' values at the running level.
    counted: HashMap<String, Value>,
}

impl Watch {
    /// The run jumps back from line `from` of the program running to
    /// `row`, the row it runs next: `Some` where it was in this very state
    /// before.
    pub(super) fn jumped_back(
        &mut self,
        machine: &Interpreter,
        from: usize,
        row: usize,
    ) -> Option<Endless> {
        let counters = self
            .counters
            .get_or_insert_with(|| counters(machine.programs));
        if let Some(kept) = &self.kept {
            if kept.state.may_be(machine, row, counters)
                && State::of(machine, row, counters).is_some_and(|now| now.is(&kept.state))
            {
                let mut counting: Vec<String> = counted(machine, counters)
                    .into_iter()
                    .filter(|(name, value)| kept.counted.get(name) != Some(value))
                    .map(|(name, _)| name)
                    .collect();
                counting.sort_unstable();
                return Some(Endless {
                    program: machine.program.clone(),
                    line: row + 1,
                    from_line: from + 1,
                    pass_blocks: machine.report.blocks - kept.blocks,
                    pass_s: machine.report.time_s - kept.time_s,
                    rests_on_unknown: machine.guesses > kept.guesses || machine.synchronized,
                    counting,
                });
            }
        }
        self.since += 1;
        if self.since >= self.next_keep {
            // Where the state cannot be kept (an element held back under
            // radius compensation), the next jump back tries again.
            if let Some(state) = State::of(machine, row, counters) {
                self.kept = Some(Kept {
                    state,
                    blocks: machine.report.blocks,
                    time_s: machine.report.time_s,
                    guesses: machine.guesses,
                    counted: counted(machine, counters),
                });
                self.since = 0;
                self.next_keep = self.next_keep.saturating_mul(2);
            }
        }
        None
    }
}

/// The values of the `counters` at the running level.
fn counted(machine: &Interpreter, counters: &HashSet<String>) -> HashMap<String, Value> {
    let locals = &machine.variables.local;
    (locals.iter())
        .filter(|(name, _)| counters.contains(*name))
        .map(|(name, value)| (name.clone(), value.clone()))
        .collect()
}

/// The `variables` but the counters, in the order of their names.
fn uncounted(
    variables: &HashMap<String, Value>,
    counters: &HashSet<String>,
) -> Vec<(String, Value)> {
    let mut kept: Vec<(String, Value)> = (variables.iter())
        .filter(|(name, _)| !counters.contains(*name))
        .map(|(name, value)| (name.clone(), value.clone()))
        .collect();
    kept.sort_unstable_by(|a, b| a.0.cmp(&b.0));
    kept
}

fn sorted<T: Ord + Copy>(items: impl Iterator<Item = T>) -> Vec<T> {
    let mut items: Vec<T> = items.collect();
    items.sort_unstable();
    items
}

/// Everything of the interpreter that a later block reads, but the
/// counters: what decides which blocks run next and what they do. What is
/// only told (the report, the travel, the violations, the times) is not in
/// it. Maps are held in the order of their keys, so that equal states
/// print alike ([`State::is`]).
#[derive(Clone, Debug, PartialEq)]
struct State {
    row: usize,
    program: Option<String>,
    /// The running program's model, by address (its name says the same;
    /// the address holds it whatever the names).
    model: usize,
    stack: Vec<Level>,
    modal_call: Option<ModalCall>,
    polar: Polar,
    locals: Vec<(String, Value)>,
    channel: Vec<(&'static str, f64)>,
    in_for: Vec<usize>,
    synchronized: bool,
    mcs: Vec<Option<f64>>,
    programmed: Vec<Option<f64>>,
    last_linear: Matrix3<f64>,
    modes: Modes,
    incremental: bool,
    plane: usize,
    length_scale: f64,
    settable: Frame,
    programmable: Frame,
    swivelled: Option<Swivelled>,
    transformed: Option<Transformed>,
    compensation: (Option<f64>, bool, bool, f64),
    turning: Turning,
    by_vector: bool,
    preselected: Option<u32>,
    tool: Option<u32>,
    edge: Option<u32>,
    /// The axes beyond a limit at the last block's end, sorted: a block
    /// that stays beyond continues their violation rather than begins one.
    beyond: Vec<(usize, bool)>,
}

/// A program level a subprogram returns to, as [`Return`] holds it.
#[derive(Clone, Debug, PartialEq)]
struct Level {
    model: usize,
    program: Option<String>,
    row: usize,
    locals: Vec<(String, Value)>,
    in_for: Vec<usize>,
    again: u32,
    arguments: Arguments,
    section: Option<(usize, usize)>,
    saved: Option<calls::Saved>,
}

impl State {
    /// The same state: equal (a NaN never equals itself, and a state holding
    /// one is never taken for a repetition) and printed alike (-0 is not 0:
    /// `ATAN2(-0, -1)` is not `ATAN2(0, -1)`; the printed number is exact).
    fn is(&self, other: &State) -> bool {
        self == other && format!("{self:?}") == format!("{other:?}")
    }

    /// The state of `machine` about to run `row`; `None` while tool radius
    /// compensation holds an element back (blocks run and not yet told).
    fn of(machine: &Interpreter, row: usize, counters: &HashSet<String>) -> Option<State> {
        // Every field is named, so that a field added to the interpreter is
        // a compile error here until it is said whether it decides what
        // comes next.
        let Interpreter {
            // The programs, the data and the options the run was given.
            programs: _,
            source: _,
            setup: _,
            options: _,
            // The running program's control blocks, of its model.
            openers: _,
            model,
            stack,
            program,
            calling,
            modal_call,
            polar,
            // The arc of the block just run, taken once told.
            last_arc: _,
            variables,
            in_for,
            mcs,
            programmed,
            last_linear,
            modes,
            incremental,
            plane,
            length_scale,
            settable,
            programmable,
            swivelled,
            transformed,
            compensation,
            turning,
            by_vector,
            preselected,
            tool,
            edge,
            // The tool offset last looked up in the data: of `tool`,
            // `edge` and `plane`.
            tool_offset: _,
            // What is told, and the counts behind it.
            report: _,
            told: _,
            minimum: _,
            maximum: _,
            violations: _,
            began: _,
            tool_times: _,
            upper_complete: _,
            guesses: _,
            synchronized,
            beyond,
            // A buffer, empty between blocks.
            words: _,
        } = machine;
        if calling.is_some() {
            return None;
        }
        let beyond = sorted(beyond.keys().copied());
        let mut channel: Vec<(&'static str, f64)> = (variables.channel.iter())
            .map(|(&name, &value)| (name, value))
            .collect();
        channel.sort_unstable_by(|a, b| a.0.cmp(b.0));
        Some(State {
            row,
            program: program.clone(),
            model: address(model),
            stack: stack
                .iter()
                .map(|level| Level::of(level, counters))
                .collect(),
            modal_call: modal_call.clone(),
            polar: polar.clone(),
            locals: uncounted(&variables.local, counters),
            channel,
            in_for: sorted(in_for.iter().copied()),
            synchronized: *synchronized,
            mcs: mcs.clone(),
            programmed: programmed.clone(),
            last_linear: *last_linear,
            modes: *modes,
            incremental: *incremental,
            plane: *plane,
            length_scale: *length_scale,
            settable: settable.clone(),
            programmable: programmable.clone(),
            swivelled: swivelled.clone(),
            transformed: transformed.clone(),
            compensation: compensation.settled()?,
            turning: *turning,
            by_vector: *by_vector,
            preselected: *preselected,
            tool: *tool,
            edge: *edge,
            beyond,
        })
    }

    /// A test of a few fields in place, without a copy: `false` where the
    /// state of `machine` at `row` is surely another (a counter that counts
    /// on, an axis that moves on).
    fn may_be(&self, machine: &Interpreter, row: usize, counters: &HashSet<String>) -> bool {
        let uncounted =
            || (machine.variables.local.iter()).filter(|(name, _)| !counters.contains(*name));
        self.row == row
            && self.program == machine.program
            && self.mcs == machine.mcs
            && self.locals.len() == uncounted().count()
            && uncounted().all(|(name, value)| {
                let at = self
                    .locals
                    .binary_search_by(|(kept, _)| kept.as_str().cmp(name));
                at.is_ok_and(|at| self.locals[at].1 == *value)
            })
    }
}

impl Level {
    fn of(level: &Return, counters: &HashSet<String>) -> Level {
        let Return {
            model,
            program,
            row,
            locals,
            // Of the model.
            openers: _,
            in_for,
            again,
            arguments,
            section,
            saved,
        } = level;
        Level {
            model: address(model),
            program: program.clone(),
            row: *row,
            locals: uncounted(locals, counters),
            in_for: sorted(in_for.iter().copied()),
            again: *again,
            arguments: arguments.clone(),
            section: *section,
            saved: saved.clone(),
        }
    }
}

/// A model by its address: the same program is the same model.
fn address<T>(model: &&T) -> usize {
    std::ptr::from_ref::<T>(*model) as usize
}
