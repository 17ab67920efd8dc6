//! N018 `argument-count-mismatch`: Finds calls that pass more arguments than the PROC (in the same file) or the EXTERN declaration

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N018",
    name: "argument-count-mismatch",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds calls that pass more arguments than the PROC (in the same file) or the EXTERN declaration
of the called subprogram has parameters.

## Why it matters
The control refuses the call (alarm 12340 and its kin) when there are too many arguments; fewer
are allowed (omitted trailing ones are 0), so they are not reported.

## Example
```
EXTERN ALIGN(REAL, REAL)
N10 ALIGN(1, 2, 3)
```

## Fix
Match the call to the declaration."#,
};

#[derive(Default)]
pub struct Checker {
    declared: HashMap<String, usize>,
    calls: Vec<(String, usize, Span)>,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        _out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block else {
            return;
        };
        for statement in &block.statements {
            match &statement.kind {
                StatementKind::Proc(proc) => {
                    self.declared
                        .insert(upper(file.source, proc.name.span), proc.parameters.len());
                }
                StatementKind::Extern { name, parameters } => {
                    let count = parameters.map_or(0, |p| {
                        let inner = &p.of(file.source)[1..p.len().saturating_sub(1).max(1)];
                        if inner.iter().all(|b| b.is_ascii_whitespace()) {
                            0
                        } else {
                            inner.iter().filter(|&&b| b == b',').count() + 1
                        }
                    });
                    self.declared.insert(upper(file.source, name.span), count);
                }
                StatementKind::Call(call) => {
                    self.calls.push((
                        upper(file.source, call.name.span),
                        call.arguments.items.len(),
                        call.arguments.span,
                    ));
                }
                _ => {}
            }
        }
    }

    fn finish(&mut self, _file: &FileContext, out: &mut Vec<Diagnostic>) {
        for (name, count, span) in &self.calls {
            if let Some(&parameters) = self.declared.get(name) {
                if *count > parameters {
                    out.push(
                        RULE.at(*span)
                            .message(format!(
                                "`{name}` takes {parameters} argument(s), this call passes {count}"
                            ))
                            .label("too many arguments")
                            .help(format!(
                                "pass at most {parameters} argument(s), or extend the declaration"
                            )),
                    );
                }
            }
        }
    }
}
