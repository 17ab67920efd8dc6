//! N005 `undefined-variable`: Finds a user variable read before any DEF, PROC parameter or assignment defines it.

use std::collections::HashSet;

use crate::diagnostic::{Applicability, Diagnostic, Fix, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::suggest::closest;
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
(`$...`), cycle data (`_...`) and one-letter addresses are not checked. A name defined before it
within two edits (one for names of up to four letters) is offered as did-you-mean, and as an
unsafe fix (`check --fix --unsafe-fixes`)."#,
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
                    out.push(self.undefined(name, variable.name.span));
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

impl Checker {
    /// The finding for `name` at `span`, with the defined name it may have
    /// been meant as (`DEPTHH` for a defined `DEPTH`).
    fn undefined(&self, name: String, span: Span) -> Diagnostic {
        let most = if name.len() <= 4 { 1 } else { 2 };
        let diagnostic = RULE
            .at(span)
            .message(format!("`{name}` is read before any DEF or assignment"))
            .label("not defined yet");
        match closest(&name, &self.defined, most) {
            Some(meant) => diagnostic
                .help(format!("did you mean `{meant}`? Otherwise declare it, as `DEF REAL {name}`, before this block"))
                .fix(Fix::replace(
                    format!("write `{meant}`"),
                    Applicability::Unsafe,
                    span,
                    meant.as_bytes(),
                )),
            None => diagnostic.help(format!("declare it, as `DEF REAL {name}`, before this block (or it must be a global defined elsewhere)")),
        }
    }
}
