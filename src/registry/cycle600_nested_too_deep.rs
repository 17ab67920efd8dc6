//! C618 `cycle600-nested-too-deep`: found by the CYCLE600 walk
//! (`semantic::walk`), which `check`, `rewrite` and `eval` share; this file
//! documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C618",
    name: "cycle600-nested-too-deep",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a CYCLE600 call inside 512 or more nested IF/WHILE/FOR/LOOP/REPEAT blocks.

## Why it matters
The walk that evaluates CYCLE600 calls follows at most 511 levels of nesting, so that no program
can exhaust its stack. A call deeper than that is not evaluated: it is left as it is, and this
error says so instead of passing it over (`rewrite --check` fails on it).

## Example
```
IF R1==1
  IF R2==1
    ; ... 512 levels ...
      CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
Take the call out of some of the nested blocks (no real program nests this deep)."#,
};
