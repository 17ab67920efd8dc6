//! N012 `traori-at-end`: Finds a main program that switches on TRAORI and ends with it still active.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::command_name;
use crate::span::Span;
use crate::syntax::ProgramKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N012",
    name: "traori-at-end",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a main program that switches on TRAORI and ends with it still active.

## Why it matters
The next program starts with the 5-axis transformation on (unless machine data resets it), so its
coordinates mean something else than its author assumed.

Subprograms are not checked: a cycle returns to its caller, and one that switches the caller's
transformation back on before `M17` (`IF _VA_TRAFO_AKTIV==TRUE TRAORI ENDIF`) restores the state
it was called in. Whether a subprogram is one is read from its PROC line, its header or its
extension.

## Example
```
N10 TRAORI
N20 G1 X10 A3=0 B3=0 C3=1
N30 M30
```

## Fix
Switch it off with TRAFOOF before the end."#,
};

#[derive(Default)]
pub struct Checker {
    active: Option<Span>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    fn statement(&mut self, file: &FileContext, at: &StatementAt, _out: &mut Vec<Diagnostic>) {
        let Some(name) = command_name(at.statement) else {
            return;
        };
        if name.is(file.source, "TRAORI") {
            self.active = Some(at.statement.span);
        } else if name.is(file.source, "TRAFOOF") {
            self.active = None;
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        if file.kind != ProgramKind::Main {
            return;
        }
        if let Some(span) = self.active {
            out.push(
                RULE.at(span)
                    .message("TRAORI is still active when the program ends")
                    .label("switched on here, never off")
                    .help("add TRAFOOF before the program end"),
            );
        }
    }
}
