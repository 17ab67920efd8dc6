//! C617 `cycle600-frames-over-programmable-frame`: found by the rewrite
//! (`emit::cycle600`) from the walk's frame facts (`semantic::frames`); this
//! file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C617",
    name: "cycle600-frames-over-programmable-frame",
    severity: Severity::Error,
    docs: r#"## What it does
Refuses to rewrite a swivelling call (`_SW_REC=0`) as frames (`--emit frames` or `--emit traori`)
where a frame statement of the program's own (`TRANS X10`, `AROT Z=5`, `$P_PFRAME=...`, a
`TOFRAME`) may be active in the programmable frame at the call.

## Why it matters
The frames form starts with `TRANS`, which replaces the whole programmable frame: the program's
own offset or rotation would be dropped without a word, and the part machined in the wrong place.
CYCLE800 (and so CYCLE600 on the control) keeps the programmable frame. Blocks that sinuprep
itself emitted (below a `; sinuprep:` line) do not count; `TRANS` or `ROT` without values clears
the programmable frame (Siemens, Fundamentals: "TRANS, ROT without values clear the programmable
frame").

## Example
```
N10 AROT Z=5
N20 CYCLE600(0, "UFK600", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 39, 0, 0, 0)
```

## Fix
Rewrite with `--emit cycle800`, or clear the programmable frame (`TRANS`) before the call."#,
};
