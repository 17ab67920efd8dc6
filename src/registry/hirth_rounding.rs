//! K004 `hirth-rounding`: found by `semantic::swivels` when `check` is
//! given a machine; this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K004",
    name: "hirth-rounding",
    severity: Severity::Warning,
    docs: r#"## What it does
With a machine given, reports the swivel (as K002 finds them) on a record with Hirth-toothed axes
(`$TC_CARR26..29`) whose axis positions, rounded to the teeth, turn the tool direction by more
than the tolerance away from the orientation asked: `hirth-tolerance` in sinuprep.toml, in
degrees (default 0.01).

## Why it matters
An indexed axis can only stop on its teeth; the control rounds the positions and machines in the
orientation the teeth give, not in the one programmed (Siemens, swivel data: Hirth tooth system).
A probed misalignment of 0.3° on a 1° coupling is not corrected at all.

## Example
With the sample machine's indexed head (`HIRTH_CA`, C every 1°, A every 2.5°):
```
CYCLE800(1,"HIRTH_CA",0,57,0,0,0,31.3,0,0,0,0,0,-1)   ; C=180 A=-31.3 asked, A=-32.5 taken
```

## Fix
Swivel to an orientation on the grid and take up the rest with a frame rotation or the CAM
program, or accept the error by raising `hirth-tolerance`."#,
};
