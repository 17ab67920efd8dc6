//! N019 `call-shares-block`: Finds STOPRE, a cycle call or a call of a subprogram the program declares, sharing its block with other statements.

use std::collections::HashSet;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{BlockAt, Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::semantic::model::is_stopre;
use crate::syntax::tree::{Call, Statement, StatementKind, Word};

pub static RULE: RuleInfo = RuleInfo {
    code: "N019",
    name: "call-shares-block",
    severity: Severity::Error,
    docs: r#"## What it does
Finds STOPRE, a cycle call (`CYCLE800(...)`, `CYCLE832(...)`) or a call of a subprogram the program
declares (EXTERN, or its own PROC) sharing its block with other statements.

## Why it matters
The control requires STOPRE in a block of its own, and a subprogram call in a separate block
(Siemens, Job Planning, "STOPRE" and "Subprogram call"; a cycle is a subprogram). A block number, a
label, a comment and the call's repetition count (`P=3`) may stand beside it. The routine named
in a SETINT block (`SETINT(1) PRIO=4 CYCLE_T LIFTFAST`) is the interrupt routine SETINT assigns,
not a call in the block (Job Planning, "SETINT"). Calls of other names
are not checked, since a bare name may be a command of the control; CYCLE600 is C616's.

## Example
```
N10 G0 X10 CYCLE800(0,"TC1",0,57,0,0,0,30,45,60,0,0,0,-1)
N20 G1 Z5 STOPRE
```

## Fix
Put the call (or STOPRE) in a block of its own."#,
};

/// Subprograms the program declares, as met so far.
#[derive(Default)]
pub struct Checker {
    declared: HashSet<String>,
}

/// The statements that may stand beside a call: the repetition count.
fn beside_a_call(source: &[u8], statement: &Statement) -> bool {
    match &statement.kind {
        StatementKind::Word(Word { address, .. }) => address.is(source, "P"),
        StatementKind::Assign(assign) => assign.target.name.is(source, "P"),
        _ => false,
    }
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::DECLARATIONS | Sees::BLOCKS
    }

    fn declaration(&mut self, file: &FileContext, at: &StatementAt, _out: &mut Vec<Diagnostic>) {
        match &at.statement.kind {
            StatementKind::Extern { name, .. } => {
                self.declared.insert(upper(file.source, name.span));
            }
            StatementKind::Proc(proc) => {
                self.declared.insert(upper(file.source, proc.name.span));
            }
            _ => {}
        }
    }

    fn block(&mut self, file: &FileContext, at: &BlockAt, out: &mut Vec<Diagnostic>) {
        let (source, block) = (file.source, at.block);
        // A plain line (read into a tree where a macro may stand) is address
        // words alone.
        if at.line.plain || block.statements.len() < 2 {
            return;
        }
        // `SETINT(1) PRIO=4 CYCLE_T LIFTFAST`: the routine an interrupt
        // starts is SETINT's to name, not a call of its own.
        let interrupt = block.statements.iter().any(|s| match &s.kind {
            StatementKind::Call(Call { name, .. }) | StatementKind::Command(name) => {
                name.is(source, "SETINT")
            }
            _ => false,
        });
        let alone = |statement: &Statement| {
            if is_stopre(source, statement) {
                return Some("STOPRE".to_string());
            }
            if interrupt {
                return None;
            }
            let name = match &statement.kind {
                StatementKind::Call(Call { name, .. }) | StatementKind::Command(name) => {
                    upper(source, name.span)
                }
                _ => return None,
            };
            let cycle = name.starts_with("CYCLE") && name != "CYCLE600";
            (cycle || self.declared.contains(&name)).then_some(name)
        };
        let Some((statement, name)) = block.statements.iter().find_map(|s| Some((s, alone(s)?)))
        else {
            return;
        };
        let others: Vec<&Statement> = block
            .statements
            .iter()
            .filter(|s| !std::ptr::eq(*s, statement))
            .filter(|s| name == "STOPRE" || !beside_a_call(source, s))
            .collect();
        if others.is_empty() {
            return;
        }
        let what = if name == "STOPRE" {
            "STOPRE"
        } else {
            "a subprogram call"
        };
        let rest = others
            .iter()
            .map(|s| String::from_utf8_lossy(s.span.of(source)))
            .collect::<Vec<_>>()
            .join(" ");
        out.push(
            RULE.at(statement.span)
                .message(format!("`{name}` shares its block with `{rest}`: {what} must stand in a block of its own"))
                .label("not alone in its block")
                .help(format!("move `{rest}` to a block of its own")),
        );
    }
}
