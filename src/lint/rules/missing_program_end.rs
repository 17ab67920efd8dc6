//! N010 `missing-program-end`: Finds a main program whose last block does not end it with M30 or M2, and a subprogram whose last

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::span::Span;
use crate::syntax::lines::RawLine;
use crate::syntax::tree::{LineKind, StatementKind, WordValue};
use crate::syntax::{LineParser, ProgramKind};

pub static RULE: RuleInfo = RuleInfo {
    code: "N010",
    name: "missing-program-end",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a main program whose last block does not end it with M30 or M2, and a subprogram whose last
block is not M17, RET (or M30/M2).

## Why it matters
Without an end, a main program stops with an alarm at its last block instead of ending, and a
subprogram does not return to its caller as intended.

## Example
```
N10 G0 X0
N20 G1 X100 F500
```

## Fix
End a main program with `M30` (or `M2`), a subprogram with `M17` or `RET`."#,
};

/// Remembers only where the last block is; `finish` reads it again, so that
/// the millions of blocks before it cost nothing.
#[derive(Default)]
pub struct Checker {
    last: Option<RawLine>,
}

impl Check for Checker {
    fn line(
        &mut self,
        _file: &FileContext,
        _row: usize,
        line: &LineView,
        _out: &mut Vec<Diagnostic>,
    ) {
        if line.block.is_some_and(|block| !block.statements.is_empty()) {
            self.last = Some(line.raw);
        }
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(
        &mut self,
        _file: &FileContext,
        lines: &[PlainLine],
        _out: &mut Vec<Diagnostic>,
    ) {
        if let Some(line) = lines.iter().rev().find(|line| line.facts.has_words) {
            self.last = Some(line.raw);
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let Some(raw) = self.last else {
            return;
        };
        let (line, _) = LineParser::default().parse_line(file.source, raw);
        let LineKind::Block(block) = &line.kind else {
            return;
        };
        let m = |values: &[f64]| {
            block.statements.iter().any(|s| match &s.kind {
                StatementKind::Word(word) => {
                    word.address.is(file.source, "M")
                        && matches!(&word.value, WordValue::Number(n) if values.contains(&n.value))
                }
                _ => false,
            })
        };
        let ret = block
            .statements
            .iter()
            .any(|s| matches!(&s.kind, StatementKind::Command(n) if n.is(file.source, "RET")));
        let (ends_main, returns) = (m(&[30.0, 2.0]), m(&[17.0]) || ret);
        let span = Span::new(raw.content.start, raw.content.end);
        let (ok, what, fix) = match file.kind {
            ProgramKind::Main => (ends_main, "main program", "end it with M30 (or M2)"),
            ProgramKind::Subprogram => {
                (returns || ends_main, "subprogram", "end it with M17 or RET")
            }
        };
        if !ok {
            out.push(
                RULE.at(span)
                    .message(format!("the {what} does not end with its end command"))
                    .label("last block")
                    .help(fix),
            );
        }
    }
}
