//! C619 `cycle600-rewritable`: a CYCLE600 call that `rewrite` can replace,
//! offered as a fix (`check --select C619 --fix`, an editor's code action);
//! found by `lint` from the walk and the rewrite, so that the fix is the
//! rewrite's own code.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C619",
    name: "cycle600-rewritable",
    severity: Severity::Info,
    docs: r#"## What it does
Finds CYCLE600 calls whose arguments are all known offline, and offers their rewrite as native
code (CYCLE800, frames or TRAORI, as `emit` in sinuprep.toml says) as a safe fix: the same bytes
`sinuprep rewrite` writes for that call, the original kept as a comment above.

Off by default: a program that keeps CYCLE600 on the control is not wrong. Select it by its code
(`check --select C619`, `select = ["C619"]`) to see the calls that could go, and add `--fix` to
rewrite them; an editor offers each as a code action.

## Why it matters
A call rewritten before the program goes to the control needs neither the custom cycle nor its
GUD variables on the machine, and the swivel it makes can be read in the program.

## Example
```
N10 CYCLE600(0, "UFK600", 1, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
What `sinuprep rewrite` writes for the call: the original as a `; sinuprep:` comment and the
CYCLE800 call (or frames) that makes the same rotation."#,
};
