//! N011 `identifier-too-long`: Finds variable, label and procedure names longer than 31 characters.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, Sees, StatementAt};
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
    fn sees(&self) -> Sees {
        Sees::DECLARATIONS | Sees::BLOCKS
    }

    /// A label is its block's.
    fn block(&mut self, _file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        check(at.block.label.iter().map(|l| l.span), out);
    }

    fn declaration(&mut self, _file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        match &at.statement.kind {
            StatementKind::Def(def) => check(def.variables.iter().map(|d| d.name.span), out),
            StatementKind::Proc(proc) => {
                let parameters = proc.parameters.iter().map(|p| p.declarator.name.span);
                check(std::iter::once(proc.name.span).chain(parameters), out);
            }
            _ => {}
        }
    }
}

/// A finding on each of `names` longer than the control allows.
fn check(names: impl Iterator<Item = Span>, out: &mut Vec<Diagnostic>) {
    for span in names.filter(|s| s.len() > LIMIT) {
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
