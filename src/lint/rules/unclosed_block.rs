//! N004 `unclosed-block`: Finds IF, WHILE, FOR, LOOP and REPEAT blocks that are not closed, closed by the wrong keyword, or

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, OnModel};
use crate::semantic::blocks::Fault;

pub static RULE: RuleInfo = RuleInfo {
    code: "N004",
    name: "unclosed-block",
    severity: Severity::Error,
    docs: r#"## What it does
Finds IF, WHILE, FOR, LOOP and REPEAT blocks that are not closed, closed by the wrong keyword, or
closers (ENDIF, ENDWHILE, ENDFOR, ENDLOOP, UNTIL, ELSE) without their opener. Reported at the opener.

## Why it matters
The control refuses the program (alarm 12640 and its kin) or runs a different structure than the
indentation suggests.

## Example
```
N10 WHILE R1<10
N20   R1=R1+1
N30 ENDIF          ; closes nothing: the WHILE stays open
```

## Fix
Add or correct the closing keyword."#,
};

/// The findings are the model's block matching's faults (`semantic::blocks`),
/// the matching the walk and the formatter follow.
pub struct Checker;

impl OnModel for Checker {
    fn check(file: &FileContext, out: &mut Vec<Diagnostic>) {
        out.extend(file.model().blocks.faults.iter().map(|fault| {
            match *fault {
                Fault::LeftOpen { open, closer, row } => {
                    let keyword = open.opener.keyword();
                    RULE.at(open.span)
                        .message(format!(
                            "{keyword} is not closed before {closer} on line {}",
                            row + 1
                        ))
                        .label(format!("{keyword} opened here"))
                        .help(format!(
                            "add {} before line {}",
                            open.opener.closer(),
                            row + 1
                        ))
                }
                Fault::Stray { closer, span } => RULE
                    .at(span)
                    .message(format!("{closer} without its opening block"))
                    .label("closes nothing")
                    .help(format!("remove {closer}, or add the block it should close")),
                Fault::StrayElse { span } => RULE
                    .at(span)
                    .message("ELSE without an open IF")
                    .label("no IF to belong to")
                    .help("add the IF, or remove the ELSE"),
                Fault::NeverClosed(open) => {
                    let keyword = open.opener.keyword();
                    RULE.at(open.span)
                        .message(format!("{keyword} is never closed"))
                        .label(format!("{keyword} opened here"))
                        .help(format!("add {} where the block ends", open.opener.closer()))
                }
            }
        }));
    }
}
