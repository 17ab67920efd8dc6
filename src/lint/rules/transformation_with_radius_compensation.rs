//! N028 `transformation-with-radius-compensation`: Finds a transformation selected or deselected (`TRAORI`, `TRAFOOF`, ...) while `G41`/`G42` is in force.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::lint::rules::support::{command_name, leaves_line_order, upper};
use crate::semantic::addresses::{self, Address};
use crate::semantic::modal::Modal;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N028",
    name: "transformation-with-radius-compensation",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a block that selects or deselects a kinematic transformation (`TRAORI`, `TRANSMIT`, `TRACYL`,
`TRAANG`, `TRACON`, `TRAFOOF`) while the tool radius compensation `G41` or `G42` programmed in an
earlier block is still in force.

The blocks are read in the order of the lines from the `G41`/`G42` on, as long as that is the order
the control runs them: a jump, a block structure (IF, ELSE, loops, CASE), a subprogram or cycle call
or a PROC ends what the rule knows, and so does a skippable block (`/`) that programs G40-G42.
`CYCLE800` is not checked: the manuals name no such constraint for it.

## Why it matters
Siemens, Programming Manual Job Planning, "Constraints when selecting a transformation": tool radius
compensation must be deselected (G40) before a transformation is selected; otherwise the control
reports it. The compensated path was computed in the coordinates before the change, so the contour
the tool would follow after it is not the one programmed.

## Example
```
N10 G1 G41 X10 Y0 D1 F500
N20 Y50
N30 TRAORI
```

## Fix
Deselect the compensation with a motion before the transformation changes:
```
N10 G1 G41 X10 Y0 D1 F500
N20 Y50
N25 G40 X0 Y60
N30 TRAORI
```"#,
};

/// The commands that select or deselect a transformation.
const TRANSFORMATIONS: [&str; 6] = [
    "TRAORI", "TRANSMIT", "TRACYL", "TRAANG", "TRACON", "TRAFOOF",
];

#[derive(Default)]
pub struct Checker {
    modal: Modal,
    /// The 0-based line of the compensation in force.
    since: usize,
    /// The compensation already reported, so that TRAORI ... TRAFOOF under
    /// one G41 is one finding.
    reported: Option<Span>,
}

impl Check for Checker {
    fn line(&mut self, file: &FileContext, row: usize, line: &LineView, out: &mut Vec<Diagnostic>) {
        let Some(block) = line.block else {
            if line.header.is_some() {
                *self = Self::default(); // another program of the file
            }
            return;
        };
        let source = file.source;
        let addresses = line.addresses(source);
        let structure = block.statements.iter().any(|s| {
            matches!(
                s.kind,
                StatementKind::If { .. }
                    | StatementKind::Else
                    | StatementKind::EndIf
                    | StatementKind::While { .. }
                    | StatementKind::EndWhile
                    | StatementKind::For { .. }
                    | StatementKind::EndFor
                    | StatementKind::Loop
                    | StatementKind::EndLoop
                    | StatementKind::Repeat { .. }
                    | StatementKind::Until { .. }
            )
        });
        if structure || leaves_line_order(file, block, addresses) {
            self.modal.radius_compensation = None;
            return;
        }
        if block.skip.is_some() {
            self.skippable(source, addresses);
            return;
        }
        self.apply(source, row, addresses);
        let Some(compensation) = self.modal.radius_compensation else {
            return;
        };
        for statement in &block.statements {
            let Some(name) = command_name(statement) else {
                continue;
            };
            let name = upper(source, name.span);
            if !TRANSFORMATIONS.contains(&name.as_str()) || self.reported == Some(compensation) {
                continue;
            }
            self.reported = Some(compensation);
            let g = upper(source, compensation);
            let at = self.since + 1;
            let verb = if name == "TRAFOOF" {
                "deselects"
            } else {
                "selects"
            };
            out.push(
                RULE.at(statement.span)
                    .message(format!(
                        "{name} {verb} a transformation while the tool radius compensation {g} of line {at} is in force; the control requires G40 first"
                    ))
                    .label(format!("{g} still in force"))
                    .help("deselect the compensation (G40 with a motion) before the transformation changes"),
            );
        }
    }

    fn sees_plain_lines(&self) -> bool {
        true
    }

    fn plain_lines(&mut self, file: &FileContext, lines: &[PlainLine], _out: &mut Vec<Diagnostic>) {
        let source = file.source;
        for line in lines {
            let facts = &line.facts;
            if facts.letters.contains(b'L') {
                self.modal.radius_compensation = None; // a subprogram call
                continue;
            }
            // Only a G function beyond G0-G3 can change the compensation.
            if !facts.motions.others() {
                continue;
            }
            let addresses = addresses::of_plain(source, line.raw.content);
            let content = line.raw.content.of(source);
            if content.iter().find(|b| !b.is_ascii_whitespace()) == Some(&b'/') {
                self.skippable(source, &addresses);
            } else {
                self.apply(source, line.row, &addresses);
            }
        }
    }
}

impl Checker {
    /// The state after the block on line `row`.
    fn apply(&mut self, source: &[u8], row: usize, addresses: &[Address]) {
        let before = self.modal.radius_compensation;
        self.modal.apply(source, addresses);
        if self.modal.radius_compensation != before {
            self.since = row;
        }
    }

    /// A block the operator may skip: a compensation it programs may or may
    /// not be in force after it.
    fn skippable(&mut self, source: &[u8], addresses: &[Address]) {
        let mut after = self.modal;
        after.apply(source, addresses);
        if after.radius_compensation != self.modal.radius_compensation {
            self.modal.radius_compensation = None;
        }
    }
}
