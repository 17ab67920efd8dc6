//! N006 `def-after-executable`: Finds a DEF after the first executable block of a program or subprogram.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, PlainLine, Sees, StatementAt};
use crate::semantic::model::is_declaration;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N006",
    name: "def-after-executable",
    severity: Severity::Error,
    docs: r#"## What it does
Finds a DEF after the first executable block of a program or subprogram.

## Why it matters
Definitions must precede the first executable statement; the control refuses the program
(alarm 12070 and its kin).

## Example
```
N10 G0 X0
N20 DEF REAL DEPTH=2.5
```

## Fix
Move the DEF to the top, after a PROC header and before the first executable block."#,
};

#[derive(Default)]
pub struct Checker {
    first_executable: Option<usize>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS | Sees::PLAIN_LINES
    }

    /// Address words are executable.
    fn plain_lines(
        &mut self,
        _file: &FileContext,
        lines: &[PlainLine],
        _out: &mut Vec<Diagnostic>,
    ) {
        if let Some(line) = lines.iter().find(|line| line.facts.has_words()) {
            self.first_executable.get_or_insert(line.row);
        }
    }

    fn statement(&mut self, _file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let statement = at.statement;
        match &statement.kind {
            StatementKind::Def(_) => {
                if let Some(first) = self.first_executable {
                    out.push(
                        RULE.at(statement.span)
                            .message(format!(
                                "DEF after the first executable block (line {})",
                                first + 1
                            ))
                            .label("too late")
                            .help(format!("move this DEF above line {}", first + 1)),
                    );
                }
            }
            _ if is_declaration(statement) => {}
            _ => {
                self.first_executable.get_or_insert(at.row);
            }
        }
    }
}
