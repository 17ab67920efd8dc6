//! N026 `missing-feed-rate`: Finds the first feed motion (`G1`, `G2`, `G3`) of a main program before any feed rate F.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::lint::rules::support::{
    is_definition_file, leaves_line_order, moves_a_named_axis, moves_an_axis, upper,
};
use crate::semantic::addresses::{self, Address};
use crate::semantic::modal::{is_feed_motion, Modal};
use crate::span::Span;

use crate::syntax::ProgramKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N026",
    name: "missing-feed-rate",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds the first block of a main program that moves an axis with `G1`, `G2` or `G3` in force (written
in that block or an earlier one) while no feed rate `F` has been programmed before it or in it.

The program is read from its start in the order of its lines, as long as that order is the order
the control runs it: the rule stops looking at the first jump, subprogram or cycle call (which may
program F), `PROC` or modal call. Subprograms are not checked, since their caller's feed rate holds
in them.

## Why it matters
A path motion needs a feed rate; without one the control stops with alarm 10860 ("feedrate not
programmed"), unless the setting data SD42110 `$SC_DEFAULT_FEED` gives a default, which is 0 as
delivered. A feed rate that was meant in the block before is a common slip of hand-written and
edited programs.

## Example
```
N10 G90 G54 G0 X0 Y0 Z5 S2000 M3
N20 G1 Z-2
N30 X50 F300
```

## Fix
Program the feed rate in or before the first feed motion (`N20 G1 Z-2 F100`)."#,
};

#[derive(Default)]
pub struct Checker {
    modal: Modal,
    /// Reported, a feed rate seen, or the order of execution no longer known.
    done: bool,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        if let Some(name) = line.header {
            // A program of its own begins (`%_N_PART_MPF`).
            let main = upper(file.source, name).ends_with("_MPF");
            *self = Self {
                done: !main,
                ..Self::default()
            };
            return;
        }
        if self.done || file.kind != ProgramKind::Main || is_definition_file(file.name) {
            return;
        }
        let Some(block) = line.block else {
            return;
        };
        let addresses = line.addresses(file.source);
        if leaves_line_order(file, block, addresses) {
            self.done = true;
            return;
        }
        let moves = moves_a_named_axis(file, block);
        self.step(file, addresses, moves, out);
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], out: &mut Vec<Diagnostic>) {
        if self.done || file.kind != ProgramKind::Main || is_definition_file(file.name) {
            return;
        }
        for line in lines {
            if self.done {
                return;
            }
            let addresses = addresses::of_plain(file.source, line.raw.content);
            if addresses.iter().any(|a| a.is(file.source, "L")) {
                self.done = true; // a subprogram call
                return;
            }
            self.step(file, &addresses, false, out);
        }
    }
}

impl Checker {
    /// The state after one more block; the finding when it moves at a feed
    /// with none programmed.
    fn step(
        &mut self,
        file: &FileContext,
        addresses: &[Address],
        moves: bool,
        out: &mut Vec<Diagnostic>,
    ) {
        let source = file.source;
        self.modal.apply(source, addresses);
        if self.modal.feed {
            self.done = true;
            return;
        }
        let Some(motion) = self.modal.motion.filter(|&m| is_feed_motion(m)) else {
            return;
        };
        let moves = moves_an_axis(source, addresses, moves);
        let (true, Some(first), Some(last)) = (moves, addresses.first(), addresses.last()) else {
            return;
        };
        self.done = true;
        out.push(
            RULE.at(Span::new(first.span.start, last.span.end))
                .message(format!(
                    "this block moves with G{motion} but no feed rate F has been programmed: the control stops with alarm 10860"
                ))
                .label("feed motion without F")
                .help("program the feed rate in this block or before it (F100)"),
        );
    }
}
