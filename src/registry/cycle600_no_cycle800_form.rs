//! C611 `cycle600-no-cycle800-form`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C611",
    name: "cycle600-no-cycle800-form",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a swivelling call (`_SW_REC=0`) with a proper Euler output (ZXZ, ...) rewritten as CYCLE800.

## Why it matters
CYCLE800 swivels axis by axis in the six Tait-Bryan orders only.

## Example
```
N10 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 55, 0, 0, 0)
```

## Fix
Rewrite with `--emit frames`, or choose a Tait-Bryan `_BIN_OUT`."#,
};
