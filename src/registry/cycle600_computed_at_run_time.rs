//! C613 `cycle600-computed-at-run-time`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C613",
    name: "cycle600-computed-at-run-time",
    severity: Severity::Info,
    docs: r#"## What it does
Reports calls that `rewrite --emit-runtime` turned into native arithmetic.

## Why it matters
The angles are computed on the control; the offline engine verified the formula, not the values.

## Example
```
N50 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, R10, R11, 0, 0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
Nothing to fix: read the generated code once."#,
};
