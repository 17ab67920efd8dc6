//! C609 `cycle600-invalid-argument`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C609",
    name: "cycle600-invalid-argument",
    severity: Severity::Error,
    docs: r#"## What it does
Finds arguments without a finite value (`ASIN(2)`, `0/0`) or of the wrong type (a string for an angle).

## Why it matters
The control stops with an arithmetic alarm, or the cycle reads nonsense.

## Example
```
N10 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, ASIN(2), ...)
```

## Fix
Correct the expression."#,
};
