//! N011 `identifier-too-long`: Finds variable, label and procedure names longer than 31 characters.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N011",
    name: "identifier-too-long",
    severity: Severity::Error,
    docs: r#"## What it does
Finds variable, label and procedure names longer than 31 characters.

## Why it matters
The control limits identifiers (31 characters for variables in the manuals at hand; newer versions
allow 32); a longer name is refused or, worse, cut to one that collides with another.

## Example
```
DEF REAL THIS_IS_A_VERY_LONG_VARIABLE_NAME_1
```

## Fix
Shorten the name."#,
};

#[derive(Default)]
pub struct Checker;

const LIMIT: usize = 31;

impl Check for Checker {
    fn line(
        &mut self,
        _file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block else {
            return;
        };
        let mut names: Vec<Span> = block.label.iter().map(|l| l.span).collect();
        for statement in &block.statements {
            match &statement.kind {
                StatementKind::Def(def) => names.extend(def.variables.iter().map(|d| d.name.span)),
                StatementKind::Proc(proc) => {
                    names.push(proc.name.span);
                    names.extend(proc.parameters.iter().map(|p| p.declarator.name.span));
                }
                _ => {}
            }
        }
        for span in names.into_iter().filter(|s| s.len() > LIMIT) {
            out.push(
                RULE.at(span)
                    .message(format!(
                        "name of {} characters; the control allows {LIMIT}",
                        span.len()
                    ))
                    .label("too long")
                    .help("shorten the name"),
            );
        }
    }
}
