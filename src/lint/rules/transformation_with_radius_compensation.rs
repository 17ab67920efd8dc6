//! N028 `transformation-with-radius-compensation`: Finds a transformation selected or deselected (`TRAORI`, `TRAFOOF`, ...) while `G41`/`G42` is in force.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, ModalRule, ModalStep};
use crate::lint::rules::support::{command_name, upper};
use crate::span::Span;
use crate::syntax::plain::PlainFacts;

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
A skippable block that changes the transformation is checked as if it ran.
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

/// The compensation already reported, so that TRAORI ... TRAFOOF under one
/// G41 is one finding.
#[derive(Default)]
pub struct Checker {
    reported: Option<Span>,
}

impl ModalRule for Checker {
    /// Only a G function beyond G0-G3 can change the compensation, and a
    /// plain line holds no command.
    fn may_matter(facts: &PlainFacts) -> bool {
        facts.motions.others()
    }

    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>) {
        let (Some(block), Some(compensation)) = (step.block, step.after.radius_compensation) else {
            return;
        };
        let source = file.source;
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
            let at = step.compensated_since + 1;
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
}
