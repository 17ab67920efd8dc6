//! N003 `duplicate-label`: Finds a label defined twice in one program.

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, Severity};
use crate::lint::rule::{Check, FileContext, LineView, RuleInfo};
use crate::lint::rules::support::*;

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

#[derive(Default)]
pub struct Checker {
    seen: HashMap<String, usize>,
}

impl Check for Checker {
    fn line(&mut self, file: &FileContext, row: usize, line: &LineView, out: &mut Vec<Diagnostic>) {
        let Some(block) = line.block else {
            return;
        };
        let Some(label) = block.label else { return };
        let name = upper(file.source, label.span);
        match self.seen.get(&name) {
            Some(first) => out.push(
                RULE.at(label.span)
                    .message(format!(
                        "label `{name}` is already defined on line {}",
                        first + 1
                    ))
                    .label("second definition")
                    .help("rename one of the labels, and the jumps meant for it"),
            ),
            None => {
                self.seen.insert(name, row);
            }
        }
    }
}
