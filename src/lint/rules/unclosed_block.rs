//! N004 `unclosed-block`: Finds IF, WHILE, FOR, LOOP and REPEAT blocks that are not closed, closed by the wrong keyword, or

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::semantic::blocks::{BlockMatcher, Event};

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

/// The matching is the model's (`semantic::blocks::BlockMatcher`), shared with the walk.
#[derive(Default)]
pub struct Checker {
    blocks: BlockMatcher,
}

impl Check for Checker {
    fn line(
        &mut self,
        _file: &FileContext,
        row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block.filter(|_| !line.plain) else {
            return;
        };
        self.blocks.line(row, block, &mut |event| match event {
            Event::Closed { .. } => {}
            Event::LeftOpen { open, closer, row } => {
                let keyword = open.opener.keyword();
                out.push(
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
                        )),
                )
            }
            Event::Stray { closer, span } => out.push(
                RULE.at(span)
                    .message(format!("{closer} without its opening block"))
                    .label("closes nothing")
                    .help(format!("remove {closer}, or add the block it should close")),
            ),
            Event::StrayElse { span } => out.push(
                RULE.at(span)
                    .message("ELSE without an open IF")
                    .label("no IF to belong to")
                    .help("add the IF, or remove the ELSE"),
            ),
        });
    }

    fn finish(&mut self, _file: &FileContext, out: &mut Vec<Diagnostic>) {
        for open in std::mem::take(&mut self.blocks).finish() {
            let keyword = open.opener.keyword();
            out.push(
                RULE.at(open.span)
                    .message(format!("{keyword} is never closed"))
                    .label(format!("{keyword} opened here"))
                    .help(format!("add {} where the block ends", open.opener.closer())),
            );
        }
    }
}
