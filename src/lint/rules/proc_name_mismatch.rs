//! N017 `proc-name-mismatch`: Finds a PROC whose name differs from its file's name.

use crate::diagnostic::{Diagnostic, RuleInfo, Severity};
use crate::lint::rule::{Check, FileContext, Sees, StatementAt};
use crate::lint::rules::support::*;
use crate::span::Span;
use crate::syntax::tree::StatementKind;

pub static RULE: RuleInfo = RuleInfo {
    code: "N017",
    name: "proc-name-mismatch",
    severity: Severity::Warning,
    docs: r#"## What it does
Finds a PROC whose name differs from its file's name. In a file that holds several programs, each
after its `%_N_NAME_SPF` header (an archive in text form), the first PROC after a header is
compared with that header's name; only a program's first PROC is its header.

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

/// The program the lines belong to: the file, or the last `%_N_NAME_SPF`
/// header of a file that holds several programs (an archive in text form).
#[derive(Default)]
pub struct Checker {
    /// The name of the program the last header starts.
    program: Option<String>,
    /// Its PROC was met: later ones are no header of this program's.
    proc_seen: bool,
}

/// `NAME` of a header `_N_NAME_SPF` (or a file stem written that way).
fn program_name(text: &str) -> &str {
    let Some(name) = text.strip_prefix("_N_") else {
        return text;
    };
    ["_SPF", "_MPF"]
        .iter()
        .find_map(|suffix| name.strip_suffix(suffix))
        .unwrap_or(name)
}

impl Check for Checker {
    fn sees(&self) -> Sees {
        Sees::HEADERS | Sees::DECLARATIONS
    }

    fn header(&mut self, file: &FileContext, _row: usize, name: Span) {
        self.program = Some(program_name(&upper(file.source, name)).to_string());
        self.proc_seen = false;
    }

    fn declaration(&mut self, file: &FileContext, at: &StatementAt, out: &mut Vec<Diagnostic>) {
        let StatementKind::Proc(proc) = &at.statement.kind else {
            return;
        };
        if std::mem::replace(&mut self.proc_seen, true) {
            return;
        }
        let stem = match &self.program {
            Some(program) => program.clone(),
            None => {
                let Some(stem) = std::path::Path::new(file.name)
                    .file_stem()
                    .and_then(|s| s.to_str())
                else {
                    return;
                };
                if file.name == "<stdin>" {
                    return;
                }
                program_name(&stem.to_ascii_uppercase()).to_string()
            }
        };
        let stem = stem.as_str();
        let name = upper(file.source, proc.name.span);
        if name != stem {
            // A file name that is no NC name (`3_KATUSHKA`) cannot be the PROC's.
            let help = if is_nc_name(stem) {
                format!("rename the PROC to `{stem}`, or the file to `{name}.SPF`")
            } else {
                format!("rename the file to `{name}.SPF` (`{stem}` is not a valid NC name: two letters or `_` first)")
            };
            let container = if self.program.is_some() {
                "program"
            } else {
                "file"
            };
            out.push(
                RULE.at(proc.name.span)
                    .message(format!("PROC `{name}` is in a {container} named `{stem}`"))
                    .label("differs from the file name")
                    .help(help),
            );
        }
    }
}

/// A name the control accepts for a program: two letters or `_` first, then
/// letters, digits and `_`.
fn is_nc_name(name: &str) -> bool {
    crate::syntax::block::is_label_name(name.as_bytes())
        && name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'_')
}
