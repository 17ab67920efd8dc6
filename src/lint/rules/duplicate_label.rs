//! N003 `duplicate-label`: Finds a label defined twice in one program.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext};

pub static RULE: RuleInfo = RuleInfo {
    code: "N003",
    name: "duplicate-label",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a label defined twice in one program.

## Why it matters
A jump goes to the first label found in its search direction, so which block runs depends on
where the jump stands: rarely what was meant. (Repeated block numbers are allowed and not reported.)

## Example
```
N10 ENDE: M30
N90 ENDE: M30
```

## Fix
Rename one of the labels and the jumps meant for it."#,
};

/// The labels are the file's ([`FileContext::labels`]), read once the line
/// pass is over.
#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        for (span, name, first) in file.labels().repeated() {
            out.push(
                RULE.at(span)
                    .message(format!(
                        "label `{name}` is already defined on line {}",
                        first + 1
                    ))
                    .label("second definition")
                    .help("rename one of the labels, and the jumps meant for it"),
            );
        }
    }
}
