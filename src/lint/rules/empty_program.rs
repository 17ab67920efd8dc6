//! N020 `empty-program`: Finds a program without a single block that executes anything.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, OnModel};
use crate::lint::rules::support::is_definition_file;
use crate::span::Span;

pub static RULE: RuleInfo = RuleInfo {
    code: "N020",
    name: "empty-program",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a program that has no block executing anything: only comments, empty lines, labels or
declarations (DEF, PROC, EXTERN, ...). Definition files (`.DEF`, `.INI`, `.GUD`, `.COM`) are not
checked: declarations are what they hold.

## Why it matters
Started, such a program does nothing; most often a file emptied by a failed transfer or saved
before it was written. Reported once, at the start of the file; the missing end (N010) is not
reported again for it.

## Example
```
; PART_17 - roughing
```

## Fix
Write the program, or remove the file."#,
};

/// Reads the model's first executable block once the pass is over.
pub struct Checker;

impl OnModel for Checker {
    fn check(file: &FileContext, out: &mut Vec<Diagnostic>) {
        if file.model().first_executable.is_some() || is_definition_file(file.name) {
            return;
        }
        let first_line = crate::span::line_end(file.source, 0);
        out.push(
            RULE.at(Span::new(0, first_line))
                .message("the program has no block that executes anything")
                .label("nothing to run in this file")
                .help("write the program's blocks, or remove the file"),
        );
    }
}
