//! C608 `cycle600-additive-extrinsic-unknown-active`: found by the CYCLE600 walk (`semantic::cycle600`,
//! `emit`), which `check`, `rewrite` and `eval` share; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C608",
    name: "cycle600-additive-extrinsic-unknown-active",
    severity: Severity::Error,
    docs: r#"## What it does
Finds an additive (`_ROT_AD=1`) extrinsic rotation while the active rotation is unknown offline.

## Why it matters
An extrinsic addition composes as R_add * R0: without R0 the total cannot be computed (an intrinsic one can be left to the control).

## Example
```
N10 CYCLE800(0,"UFK600",0,57,0,0,0,0,0,R5,0,0,0,-1)
N20 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, 10, 0, 0, 0, 0, 0, 1, 57, 1, 0, 0)
```

## Fix
Make the earlier swivel known offline, or give the total rotation with `_ROT_AD=0`."#,
};
