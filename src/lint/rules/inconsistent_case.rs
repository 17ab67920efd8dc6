//! N015 `inconsistent-case`: Finds a variable written with other capitals than in its definition.

use std::collections::HashMap;

use crate::diagnostic::{Applicability, Diagnostic, Fix, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N015",
    name: "inconsistent-case",
    severity: Severity::Info,
    docs: r#"## What it does
Finds a variable written with other capitals than in its definition. Off by default: it runs
when `--select N015` (or `select = ["N015"]` in sinuprep.toml) names it in full.

## Why it matters
The control ignores case, so the program works; but readers and search tools do not, and two
spellings of one name often hide a typo that happens to match.

## Example
```
DEF REAL lAYER_HEIGHT
N10 LAYER_HEIGHT=2.5
```

## Fix
Write the name as it is defined. `check --fix` does it (a safe fix: the control ignores case)."#,
};

#[derive(Default)]
pub struct Checker {
    spelling: HashMap<String, String>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    fn statement(&mut self, file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let statement = at.statement;
        if let StatementKind::Def(def) = &statement.kind {
            for d in &def.variables {
                let text = String::from_utf8_lossy(d.name.span.of(file.source)).into_owned();
                self.spelling
                    .entry(text.to_ascii_uppercase())
                    .or_insert(text);
            }
            return;
        }
        let mut used: Vec<&crate::syntax::tree::Variable> = at.reads().collect();
        if let StatementKind::Assign(assign) = &statement.kind {
            used.push(&assign.target);
        }
        for variable in used {
            let text = String::from_utf8_lossy(variable.name.span.of(file.source));
            if let Some(defined) = self.spelling.get(&text.to_ascii_uppercase()) {
                if *defined != text {
                    // The control ignores case: the fix changes nothing it runs.
                    out.push(
                        RULE.at(variable.name.span)
                            .message(format!("`{text}` is defined as `{defined}`"))
                            .label("other capitals")
                            .help(format!("write `{defined}`"))
                            .fix(Fix::replace(
                                format!("write `{defined}`"),
                                Applicability::Safe,
                                variable.name.span,
                                defined.as_bytes(),
                            )),
                    );
                }
            }
        }
    }
}
