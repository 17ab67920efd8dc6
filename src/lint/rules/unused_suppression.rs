//! N099 `unused-suppression`: found while applying `; sinuprep: ignore`
//! comments (`lint::suppression`); this file documents it.

use crate::diagnostic::{RuleInfo, Severity};

pub static RULE: RuleInfo = RuleInfo {
    code: "N099",
    name: "unused-suppression",
    severity: Severity::Info,
    docs: r#"## What it does
Reports a `; sinuprep: ignore CODE` or `; sinuprep: ignore-file CODE` comment that suppresses
nothing: it covers no finding, its directive is misspelt (`ignor`, with a did-you-mean), or its
code names no rule (`N05`, with a did-you-mean). Directives and codes are read in any case.

## Why it matters
A stale suppression hides the next real finding of that rule on the block, and misleads readers;
a misspelt one suppresses nothing while it seems to.

## Example
```
N10 G0 X0 ; sinuprep: ignore N005
N20 X=UNDEFINED_NAME ; sinuprep: ignor N005
```

## Fix
Remove the suppression (or the code from its list), or correct its spelling. `check --fix` removes
the codes that suppress nothing (a safe fix; codes of rules not checked in the run are kept), and
the comment when it held only the suppression."#,
};
