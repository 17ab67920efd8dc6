//! K006 `unreadable-machine-data`: found where machine data are read
//! (`machine::data`: `check` of a file of machine data, and `sinuprep
//! machine`); this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "K006",
    name: "unreadable-machine-data",
    severity: Severity::Warning,
    docs: r#"## What it does
Reports a line of machine data (`$MN_`, `$MC_`, `$MA_`) or setting data (`$SN_`, `$SC_`, `$SA_`)
that sinuprep cannot read, in a file of machine data (an `.INI` the control writes, an archive's
`INITIAL_INI`, or any file whose blocks are machine data): a value that is no constant (`$MA_POS_LIMIT_PLUS[AX1]=_LIMIT`), an index that is neither a whole number
nor an axis (`[AX1]`, `[0,AX1]`), a `CHANDATA` without its channel's number, a frame
(`$P_UIFR[n]`, `$P_NCBFR[n]`, `$P_CHBFR[n]`) written whole other than as a chain of `CTRANS`,
`CFINE`, `CROT`, `CSCALE` and `CMIRROR` with constants, each at most once. A line with a
syntax error is not read either; the syntax error is its finding. The checksum a line of an
archive may end in (` '5b7e`) is not part of the line's datum.

## Why it matters
What sinuprep knows of the machine (its axes, their limits and dynamics) comes from these data
alone: a datum it cannot read is one it does not know, and it says so rather than assume a
value.

## Example
```
CHANDATA(1)
N36110 $MA_POS_LIMIT_PLUS[AX1]=_LIMIT
```

## Fix
Copy the data from the control as it writes them (`INITIAL.INI`, the archive of a series
start-up), or correct the line the finding names."#,
};
