//! N007 `duplicate-def`: Finds a variable defined twice (DEF or PROC parameter), names compared without case.

use std::collections::HashMap;

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{FileContext, OnModel};
use crate::span::Span;

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

/// The definitions are the model's ([`crate::semantic::Model::symbols`]).
pub struct Checker;

impl OnModel for Checker {
    fn check(file: &FileContext, out: &mut Vec<Diagnostic>) {
        let mut first: HashMap<&str, (usize, Span)> = HashMap::new();
        for symbol in &file.model().symbols {
            match first.get(symbol.name.as_str()) {
                Some(&(row, span)) => out.push(
                    RULE.at(symbol.span)
                        .message(format!(
                            "`{}` is already defined on line {}",
                            symbol.name,
                            row + 1
                        ))
                        .label("defined again")
                        .help("remove one definition, or rename one of the variables")
                        .related(span, format!("`{}` is first defined here", symbol.name)),
                ),
                None => {
                    first.insert(&symbol.name, (symbol.row, symbol.span));
                }
            }
        }
    }
}
