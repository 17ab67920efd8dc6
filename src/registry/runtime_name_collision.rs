//! C612 `runtime-name-collision`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C612",
    name: "runtime-name-collision",
    severity: Severity::Error,
    docs: r#"## What it does
Finds programs whose own variables collide with those of `rewrite --emit-runtime` (`SNP_...`, or the `--runtime-r` range).

## Why it matters
The generated code would overwrite the program's values.

## Example
```
DEF REAL SNP_A1
```

## Fix
Rename the program's variables, or choose another `--runtime-r` range."#,
};
