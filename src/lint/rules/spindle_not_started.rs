//! N029 `spindle-not-started`: Finds the first feed motion of a main program that sets a spindle speed but has not started the spindle.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, FromProgramStart, Moves};
use crate::lint::rules::support::feed_move;
use crate::semantic::addresses::Address;
use crate::semantic::modal::Modal;
use crate::span::Span;

pub static RULE: RuleInfo = RuleInfo {
    code: "N029",
    name: "spindle-not-started",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds the first block of a main program that moves an axis with `G1`, `G2` or `G3` in force after a
spindle speed `S` has been programmed, while the spindle has not been started: no `M3` or `M4`
(`M1=3` and the like for another spindle) before it or in it.

Only a program that has not started its spindle at all is reported: a spindle stopped with `M5`,
positioned (`M19`, `SPOS`) or switched to an axis (`M70`) before a feed motion is the program's
intent (probing, broaching, retracts), and a program without `S` may have no spindle to start
(probes, lasers). The program is read from its start in the order of its lines, as long as that
order is the order the control runs it: the rule stops at the first jump, subprogram or cycle call
(which may start the spindle), `PROC`, modal call, and at any M function other than the standard
ones (M0, M1, M2, M30, M17, M6, M7, M8, M9, M40 to M45), since a machine's own M functions may
start the spindle (`M13` on many machines). Subprograms are not checked.

## Why it matters
A cutting tool fed into the work with its spindle standing breaks, and the workpiece with it. The
usual slip is `M6` (tool change) written where `M3` was meant, or the start left out after a tool
change: the speed is set, so the program means to cut.

## Example
```
N10 G90 G54 T="MILL_10" M6
N20 S3000 M6
N30 G0 X0 Y0 Z5
N40 G1 Z-2 F200
```

## Fix
Start the spindle before the first cut: `N20 S3000 M3` (or `M4` for the other direction)."#,
};

#[derive(Default)]
pub struct Checker {
    modal: Modal,
    /// The spindle speed programmed, if any.
    speed: Option<Span>,
}

/// An M function that answers this rule's question: it starts, stops or
/// positions the spindle, or may (a machine's own M function); the
/// standard ones that leave the spindle as it is do not.
fn settles_spindle(source: &[u8], address: &Address) -> bool {
    !matches!(
        (address.extension.is_some(), address.whole(source)),
        (false, Some(0 | 1 | 2 | 6..=9 | 17 | 30 | 40..=45))
    )
}

impl FromProgramStart for Checker {
    /// The state after one more block; the finding when it feeds with a
    /// speed set and the spindle not started. Answered once the spindle is
    /// started, stopped, positioned or may be (a machine's own M function).
    fn block(&mut self, file: &FileContext, at: &Moves, out: &mut Vec<Diagnostic>) -> bool {
        let (addresses, moves) = (at.addresses, at.named);
        let source = file.source;
        for address in addresses {
            if address.is(source, "S") {
                self.speed.get_or_insert(address.span);
            } else if address.is(source, "M") && settles_spindle(source, address) {
                return true;
            }
        }
        self.modal.apply(source, addresses);
        let (Some(speed), Some((motion, words))) =
            (self.speed, feed_move(source, &self.modal, addresses, moves))
        else {
            return false;
        };
        let speed = String::from_utf8_lossy(speed.of(source));
        out.push(
            RULE.at(words)
                .message(format!(
                    "this block feeds with G{motion} after the spindle speed `{speed}` was set, but the spindle was never started: no M3 or M4 before it"
                ))
                .label("cuts with the spindle standing")
                .help("start the spindle before the first cut (M3, or M4 for the other direction); M6 written for M3 is a common slip"),
        );
        true
    }
}
