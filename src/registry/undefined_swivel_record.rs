//! K005 `undefined-swivel-record`: found by `semantic::swivels` when
//! `check` is given a machine; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K005",
    name: "undefined-swivel-record",
    severity: Severity::Error,
    docs: r#"## What it does
With a machine given, reports a swivel (a CYCLE800 with constant arguments, or a CYCLE600
evaluated offline: its head) that names a swivel data record the machine file does not define,
by name (`$TC_CARR34`) or number; the finding lists the records it holds.

## Why it matters
The control stops the cycle with an alarm (Siemens, CYCLE800 `_TC`: the swivel data record
must exist); a misspelt or renamed record is found only when the program reaches it.

## Example
```
CYCLE800(1,"HEAD_AC",0,57,0,0,0,0,30,0,0,0,0,-1)   ; the machine calls it HEAD_CA
```

## Fix
Name a record of the machine, or add the record to the machine's swivel data."#,
};
