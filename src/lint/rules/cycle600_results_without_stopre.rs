//! C614 `cycle600-results-without-stopre`: Finds a read of `_CYC600_1` .. `_CYC600_6` after a CYCLE600 call with no STOPRE between them.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::semantic::model::is_stopre;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "C614",
    name: "cycle600-results-without-stopre",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a read of `_CYC600_1` .. `_CYC600_6` after a CYCLE600 call with no STOPRE between them.

## Why it matters
CYCLE600 writes its results while it runs in the main run; the blocks after it are prepared
earlier, so without STOPRE they read the results of the previous call. The paper's Example 3 has
`N125 STOPRE` for this reason.

## Example
```
N120 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)
N130 IF _CYC600_5==1
```

## Fix
Write STOPRE in its own block after the CYCLE600 call."#,
};

#[derive(Default)]
pub struct Checker {
    pending: Option<usize>,
}

impl Check for Checker {
    fn line(&mut self, file: &FileContext, row: usize, line: &LineView, out: &mut Vec<Diagnostic>) {
        let Some(block) = line.block.filter(|_| !line.plain) else {
            return;
        };
        for (index, statement) in block.statements.iter().enumerate() {
            match &statement.kind {
                _ if is_stopre(file.source, statement) => self.pending = None,
                StatementKind::Call(call) if call.name.is(file.source, "CYCLE600") => {
                    self.pending = Some(row)
                }
                _ => {
                    let Some(call_row) = self.pending else {
                        continue;
                    };
                    for variable in line.reads(index) {
                        if upper(file.source, variable.name.span).starts_with("_CYC600_") {
                            out.push(
                                RULE.at(variable.span)
                                    .message(format!("CYCLE600 results read without STOPRE after the call on line {}", call_row + 1))
                                    .label("may still hold the previous results")
                                    .help("write STOPRE in its own block after the CYCLE600 call"),
                            );
                            self.pending = None;
                            break;
                        }
                    }
                }
            }
        }
    }
}
