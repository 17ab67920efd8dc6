//! Subprograms: into one with its arguments, back to the caller, again
//! while its `P` asks; what every program level shares.

use std::collections::HashMap;

use super::{openers, Calling, Interpreter, Return, MOST_LEVELS};
use crate::semantic::eval::key;
use crate::semantic::value::Value;
use crate::syntax::tree::{LineKind, StatementKind};

impl Interpreter<'_, '_> {
    /// Into the subprogram `call` names, from the block on `row`: where
    /// the run goes on (`next` where it is not followed).
    pub(super) fn enter(&mut self, row: usize, call: Calling, next: usize) -> usize {
        let span = self.model.lines.raw(row).content;
        let Some(callee) = self.programs.subprograms.get(&call.name) else {
            self.unknown(row, span, format!("`{}` is not followed: no subprogram of that name beside the program or in the cycle directories (--cycles); what it moves, and its time, are not in the run", call.name));
            return next;
        };
        if self.stack.len() + 1 >= MOST_LEVELS {
            self.unknown(row, span, format!("`{}` would nest deeper than {MOST_LEVELS} program levels: the control stops with an alarm (14000s); not followed", call.name));
            return next;
        }
        let caller = Return {
            model: self.model,
            program: self.program.replace(call.name.clone()),
            row: next,
            locals: std::mem::take(&mut self.variables.local),
            openers: std::mem::replace(&mut self.openers, openers(callee)),
            in_for: std::mem::take(&mut self.in_for),
            again: call.times.saturating_sub(1),
            arguments: call.arguments,
        };
        self.model = callee;
        self.source = callee.source;
        self.variables.local = globals(&caller.locals);
        self.bind(&caller.arguments);
        self.stack.push(caller);
        0
    }

    /// The PROC line's parameters of the program now running, given
    /// `arguments` (by position; one not given or unknown stays unknown).
    pub(super) fn bind(&mut self, arguments: &[Option<Value>]) {
        let source = self.source;
        let Some(parameters) = self
            .model
            .lines
            .other_lines()
            .take(50)
            .find_map(|(_, line)| {
                let LineKind::Block(block) = &line.kind else {
                    return None;
                };
                block.statements.iter().find_map(|s| match &s.kind {
                    StatementKind::Proc(proc) => Some(
                        proc.parameters
                            .iter()
                            .map(|p| p.declarator.name.upper(source))
                            .collect::<Vec<_>>(),
                    ),
                    _ => None,
                })
            })
        else {
            return;
        };
        for (name, value) in parameters.into_iter().zip(arguments) {
            if let Some(value) = value {
                self.variables.local.insert(key(&name, &[]), value.clone());
            }
        }
    }

    /// Back from a subprogram at its end (M17, RET, M2, M30 or its last
    /// line), or into it again while its `P` asks: where the caller goes on;
    /// `None` at the main program's end. R parameters are the channel's:
    /// what the subprogram wrote, the caller reads.
    pub(super) fn give_back(&mut self) -> Option<usize> {
        let mut caller = self.stack.pop()?;
        let written = std::mem::take(&mut self.variables.local);
        if caller.again > 0 {
            caller.again -= 1;
            self.variables.local = globals(&written);
            self.in_for.clear();
            let arguments = std::mem::take(&mut caller.arguments);
            self.bind(&arguments);
            caller.arguments = arguments;
            self.stack.push(caller);
            return Some(0);
        }
        self.variables.local = caller.locals;
        self.variables.local.extend(globals(&written));
        self.model = caller.model;
        self.program = caller.program;
        self.source = caller.model.source;
        self.openers = caller.openers;
        self.in_for = caller.in_for;
        Some(caller.row)
    }
}

/// The variables every program level shares: the R parameters.
fn globals(variables: &HashMap<String, Value>) -> HashMap<String, Value> {
    variables
        .iter()
        .filter(|(key, _)| {
            key.strip_prefix('R')
                .is_some_and(|n| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()))
        })
        .map(|(key, value)| (key.clone(), value.clone()))
        .collect()
}

/// `L105`: a subprogram called by its number (the digits as written:
/// `L0105` is another).
pub(super) fn is_numbered_call(name: &str) -> bool {
    name.len() > 1 && name.starts_with('L') && name[1..].bytes().all(|b| b.is_ascii_digit())
}
