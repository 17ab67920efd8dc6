//! The line pass's hand-out: which of the selected rules read each kind of
//! thing ([`Sees`]), and each line's headers, statements, declarations,
//! calls, jumps and blocks given to those alone.

use crate::diagnostic::Diagnostic;
use crate::lint::rule::{BlockAt, CallAt, Check, FileContext, JumpAt, Sees, StatementAt};
use crate::semantic::model::{LineView, PlainLine};
use crate::syntax::tree::{Block, Goto, StatementKind};

/// The selected rules' checkers, and which of them read each kind of thing:
/// a kind no rule reads costs nothing.
pub(crate) struct Checkers {
    all: Vec<Box<dyn Check>>,
    headers: Vec<usize>,
    blocks: Vec<usize>,
    statements: Vec<usize>,
    calls: Vec<usize>,
    declarations: Vec<usize>,
    jumps: Vec<usize>,
    plain_lines: Vec<usize>,
}

impl Checkers {
    pub(crate) fn new(all: Vec<Box<dyn Check>>) -> Self {
        let seeing = |kind: Sees| -> Vec<usize> {
            (0..all.len())
                .filter(|&n| all[n].sees().has(kind))
                .collect()
        };
        Self {
            headers: seeing(Sees::HEADERS),
            blocks: seeing(Sees::BLOCKS),
            statements: seeing(Sees::STATEMENTS),
            calls: seeing(Sees::CALLS),
            declarations: seeing(Sees::DECLARATIONS),
            jumps: seeing(Sees::JUMPS),
            plain_lines: seeing(Sees::PLAIN_LINES),
            all,
        }
    }

    /// One line read into a tree, handed out by kind.
    pub(crate) fn line(
        &mut self,
        file: &FileContext,
        row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        if let Some(name) = line.header {
            for &n in &self.headers {
                self.all[n].header(file, row, name);
            }
        }
        let Some(block) = line.block else {
            return;
        };
        self.statements(file, row, block, line, out);
        let at = BlockAt { row, block, line };
        for &n in &self.blocks {
            self.all[n].block(file, &at, out);
        }
    }

    fn statements(
        &mut self,
        file: &FileContext,
        row: usize,
        block: &Block,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        for (index, statement) in block.statements.iter().enumerate() {
            let at = StatementAt {
                row,
                block,
                index,
                statement,
                line,
            };
            for &n in &self.statements {
                self.all[n].statement(file, &at, out);
            }
            let declares = matches!(
                statement.kind,
                StatementKind::Def(_) | StatementKind::Proc(_) | StatementKind::Extern { .. }
            );
            if declares {
                for &n in &self.declarations {
                    self.all[n].declaration(file, &at, out);
                }
            }
            if let StatementKind::Call(call) = &statement.kind {
                let at = CallAt { row, call };
                for &n in &self.calls {
                    self.all[n].call(file, &at, out);
                }
            }
            if self.jumps.is_empty() {
                continue;
            }
            let mut hand = |goto: &Goto| {
                let at = JumpAt {
                    row,
                    goto,
                    target: crate::lint::rules::support::target(file, goto),
                };
                for &n in &self.jumps {
                    self.all[n].jump(file, &at, out);
                }
            };
            match &statement.kind {
                StatementKind::Goto(goto) => hand(goto),
                StatementKind::Case(case) => {
                    let branches = case.branches.iter().map(|(_, goto)| goto);
                    branches.chain(&case.default).for_each(hand);
                }
                _ => {}
            }
        }
    }

    /// A run of plain lines, to the rules that read them.
    pub(crate) fn plain_lines(
        &mut self,
        file: &FileContext,
        lines: &[PlainLine],
        out: &mut Vec<Diagnostic>,
    ) {
        for &n in &self.plain_lines {
            self.all[n].plain_lines(file, lines, out);
        }
    }

    /// Every rule's last step, once the file is over; `false` when `stopped`
    /// said so before one of them.
    pub(crate) fn finish(
        &mut self,
        file: &FileContext,
        out: &mut Vec<Diagnostic>,
        stopped: impl Fn() -> bool,
    ) -> bool {
        for checker in &mut self.all {
            if stopped() {
                return false;
            }
            checker.finish(file, out);
        }
        true
    }
}
