//! C604 `cycle600-unknown-head`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C604",
    name: "cycle600-unknown-head",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a `_MIHEAD` that HEAD_DEF does not define, or defines with `_HEAD_ALLOWED` other than 1 (with a did-you-mean).

## Why it matters
CYCLE600 raises an error on the control; offline nothing can be checked against the accessory.

## Example
```
N10 CYCLE600(0, "UFK060", ...)   ; HEAD_DEF has UFK600
```

## Fix
Correct the name, or allow the accessory in HEAD_DEF."#,
};
