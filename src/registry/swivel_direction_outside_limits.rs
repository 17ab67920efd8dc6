//! K003 `swivel-direction-outside-limits`: found by `semantic::swivels`
//! when `check` is given a machine; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K003",
    name: "swivel-direction-outside-limits",
    severity: Severity::Warning,
    docs: r#"## What it does
With a machine given, reports the swivel (as K002 finds them) whose `_DIR` solution, the lower
(`-1`) or higher (`1`) position of the record's direction-reference axis, lies outside the axis
limits while the other solution lies inside them: the finding names both sets of positions.

## Why it matters
The control then takes the other solution without a word (Siemens, CYCLE800 `_DIR`: "if the
selected direction cannot be reached, the alternative is selected automatically"): the head or
table turns the other way than the program says, and what stands around it (a fixture, a
clamp, the cable of a probe) may not be where the programmer looked.

## Example
With the sample machine's trunnion table (`TABLE_AC`, A from -120° to 30°):
```
CYCLE800(1,"TABLE_AC",0,57,0,0,0,60,0,0,0,0,0,1)   ; A=60 asked, A=-60 taken
```

## Fix
Give `_DIR` the sign of the solution that is taken, so that the program says what the machine
does."#,
};
