//! K001 `invalid-swivel-data`: found where a machine file is read
//! (`semantic::machine`, through `workspace::Workspace::machine` for every
//! command); this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K001",
    name: "invalid-swivel-data",
    severity: Severity::Error,
    docs: r#"## What it does
Reports what in a machine file (`--machine`, `machine = "..."` in sinuprep.toml) cannot be the
swivel data records the control holds: an assignment to `$TC_CARRn[m]` whose `n` names no
parameter (1 to 65 less 47-54 and 61-63: the control raises an alarm for them), a record number
that is not a whole number from 1 to 999999, a value that is not a constant or not of the parameter's
type (a value that reads a variable, `$TC_CARR5[1]=_RT_HOEHE_Y`, as setup programs of some machine
builders write, is read from the values given with `--set` or a `values` file; without one the
finding names the variable), a kinematic type other than T, P or M (`$TC_CARR23`, alarm 14153), and a record with a
name or axes whose data cannot describe a machine: rotary axis 1 without a direction vector,
mixed kinematics with one axis, two parallel axes, a position limit (`$TC_CARR30..33`) beyond
±100,000,000 degrees (no rotary axis has one: it is a typo or garbage), a minimum position above
the maximum, a negative Hirth increment. `check`, `eval`, `rewrite` and `axes` read a machine file
the same way and report the same findings; K001 is an error (exit 1).

Only swivel *data* are checked so: the machine file, and an archive's data members. In a program
(a measuring cycle that writes what it measured, `$TC_CARR5[1]=_RT_HOEHE_Y`) a `$TC_CARR`
assignment is a write at run time, whose value may be any expression: `check` reports nothing
there.

## Why it matters
sinuprep computes the rotary axis positions from these data; a record it cannot trust gives no
answer rather than a wrong one.

## Example
```
$TC_CARR7[1]=0 $TC_CARR8[1]=0 $TC_CARR9[1]=1
$TC_CARR10[1]=0 $TC_CARR11[1]=0 $TC_CARR12[1]=-1
```

## Fix
Copy the records from the control as they are (a setup program, `TO_INI.INI`, an archive's
`INITIAL.INI`), or correct the assignment the finding names; for a variable, give the value the
control holds (`--set _RT_HOEHE_Y=125.5`)."#,
};
