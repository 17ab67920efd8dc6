//! N013 `main-run-read-without-stopre`: Finds a read, during preprocessing, of a variable a synchronized action writes in the main run, with no STOPRE between them.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use std::collections::HashMap;

use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::semantic::eval::key;
use crate::semantic::model::is_stopre;
use crate::semantic::structure::sync_writes;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N013",
    name: "main-run-read-without-stopre",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a read, in the part program, of a variable a synchronized action of the program writes in the
main run (`DO $R1=...`, then `R2=R1`), with no STOPRE between the synchronized action and the read.

## Why it matters
The control prepares (preprocesses) blocks ahead of the main run. A synchronized action writes in the
main run, at a time preprocessing cannot know: a block prepared before that reads the value the
variable had before. STOPRE makes preprocessing wait until the main run has caught up.

Reading a main-run variable itself (`$AA_IW`, `$AA_MW`, `$AC_PARAM`, `$A_IN`, ...) is not reported:
the control stops preprocessing for such a read on its own (an implicit preprocessing stop; Siemens
machine data text: "run-in/main-run synchronization block (e.g. STOPRE, $Variable)"). Nor are
reads inside synchronized actions, which run in the main run.

## Example
```
N10 WHEN $AA_IW[Z]>10 DO $R1=$AA_IW[X]
N20 G1 Z20 F100
N30 R2=R1*2          ; R1 as it was before N10's action ran
```

## Fix
Write STOPRE in its own block before the read. (A value written at an unknown time may still be
written after the STOPRE: the read then sees the main run's value at the STOPRE.)"#,
};

/// The variables synchronized actions wrote (in the walk's keys), each with
/// the line of the action, since the last STOPRE.
#[derive(Default)]
pub struct Checker {
    written: HashMap<String, usize>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    fn statement(&mut self, file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let statement = at.statement;
        if is_stopre(file.source, statement) {
            self.written.clear();
            return;
        }
        if let StatementKind::SyncAction(sync) = &statement.kind {
            for name in sync_writes(file.source, sync) {
                self.written.insert(name, at.row);
            }
            return;
        }
        if self.written.is_empty() {
            return;
        }
        for variable in at.reads() {
            let name = upper(file.source, variable.name.span);
            if name.starts_with('$') {
                continue;
            }
            let read = if variable.indices.is_empty() {
                key(&name, &[])
            } else {
                name
            };
            let Some(action) = self.written.remove(&read) else {
                continue;
            };
            out.push(
                    RULE.at(variable.span)
                        .message(format!(
                            "`{read}` is written in the main run by the synchronized action on line {}, and read here without STOPRE",
                            action + 1
                        ))
                        .label("may read the value before the action wrote it")
                        .help("write STOPRE in its own block before this one"),
                );
        }
    }
}
