//! C605 `cycle600-unknown-argument`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C605",
    name: "cycle600-unknown-argument",
    severity: Severity::Error,
    docs: r#"## What it does
Finds CYCLE600 arguments whose value is not known offline: measured by a probe, never assigned, written in a loop. An error for `rewrite`, which leaves the call unchanged; info for `check`.

## Why it matters
The conversion cannot be done before the program reaches the control.

## Example
```
N40 R10=_OVR[16]
N50 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, R10, 0, 0, 0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
Give the measured value with `--set R10=...` or `--values FILE`, or let the control compute it with `rewrite --emit-runtime`."#,
};
