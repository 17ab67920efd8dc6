//! Subprograms: into one with its arguments, back to the caller, again
//! while its `P` asks; sections of a program repeated (REPEAT); what every
//! program level shares.

use std::collections::{HashMap, HashSet};

use super::{openers, Arguments, Calling, Flow, Interpreter, Modes, Return, MOST_LEVELS};
use crate::run::frame::Frame;
use crate::semantic::eval::{evaluate, key};
use crate::semantic::jumps::Target;
use crate::semantic::model::Model;
use crate::semantic::value::Value;
use crate::semantic::vocabulary::is_r_parameter;
use crate::span::Span;
use crate::syntax::tree::{upper, Expr, GotoKind, LineKind, Name, StatementKind, TypeKind};

impl Interpreter<'_, '_> {
    /// Into the subprogram `call` names, from the block on `row`: where
    /// the run goes on (`next` where it is not followed), `None` where the
    /// control stops.
    pub(super) fn enter(&mut self, row: usize, call: Calling, next: usize) -> Option<usize> {
        let span = self.model.lines.raw(row).content;
        let Some(callee) = self.programs.subprograms.get(&call.name) else {
            self.unknown(row, span, format!("`{}` is not followed: no subprogram of that name beside the program or in the cycle directories (--cycles); what it moves, and its time, are not in the run", call.name));
            return Some(next);
        };
        // Going on past the alarm would run each level's calls again, a
        // number of blocks growing with every level (a subprogram calling
        // itself three times: 43 million blocks before the block limit).
        if self.stack.len() + 1 >= MOST_LEVELS {
            self.unknown(row, span, format!("`{}` would nest deeper than {MOST_LEVELS} program levels: the control stops with an alarm (14000s); the run ends here", call.name));
            return None;
        }
        let mut caller = Return {
            model: self.model,
            program: self.program.replace(call.name.clone()),
            row: next,
            locals: std::mem::take(&mut self.variables.local),
            openers: std::mem::replace(&mut self.openers, openers(callee)),
            in_for: std::mem::take(&mut self.in_for),
            again: call.times.saturating_sub(1),
            arguments: call.arguments,
            section: None,
            saved: None,
        };
        // What SAVE restores, as the caller has it now.
        let saved = Saved {
            modes: self.modes,
            plane: self.plane,
            incremental: self.incremental,
            length_scale: self.length_scale,
            programmable: self.programmable.clone(),
            compensation: self.compensation.modes(),
        };
        self.model = callee;
        self.source = callee.source;
        self.variables.local = globals(&caller.locals, caller.model);
        if self.bind(&caller.arguments) {
            caller.saved = Some(saved);
        }
        self.stack.push(caller);
        Some(0)
    }

    /// The PROC line's parameters of the program now running, given
    /// `arguments` by position: one the call leaves out is 0 where it is a
    /// number (INT, REAL, BOOL) passed by value; one unknown offline, or
    /// of another kind left out, stays unknown.
    /// Whether the PROC line says SAVE.
    pub(super) fn bind(&mut self, arguments: &Arguments) -> bool {
        let source = self.source;
        let Some((parameters, saves)) =
            self.model
                .lines
                .other_lines()
                .take(50)
                .find_map(|(_, line)| {
                    let LineKind::Block(block) = &line.kind else {
                        return None;
                    };
                    block.statements.iter().find_map(|s| match &s.kind {
                        StatementKind::Proc(proc) => Some((
                            proc.parameters
                                .iter()
                                .map(|p| {
                                    let number = !p.by_reference
                                        && matches!(
                                            p.data_type.kind,
                                            TypeKind::Int | TypeKind::Real | TypeKind::Bool
                                        )
                                        && p.declarator.dimensions.is_empty();
                                    (p.declarator.name.upper(source), number, p.by_reference)
                                })
                                .collect::<Vec<_>>(),
                            proc.attributes.iter().any(|a| a.is(source, "SAVE")),
                        )),
                        _ => None,
                    })
                })
        else {
            return false;
        };
        for (k, (name, number, by_reference)) in parameters.into_iter().enumerate() {
            if by_reference {
                self.guesses += 1;
                self.note(format!("the VAR parameter `{name}` of `{}`: what the subprogram writes to it is not given back to the caller offline", self.program.as_deref().unwrap_or("")));
            }
            let omitted = arguments.omitted.get(k).copied().unwrap_or(true);
            // `$P_SUBPAR[n]`: whether the call gives parameter n.
            self.variables.local.insert(
                key("$P_SUBPAR", &[(k + 1).to_string()]),
                Value::Number(if omitted { 0.0 } else { 1.0 }),
            );
            let value = match arguments.values.get(k).cloned().flatten() {
                Some(value) => value,
                None if omitted && number => Value::Number(0.0),
                None => continue,
            };
            self.variables.local.insert(key(&name, &[]), value);
        }
        saves
    }

    /// Back from a subprogram at its end (M17, RET, M2, M30 or its last
    /// line), or into it again while its `P` asks: where the caller goes on;
    /// `None` at the main program's end. R parameters, GUD and system
    /// variables are the channel's: what the subprogram wrote, the caller
    /// reads.
    pub(super) fn give_back(&mut self) -> Option<usize> {
        // A program that ends inside a section it repeats ends the repetition.
        while self.stack.last().is_some_and(|r| r.section.is_some()) {
            self.stack.pop();
        }
        let mut caller = self.stack.pop()?;
        let written = std::mem::take(&mut self.variables.local);
        if caller.again > 0 {
            caller.again -= 1;
            self.variables.local = globals(&written, self.model);
            self.in_for.clear();
            let arguments = std::mem::take(&mut caller.arguments);
            if let Some(saved) = caller.saved.clone() {
                self.restore(saved);
            }
            self.bind(&arguments);
            caller.arguments = arguments;
            self.stack.push(caller);
            return Some(0);
        }
        self.variables.local = caller.locals;
        self.variables.local.extend(globals(&written, self.model));
        if let Some(saved) = caller.saved {
            self.restore(saved);
        }
        self.model = caller.model;
        self.program = caller.program;
        self.source = caller.model.source;
        self.openers = caller.openers;
        self.in_for = caller.in_for;
        Some(caller.row)
    }
}

/// What a subprogram with SAVE gives back to its caller on its return
/// (Programming Manual, "Subprogram with SAVE mechanism"): the modal G
/// functions and the programmable frame as they were at the call. The
/// feed and the spindle speed are no G functions and stay.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Saved {
    modes: Modes,
    plane: usize,
    incremental: bool,
    length_scale: f64,
    programmable: Frame,
    compensation: (Option<f64>, bool, f64),
}

impl Interpreter<'_, '_> {
    fn restore(&mut self, saved: Saved) {
        // The element held back ends under the subprogram's frames.
        self.end_held(None);
        self.compensation.set_modes(saved.compensation);
        let (feed, spindle) = (self.modes.feed, self.modes.spindle);
        self.modes = saved.modes;
        self.modes.feed = feed;
        self.modes.spindle = spindle;
        self.plane = saved.plane;
        self.incremental = saved.incremental;
        self.length_scale = saved.length_scale;
        self.programmable = saved.programmable;
        self.note("a subprogram with SAVE gives back the caller's G functions and programmable frame; whether it also gives back the settable frame is MD10617 $MN_FRAME_SAVE_MASK's, which the run does not read: it keeps the subprogram's".into());
    }
}

impl Interpreter<'_, '_> {
    /// `REPEAT LABEL P=n` (from the label to the REPEAT, or to an
    /// `ENDLABEL:` between them), `REPEAT START END P=n` (from one label to
    /// the other), `REPEATB LABEL P=n` (the labelled block): the section
    /// run `n` times more (once without `P`), then on after the REPEAT
    /// (Siemens, Job Planning, "Program section repetition").
    pub(super) fn repeat(
        &mut self,
        row: usize,
        span: Span,
        targets: &[Name],
        count: Option<&Expr>,
    ) -> Flow {
        let source = self.source;
        let times = match count.map(|c| evaluate(source, c, &self.variables)) {
            None => 1,
            Some(Ok(Value::Number(n))) if n >= 1.0 && n.fract() == 0.0 => n as u32,
            Some(_) => {
                self.unknown(row, span, "REPEAT's count (P) is unknown offline or no whole number from 1: the section is repeated once".into());
                1
            }
        };
        let label = |name: &Name| Target::Label(name.upper(source));
        let single = upper(span.of(source)).starts_with("REPEATB");
        let model = self.model;
        let section = match targets {
            [block] if single => model
                .target_landing(&label(block), GotoKind::Both, row)
                .map(|at| (at, at)),
            [start] => model
                .target_landing(&label(start), GotoKind::Backward, row)
                .map(|at| {
                    let end = model
                        .target_rows(&Target::Label("ENDLABEL".into()))
                        .into_iter()
                        .find(|&r| r > at && r < row);
                    (at, end.unwrap_or(row.saturating_sub(1)))
                }),
            [start, end] => model
                .target_landing(&label(start), GotoKind::Both, row)
                .and_then(|at| {
                    Some((
                        at,
                        model.target_landing(&label(end), GotoKind::Forward, at)?,
                    ))
                }),
            _ => None,
        };
        let Some((start, end)) = section.filter(|(start, end)| start <= end) else {
            self.unknown(row, span, "REPEAT's label is not found where the control searches it: the control stops with an alarm here".into());
            return Flow::Stop;
        };
        if self.stack.len() + 1 >= MOST_LEVELS {
            self.unknown(
                row,
                span,
                format!("REPEAT would nest deeper than {MOST_LEVELS} program levels (each repetition takes one): the control stops with an alarm; the run ends here"),
            );
            return Flow::Stop;
        }
        self.stack.push(Return {
            model,
            program: self.program.clone(),
            row: row + 1,
            locals: HashMap::new(),
            openers: HashMap::new(),
            in_for: HashSet::new(),
            again: times - 1,
            arguments: Arguments::default(),
            section: Some((start, end)),
            saved: None,
        });
        Flow::To(start)
    }

    /// At the last block of the section on top: again from its start, or
    /// back after its REPEAT.
    pub(super) fn end_section(&mut self) -> usize {
        let top = self.stack.last_mut().expect("a section");
        let (start, _) = top.section.expect("a section");
        if top.again > 0 {
            top.again -= 1;
            return start;
        }
        let row = top.row;
        self.stack.pop();
        row
    }
}

/// The variables every program level shares, of those `model`'s level
/// holds: all but the level's own (defined by its DEF or its PROC line) and
/// `$P_SUBPAR` (of its call): the R parameters, GUD variables, system
/// variables.
fn globals(variables: &HashMap<String, Value>, model: &Model) -> HashMap<String, Value> {
    let own: HashSet<&str> = (model.symbols.iter())
        .filter(|symbol| !symbol.global)
        .map(|symbol| symbol.name.as_str())
        .collect();
    variables
        .iter()
        .filter(|(key, _)| {
            let name = key.split('[').next().unwrap_or(key);
            is_r_parameter(key.as_bytes()) || !(own.contains(name) || name == "$P_SUBPAR")
        })
        .map(|(key, value)| (key.clone(), value.clone()))
        .collect()
}

/// `L105`: a subprogram called by its number (the digits as written:
/// `L0105` is another).
pub(super) fn is_numbered_call(name: &str) -> bool {
    name.len() > 1 && name.starts_with('L') && name[1..].bytes().all(|b| b.is_ascii_digit())
}
