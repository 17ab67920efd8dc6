//! C607 `cycle600-reserved-not-zero`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C607",
    name: "cycle600-reserved-not-zero",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a 19-value call whose reserved 14th value is not 0 or empty.

## Why it matters
The paper's calls carry this extra value as 0; anything else suggests the arguments are shifted.

## Example
```
N10 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 5, 1, 39, 0, 0, 0)
```

## Fix
Write 0, or use the canonical 18-argument form."#,
};
