//! C620 `cycle600-split-over-table`: found by the rewrite (`emit::cycle600`,
//! worded by `emit::split`) on a machine with a rotary table under its heads;
//! this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "C620",
    name: "cycle600-split-over-table",
    severity: Severity::Error,
    docs: r#"## What it does
Refuses to rewrite a swivelling call (`_SW_REC=0`) as CYCLE800 when the machine has a rotary table
under the head record the call names: the table is named with `--table NAME` (or `table = "NAME"`
beside `machine` in sinuprep.toml), a record of kinematics `P` with one rotary axis, and lies under
every head record (`T`, two rotary axes) of the machine. The swivel is then split over three
rotary axes as `sinuprep axes --record HEAD --table NAME` splits it (the table's angle chosen with
the head nearest the middles of its limits), and the finding says what the machine would be told:
the table's positioning block, the head's frame (the request with the table's turn taken out) as
CYCLE800 angles in the call's `_MODE`, the head's axis positions and the rotation left about the
tool. The call's bytes stay as they are. `eval --machine FILE --table NAME` shows the same split for
each call. The frames and TRAORI forms name no record and are written as before, the comment above
them naming the split's positions (`; sinuprep: with the table TABLE_B under HEAD_H the axes go to
B=50.361 C=0 A=-16.28`).

## Why it matters
CYCLE800 drives one swivel data record, and a record combines two rotary axes at most (Siemens,
Commissioning Manual, CYCLE800 checklist: "Combinations of two (or one) rotary axis and the three
linear axes are always formed"; a tool carrier on a kinematic chain may hold more rotary axes, but
only two are its own: `$TC_CARR_KIN_ROTAX_NAME[n,m]`, m 0 or 1, Function Manual Tools, W1). No
Siemens text found says that a table turned (`G0 B=..`, `PAROT`) before a CYCLE800 on the head's
record keeps its turn in the frame: the same `$P_PARTFRAME` holds `TCARR`'s and `PAROT`'s frame.
The plain rewrite, CYCLE800 on the head's record alone, would leave the table out and make the head
take the whole rotation, which it may not reach, or reaches with other positions.

## Example
With `--machine samples/MACHINE.SPF --table TABLE_B` (a table B under the head `HEAD_H`):
```
N10 CYCLE600(0, "HEAD_H", 0, 57, 0, 0, 0, 30, 45, 60, 0, 0, 0, 1, 57, 0, 0, 0)
```

## Fix
Position the table and swivel the head as the message says (a person who has checked the sequence on
the machine), or keep CYCLE600 on the control; without `--table` the call is rewritten as CYCLE800
of its head record."#,
};
