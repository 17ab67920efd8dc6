//! N030 `plane-change-with-radius-compensation`: Finds a change of the working plane (`G17`, `G18`, `G19`) while `G41`/`G42` is in force.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, ModalRule, ModalStep};
use crate::lint::rules::support::upper;
use crate::syntax::plain::PlainFacts;

pub static RULE: RuleInfo = RuleInfo {
    code: "N030",
    name: "plane-change-with-radius-compensation",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a block that changes the working plane (`G17`, `G18`, `G19`) while the tool radius
compensation `G41` or `G42` of an earlier block is in force and the block does not deselect it.

Only a change between planes the program itself programmed is reported: before the first `G17`,
`G18` or `G19` the plane is the machine's reset value, which the program cannot see. The blocks
are read in the order of the lines, as long as that is the order the control runs them: a jump, a
block structure (IF, ELSE, loops, CASE), a subprogram or cycle call or a PROC ends what the rule
knows, and so does a skippable block (`/`) that programs the compensation or the plane.

## Why it matters
Siemens, alarm 10757 "changing the compensation plane while tool radius compensation is active not
possible": the compensation must be deselected with `G40` before the plane changes. The control
stops the program at this block.

## Example
```
N10 G17 G1 G41 X10 Y0 D1 F500
N20 Y50
N30 G18 X20 Z5
```

## Fix
Deselect the compensation in a block with a motion, change the plane, and select it again in an
approach block with `G1`:
```
N10 G17 G1 G41 X10 Y0 D1 F500
N20 Y50
N25 G40 X0 Y60
N30 G18 X20 Z5
```"#,
};

#[derive(Default)]
pub struct Checker;

impl ModalRule for Checker {
    /// Only a G function beyond G0-G3 changes the plane or the compensation.
    fn may_matter(facts: &PlainFacts) -> bool {
        facts.motions.others()
    }

    fn block(&mut self, file: &FileContext, step: &ModalStep, out: &mut Vec<Diagnostic>) {
        let before = &step.before;
        let (Some(compensation), Some(plane)) = (before.radius_compensation, before.plane) else {
            return;
        };
        // A block that deselects the compensation is the deselection's own.
        if step.after.radius_compensation.is_none() {
            return;
        }
        let source = file.source;
        let Some(change) = step.addresses.iter().find(|a| {
            a.is(source, "G") && matches!(a.whole(source), Some(new @ 17..=19) if new != plane)
        }) else {
            return;
        };
        let g = upper(source, compensation);
        let new = upper(source, change.span);
        let at = step.compensated_since + 1;
        out.push(
            RULE.at(change.span)
                .message(format!(
                    "{new} changes the working plane from G{plane} while the tool radius compensation {g} of line {at} is in force: the control refuses it (alarm 10757)"
                ))
                .label(format!("{g} still in force"))
                .help("deselect the compensation (G40 with a motion) before the plane changes, and select it again after"),
        );
    }
}
