//! N018 `argument-count-mismatch`: Finds calls that pass more arguments than the PROC (in the same file or a cycle directory) or the EXTERN declaration

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{CallAt, Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::semantic::calls::is_predefined;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N018",
    name: "argument-count-mismatch",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds calls that pass more arguments than the PROC (in the same file) or the EXTERN declaration
of the called subprogram has parameters. With the machine's cycle directories given (`cycles =
["CST", "CMA", "CUS"]` in sinuprep.toml, or `--cycles DIR`), the PROC headers of their `.SPF`
files count too; a declaration in the program comes first.

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
    fn sees(&self) -> Sees {
        Sees::DECLARATIONS | Sees::CALLS
    }

    fn declaration(&mut self, file: &FileContext, at: &StatementAt, _out: &mut Vec<Diagnostic>) {
        let source = file.source;
        match &at.statement.kind {
            StatementKind::Proc(proc) => {
                let name = upper(source, proc.name.span);
                self.declared.insert(name, proc.parameters.len());
            }
            StatementKind::Extern { name, parameters } => {
                let count = parameters.map_or(0, |p| parameter_count(p.of(source)));
                self.declared.insert(upper(source, name.span), count);
            }
            _ => {}
        }
    }

    fn call(&mut self, file: &FileContext, at: &CallAt, _out: &mut Vec<Diagnostic>) {
        let name = upper(file.source, at.call.name.span);
        let arguments = &at.call.arguments;
        self.calls
            .push((name, arguments.items.len(), arguments.span));
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let procedures = &file.environment.procedures;
        for (name, count, span) in &self.calls {
            // The program's own declarations first, then the cycle directories'.
            let machine = || {
                procedures
                    .get(name)
                    .map(|procedure| procedure.parameters.len())
            };
            let Some(parameters) = self.declared.get(name).copied().or_else(machine) else {
                // The control's commands and cycles are not looked for.
                if !is_predefined(name) {
                    file.unresolved_call(name);
                }
                continue;
            };
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

/// How many parameters `(REAL, VAR REAL A[2,3])` declares: its commas
/// outside brackets, plus one unless it is empty.
fn parameter_count(list: &[u8]) -> usize {
    let inner = list
        .strip_prefix(b"(")
        .and_then(|l| l.strip_suffix(b")"))
        .unwrap_or(list);
    if inner.iter().all(|b| b.is_ascii_whitespace()) {
        return 0;
    }
    let mut depth = 0usize;
    let mut commas = 0;
    for &byte in inner {
        match byte {
            b'[' | b'(' => depth += 1,
            b']' | b')' => depth = depth.saturating_sub(1),
            b',' if depth == 0 => commas += 1,
            _ => {}
        }
    }
    commas + 1
}

#[cfg(test)]
mod tests {
    use super::parameter_count;

    #[test]
    fn array_dimensions_are_not_parameters() {
        assert_eq!(parameter_count(b"(REAL, VAR REAL A[2,3])"), 2);
        assert_eq!(parameter_count(b"(AXIS,VAR BOOL)"), 2);
        assert_eq!(parameter_count(b"( )"), 0);
        assert_eq!(parameter_count(b"(INT)"), 1);
    }
}
