//! K007 `axis-beyond-limit`: found by the dry run (`run::execute`:
//! `sinuprep run`, and `check` and the language server where a machine is
//! given, `run::on_machine`); this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K007",
    name: "axis-beyond-limit",
    severity: Severity::Error,
    docs: r#"## What it does
Reports a block of the dry run (`sinuprep run PROGRAM --machine M`) that takes a machine axis
past its software limit: MD36100 `$MA_POS_LIMIT_MINUS` or MD36110 `$MA_POS_LIMIT_PLUS` (the
second pair, MD36120/MD36130, with `--second-limits`), with the axis, the furthest position the
block reaches, the limit and by how much. The position is the machine axis's (MCS): the programmed
point through the settable frame (G54..G599 from `$P_UIFR`), the programmable frame (TRANS,
ATRANS, ROT, AROT) and the tool's length (`$TC_DP3` of the active T and D along the plane's infeed
axis). An arc is checked at its ends and at the points where an axis turns inside it; a straight
move (G0 as G1) reaches its furthest points at its ends, except under TRAORI, where the linear
axes follow curves as the tool turns and the way (along the arc, for G2/G3) is sampled and its
extremes searched. A modulo
rotary axis (MD30310) has no limits. `sinuprep check` and the language server report it too where
a machine is given (`--machine`, `machine` in sinuprep.toml): for a program up to 10 MB, run on its
own (the subprograms it calls are `sinuprep run`'s to follow).

The limits and every other datum come from the machine's own data; an axis without them is not
checked, and the run says so.

## Why it matters
The control stops the program with alarm 10720 ("software limit switch") when an axis would pass
its limit (Siemens, SINUMERIK 840D sl Diagnostics Manual, alarm 10720; Function Manual Basic
Functions, "Axis monitoring": software limit switches): on the machine, at that block, often after
hours of machining. Knowing it before the program reaches the machine saves the part and the time.

## Example
```
G54 T1 M6 D1
G0 Z-400   ; with a tool of 95.5 mm and G54's Z, beyond MD36100 of Z1
```

## Fix
Program the move within the travel (a shorter approach, another clamping position, the zero
offset set as on the machine); or check that the machine data and frames given are those of the
machine that runs the program."#,
};
