//! N005 `undefined-variable`: Finds a user variable read before any DEF, PROC parameter or assignment defines it.

use std::collections::HashSet;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N005",
    name: "undefined-variable",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a user variable read before any DEF, PROC parameter or assignment defines it.

## Why it matters
The control stops with alarm 12550 ("name not defined") unless the name is a global (GUD) defined
in a definition file; a typo in a name reads as an undefined variable.

## Example
```
DEF REAL LAYER_HEIGHT
N10 Z=IC(LAYER_HIGHT)   ; typo
```

## Fix
Declare the variable with DEF (or correct its spelling). Names of R parameters, system variables
(`$...`), cycle data (`_...`) and one-letter addresses are not checked."#,
};

#[derive(Default)]
pub struct Checker {
    defined: HashSet<String>,
    reported: HashSet<String>,
}

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block.filter(|_| !line.plain) else {
            return;
        };
        for (index, statement) in block.statements.iter().enumerate() {
            for variable in line.reads(index) {
                let name = upper(file.source, variable.name.span);
                if is_user_name(&name)
                    && !self.defined.contains(&name)
                    && self.reported.insert(name.clone())
                {
                    out.push(
                        RULE.at(variable.name.span)
                            .message(format!("`{name}` is read before any DEF or assignment"))
                            .label("not defined yet")
                            .help(format!("declare it, as `DEF REAL {name}`, before this block (or it must be a global defined elsewhere)")),
                    );
                }
            }
            match &statement.kind {
                StatementKind::Def(def) => self.defined.extend(
                    def.variables
                        .iter()
                        .map(|d| upper(file.source, d.name.span)),
                ),
                StatementKind::Proc(proc) => self.defined.extend(
                    proc.parameters
                        .iter()
                        .map(|p| upper(file.source, p.declarator.name.span)),
                ),
                StatementKind::Assign(assign) => {
                    self.defined
                        .insert(upper(file.source, assign.target.name.span));
                }
                StatementKind::For { variable, .. } => {
                    self.defined.insert(upper(file.source, variable.span));
                }
                _ => {}
            }
        }
    }
}
