//! N013 `main-run-read-without-stopre`: Finds reads of main-run variables (`$A...`: `$AA_IW`, `$AA_MW`, `$AC_...`) in the part program with

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView, PlainLine};
use crate::lint::rules::support::*;
use crate::semantic::model::is_stopre;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N013",
    name: "main-run-read-without-stopre",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds reads of main-run variables (`$A...`: `$AA_IW`, `$AA_MW`, `$AC_...`) in the part program with
no STOPRE since the last motion or call.

## Why it matters
The control prepares blocks ahead of the main run. Reading a main-run value forces an implicit
preprocessing stop, but relying on it hides the intent, and a value read in the wrong place (for
instance a measured one before the measurement has run) is stale.

## Example
```
N10 G1 Z=IC(2)
N20 R1=$AA_IW[Z]
```

## Fix
Write STOPRE in its own block before the read."#,
};

pub struct Checker {
    stopped: bool,
}

impl Default for Checker {
    fn default() -> Self {
        Self { stopped: true }
    }
}

impl Check for Checker {
    fn sees_plain_lines(&self) -> bool {
        true
    }

    /// An address word is motion (or may be): values read after it need a
    /// new STOPRE.
    fn plain_lines(
        &mut self,
        _file: &FileContext,
        lines: &[PlainLine],
        _out: &mut Vec<Diagnostic>,
    ) {
        if lines.iter().any(|line| line.facts.has_words) {
            self.stopped = false;
        }
    }

    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block else {
            return;
        };
        // Synchronized actions read main-run values in the main run: that is their purpose.
        if block
            .statements
            .iter()
            .any(|s| matches!(s.kind, StatementKind::SyncAction(_)))
        {
            return;
        }
        for (index, statement) in block.statements.iter().enumerate() {
            if is_stopre(file.source, statement) {
                self.stopped = true;
                continue;
            }
            for variable in line.reads(index) {
                let name = upper(file.source, variable.name.span);
                if name.starts_with("$A") && !self.stopped {
                    out.push(
                        RULE.at(variable.span)
                            .message(format!("`{name}` is a main-run value, read without STOPRE since the last motion"))
                            .label("read during preprocessing")
                            .help("write STOPRE in its own block before this one"),
                    );
                    self.stopped = true;
                }
            }
            if matches!(
                statement.kind,
                StatementKind::Word(_) | StatementKind::Call(_) | StatementKind::Command(_)
            ) {
                self.stopped = false;
            }
        }
    }
}
