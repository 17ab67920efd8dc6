//! K002 `swivel-unreachable`: found by `semantic::swivels` when `check` is
//! given a machine; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K002",
    name: "swivel-unreachable",
    severity: Severity::Error,
    docs: r#"## What it does
With a machine given (`check --machine FILE`, `machine = "..."` in sinuprep.toml), solves each
swivel of the program on the swivel data record it names: every CYCLE800 whose arguments are
constants (a new plane, `_ST` ending in 0, axis by axis, `_MODE` below 64, `_DIR` -1 or 1) and
every CYCLE600 evaluated offline (the CYCLE800 its rewrite writes). Reports the swivel whose
orientation no position of the record's rotary axes reaches, or reaches only outside the axis
limits (`$TC_CARR30..33`). Additive swivels, swivels whose arguments are known only at run time
and other `_MODE`s are left to the control.

## Why it matters
The control finds out when the cycle runs: it stops with a cycle alarm in the middle of the
program (Siemens, CYCLE800: "swivel plane not possible"), often with a heavy part clamped.

## Example
With the sample machine's 45° nutating head (`samples/MACHINE.SPF`, record `NUTATING_M`), which
tilts the tool by 90° at most:
```
CYCLE800(1,"NUTATING_M",0,57,0,0,0,120,0,0,0,0,0,-1)
```

## Fix
Swivel to an orientation the head or table can take (clamp the part otherwise, or turn it with
another axis), or name the record that can."#,
};
