//! N016 `unused-variable`: Finds local variables (DEF without NCK/CHAN) that the program never reads.

use std::collections::HashSet;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N016",
    name: "unused-variable",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds local variables (DEF without NCK/CHAN) that the program never reads.

## Why it matters
An unused variable is dead weight at best, and often the trace of a typo: the value was written
to one name and read from another.

## Example
```
DEF REAL ANG, DX
N10 ANG=30
N20 G0 X=ANG      ; DX is never read
```

## Fix
Remove the variable, or read it where it was meant to be read."#,
};

#[derive(Default)]
pub struct Checker {
    defined: Vec<(String, Span)>,
    read: HashSet<String>,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        _out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block.filter(|_| !line.plain) else {
            return;
        };
        for (index, statement) in block.statements.iter().enumerate() {
            if let StatementKind::Def(def) = &statement.kind {
                if def.scope.is_none() {
                    self.defined.extend(
                        def.variables
                            .iter()
                            .map(|d| (upper(file.source, d.name.span), d.name.span)),
                    );
                }
            }
            self.read
                .extend(line.reads(index).map(|v| upper(file.source, v.name.span)));
        }
    }

    fn finish(&mut self, _file: &FileContext, out: &mut Vec<Diagnostic>) {
        for (name, span) in &self.defined {
            if !self.read.contains(name) {
                out.push(
                    RULE.at(*span)
                        .message(format!("`{name}` is defined but never read"))
                        .label("never read")
                        .help("remove it, or read it where it was meant to be read"),
                );
            }
        }
    }
}
