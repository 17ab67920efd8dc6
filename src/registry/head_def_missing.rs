//! C610 `head-def-missing`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C610",
    name: "head-def-missing",
    severity: Severity::Warning,
    docs: r#"## What it does
Reports, once per file with CYCLE600 calls, that no HEAD_DEF was found to check `_MIHEAD` against.

## Why it matters
Head names are then not checked at all.

## Example
```
A program without a HEAD_DEF.SPF next to it.
```

## Fix
Put HEAD_DEF.SPF next to the program, pass `--heads FILE`, or set `heads` in sinuprep.toml."#,
};
