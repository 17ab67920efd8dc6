//! C616 `cycle600-shares-block`: found by the CYCLE600 walk (`semantic::cycle600`),
//! which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C616",
    name: "cycle600-shares-block",
    severity: Severity::Error,
    docs: r#"## What it does
Finds CYCLE600 calls followed by other statements in the same block.

## Why it matters
`rewrite` replaces the call with several blocks (and comments that say what each computes). What
followed the call would run between those blocks, or end up inside a comment and not run at all.
A cycle call belongs in a block of its own.

## Example
```
N10 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0) X5
```

## Fix
```
N10 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)
N11 X5
```"#,
};
