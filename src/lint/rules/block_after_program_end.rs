//! N027 `block-after-program-end`: Finds blocks after the program's end (M30, M2, M17, RET) that no jump reaches.

use std::collections::HashSet;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, JumpAt, LineView, PlainLine, Sees};
use crate::lint::rules::support::{self, Target};
use crate::semantic::addresses::{self, is_end_word};
use crate::semantic::blocks::opener;
use crate::span::Span;
use crate::syntax::plain::digits_value;
use crate::syntax::tree::{Block, BlockNumber, StatementKind};

pub static RULE: RuleInfo = RuleInfo {
    code: "N027",
    name: "block-after-program-end",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds the first block after a program end (`M30`, `M2`, `M17`, `RET`) that stands outside every
control block (IF, WHILE, FOR, LOOP, REPEAT) and that no jump can reach: it has no label, and no
jump names its block number. Blocks after a label stay reachable (a GOTO, a REPEAT or a CASE may go
there), a `PROC` or a program header (`%_N_..._SPF`) starts another program, and a file with a
computed jump (`GOTOF "L"<<R1`) is not checked after it.

## Why it matters
The control stops at the program end, so these blocks never run: a program end left in by an edit,
or blocks meant for before it.

## Example
```
N10 G1 X10 F100
N20 M30
N30 G0 Z100
```

## Fix
Move the blocks before the end, give them the label a jump goes to, or delete them."#,
};

#[derive(Default)]
pub struct Checker {
    /// Control blocks open.
    depth: usize,
    /// The end the lines since stand after.
    end: Option<Span>,
    /// The first block after an end, with its block number.
    after: Vec<(Span, Option<u64>, Span)>,
    /// Block numbers some jump names.
    jumped_to: HashSet<u64>,
    computed_jump: bool,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::JUMPS | Sees::BLOCKS | Sees::PLAIN_LINES
    }

    fn header(&mut self, _file: &FileContext, _row: usize, _name: Span) {
        self.end = None;
        self.depth = 0;
    }

    fn jump(&mut self, _file: &FileContext, at: &JumpAt, _out: &mut Vec<Diagnostic>) {
        match &at.target {
            Some((Target::Number(number), _)) => {
                self.jumped_to.insert(*number);
            }
            Some(_) => {}
            None => self.computed_jump = true,
        }
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, _out: &mut Vec<Diagnostic>) {
        let (block, line) = (at.block, at.line);
        if block
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Case(_)))
        {
            self.computed_jump = true;
        }
        let starts_program = block
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::Proc(_)));
        if block.label.is_some() || starts_program {
            self.end = None;
        }
        let executes = !block.statements.is_empty() || block.unparsed.is_some();
        if let Some(end) = self.end.filter(|_| executes) {
            self.end = None;
            self.after.push((
                span_of(block, line),
                number_of(file.source, block.number),
                end,
            ));
        }
        self.depth = match opener(block) {
            Some(_) => self.depth + 1,
            None if closes(block) => self.depth.saturating_sub(1),
            None => self.depth,
        };
        if self.depth == 0 {
            if let Some(end) = support::program_end(file, block, line.addresses(file.source)) {
                self.end = Some(end);
            }
        }
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], _out: &mut Vec<Diagnostic>) {
        let source = file.source;
        for line in lines {
            if !line.facts.has_words() {
                continue;
            }
            let after_end = self.end.take();
            let may_end = self.depth == 0 && line.facts.letters.contains(b'M');
            if after_end.is_none() && !may_end {
                continue; // nearly every CAM line: no word read
            }
            let words = addresses::of_plain(source, line.raw.content);
            if let (Some(end), Some(first), Some(last)) = (after_end, words.first(), words.last()) {
                let number = number_of(source, line.facts.number);
                self.after.push((first.span.to(last.span), number, end));
            }
            if may_end {
                if let Some(end) = words.iter().find(|a| is_end_word(source, a)) {
                    self.end = Some(end.span);
                }
            }
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        if self.computed_jump {
            return;
        }
        for &(span, number, end) in &self.after {
            if number.is_some_and(|n| self.jumped_to.contains(&n)) {
                continue;
            }
            let end = String::from_utf8_lossy(end.of(file.source));
            out.push(
                RULE.at(span)
                    .message(format!("this block comes after the program's end (`{end}`) and no jump reaches it: it never runs"))
                    .label("never runs")
                    .help("move it before the end, give it the label a jump goes to, or delete it"),
            );
        }
    }
}

/// A block number's value (`N100`; not a main block number `:100`).
fn number_of(source: &[u8], number: Option<BlockNumber>) -> Option<u64> {
    number
        .filter(|n| !n.main)
        .and_then(|n| digits_value(n.digits.of(source)))
}

/// The block's words, or its content when it has none to point at.
fn span_of(block: &Block, line: &LineView) -> Span {
    match (block.statements.first(), block.statements.last()) {
        (Some(first), Some(last)) => first.span.to(last.span),
        _ => line.raw.content,
    }
}

/// The block closes a control block.
fn closes(block: &Block) -> bool {
    block.statements.iter().any(|s| {
        matches!(
            s.kind,
            StatementKind::EndIf
                | StatementKind::EndWhile
                | StatementKind::EndFor
                | StatementKind::EndLoop
                | StatementKind::Until { .. }
        )
    })
}
