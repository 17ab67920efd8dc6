//! C606 `cycle600-gimbal-lock`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C606",
    name: "cycle600-gimbal-lock",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds conversions whose output is at gimbal lock (middle angle ±90° Tait-Bryan, 0°/180° proper Euler).

## Why it matters
Only the sum or difference of the first and third angle is defined; the third is set to 0 and the first carries the whole rotation. The rotation is exact, but a two-axis head may reach it another way than expected.

## Example
```
N10 CYCLE600(1, "UFK600", 0, 57, 0, 0, 0, 10, 90, 40, 0, 0, 0, 1, 57, 0, 0, 0)
```

## Fix
Check that the head may take that position; choose another output order to avoid the lock."#,
};
