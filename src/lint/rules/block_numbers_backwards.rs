//! N014 `block-numbers-backwards`: Finds a block number lower than the one before it.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::syntax::plain::digits_value;
use crate::syntax::tree::BlockNumber;

pub static RULE: RuleInfo = RuleInfo {
    code: "N014",
    name: "block-numbers-backwards",
    severity: Severity::Info,
    docs: r#"## What it does
Finds a block number lower than the one before it.

## Why it matters
Block numbers are not executed in order, but a jump to a block number searches in a direction,
and readers expect them to grow: a number going backwards often marks blocks pasted from
elsewhere.

## Example
```
N100 G0 X0
N40 G1 X10
```

## Fix
Renumber the blocks."#,
};

#[derive(Default)]
pub struct Checker {
    previous: Option<u64>,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        if let Some(block) = line.block {
            self.number(file, block.number, out);
        }
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        for line in lines {
            self.number(file, line.facts.number, out);
        }
    }
}

impl Checker {
    fn number(
        &mut self,
        file: &FileContext,
        number: Option<BlockNumber>,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(number) = number.filter(|n| !n.main) else {
            return;
        };
        let Some(value) = digits_value(number.digits.of(file.source)) else {
            return;
        };
        if let Some(previous) = self.previous.filter(|&p| value < p) {
            out.push(backwards(number, value, previous));
        }
        self.previous = Some(value);
    }
}

/// Apart and cold, so that the path every line takes does not set up the
/// message's formatting (it was a 300-byte stack frame a line).
#[cold]
fn backwards(number: BlockNumber, value: u64, previous: u64) -> Diagnostic {
    RULE.at(number.span)
        .message(format!("block number N{value} after N{previous}"))
        .label("goes backwards")
        .help("renumber the blocks in ascending order")
}
