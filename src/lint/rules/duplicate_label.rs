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
where the jump stands: rarely what was meant. Not reported: repeated block numbers, and `ENDLABEL`,
the predefined label that ends a section `REPEAT` repeats, which the manual lets stand as often as
there are sections (Siemens, Job Planning, "Program section repetition (REPEAT, REPEATB,
ENDLABEL, P)").

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
        let repeated = file.labels().repeated();
        for (span, name, first) in repeated.into_iter().filter(|(_, n, _)| n != "ENDLABEL") {
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
