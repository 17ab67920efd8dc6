//! C614 `cycle600-results-without-stopre`: Finds a read of `_CYC600_1` .. `_CYC600_6` after a CYCLE600 call with no STOPRE between them.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::semantic::model::is_stopre;
use crate::syntax::tree::{starts_with_upper, StatementKind};

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
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    fn statement(&mut self, file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let (source, statement) = (file.source, at.statement);
        match &statement.kind {
            _ if is_stopre(source, statement) => self.pending = None,
            StatementKind::Call(call) if call.name.is(source, "CYCLE600") => {
                self.pending = Some(at.row)
            }
            _ => {
                let Some(call_row) = self.pending else {
                    return;
                };
                let mut reads = at.reads();
                if let Some(variable) =
                    reads.find(|v| starts_with_upper(v.name.text(source), "_CYC600_"))
                {
                    out.push(
                        RULE.at(variable.span)
                            .message(format!(
                                "CYCLE600 results read without STOPRE after the call on line {}",
                                call_row + 1
                            ))
                            .label("may still hold the previous results")
                            .help("write STOPRE in its own block after the CYCLE600 call"),
                    );
                    self.pending = None;
                }
            }
        }
    }
}
