//! C601 `cycle600-argument-count`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C601",
    name: "cycle600-argument-count",
    severity: Severity::Error,
    docs: r#"## What it does
Finds CYCLE600 calls with neither 18 (canonical) nor 19 (the paper's form) arguments.

## Why it matters
Every parameter after a missing or extra one is read in the wrong place: angles become translations, flags become codes.

## Example
```
N10 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, 1, 2, 3, 0, 0, 0, 1, 39, 0, 0)   ; 17
```

## Fix
Write the 18 parameters; empty positions (`,,`) count as 0."#,
};
