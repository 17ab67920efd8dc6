//! C603 `cycle600-flag-not-boolean`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C603",
    name: "cycle600-flag-not-boolean",
    severity: Severity::Error,
    docs: r#"## What it does
Finds BOOL parameters (`_INEXIN`, `_SW_REC`, `_INEXOUT`, `_ROT_AD`, `_ROT_INV`, `_RETR_Z`) that are not 0 or 1.

## Why it matters
The cycle's behaviour for other values is undefined.

## Example
```
N10 CYCLE600(0, "UFK600", 2, 57, ...)
```

## Fix
Write 0 or 1."#,
};
