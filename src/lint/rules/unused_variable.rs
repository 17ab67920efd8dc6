//! N016 `unused-variable`: Finds local variables (DEF without NCK/CHAN) that the program never reads.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext};

pub static RULE: RuleInfo = RuleInfo {
    code: "N016",
    name: "unused-variable",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds local variables (DEF without NCK/CHAN) that the program never reads.

## Why it matters
An unused variable is dead weight at best, and often the trace of a typo: the value was written
to one name and read from another.

## Example
```
DEF REAL ANG, DX
N10 ANG=30
N20 G0 X=ANG      ; DX is never read
```

## Fix
Remove the variable, or read it where it was meant to be read."#,
};

/// The definitions and the names read are the model's.
#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let model = file.model();
        let local = model.symbols.iter().filter(|s| !s.global && !s.parameter);
        for symbol in local.filter(|s| !model.read_names.contains(&s.name)) {
            out.push(
                RULE.at(symbol.span)
                    .message(format!("`{}` is defined but never read", symbol.name))
                    .label("never read")
                    .help("remove it, or read it where it was meant to be read"),
            );
        }
    }
}
