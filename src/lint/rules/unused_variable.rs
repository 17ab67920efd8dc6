//! N016 `unused-variable`: Finds local variables (DEF without NCK/CHAN) that the program never reads.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use std::collections::HashSet;

use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::syntax::tree::{upper, StatementKind};

pub static RULE: RuleInfo = RuleInfo {
    code: "N016",
    name: "unused-variable",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds local variables (DEF without NCK/CHAN) that the program never reads. The target of an
indirect call (`CALL _PNAME`, `PCALL`, `MCALL`, `EXTCALL`, with the name built as
`CALL "PART"<<_NR`) is read when the call runs: a variable named there is read.

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

/// The definitions and the names read are the model's, but for the names
/// in an indirect call's target, which the parser keeps as written.
#[derive(Default)]
pub struct Checker {
    called_through: HashSet<String>,
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::STATEMENTS
    }

    /// The names an indirect call (`CALL "PART" << _SUFFIX`) reads.
    fn statement(&mut self, file: &FileContext, at: &StatementAt, _out: &mut Vec<Diagnostic>) {
        if let StatementKind::IndirectCall {
            target: Some(target),
            ..
        } = &at.statement.kind
        {
            let names = names_outside_strings(target.of(file.source));
            self.called_through.extend(names);
        }
    }

    fn finish(&mut self, file: &FileContext, out: &mut Vec<Diagnostic>) {
        let model = file.model();
        let local = model.symbols.iter().filter(|s| !s.global && !s.parameter);
        let read =
            |name: &String| model.read_names.contains(name) || self.called_through.contains(name);
        for symbol in local.filter(|s| !read(&s.name)) {
            out.push(
                RULE.at(symbol.span)
                    .message(format!("`{}` is defined but never read", symbol.name))
                    .label("never read")
                    .help("remove it, or read it where it was meant to be read"),
            );
        }
    }
}

/// The names in `text` (upper case), but for those in string literals:
/// `"PART"<<_NR` names `_NR`.
fn names_outside_strings(text: &[u8]) -> Vec<String> {
    // Pieces between quotes alternate: outside, inside, outside, ...
    text.split(|&b| b == b'"')
        .step_by(2)
        .flat_map(|outside| {
            outside.split(|b| !(b.is_ascii_alphanumeric() || *b == b'_' || *b == b'$'))
        })
        .filter(|word| word.first().is_some_and(|b| !b.is_ascii_digit()))
        .map(upper)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::names_outside_strings;

    #[test]
    fn names_of_an_indirect_calls_target_leave_strings_out() {
        assert_eq!(names_outside_strings(b"_PNAME"), ["_PNAME"]);
        assert_eq!(
            names_outside_strings(b"\"PART_\"<<_NR << _sub[2]"),
            ["_NR", "_SUB"]
        );
        assert!(names_outside_strings(b"\"L100\"").is_empty());
    }
}
