//! N026 `missing-feed-rate`: Finds the first feed motion (`G1`, `G2`, `G3`) of a main program before any feed rate F.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, FromProgramStart, Moves};
use crate::lint::rules::support::feed_move;
use crate::semantic::modal::Modal;

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
}

impl FromProgramStart for Checker {
    /// The state after one more block; the finding when it moves at a feed
    /// with none programmed. Answered once a feed rate is programmed.
    fn block(&mut self, file: &FileContext, at: &Moves, out: &mut Vec<Diagnostic>) -> bool {
        let (addresses, moves) = (at.addresses, at.named);
        let source = file.source;
        self.modal.apply(source, addresses);
        if self.modal.feed {
            return true;
        }
        let Some((motion, words)) = feed_move(source, &self.modal, addresses, moves) else {
            return false;
        };
        out.push(
            RULE.at(words)
                .message(format!(
                    "this block moves with G{motion} but no feed rate F has been programmed: the control stops with alarm 10860"
                ))
                .label("feed motion without F")
                .help("program the feed rate in this block or before it (F100)"),
        );
        true
    }
}
