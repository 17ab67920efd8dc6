//! N017 `proc-name-mismatch`: Finds a PROC whose name differs from its file's name.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, LineView};
use crate::lint::rules::support::*;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N017",
    name: "proc-name-mismatch",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a PROC whose name differs from its file's name.

## Why it matters
The control calls a subprogram by its file name; a PROC header with another name is refused or
called under a name nobody reads in the source.

## Example
File `ALIGN.SPF`:
```
PROC ALIGN_HEAD(REAL _A) SAVE
```

## Fix
Rename the PROC or the file so that both match."#,
};

#[derive(Default)]
pub struct Checker;

impl Check for Checker {
    fn line(
        &mut self,
        file: &FileContext,
        _row: usize,
        line: &LineView,
        out: &mut Vec<Diagnostic>,
    ) {
        let Some(block) = line.block else {
            return;
        };
        for statement in &block.statements {
            let StatementKind::Proc(proc) = &statement.kind else {
                continue;
            };
            let Some(stem) = std::path::Path::new(file.name)
                .file_stem()
                .and_then(|s| s.to_str())
            else {
                continue;
            };
            if file.name == "<stdin>" {
                continue;
            }
            let name = upper(file.source, proc.name.span);
            let stem = stem.to_ascii_uppercase();
            let stem = stem
                .strip_prefix("_N_")
                .map(|s| s.trim_end_matches("_SPF"))
                .unwrap_or(&stem);
            if name != stem {
                // A file name that is no NC name (`3_KATUSHKA`) cannot be the PROC's.
                let help = if is_nc_name(stem) {
                    format!("rename the PROC to `{stem}`, or the file to `{name}.SPF`")
                } else {
                    format!("rename the file to `{name}.SPF` (`{stem}` is not a valid NC name: two letters or `_` first)")
                };
                out.push(
                    RULE.at(proc.name.span)
                        .message(format!("PROC `{name}` is in a file named `{stem}`"))
                        .label("differs from the file name")
                        .help(help),
                );
            }
        }
    }
}

/// A name the control accepts for a program: two letters or `_` first, then
/// letters, digits and `_`.
fn is_nc_name(name: &str) -> bool {
    crate::syntax::block::is_label_name(name.as_bytes())
        && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
}
