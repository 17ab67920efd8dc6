//! C602 `cycle600-invalid-sequence-code`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C602",
    name: "cycle600-invalid-sequence-code",
    severity: Severity::Error,
    docs: r#"## What it does
Finds `_BIN_IN`/`_BIN_OUT` values that are no axis sequence code (three 2-bit groups X=01, Y=10, Z=11, first rotation in bits 1-0, no axis twice in a row).

## Why it matters
CYCLE600 stops with an error, or converts to an order nobody meant.

## Example
```
N10 CYCLE600(0, "UFK600", 1, 58, ...)   ; 58 = Y, Y, Z
```

## Fix
Use 57 (XYZ), 45 (XZY), 54 (YXZ), 30 (YZX), 39 (ZXY), 27 (ZYX) or a proper Euler code (25, 29, 38, 46, 55, 59)."#,
};
