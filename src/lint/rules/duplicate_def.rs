//! N007 `duplicate-def`: Finds a variable defined twice (DEF or PROC parameter), names compared without case.

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N007",
    name: "duplicate-def",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a variable defined twice (DEF or PROC parameter), names compared without case.

## Why it matters
The control refuses a second definition of the same name (alarm 12080 and its kin).

## Example
```
DEF REAL ANG
DEF INT ANG
```

## Fix
Remove one definition or rename one variable."#,
};

#[derive(Default)]
pub struct Checker {
    seen: HashMap<String, usize>,
}

impl Check for Checker {
    fn line(&mut self, file: &FileContext, row: usize, line: &LineView, out: &mut Vec<Diagnostic>) {
        let Some(block) = line.block else {
            return;
        };
        for statement in &block.statements {
            let names: Vec<Span> = match &statement.kind {
                StatementKind::Def(def) => def.variables.iter().map(|d| d.name.span).collect(),
                StatementKind::Proc(proc) => proc
                    .parameters
                    .iter()
                    .map(|p| p.declarator.name.span)
                    .collect(),
                _ => continue,
            };
            for span in names {
                let name = upper(file.source, span);
                if let Some(first) = self.seen.get(&name) {
                    out.push(
                        RULE.at(span)
                            .message(format!("`{name}` is already defined on line {}", first + 1))
                            .label("defined again")
                            .help("remove one definition, or rename one of the variables"),
                    );
                } else {
                    self.seen.insert(name, row);
                }
            }
        }
    }
}
